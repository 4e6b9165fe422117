"""An interrupted run (SIGINT or SIGTERM at any moment) leaves every file wholly old or
wholly new, leaves no temporary file, says what it wrote, exits 128 + the signal; a second
run finishes the job.

The corpus is the legacy fixtures copied three times into three folders, plus one skill
module whose import waits for the test. Each scenario starts ``rewrite`` in a subprocess
and holds it, by construction and not by timing, exactly where the signal must land: at a
named hold point of the run (``ezmigrate.project.holdpoint``: after discovery, while the migration
workers are busy, inside or after the N-th write) or, for the verification phase, inside
that skill module's import in a verification child. It then signals (twice in one
scenario), releases the hold, and checks every byte on disk against the original and the
reference migration, the list of written files it printed against the disk, and that a
second run finishes the job. No scenario depends on how fast the machine is.
"""

from __future__ import annotations

import ast
import os
import re
import shutil
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest
from safety_support import (
    ISOLATION,
    LEGACY,
    assert_no_traceback,
    cli,
    leftovers,
    snapshot,
    start_cli,
)

pytestmark = pytest.mark.slow

COPIES = 3
WORKER_MARK = "317.25"  # an unusual --timeout: lets the test find this run's workers
IMPORT_HOLD = ".hold"
HOLDING_MODULE = "waits_for_the_test.py"
"""A legacy skill module whose import, when the folder IMPORT_HOLD is beside it, says so
there (``imported``) and waits for ``go``: a verification child loading it holds the run
in its verification phase for as long as the test needs. (A folder, not an environment
variable: the child gets none of the test's variables; a hidden folder, which ``rewrite``
never enters.)"""
_HOLDING_PREAMBLE = f"""import pathlib as _pathlib
import time as _time

_HOLD = _pathlib.Path(__file__).with_name("{IMPORT_HOLD}")
if _HOLD.is_dir():
    _pathlib.Path(_HOLD, "imported").touch()
    while not _pathlib.Path(_HOLD, "go").exists():
        _time.sleep(0.005)
"""


def _build(folder: Path) -> None:
    for copy in range(COPIES):
        for index, source in enumerate(sorted(LEGACY.glob("*.py"))):
            sub = folder / ("" if index % 3 == 0 else f"pkg{index % 3}")
            sub.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(source, sub / f"{source.stem}_{copy}.py")
    (folder / HOLDING_MODULE).write_text(
        _HOLDING_PREAMBLE + (LEGACY / "descriptions.py").read_text(encoding="utf-8"),
        encoding="utf-8")


@pytest.fixture(scope="module")
def corpus(tmp_path_factory):
    """(template folder, original bytes, reference bytes after a full run, its exit code)."""
    template = tmp_path_factory.mktemp("template")
    _build(template)
    originals = snapshot(template)
    reference = tmp_path_factory.mktemp("reference")
    shutil.copytree(template, reference, dirs_exist_ok=True)
    run = cli("rewrite", reference, "--no-verify")
    assert_no_traceback(run.stderr)
    expected = snapshot(reference)
    assert sum(expected[n] != originals[n] for n in originals) > len(originals) // 2
    return template, originals, expected, run.returncode


def _hold_until(process, marker: Path) -> None:
    """Wait until the run created ``marker`` (it is then held); fail if it ended first."""
    deadline = time.monotonic() + 600
    while not marker.exists():
        assert process.poll() is None, (
            f"the run ended (exit {process.returncode}) before reaching {marker.name}: "
            f"{process.stderr.read()[-2000:] if process.stderr else ''}")
        assert time.monotonic() < deadline, f"the run never reached {marker.name}"
        time.sleep(0.005)


def _wait_until_handling(process) -> None:
    """Until the process catches SIGTERM: its handlers are in (Python's start-up is over).

    A signal before that finds Python's defaults (nothing is written yet, either way)."""
    deadline = time.monotonic() + 120
    while process.poll() is None and time.monotonic() < deadline:
        try:
            status = Path(f"/proc/{process.pid}/status").read_text()
        except OSError:
            return
        caught = next((int(line.split()[1], 16) for line in status.splitlines()
                       if line.startswith("SigCgt:")), 0)
        if caught & (1 << (signal.SIGTERM - 1)):
            return
        time.sleep(0.002)


