"""Which discovered files git ignores: asked once per checkout, answered while the run
goes on.

git is asked once per checkout: folders that find the same ``.git`` walking up (same
device all the way) are in the same checkout, so one ``git check-ignore`` run from the
folder holding it answers for all of them; folders with no ``.git`` above them ask
nothing. When the git environment variables could change how git finds its checkout,
every folder asks git for its top level first, as git would find it.

A workspace of many checkouts (a catkin ``src/`` folder, the 21 public repositories side
by side) asks many gits, and starting each from Python costs the run's own thread a
millisecond or more. So one ``sh`` starts them all, at once and in the background, each
reading its checkout's files from a file and writing its answer to another:
``IgnoredQuery`` returns as soon as the shell is started, and ``answer`` waits for it,
after the run did its other searches. Without ``/bin/sh`` the gits are asked one by one
when the answer is wanted.
"""

from __future__ import annotations

import contextlib
import os
import shutil
import signal
import subprocess
import tempfile
import time
import weakref
from collections.abc import Callable
from typing import TypeVar

_T = TypeVar("_T")
_R = TypeVar("_R")

SHELL = "/bin/sh"

TIMEOUT = 60.0
"""Seconds the gits of a run may take together; past that, nothing is taken as ignored."""

_ASK_EACH = ('while [ "$#" -gt 0 ]; do '
             'git -C "$1" check-ignore --stdin -z <"$2" >"$3" 2>/dev/null & shift 3; '
             'done; wait')
"""The shell's script: one ``git check-ignore`` per ``(top, input, output)`` argument
triple, all at once (the paths are arguments, never part of the script)."""

_GIT_DISCOVERY_ENV = ("GIT_DIR", "GIT_WORK_TREE", "GIT_CEILING_DIRECTORIES",
                      "GIT_DISCOVERY_ACROSS_FILESYSTEM", "GIT_COMMON_DIR")


class IgnoredQuery:
    """The real paths among ``files`` (real paths) that git ignores; nothing when git is
    absent. Asked on construction, answered by ``answer``."""

    def __init__(self, files: list[str]) -> None:
        self._groups = list(_checkouts(files).items())
        self._folder: str | None = None
        self._shell: subprocess.Popen[bytes] | None = None
        self._deadline = time.monotonic() + TIMEOUT
        if self._groups and os.path.exists(SHELL):
            self._start()

    def _start(self) -> None:
        folder = tempfile.mkdtemp(prefix="ezmigrate-git-")
        arguments: list[str] = []
        for number, (top, group) in enumerate(self._groups):
            given = os.path.join(folder, f"{number}.in")
            with open(given, "wb") as handle:
                handle.write(_asked(group))
            arguments += [top, given, os.path.join(folder, f"{number}.out")]
        try:
            self._shell = subprocess.Popen([SHELL, "-c", _ASK_EACH, "sh", *arguments],
                                           stdin=subprocess.DEVNULL,
                                           stdout=subprocess.DEVNULL,
                                           stderr=subprocess.DEVNULL,
                                           start_new_session=True)  # killed as a group
        except OSError:
            shutil.rmtree(folder, ignore_errors=True)
            return
        self._folder = folder
        # gone with the query, or at exit when a run stopped before it asked for the answer
        self._remove = weakref.finalize(self, shutil.rmtree, folder, ignore_errors=True)

    def answer(self) -> set[str]:
        """What git ignores, once every git has answered (or the time is up)."""
        if self._shell is None or self._folder is None:
            ignored: set[str] = set()
            for found in _each(_check_ignore, self._groups):
                ignored |= found
            return ignored
        try:
            return self._answers(self._shell, self._folder)
        finally:
            self._remove()

    def _answers(self, shell: subprocess.Popen[bytes], folder: str) -> set[str]:
        try:
            shell.wait(timeout=max(0.0, self._deadline - time.monotonic()))
        except subprocess.TimeoutExpired:
            with contextlib.suppress(OSError):
                os.killpg(shell.pid, signal.SIGKILL)
            shell.wait()
            return set()
        ignored: set[str] = set()
        for number in range(len(self._groups)):
            try:
                with open(os.path.join(folder, f"{number}.out"), "rb") as handle:
                    output = handle.read()
            except OSError:
                continue
            ignored |= _answered(output)
        return ignored


