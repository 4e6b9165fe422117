"""``files/git_ignored.py``: one shell asks every checkout's git at once, in the
background, and its answer is the one asking each git in turn gives: on checkouts side by
side, with folder names a shell would mangle, without ``/bin/sh``, and with a git that
never answers (the time runs out, the gits are killed, nothing is taken as ignored)."""

from __future__ import annotations

import os
import subprocess
import time
from pathlib import Path

import pytest

from ezmigrate.files import git_ignored
from ezmigrate.files.git_ignored import IgnoredQuery, _check_ignore, _checkouts


def _git(*args: str | Path) -> None:
    subprocess.run(["git", *map(str, args)], check=True, capture_output=True)


NAMES = ["plain", "with space", "quote's \"both\"", "$HOME `x` ;&|", "new\nline", "ünï"]


@pytest.fixture
def workspace(tmp_path: Path) -> list[str]:
    """Checkouts side by side, each ignoring its own files, and the real paths of all."""
    files: list[str] = []
    for number, name in enumerate(NAMES):
        top = tmp_path / "src" / name
        (top / "pkg").mkdir(parents=True)
        _git("init", "-q", top)
        (top / ".gitignore").write_text(f"secret{number}.py\nbuild/\n")
        for file in (f"secret{number}.py", "kept.py", f"pkg/secret{number}.py",
                     "pkg/kept.py"):
            (top / file).write_text("")
            files.append(os.path.realpath(top / file))
    return files


def _one_by_one(files: list[str]) -> set[str]:
    found: set[str] = set()
    for checkout in _checkouts(files).items():
        found |= _check_ignore(checkout)
    return found


def test_one_shell_answers_as_each_git_does(workspace: list[str]) -> None:
    expected = _one_by_one(workspace)
    assert len(expected) == 2 * len(NAMES)  # each checkout ignores two of its four files
    assert IgnoredQuery(workspace).answer() == expected


def test_without_a_shell_each_git_is_asked_in_turn(workspace: list[str],
                                                  monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(git_ignored, "SHELL", "/nonexistent/sh")
    assert IgnoredQuery(workspace).answer() == _one_by_one(workspace)


def test_a_git_that_never_answers_costs_the_timeout_and_nothing_more(
        workspace: list[str], tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A ``git`` on PATH that blocks on a pipe no one writes: the shell and every git are
    killed when the time is up, and no file is taken as ignored."""
    fake = tmp_path / "bin"
    fake.mkdir()
    (tmp_path / "never").mkdir()
    os.mkfifo(tmp_path / "never" / "pipe")
    (fake / "git").write_text(f"#!/bin/sh\necho $$ >> '{tmp_path / 'pids'}'\n"
                              f"read line < '{tmp_path / 'never' / 'pipe'}'\n")
    (fake / "git").chmod(0o755)
    monkeypatch.setenv("PATH", f"{fake}{os.pathsep}{os.environ['PATH']}")
    monkeypatch.setattr(git_ignored, "TIMEOUT", 0.5)
    query = IgnoredQuery(workspace)
    assert query.answer() == set()
    pids = [int(p) for p in (tmp_path / "pids").read_text().split()] \
        if (tmp_path / "pids").exists() else []
    for pid in pids:  # killed with the shell's group: gone, or a zombie for init to reap
        deadline = time.monotonic() + 30
        while _running(pid):
            assert time.monotonic() < deadline, f"git {pid} outlived the query"
            time.sleep(0.01)


def _running(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except (OSError, IndexError):
        return False
    return state not in ("Z", "X")


def test_a_query_never_answered_leaves_no_folder_behind(workspace: list[str]) -> None:
    """A run that stops before it asks for the answer (a bad ontology: exit 2) removes the
    files the gits read and wrote, once the query is gone."""
    query = IgnoredQuery(workspace)
    folder = query._folder
    assert folder is not None and os.path.isdir(folder)
    assert query._shell is not None
    query._shell.wait()
    del query
    assert not os.path.exists(folder)
