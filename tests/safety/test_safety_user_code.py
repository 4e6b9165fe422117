"""User code runs only when verifying, in child processes: a timeout, a memory limit, stdin
closed, stdout/stderr captured (never on our terminal), a cap on what it may write, and no
way to reach the worker's protocol pipe. Every hostile module becomes a finding; the run
finishes, and the hostile file is left as it was.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time

import pytest
from safety_support import (
    ISOLATION,
    LEGACY,
    assert_no_traceback,
    cli,
    copy_fixtures,
    expected_migration,
)

HEADER = '''import os, sys
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


class {name}(SkillDescription):
    def createDescription(self):
        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)

'''

HOSTILE = {
    # reads stdin at import: must see EOF at once, not hang on our (open) stdin
    "reads_stdin.py": "DATA = sys.stdin.read()\nLINE = input('robot name? ')\n",
    # tries to answer for the worker on every descriptor it may have inherited
    "writes_to_inherited_fds.py": (
        "for fd in range(3, 64):\n"
        "    try:\n"
        "        os.write(fd, b'{\"status\": \"ok\", \"models\": []}\\n')\n"
        "    except OSError:\n"
        "        pass\n"),
    # prints without end: the file size cap stops it long before the timeout
    "floods_stdout.py": "for _ in range(200):\n    sys.stdout.write('x' * 1000000)\n",
    # a fake traceback on both streams, then a real error: neither reaches our terminal
    "prints_fake_traceback.py": (
        "print('Traceback (most recent call last):')\n"
        "print('Traceback (most recent call last):', file=sys.stderr)\n"
        "raise ValueError('configuration missing')\n"),
    # kills itself hard while being imported
    "kills_itself.py": "import signal\nos.kill(os.getpid(), signal.SIGKILL)\n",
}


def _hostile(folder):
    for index, (name, tail) in enumerate(HOSTILE.items()):
        (folder / name).write_text(HEADER.format(name=f"Hostile{index}") + tail,
                                   encoding="utf-8")
    return {name: (folder / name).read_bytes() for name in HOSTILE}


@pytest.fixture(scope="module")
def hostile_run(tmp_path_factory):
    """One verifying rewrite over hostile modules, the isolation fixtures and a good file,
    started with an open stdin pipe that nobody ever writes to or closes."""
    folder = tmp_path_factory.mktemp("hostile")
    originals = _hostile(folder)
    originals |= copy_fixtures(folder, sorted(ISOLATION.glob("*.py")))
    originals |= copy_fixtures(folder, [LEGACY / "descriptions.py"])
    report = folder.parent / f"{folder.name}.json"
    started = time.monotonic()
    process = subprocess.Popen(
        [sys.executable, "-m", "ezmigrate", "rewrite", str(folder), "--timeout", "5",
         "--report", str(report)],
        stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        stdout, stderr = process.communicate(timeout=600)  # never closes stdin before exit
    finally:
        if process.poll() is None:
            process.kill()
    elapsed = time.monotonic() - started
    data = json.loads(report.read_text(encoding="utf-8"))
    return folder, originals, process.returncode, stdout, stderr, data, elapsed


def _skills(data, name):
    return [s for s in data["skills"] if s["file"] == name]


def test_the_run_finishes_without_traceback_or_user_output_on_our_streams(hostile_run):
    _folder, _originals, code, stdout, stderr, _data, elapsed = hostile_run
    assert code == 1, stderr
    assert_no_traceback(stdout, stderr)
    assert stdout == ""  # nothing the modules printed reaches the user's terminal
    assert "loading lamp skills" not in stderr and "xxxxxxxxxx" not in stderr
    assert elapsed < 300


LEFT_ALONE = ["reads_stdin.py", "floods_stdout.py", "prints_fake_traceback.py",
              "kills_itself.py", "loops_forever.py", "raises_on_import.py"]


@pytest.mark.parametrize("name", LEFT_ALONE)
def test_each_file_that_does_not_load_is_a_finding_and_left_alone(hostile_run, name):
    folder, originals, _, _, stderr, data, _ = hostile_run
    assert (folder / name).read_bytes() == originals[name]
    statuses = {s["status"] for s in _skills(data, name)}
    assert "failed" in statuses and statuses <= {"failed", "skipped"}, _skills(data, name)
    assert f"{folder / name}:" in stderr


def test_reasons_say_what_the_module_did(hostile_run):
    _, _, _, _, _, data, _ = hostile_run

    def reason(name):
        return " ".join(s["reason"] or "" for s in _skills(data, name))

    assert "EOFError" in reason("reads_stdin.py")
    assert "timeout" in reason("loops_forever.py")
    assert "File too large" in reason("floods_stdout.py") or "OSError" in reason(
        "floods_stdout.py")
    assert "SIGKILL" in reason("kills_itself.py")
    assert "ValueError: configuration missing" in reason("prints_fake_traceback.py")
    assert "sys.exit" in reason("calls_sys_exit.py")
    assert "RuntimeError: cell configuration not found" in reason("raises_on_import.py")
    # 4 GiB under the 2 GiB cap: the allocation fails inside the child, not the machine
    assert "MemoryError" in reason("allocates_memory.py"), _skills(data, "allocates_memory.py")
    assert {s["class"]: s["status"] for s in _skills(data, "allocates_memory.py")} == {
        "BuildMap": "failed", "SaveMap": "converted"}


def test_forged_protocol_lines_are_not_believed(hostile_run):
    folder, originals, _, _, _, data, _ = hostile_run
    skills = _skills(data, "writes_to_inherited_fds.py")
    # the module itself loads fine: its forged lines went nowhere, the real verdict stands
    assert [(s["status"], s["equivalent"]) for s in skills] == [("converted", True)]
    new = (folder / "writes_to_inherited_fds.py").read_bytes()
    assert new == expected_migration(originals["writes_to_inherited_fds.py"])


def test_a_class_that_exits_is_skipped_and_its_neighbour_converted(hostile_run):
    _, _, _, _, _, data, _ = hostile_run
    statuses = {s["class"]: s["status"] for s in _skills(data, "calls_sys_exit.py")}
    assert statuses == {"Shutdown": "skipped", "Reboot": "converted"}


def test_output_of_a_failing_module_is_captured_into_the_report(hostile_run):
    _, _, _, _, _, data, _ = hostile_run
    notes = " ".join(n for f in data["files"] if f["file"] == "prints_fake_traceback.py"
                     for n in f["notes"])
    assert "Traceback (most recent call last):" in notes  # its stdout, kept for the reviewer


def test_the_good_file_next_to_them_is_rewritten(hostile_run):
    folder, originals, *_ = hostile_run
    new = (folder / "descriptions.py").read_bytes()
    assert new == expected_migration(originals["descriptions.py"], "descriptions.py")


def test_dry_run_without_verification_runs_no_user_code_even_when_hostile(tmp_path):
    _hostile(tmp_path)
    run = cli("rewrite", tmp_path, "--dry-run", "--no-verify", stdin=subprocess.PIPE,
              timeout=300)
    assert run.returncode == 0, run.stderr
    assert_no_traceback(run.stderr)
    assert "xxxxxxxxxx" not in run.stdout


FORKS = """
import time
_held = os.open({fifo!r}, os.O_WRONLY | os.O_NONBLOCK)
if os.fork() == 0:  # a daemon started at import; it never ends by itself
    os.write(_held, b"x")  # and it holds the FIFO open while it lives
    while True:
        time.sleep(0.05)