def _workers_of_this_test() -> list[str]:
    found = []
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            command = (entry / "cmdline").read_bytes().replace(b"\0", b" ").decode()
        except OSError:
            continue
        if "ezmigrate.verify.zygote" in command and f"--timeout {WORKER_MARK}" in command:
            found.append(command)
    return found


def _check_consistent(folder: Path, originals: dict[str, bytes], expected: dict[str, bytes],
                      stderr: str) -> tuple[set[str], set[str]]:
    """Every file old or new and parsing; no temporaries; the report matches the disk."""
    now = snapshot(folder)
    assert sorted(now) == sorted(originals), "no file appeared or disappeared"
    assert leftovers(folder) == []
    new: set[str] = set()
    for name, data in now.items():
        assert data in (originals[name], expected[name]), f"{name} is neither old nor new"
        ast.parse(data)  # parses as Python, whichever it is
        if data != originals[name]:
            new.add(name)
    reported = set(re.findall(r"^ezmigrate: written: (.+)$", stderr, re.M))
    assert reported == new, "the files said to be written are exactly the new ones"
    left = {n for n in now if expected[n] != originals[n]} - new
    return new, left


SCENARIOS = [  # (id, signal, verify, where the run is held, signals sent)
    ("sigterm-after-discovery", signal.SIGTERM, False, "discovered", 1),
    ("sigint-while-migrating", signal.SIGINT, False, "migrating", 1),
    ("sigterm-after-migration", signal.SIGTERM, True, "migrated", 1),
    ("sigint-while-verifying", signal.SIGINT, True, "verifying", 1),
    ("sigint-first-write", signal.SIGINT, False, "written:1", 1),
    ("sigterm-during-second-write", signal.SIGTERM, False, "writing:2", 1),
    ("sigint-twice-during-second-write", signal.SIGINT, False, "writing:2", 2),
    ("sigterm-verifying-first-write", signal.SIGTERM, True, "written:1", 1),
]


@pytest.mark.parametrize(("signum", "verify", "point", "signals"),
                         [s[1:] for s in SCENARIOS], ids=[s[0] for s in SCENARIOS])
def test_interrupted_run_leaves_old_or_new_files_and_a_second_run_finishes(
        corpus, tmp_path, signum, verify, point, signals):
    template, originals, expected, reference_code = corpus
    folder = tmp_path / "tree"
    shutil.copytree(template, folder)
    hold = tmp_path / "hold"
    hold.mkdir()
    args = ["rewrite", folder, "--timeout", WORKER_MARK]
    if not verify:
        args.append("--no-verify")
    env = dict(os.environ)
    if point == "verifying":  # the holding module's import, in a verification child
        hold = folder / IMPORT_HOLD
        hold.mkdir()
        reached, release = hold / "imported", hold / "go"
    else:
        env.update(EZMIGRATE_HOLD_DIR=str(hold), EZMIGRATE_HOLD_AT=point)
        reached, release = hold / f"{point}.reached", hold / f"{point}.go"

    process = start_cli(*args, env=env)
    try:
        _hold_until(process, reached)
        for _ in range(signals):
            process.send_signal(signum)
        release.touch()
        stdout, stderr = process.communicate(timeout=600)
    finally:
        release.touch()
        if process.poll() is None:
            process.kill()
            process.wait()
    if hold.parent == folder:  # the holding module's folder is no file of the tree
        shutil.rmtree(hold)

    note = f"(held at {point}; stderr: {stderr[-2000:]})"
    assert process.returncode == 128 + signum, note
    assert_no_traceback(stdout, stderr)
    name = signal.Signals(signum).name
    assert f"ezmigrate: interrupted by {name}" in stderr, note
    new, left = _check_consistent(folder, originals, expected, stderr)
    if point.startswith("writ"):  # the held write (and those before it) completed
        assert len(new) == int(point.partition(":")[2]), note
        assert f"{len(new)} files written (each wholly new), {len(left)} not yet written" \
            in stderr, note
    else:
        assert not new, note
        assert "before any file was written: every file is as it was" in stderr, note
    if verify:
        deadline = time.monotonic() + 60
        while _workers_of_this_test() and time.monotonic() < deadline:
            time.sleep(0.2)
        assert _workers_of_this_test() == [], "verification workers outlived the run"

    again = [a for a in args if a not in ("--timeout", WORKER_MARK)]
    if point == "verifying":
        again.append("--no-verify")  # the quick way to finish (the other case verifies)
    second = cli(*again)

    assert_no_traceback(second.stderr)
    if "--no-verify" in again:
        assert second.returncode == reference_code, second.stderr
        assert snapshot(folder) == expected, "the second run finished the job"
    else:
        assert second.returncode in (0, 1), second.stderr
        _check_consistent(folder, originals, expected, "".join(
            f"ezmigrate: written: {n}\n" for n, d in snapshot(folder).items()
            if d != originals[n]))
    assert leftovers(folder) == []


