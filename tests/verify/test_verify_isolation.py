"""Loading user code is isolated: each file in its own child with a timeout, its output
captured. A module that raises on import, one that loops forever in ``createDescription``,
one that calls ``sys.exit`` and one that prints to stdout each get a clear verdict, and the
run carries on with the other files. User code is imported only when verifying."""

from __future__ import annotations

import time
from pathlib import Path

import pytest
from verify_support import (
    ISOLATION,
    LEGACY,
    MIGRATED,
    cli,
    file_entry,
    read_json,
    skills_of,
    snapshot,
    tree,
)

from ezmigrate.codemod.migrate import migrate

HOSTILE = ("raises_on_import.py", "loops_forever.py", "calls_sys_exit.py", "prints_stdout.py")


def _migrated(path: Path) -> bytes:
    """The migrated text of a fixture (static: no user code runs), or the text itself."""
    data = path.read_bytes()
    new = migrate(data).new_source
    return new if isinstance(new, bytes) else data


@pytest.fixture(scope="module")
def verified(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("isolation")
    before = tree(tmp / "before", {**{n: ISOLATION / n for n in HOSTILE},
                                   "pick_and_place.py": LEGACY / "pick_and_place.py"})
    after = tree(tmp / "after", {**{n: _migrated(ISOLATION / n) for n in HOSTILE},
                                 "pick_and_place.py": MIGRATED / "pick_and_place.py"})
    started = time.monotonic()
    run = cli("verify", before, after, "--timeout", "2", "--report", tmp / "r.json")
    return run, read_json(tmp / "r.json"), time.monotonic() - started


def test_verify_gives_each_problem_file_a_clear_verdict_and_carries_on(verified):
    run, report, elapsed = verified
    assert run.returncode == 2, run.stderr  # some file could not be loaded
    raises = file_entry(report, "raises_on_import.py")["error"]
    assert "import-error" in raises and "RuntimeError: cell configuration not found" in raises
    loops = file_entry(report, "loops_forever.py")["error"]
    assert "timeout" in loops and "longer than 2 s" in loops
    exits = skills_of(report, "calls_sys_exit.py")
    assert exits["Shutdown"]["equivalent"] is None
    assert "cannot be verified" in exits["Shutdown"]["reason"]
    assert "SystemExit: 3" in exits["Shutdown"]["reason"]
    assert exits["Reboot"]["equivalent"] is True
    assert elapsed < 60  # the endless loop was stopped after 2 s, not waited for


def test_printing_modules_neither_reach_our_streams_nor_fool_the_verdict(verified):
    run, report, _ = verified
    assert run.stdout == ""
    assert "loading lamp skills" not in run.stderr and '{"ok"' not in run.stderr
    lamps = skills_of(report, "prints_stdout.py")
    assert {k: v["equivalent"] for k, v in lamps.items()} == {"DimLamp": True,
                                                              "ToggleLamp": True}


def test_the_normal_file_next_to_them_is_verified(verified):
    _, report, _ = verified
    normal = skills_of(report, "pick_and_place.py")
    assert set(normal) == {"Pick", "Place", "PickAndPlace"}
    assert all(s["equivalent"] is True for s in normal.values())


def test_a_verifying_rewrite_carries_on_past_every_problem_file(tmp_path):
    folder = tree(tmp_path / "skills", {**{n: ISOLATION / n for n in HOSTILE},
                                        "pick_and_place.py": LEGACY / "pick_and_place.py"})
    original = snapshot(folder)
    run = cli("rewrite", folder, "--timeout", "2", "--report", tmp_path / "r.json")
    assert run.returncode == 1, run.stderr
    assert run.stdout == "" and "loading lamp skills" not in run.stderr
    report = read_json(tmp_path / "r.json")
    assert (folder / "pick_and_place.py").read_bytes() == \
        (MIGRATED / "pick_and_place.py").read_bytes()
    for name, words in (("raises_on_import.py", "RuntimeError: cell configuration not found"),
                        ("loops_forever.py", "timeout")):
        assert (folder / name).read_bytes() == original[name]
        reasons = " ".join(s["reason"] or "" for s in skills_of(report, name).values())
        assert words in reasons, reasons
    statuses = {n: {k: (v["status"], v["equivalent"]) for k, v in skills_of(report, n).items()}
                for n in ("calls_sys_exit.py", "prints_stdout.py")}
    assert statuses == {
        "calls_sys_exit.py": {"Shutdown": ("skipped", None), "Reboot": ("converted", True)},
        "prints_stdout.py": {"DimLamp": ("skipped", None), "ToggleLamp": ("converted", True)}}
    assert (folder / "calls_sys_exit.py").read_bytes() == _migrated(ISOLATION /
                                                                    "calls_sys_exit.py")


@pytest.mark.parametrize(("command", "imported"), [
    (("rewrite", "--dry-run", "--no-verify"), False),
    (("rewrite", "--dry-run"), True),
    (("verify",), True),
])
def test_user_code_is_imported_only_when_verifying(tmp_path, command, imported):
    folder = tree(tmp_path / "skills", {"creates_marker.py": ISOLATION / "creates_marker.py"})
    (folder / ".markers").mkdir()
    marker = folder / ".markers" / "imported"
    args = (*command, folder, folder) if command == ("verify",) else (*command, folder)
    run = cli(*args)
    assert run.returncode == 0, run.stderr
    assert marker.exists() == imported
    if command[0] == "rewrite":  # the dry run did its work either way
        assert "+    def description(self," in run.stdout
