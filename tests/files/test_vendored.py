"""A vendored copy of SkiROS2's own Python is not the lab's code: passed over with one note.

Labs vendor the framework or its standard skill libraries next to their own packages.
``rewrite`` and ``check`` at the repository root leave those folders alone (one note each),
as ontology discovery leaves vendored core ``.owl`` files alone; naming the folder, or
``--include-vendored``, takes them in.
"""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from ezmigrate.files.discover import discover, vendored_package

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures"


@pytest.fixture
def lab(tmp_path: Path) -> Path:
    """A lab workspace: its own package, a vendored skiros2_std_skills (by folder name) and
    a vendored framework package renamed on disk (known by its package.xml)."""
    root = tmp_path / "ws"
    own = root / "cell" / "src" / "cell"
    own.mkdir(parents=True)
    shutil.copy(FIXTURES / "legacy" / "pick_and_place.py", own / "skills.py")
    std = root / "third_party_skills" / "skiros2_std_skills" / "src" / "skiros2_std_skills"
    std.mkdir(parents=True)
    shutil.copy(FIXTURES / "legacy" / "descriptions.py", std / "std.py")
    renamed = root / "framework_copy"
    (renamed / "src").mkdir(parents=True)
    (renamed / "package.xml").write_text("<package>\n  <name>skiros2_skill</name>\n</package>\n")
    shutil.copy(FIXTURES / "legacy" / "conditions.py", renamed / "src" / "core.py")
    return root


def _run(*args: object, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "ezmigrate", *map(str, args)], cwd=cwd,
                          capture_output=True, text=True, timeout=600, check=False)


def test_vendored_packages_are_known_by_folder_or_package_xml(lab: Path) -> None:
    assert vendored_package(lab / "third_party_skills" / "skiros2_std_skills") == \
        "skiros2_std_skills"
    assert vendored_package(lab / "framework_copy") == "skiros2_skill"
    assert vendored_package(lab / "cell") is None
    assert vendored_package(lab / "third_party_skills") is None


def test_a_run_at_the_root_passes_over_vendored_code_with_one_note_each(lab: Path) -> None:
    found, notes = discover([lab])
    assert [c.relative for c in found] == ["cell/src/cell/skills.py"]
    vendored = [note for note in notes if "vendored copy of SkiROS2" in note]
    assert len(vendored) == 2, notes
    included, _ = discover([lab], include_vendored=True)
    assert len(included) == 3


def test_naming_a_vendored_folder_includes_all_of_it(lab: Path) -> None:
    named = lab / "third_party_skills" / "skiros2_std_skills"
    found, notes = discover([named])
    assert [c.relative for c in found] == ["src/skiros2_std_skills/std.py"]
    assert not notes


@pytest.mark.parametrize("command", ["rewrite", "check"])
def test_rewrite_and_check_say_what_they_passed_over(lab: Path, command: str) -> None:
    extra = ("--dry-run", "--no-verify") if command == "rewrite" else ("--exit-zero",)
    run = _run(command, *extra, ".", cwd=lab)
    assert run.returncode == 0, run.stderr
    notes = [line for line in run.stderr.splitlines() if "vendored copy" in line]
    assert len(notes) == 2 and "--include-vendored" in notes[0], run.stderr
    assert "std.py" not in run.stdout and "core.py" not in run.stdout
    everything = _run(command, *extra, "--include-vendored", ".", cwd=lab)
    assert "vendored copy" not in everything.stderr
    if command == "rewrite":
        assert "std.py" in everything.stdout  # its diff is shown