def test_a_killed_run_leaves_whole_files_and_the_next_run_removes_its_temporaries(
        corpus, tmp_path):
    """SIGKILL cannot be caught: it may leave a temporary file, never a half-written .py.
    A dry run lists the temporary files; the next run that writes removes them and
    finishes the job."""
    template, originals, expected, reference_code = corpus
    folder = tmp_path / "tree"
    shutil.copytree(template, folder)
    hold = tmp_path / "hold"
    hold.mkdir()
    env = dict(os.environ, EZMIGRATE_HOLD_DIR=str(hold), EZMIGRATE_HOLD_AT="written:1")
    process = start_cli("rewrite", folder, "--no-verify", env=env)
    try:
        _hold_until(process, hold / "written:1.reached")
        process.send_signal(signal.SIGKILL)
        process.communicate(timeout=600)
    finally:
        if process.poll() is None:
            process.kill()
            process.wait()
    assert process.returncode == -signal.SIGKILL
    assert sum(snapshot(folder)[n] != originals[n] for n in originals) == 1, "one file written"
    for name, data in snapshot(folder).items():
        if name.endswith(".py"):
            assert data in (originals[name], expected[name]), f"{name} is neither old nor new"
            ast.parse(data)
    # what a kill in the middle of a write leaves: a temporary file beside its original
    changed = next(n for n in sorted(originals) if expected[n] != originals[n])
    stale = folder / Path(changed).parent / f".{Path(changed).name}.k1ll3d00.ezmigrate"
    stale.write_bytes(expected[changed][: len(expected[changed]) // 2])

    dry = cli("rewrite", folder, "--no-verify", "--dry-run")
    assert f"{stale}: temporary file left by an interrupted run" in dry.stderr, dry.stderr
    assert stale.exists(), "a dry run writes (and removes) nothing"
    second = cli("rewrite", folder, "--no-verify")

    assert_no_traceback(second.stderr)
    assert second.returncode == reference_code, second.stderr
    assert f"{stale}: removed" in second.stderr, second.stderr
    assert snapshot(folder) == expected, "the second run finished the job"
    assert leftovers(folder) == []


@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM, signal.SIGHUP])
def test_stdin_mode_interrupted_while_reading_exits_cleanly(signum):
    """``rewrite -`` waiting for its input: stopped, it writes nothing and says so."""
    process = subprocess.Popen([sys.executable, "-m", "ezmigrate", "rewrite", "-"],
                               stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True)
    try:
        _wait_until_handling(process)
        time.sleep(0.3)
        process.send_signal(signum)
        stdout, stderr = process.communicate(timeout=120)
    finally:
        if process.poll() is None:
            process.kill()
            process.wait()
    assert process.returncode == 128 + signum, stderr
    assert stdout == ""
    assert_no_traceback(stderr)
    assert f"interrupted by {signal.Signals(signum).name} before any file was written" in stderr


