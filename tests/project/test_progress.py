"""The progress line: on a terminal after a second, throttled, never wider than the terminal,
erased at the end; never in a pipe, a file or CI. A fake clock holds time still, so no test
sleeps; the end-to-end tests run a child on a real pseudo-terminal and on a pipe."""

from __future__ import annotations

import io
import os
import re
import select
import shutil
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest

from ezmigrate.project.progress import ERASE, Progress

REPO = Path(__file__).resolve().parents[2]
TERMINAL = {"TERM": "xterm-256color"}


class Clock:
    """Time that moves only when a test says so."""

    def __init__(self) -> None:
        self.now = 0.0

    def __call__(self) -> float:
        return self.now


class Tty(io.StringIO):
    def isatty(self) -> bool:
        return True


@pytest.fixture(autouse=True)
def columns(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(shutil, "get_terminal_size", lambda *_: os.terminal_size((80, 24)))


def make(total: int = 10, env: dict[str, str] | None = None,
         stream: io.StringIO | None = None) -> tuple[Progress, Clock, io.StringIO]:
    clock, out = Clock(), Tty() if stream is None else stream
    return Progress.for_stream(total, out, clock=clock,
                               env=TERMINAL if env is None else env), clock, out


def step(progress: Progress, clock: Clock, at: float, files: int = 1, skills: int = 0) -> None:
    clock.now = at
    progress.advance(files, skills)


def drawn(out: io.StringIO) -> list[str]:
    """The texts of the lines drawn, in order."""
    return [part.removesuffix(ERASE) for part in out.getvalue().split("\r")[1:]]


def test_nothing_is_shown_within_the_first_second() -> None:
    progress, clock, out = make()
    for at in (0.1, 0.5, 1.0):
        step(progress, clock, at, skills=2)
    assert out.getvalue() == ""
    progress.close()
    assert out.getvalue() == ""  # nothing drawn, nothing to erase


def test_shown_in_place_after_a_second() -> None:
    progress, clock, out = make()
    step(progress, clock, 0.5, files=1, skills=1)
    step(progress, clock, 2.0, files=4, skills=2)
    assert out.getvalue() == ("\rezmigrate: 5/10 files, 3 skills converted, about 2 s left"
                              + ERASE)


def test_redrawn_at_most_ten_times_a_second() -> None:
    progress, clock, out = make(total=100)
    step(progress, clock, 2.0)
    for at in (2.01, 2.05, 2.09):
        step(progress, clock, at)
    assert len(drawn(out)) == 1
    step(progress, clock, 2.15)
    assert drawn(out)[-1].startswith("ezmigrate: 5/100 files")
    assert len(drawn(out)) == 2


def test_time_left_comes_from_the_rate_so_far() -> None:
    progress, clock, out = make(total=1000)
    step(progress, clock, 1.5, files=0)
    assert drawn(out) == ["ezmigrate: 0/1000 files, 0 skills converted"]  # no rate yet
    step(progress, clock, 2.0, files=10)  # 10 files in 2 s: 990 more take 198 s
    assert drawn(out)[-1].endswith(", about 3 min left")
    step(progress, clock, 4.0, files=790)  # 800 files in 4 s: 200 more take 1 s
    assert drawn(out)[-1] == "ezmigrate: 800/1000 files, 0 skills converted, about 1 s left"
    step(progress, clock, 5.0, files=200)
    assert drawn(out)[-1] == "ezmigrate: 1000/1000 files, 0 skills converted"


def test_truncated_to_the_terminal_width(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(shutil, "get_terminal_size", lambda *_: os.terminal_size((30, 24)))
    progress, clock, out = make(total=2080)
    step(progress, clock, 2.0, files=812, skills=190)
    [line] = drawn(out)
    assert len(line) < 30
    assert progress.text(2.0).startswith(line)


def test_close_erases_the_line_and_ends_the_drawing() -> None:
    progress, clock, out = make()
    step(progress, clock, 2.0)
    progress.close()
    assert out.getvalue().endswith("\r" + ERASE)
    before = out.getvalue()
    step(progress, clock, 9.0)
    progress.close()
    assert out.getvalue() == before


def test_a_context_manager_erases_the_line_even_on_error() -> None:
    progress, clock, out = make()
    with pytest.raises(KeyboardInterrupt), progress:
        step(progress, clock, 2.0)
        raise KeyboardInterrupt
    assert out.getvalue().endswith("\r" + ERASE)


@pytest.mark.parametrize(("stream", "env"), [
    (io.StringIO(), TERMINAL),  # not a terminal: a file, a pipe
    (Tty(), {**TERMINAL, "CI": "true"}),
    (Tty(), {**TERMINAL, "CI": "1"}),
    (Tty(), {"TERM": "dumb"}),
], ids=["not-a-tty", "CI=true", "CI=1", "TERM=dumb"])
def test_nothing_where_a_redrawn_line_would_be_garbage(stream: io.StringIO,
                                                       env: dict[str, str]) -> None:
    progress, clock, out = make(env=env, stream=stream)
    with progress:
        for at in (2.0, 3.0, 4.0):
            step(progress, clock, at, skills=1)
    assert out.getvalue() == ""
    assert (progress.files, progress.skills) == (3, 3)  # still counts


def test_ci_set_to_false_is_not_ci() -> None:
    progress, clock, out = make(env={**TERMINAL, "CI": "false"})
    step(progress, clock, 2.0)
    assert len(drawn(out)) == 1


def test_a_terminal_gone_does_not_stop_the_run() -> None:
    class Gone(Tty):
        def write(self, text: str) -> int:
            raise OSError(5, "Input/output error")

    progress, clock, _ = make(stream=Gone())
    step(progress, clock, 2.0)
    step(progress, clock, 3.0)
    progress.close()
    assert progress.files == 2


CHILD = textwrap.dedent("""
    import sys
    from ezmigrate.project.progress import Progress

    now = [0.0]
    with Progress.for_stream(3, clock=lambda: now[0]) as progress:
        for at in (0.5, 1.5, 2.5):
            now[0] = at
            progress.advance(skills_converted=2)
    print("ezmigrate: summary", file=sys.stderr)
""")


def child_env() -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if k not in ("CI", "COLUMNS")}
    return {**env, "TERM": "xterm-256color"}


def read_until_closed(master: int) -> bytes:
    """Everything written to a pseudo-terminal until its other end is closed."""
    output = b""
    while True:
        ready, _, _ = select.select([master], [], [], 60)
        assert ready, "the child neither wrote nor exited within 60 s"
        try:
            chunk = os.read(master, 4096)
        except OSError:  # EIO on Linux: the slave side is closed
            return output
        if not chunk:
            return output
        output += chunk


@pytest.mark.skipif(not hasattr(os, "openpty"), reason="needs a pseudo-terminal")
def test_a_real_terminal_gets_the_line() -> None:
    master, slave = os.openpty()
    try:
        child = subprocess.Popen([sys.executable, "-c", CHILD], cwd=REPO, env=child_env(),
                                 stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                 stderr=slave)
    finally:
        os.close(slave)  # the child holds the only other end: EOF when it exits
    try:
        text = read_until_closed(master).decode()
    finally:
        os.close(master)
        assert child.wait(timeout=60) == 0
    assert "\rezmigrate: 2/3 files, 4 skills converted, about 1 s left" + ERASE in text
    assert text.count("\rezmigrate: ") == 2  # none at 0.5 s: too early
    assert ("\rezmigrate: 3/3 files, 6 skills converted" + ERASE + "\r" + ERASE
            + "ezmigrate: summary") in text  # erased before the summary


def test_a_pipe_gets_nothing() -> None:
    child = subprocess.run([sys.executable, "-c", CHILD], cwd=REPO, env=child_env(),
                           stdin=subprocess.DEVNULL, capture_output=True, text=True,
                           timeout=60, check=True)
    assert child.stderr == "ezmigrate: summary\n"


LEGACY = Path(__file__).resolve().parents[2] / "fixtures" / "legacy"


def _rewrite(tmp_path: Path, stderr: int) -> subprocess.Popen[bytes]:
    """``rewrite --dry-run`` over three legacy files, held once the workers have started
    (``ezmigrate.project.holdpoint``) until the test lets it go: the run lasts over a second by
    construction, on any machine."""
    repo = tmp_path / "repo"
    repo.mkdir()
    for name in ("conditions.py", "descriptions.py", "inheritance.py"):
        shutil.copy(LEGACY / name, repo / name)
    hold = tmp_path / "hold"
    hold.mkdir()
    env = {**child_env(), "EZMIGRATE_HOLD_DIR": str(hold), "EZMIGRATE_HOLD_AT": "migrating"}
    return subprocess.Popen([sys.executable, "-m", "ezmigrate", "rewrite", "--dry-run",
                             "--no-verify", "-j", "2", str(repo)], cwd=REPO, env=env,
                            stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                            stderr=stderr)


def _hold_past_a_second(tmp_path: Path) -> None:
    reached = tmp_path / "hold" / "migrating.reached"
    deadline = time.monotonic() + 60
    while not reached.exists():
        assert time.monotonic() < deadline, "the run never reached the hold point"
        time.sleep(0.01)
    time.sleep(1.1)  # the run is held: this only makes sure it has lasted over a second
    (tmp_path / "hold" / "migrating.go").touch()


@pytest.mark.skipif(not hasattr(os, "openpty"), reason="needs a pseudo-terminal")
def test_rewrite_shows_the_line_on_a_terminal(tmp_path: Path) -> None:
    master, slave = os.openpty()
    try:
        child = _rewrite(tmp_path, slave)
    finally:
        os.close(slave)
    try:
        _hold_past_a_second(tmp_path)
        text = read_until_closed(master).decode()
    finally:
        os.close(master)
        assert child.wait(timeout=60) == 0
    assert re.search(r"\rezmigrate: [1-3]/3 files, \d+ skills converted", text), text
    assert "\r" + ERASE + "ezmigrate: " in text  # erased before the summary


def test_rewrite_writes_no_line_into_a_pipe(tmp_path: Path) -> None:
    child = _rewrite(tmp_path, subprocess.PIPE)
    _hold_past_a_second(tmp_path)
    _, err = child.communicate(timeout=60)
    assert child.returncode == 0
    assert b"\r" not in err and b"would change" in err


@pytest.mark.skipif(not hasattr(os, "openpty"), reason="needs a pseudo-terminal")
def test_check_shows_the_line_on_a_terminal(tmp_path: Path) -> None:
    repo = tmp_path / "repo"
    repo.mkdir()
    for name in ("conditions.py", "descriptions.py", "inheritance.py"):
        shutil.copy(LEGACY / name, repo / name)
    (tmp_path / "hold").mkdir()
    env = {**child_env(), "EZMIGRATE_HOLD_DIR": str(tmp_path / "hold"),
           "EZMIGRATE_HOLD_AT": "checking"}
    master, slave = os.openpty()
    try:
        child = subprocess.Popen([sys.executable, "-m", "ezmigrate", "check", str(repo)],
                                 cwd=REPO, env=env, stdin=subprocess.DEVNULL,
                                 stdout=subprocess.DEVNULL, stderr=slave)
    finally:
        os.close(slave)
    try:
        reached = tmp_path / "hold" / "checking.reached"
        deadline = time.monotonic() + 60
        while not reached.exists():
            assert time.monotonic() < deadline, "check never reached the hold point"
            time.sleep(0.01)
        time.sleep(1.1)  # held: this only makes sure the run has lasted over a second
        (tmp_path / "hold" / "checking.go").touch()
        text = read_until_closed(master).decode()
    finally:
        os.close(master)
        child.wait(timeout=60)
    assert re.search(r"\rezmigrate: [23]/3 files, \d+ skills found", text), text


def test_time_left_is_weighted_by_skill_files() -> None:
    """Issue 22: the quick files come first (skill files wait for a worker), so a rate over
    files said "about 1 s left" while nearly all the work was still to do. The estimate is
    the measured time per skill file times the skill files left; none before there is one."""
    progress, clock, out = make(total=10)
    progress.queued(2)  # two skill files read, waiting for a worker
    step(progress, clock, 1.5, files=8)  # the eight other files: read and passed over
    assert drawn(out) == ["ezmigrate: 8/10 files, 0 skills converted"]  # no rate: no guess
    clock.now = 4.0
    progress.advance(1, 3, skill_file=True)  # one skill file in 4 s: the other takes 4 s
    assert drawn(out)[-1] == "ezmigrate: 9/10 files, 3 skills converted, about 4 s left"


def test_unread_files_count_at_the_share_of_skill_files_seen() -> None:
    progress, clock, _ = make(total=100)
    progress.queued(5)
    step(progress, clock, 1.0, files=5)  # 10 files read: 5 skill files, 5 others
    clock.now = 2.0
    progress.advance(2, 0, skill_file=True)  # 2 skill files in 2 s; 3 queued, 90 unread
    assert progress.seconds_left(2.0) == pytest.approx(2.0 * (3 + 90 * 5 / 10) / 2)


def test_the_runner_announces_and_finishes_each_skill_file(tmp_path: Path) -> None:
    from ezmigrate.files.discover import Candidate
    from ezmigrate.project.runner import migrate_all

    shutil.copy(REPO / "fixtures" / "legacy" / "pick_and_place.py", tmp_path / "skills.py")
    (tmp_path / "util.py").write_text("def helper():\n    return 1\n", encoding="utf-8")
    progress = Progress(2, io.StringIO(), active=False)
    migrate_all([Candidate(tmp_path / n, tmp_path) for n in ("skills.py", "util.py")],
                None, 1, progress)
    assert (progress.files, progress.skill_files, progress.skill_files_done) == (2, 1, 1)