os.close(_held)
{tail}"""


@pytest.mark.parametrize(("tail", "verdict", "timeout"),
                         [("while True:\n    pass\n", "timeout", "3"),
                          ("", "converted", "120")])  # a load that must end: never timed
def test_processes_a_module_forks_do_not_outlive_its_load(tmp_path, tail, verdict, timeout):
    """Whatever a module forks is killed when its load ends, by timeout or normally (the
    child's PID namespace, or else its process group), so it leaves no orphan behind. A
    daemon holds the write end of a FIFO the test reads: its death is the FIFO's end of
    file (PIDs would not do: inside its namespace the daemon's PID is not the host's)."""
    folder, fifo = tmp_path / "tree", tmp_path / "held"
    folder.mkdir()
    os.mkfifo(fifo)
    reader = os.open(fifo, os.O_RDONLY | os.O_NONBLOCK)
    (folder / "forks.py").write_text(
        HEADER.format(name="Forks") + FORKS.format(fifo=str(fifo), tail=tail),
        encoding="utf-8")
    report = tmp_path / "r.json"
    try:
        run = cli("rewrite", folder, "--dry-run", "--timeout", timeout, "--report", report,
                  timeout=300)
        assert_no_traceback(run.stderr)
        skills = json.loads(report.read_text(encoding="utf-8"))["skills"]
        assert verdict in " ".join(f"{s['status']} {s['reason']}" for s in skills), skills
        written = b""
        deadline = time.monotonic() + 5  # a bound on failure: the kill is done on return
        while time.monotonic() < deadline:
            try:
                chunk = os.read(reader, 64)
            except BlockingIOError:  # a writer still lives
                time.sleep(0.05)
                continue
            if not chunk:
                break
            written += chunk
        else:
            pytest.fail("a process the module forked outlived its load")
        assert written.startswith(b"x"), "the module forked"
    finally:
        os.close(reader)