def _checkouts(files: list[str]) -> dict[str, list[str]]:
    """``{the folder git is asked from: the files of its checkout}``."""
    by_folder: dict[str, list[str]] = {}
    for file in files:
        by_folder.setdefault(os.path.dirname(file), []).append(file)
    groups: dict[str, list[str]] = {}
    if any(name in os.environ for name in _GIT_DISCOVERY_ENV):
        tops = dict(zip(by_folder, _each(_git_top, list(by_folder)), strict=True))
        for folder, group in by_folder.items():
            top = tops[folder]
            if top is not None:
                groups.setdefault(top, []).extend(group)
    else:
        keys: dict[str, str] = {}
        for folder, group in by_folder.items():
            key = _checkout_key(folder, keys)
            if not key.startswith(NO_CHECKOUT):  # no ``.git`` up to where git stops looking
                groups.setdefault(key, []).extend(group)
    return groups


def _each(ask: Callable[[_T], _R], items: list[_T]) -> list[_R]:
    """``ask`` of each item, in order: at once in threads when there are several (a
    folder of many checkouts asks git once per checkout, and each answer is a process's
    start-up, mostly waited for). The threads are gone when this returns, before any
    worker is forked."""
    if len(items) <= 1:
        return [ask(item) for item in items]
    from concurrent.futures import ThreadPoolExecutor  # (the shell asks, where there is one)

    with ThreadPoolExecutor(max_workers=min(8, len(items))) as threads:
        return list(threads.map(ask, items))


def _check_ignore(checkout: tuple[str, list[str]]) -> set[str]:
    """The real paths among a checkout's files that git ignores, asked from a folder of
    the checkout (its top level, or the folder holding its ``.git``)."""
    top, group = checkout
    try:
        proc = subprocess.run(["git", "-C", top, "check-ignore", "--stdin", "-z"],
                              input=_asked(group), capture_output=True, timeout=TIMEOUT,
                              check=False)
    except (OSError, subprocess.TimeoutExpired):
        return set()
    return _answered(proc.stdout)


def _asked(group: list[str]) -> bytes:
    """``git check-ignore --stdin -z``'s input: the paths, NUL-separated."""
    return b"\0".join(os.fsencode(p) for p in group)


def _answered(output: bytes) -> set[str]:
    """The real paths of ``git check-ignore -z``'s answer."""
    return {os.path.realpath(os.fsdecode(p)) for p in output.split(b"\0") if p}


NO_CHECKOUT = "\0"
"""How the key of a folder with no ``.git`` at or above it begins (no path holds it)."""


def _checkout_key(folder: str, memo: dict[str, str]) -> str:
    """Folders with the same key find the same checkout when git looks for one.

    The key is the nearest folder at or above ``folder`` holding a ``.git`` entry, or, when
    there is none, the highest folder git would look in (below the root or a device
    boundary, where git stops looking). A folder inside a ``.git`` folder is its own group.
    """
    if f"{os.sep}.git{os.sep}" in os.path.join(folder, ""):
        return folder
    chain: list[str] = []
    current = folder
    try:
        device = os.stat(current).st_dev
    except OSError:
        return folder
    while True:
        if current in memo:
            key = memo[current]
            break
        chain.append(current)
        if os.path.lexists(os.path.join(current, ".git")):
            key = current
            break
        parent = os.path.dirname(current)
        try:
            boundary = parent == current or os.stat(parent).st_dev != device
        except OSError:
            boundary = True
        if boundary:
            key = NO_CHECKOUT + current  # no checkout found up to here
            break
        current = parent
    for visited in chain:
        memo[visited] = key
    return key


def _git_top(folder: str) -> str | None:
    try:
        proc = subprocess.run(["git", "-C", folder, "rev-parse", "--show-toplevel"],
                              capture_output=True, timeout=30, check=False)
    except (OSError, subprocess.TimeoutExpired):
        return None
    return os.path.realpath(os.fsdecode(proc.stdout.strip())) if proc.returncode == 0 \
        else None
