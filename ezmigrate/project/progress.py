"""One updating progress line on stderr for long runs, on a terminal only.

Why: a run over thousands of files is otherwise silent for many seconds, and on a terminal
the user wants to see that it is alive and how long is left. Anywhere else the ``\\r``
redraws are garbage (a pipe, a file, a CI log), so the line is drawn only when the stream is
a terminal, ``CI`` is not set to a true value and ``TERM`` is not ``dumb``; and only once the
run has lasted more than a second, so a quick run prints nothing extra. It is redrawn at
most ten times a second, never wider than the terminal (a wrapped line cannot be redrawn in
place), and ``close`` erases it so the summary that follows starts on a clean line. The
clock is injectable so that tests never sleep.

The time left is an estimate only when there is a measured rate for the work that is left.
Nearly all the time of a run goes to skill files (those the prefilter lets through); the
others are read and passed over in a blink, and they come first, since skill files wait for
a worker. So once skill files are announced (``queued``) the estimate is the measured time
per finished skill file times the skill files left, those not yet read counted at the share
seen so far. Before the first skill file finishes there is no rate, and the line shows no
estimate rather than a guess from the quick files (which said "about 1 s left" for the last
28 s of a 29 s run).
"""

from __future__ import annotations

import contextlib
import os
import shutil
import sys
import time
from collections.abc import Callable, Mapping
from typing import TextIO

DELAY = 1.0
"""Seconds a run lasts before the line first appears."""
INTERVAL = 0.1
"""Least seconds between two redraws."""
ERASE = "\x1b[K"
"""Erase from the cursor to the end of the line."""


def wanted(stream: TextIO | None, env: Mapping[str, str]) -> bool:
    """Whether a progress line belongs on ``stream``: a terminal, outside CI, not dumb."""
    if stream is None or env.get("TERM") == "dumb":
        return False
    if env.get("CI", "").strip().lower() not in ("", "0", "false", "no", "off"):
        return False
    try:
        return bool(stream.isatty())
    except (AttributeError, OSError, ValueError):  # no isatty, or a closed stream
        return False


class Progress:
    """Files done of ``total``, skills converted and time left, redrawn in place.

    Build it with ``for_stream`` (which decides whether to draw at all); an inactive one
    accepts every call and writes nothing. Use it as a context manager, or call ``close``.
    """

    def __init__(self, total: int, stream: TextIO | None = None, *,
                 clock: Callable[[], float] = time.monotonic, active: bool = True,
                 skills_label: str = "skills converted") -> None:
        self.total = total
        self.stream = sys.stderr if stream is None else stream
        self.clock = clock
        self.active = active and self.stream is not None
        self.skills_label = skills_label
        self.files = 0
        self.skills = 0
        self.skill_files = 0
        """Skill files announced (``queued``); their weight is what the estimate counts."""
        self.skill_files_done = 0
        self.start = clock()
        self._drawn_at: float | None = None  # when the line was last drawn; None: not shown

    @classmethod
    def for_stream(cls, total: int, stream: TextIO | None = None, *,
                   clock: Callable[[], float] = time.monotonic,
                   env: Mapping[str, str] | None = None,
                   skills_label: str = "skills converted") -> Progress:
        """A progress line on ``stream`` (default stderr): inactive unless ``wanted``."""
        stream = sys.stderr if stream is None else stream
        active = wanted(stream, os.environ if env is None else env)
        return cls(total, stream, clock=clock, active=active, skills_label=skills_label)

    def queued(self, skill_files: int = 1) -> None:
        """Announce skill files read and waiting to be migrated (finished by ``advance``
        with ``skill_file=True``): from then on the estimate is weighted by them."""
        self.skill_files += skill_files

    def advance(self, files: int = 1, skills_converted: int = 0, *,
                skill_file: bool = False) -> None:
        """Count finished files (``skill_file``: one that was ``queued``) and converted
        skills; redraw when it is time to."""
        self.files += files
        self.skills += skills_converted
        if skill_file:
            self.skill_files_done += files
        if not self.active:
            return
        now = self.clock()
        if now - self.start <= DELAY:
            return
        if self._drawn_at is not None and now - self._drawn_at < INTERVAL:
            return
        self._drawn_at = now
        self._write("\r" + self.text(now)[:max(1, self._columns() - 1)] + ERASE)

    def text(self, now: float) -> str:
        """The line, untruncated: ``ezmigrate: 812/2080 files, 190 skills converted, ...``."""
        line = (f"ezmigrate: {self.files}/{self.total} files, {self.skills} "
                f"{self.skills_label}")
        left = self.seconds_left(now)
        if left is not None:
            seconds = max(1, round(left))
            line += (f", about {seconds} s left" if seconds < 60
                     else f", about {round(seconds / 60)} min left")
        return line

    def seconds_left(self, now: float) -> float | None:
        """The estimate of the module doc; ``None``: no measured rate for what is left."""
        if not 0 < self.files < self.total:
            return None
        elapsed = now - self.start
        if not self.skill_files:  # no skill file seen yet: every file weighs the same
            return elapsed * (self.total - self.files) / self.files
        if not self.skill_files_done:
            return None
        read = self.files - self.skill_files_done + self.skill_files
        unread = max(0, self.total - read)
        remaining = self.skill_files - self.skill_files_done + unread * self.skill_files / read
        return elapsed * remaining / self.skill_files_done if remaining > 0 else None

    def close(self) -> None:
        """Erase the line (if it was ever drawn) and draw no more."""
        if self.active and self._drawn_at is not None:
            self._write("\r" + ERASE)
        self.active = False

    def __enter__(self) -> Progress:
        return self

    def __exit__(self, *_: object) -> None:
        self.close()

    def _columns(self) -> int:
        """The terminal's width ($COLUMNS, else stdout's), narrowed to the stream's own."""
        columns = shutil.get_terminal_size().columns
        with contextlib.suppress(AttributeError, OSError, ValueError):  # no fd: a StringIO
            columns = min(columns, os.get_terminal_size(self.stream.fileno()).columns or columns)
        return columns

    def _write(self, text: str) -> None:
        try:
            self.stream.write(text)
            self.stream.flush()
        except (OSError, ValueError):  # the terminal is gone: the run must go on without it
            self.active = False
