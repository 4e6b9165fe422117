"""SIGINT, SIGTERM and SIGHUP during a run: stop cleanly, never leave a file half-written.

A write (temporary file, flush, rename) is a *deferred* section: a signal that arrives
inside one is only recorded, the write finishes (or is abandoned with its temporary file
removed) and ``Interrupted`` is raised as the section ends. Outside deferred sections the
handler raises ``Interrupted`` at once, so discovery, migration and verification stop
promptly; they write nothing, so stopping them anywhere is safe. Either way no new write
starts, the CLI prints what was done and exits with 128 + the signal number (130 for
SIGINT, 143 for SIGTERM).

Processes forked from the one that installed the handlers (the migration workers) inherit
them; there the handler leaves at once with ``os._exit`` (no traceback on the terminal),
and the main process stops them itself when it is the only one signalled.

Only one ``Interrupted`` is raised per run: signals that arrive while the program is
already unwinding (a second Ctrl-C while the summary prints) are ignored. A signal that is
ignored when the handlers are installed (``nohup``, a background job) stays ignored.
"""

from __future__ import annotations

import os
import signal
import threading
from collections.abc import Iterator
from contextlib import contextmanager, suppress
from types import FrameType
from typing import Any

HANDLED = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)


class Interrupted(BaseException):  # like KeyboardInterrupt: not an error
    """The run was stopped by a signal. A ``BaseException``: ``except Exception`` lets it by.

    ``written`` lists the files replaced before the signal (each wholly new), ``left`` the
    files that would have changed and were not touched; both are empty when the signal came
    before the writing started.
    """

    def __init__(self, signum: int) -> None:
        super().__init__(signum)
        self.signum = signum
        self.written: list[str] = []
        self.left: list[str] = []

    @property
    def exit_code(self) -> int:
        return 128 + self.signum

    @property
    def signal_name(self) -> str:
        try:
            return signal.Signals(self.signum).name
        except ValueError:
            return f"signal {self.signum}"

    def report(self) -> list[str]:
        """Lines telling the user what was done (the CLI prefixes them with ``ezmigrate:``)."""
        if not self.written and not self.left:
            return [f"interrupted by {self.signal_name} before any file was written: "
                    "every file is as it was"]
        if not self.left:
            return [f"interrupted by {self.signal_name} after all {len(self.written)} files "
                    "were written; only the summary was cut short",
                    *(f"written: {path}" for path in self.written)]
        lines = [f"interrupted by {self.signal_name}: {len(self.written)} files written "
                 f"(each wholly new), {len(self.left)} not yet written (each as it was); "
                 "run the same command again to finish"]
        lines += [f"written: {path}" for path in self.written]
        return lines


class _State:
    def __init__(self) -> None:
        self.owner: int | None = None  # pid of the process that installed the handlers
        self.depth = 0  # nesting of deferred sections in the main thread
        self.pending: int | None = None
        self.raised = False
        self.written: list[str] = []  # the session's own list, appended as files are written
        self.planned: list[str] = []  # files the session means to change


_STATE = _State()


def _interrupted(signum: int) -> Interrupted:
    _STATE.raised = True
    stop = Interrupted(signum)
    stop.written = list(_STATE.written)
    done = set(stop.written)
    stop.left = [path for path in _STATE.planned if path not in done]
    return stop


def track(written: list[str], planned: list[str]) -> None:
    """Let an interruption report progress: ``written`` is appended to as files are written."""
    _STATE.written = written
    _STATE.planned = planned


def _handler(signum: int, frame: FrameType | None) -> None:
    state = _STATE
    if state.owner is not None and os.getpid() != state.owner:
        os._exit(128 + signum)  # a forked worker: the main process reports and cleans up
    if state.raised or state.pending is not None:
        return  # already stopping: one report, one exit
    state.pending = signum
    _stop_workers(signum)
    if state.depth == 0:
        raise _interrupted(signum)


def _stop_workers(signum: int) -> None:
    """Pass the signal on to forked workers (they leave at once, see ``_handler``)."""
    import multiprocessing  # (imported by then wherever a worker was forked)

    try:
        children = multiprocessing.active_children()
    except Exception:  # stopping must never fail
        return
    for child in children:
        if child.pid is not None:
            with suppress(OSError):
                os.kill(child.pid, signum)


def install() -> bool:
    """Install the handlers in this process (main thread only); ``False`` if impossible.

    The CLI installs them for the life of the process; ``handling_interrupts`` is the
    variant for library use, restoring the previous handlers afterwards.
    """
    if threading.current_thread() is not threading.main_thread():
        return False
    _STATE.owner = os.getpid()
    _STATE.depth = 0
    _STATE.pending = None
    _STATE.raised = False
    _STATE.written, _STATE.planned = [], []
    for signum in HANDLED:
        try:
            if signal.getsignal(signum) is signal.SIG_IGN:
                continue
            signal.signal(signum, _handler)
        except (OSError, ValueError):
            continue
    return True


@contextmanager
def handling_interrupts() -> Iterator[None]:
    """Install the handlers for the block, restoring the previous ones afterwards."""
    previous: dict[int, Any] = {}
    if threading.current_thread() is threading.main_thread():
        previous = {s: signal.getsignal(s) for s in HANDLED}
    installed = install()
    try:
        yield
    finally:
        _STATE.written, _STATE.planned = [], []
        if installed:
            for signum, handler in previous.items():
                with suppress(OSError, ValueError):
                    signal.signal(signum, handler if handler is not None else signal.SIG_DFL)
            _STATE.owner = None


@contextmanager
def deferred() -> Iterator[None]:
    """A section a signal must not cut: it runs to its end, then ``Interrupted`` is raised.

    Without installed handlers (library use) this only counts depth; the default SIGINT
    handler may then raise ``KeyboardInterrupt`` anywhere, which ``atomic_write`` also
    survives (it removes its temporary file).
    """
    _STATE.depth += 1
    try:
        yield
    finally:
        _STATE.depth -= 1
        if _STATE.depth == 0 and _STATE.pending is not None and not _STATE.raised \
                and _STATE.owner == os.getpid():
            raise _interrupted(_STATE.pending)


def requested() -> int | None:
    """The signal received so far in this run, if any."""
    return _STATE.pending


def check() -> None:
    """Raise ``Interrupted`` if a signal came and none was raised yet (between writes)."""
    if _STATE.pending is not None and not _STATE.raised and _STATE.owner == os.getpid():
        raise _interrupted(_STATE.pending)


def ignore_further() -> None:
    """Ignore the handled signals from now on: the process is exiting after an interrupt.

    (Python resets its handlers to the defaults late in shutdown, so a second Ctrl-C there
    would kill the process by the signal instead of letting it exit with 128 + signal.)
    """
    if threading.current_thread() is not threading.main_thread():
        return
    for signum in HANDLED:
        with suppress(OSError, ValueError):
            if signal.getsignal(signum) is not signal.SIG_IGN:
                signal.signal(signum, signal.SIG_IGN)