def _processes() -> dict[int, tuple[int, int, str]]:
    """pid -> (parent pid, process group, state) of every process, from ``/proc``."""
    found = {}
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            stat = (entry / "stat").read_text()
        except OSError:
            continue
        fields = stat[stat.rindex(")") + 2:].split()  # after "pid (comm) "
        found[int(entry.name)] = (int(fields[1]), int(fields[2]), fields[0])
    return found


def _descendants(pid: int) -> dict[int, tuple[int, int]]:
    """Living descendants of ``pid``: pid -> (process group, depth: 1 for a child)."""
    table = _processes()
    found: dict[int, tuple[int, int]] = {}
    todo = [(pid, 0)]
    while todo:
        parent, depth = todo.pop()
        for child, (ppid, pgid, state) in table.items():
            if ppid == parent and state != "Z" and child not in found:
                found[child] = (pgid, depth + 1)
                todo.append((child, depth + 1))
    return found


def _left(pids: set[int], groups: set[int]) -> list[int]:
    """Those of ``pids``, or members of ``groups``, still alive (zombies count as gone)."""
    return sorted(pid for pid, (_, pgid, state) in _processes().items()
                  if state != "Z" and (pid in pids or pgid in groups))


@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGINT])
def test_an_interrupted_verification_leaves_no_worker_or_child_running(tmp_path, signum):
    """A module looping at import, 30 s timeout: stopping the run stops its load at once."""
    folder = tmp_path / "tree"
    folder.mkdir()
    shutil.copyfile(ISOLATION / "loops_forever.py", folder / "loops_forever.py")
    process = start_cli("rewrite", folder, "--timeout", "30")
    ours: dict[int, tuple[int, int]] = {}
    try:
        deadline = time.monotonic() + 120
        while process.poll() is None and time.monotonic() < deadline:
            ours = _descendants(process.pid)
            if any(depth >= 2 for _, depth in ours.values()):
                break  # a worker's verification child is loading
            time.sleep(0.05)
        time.sleep(0.5)
        ours = _descendants(process.pid)
        assert process.poll() is None, "the run ended before a child was loading"
        process.send_signal(signum)
        stopped = time.monotonic()
        _, stderr = process.communicate(timeout=60)
    finally:
        if process.poll() is None:
            process.kill()
            process.wait()
    assert process.returncode == 128 + signum, stderr
    assert_no_traceback(stderr)
    groups = {pgid for pgid, _ in ours.values() if pgid != os.getpgid(0)}
    while _left(set(ours), groups) and time.monotonic() < stopped + 5:
        time.sleep(0.05)
    assert _left(set(ours), groups) == [], "workers or their children outlived the run"


def test_ctrl_c_while_the_command_is_still_importing_is_one_line(tmp_path: Path) -> None:
    """The import of the CLI (click, libcst: a noticeable part of a second) is held by a
    finder that waits on stdin until the test has signalled: the interrupt lands inside it."""
    code = textwrap.dedent("""\
        import sys

        class HoldClick:
            def find_spec(self, name, path=None, target=None):
                if name == "click":
                    sys.stdout.write("importing\\n")
                    sys.stdout.flush()
                    sys.stdin.readline()
                return None

        sys.meta_path.insert(0, HoldClick())
        sys.argv = ["ezmigrate", "check", "."]
        from ezmigrate.__main__ import main
        main()
        """)
    proc = subprocess.Popen([sys.executable, "-c", code], cwd=tmp_path, stdin=subprocess.PIPE,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    assert proc.stdout is not None
    assert proc.stdout.readline() == b"importing\n"
    proc.send_signal(signal.SIGINT)
    _out, err = proc.communicate(timeout=120)
    assert proc.returncode == 130, err
    assert err.decode().splitlines() == ["ezmigrate: interrupted by SIGINT before any file "
                                         "was written: every file is as it was"]
