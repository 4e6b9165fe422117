"""The second core during ``check``'s reading: scenes and file readings in forked workers.

Before this, the main process parsed every skill file and every scene one after the
other while the other core idled (its workers run only for the files the codemod reads
and for tracing). Parsing a file or a scene needs nothing but its path and bytes and gives
a picklable reading (``file_facts.FileFacts``, ``world.scene.Scene``), so both go to a
pool forked at the start of the run, before any thread exists: the files' readings are
split into small chunks once the misses of the cache are known, the workers taking them
from the start and the main process from the end until they meet (so a chunk of costly
files slows nobody more than its share); the scenes follow, and parse while the main
process goes on with the files' findings. Results are taken in the order they were asked
for, so a run reports the same bytes as one without the pool (``--jobs 1``, or too little
to share).

A file the plain reader declines is read by the codemod (``runner.own_reading``) in the
same turn, by the main process when it read the file; a worker leaves its first such files
to the main process (read after the workers' chunks) and reads them itself from the
``TAKES_ON``-th on. libcst, which only the codemod needs, is then imported by one process
when few files need it (``codemod/core/lazy_cst.py``), by every process when many do, and
by none when all are plain.
"""

from __future__ import annotations

import functools
import multiprocessing
import os
from collections.abc import Callable, Sequence
from concurrent.futures import Future, ProcessPoolExecutor
from concurrent.futures.process import BrokenProcessPool
from pathlib import Path
from typing import TYPE_CHECKING

from ..lint.plain_reader import Declined
from ..project.lifetime import exit_with_parent
from ..project.runner import own_reading
from ..report.results import FileResult
from .file_facts import FileFacts, file_facts

if TYPE_CHECKING:
    from ezskiros_runtime.world.scene import Scene

    from ..codemod.settings import Settings
    from ..files.discover import Candidate

SHARED_FROM = 24
"""Fewer files than this are read in the main process: a fork and the pickles back cost
more than they save."""


def _parse_scene(path: str) -> tuple[str, Scene] | None:
    """``(text, scene)`` of a scene file, or None when it cannot be read or parsed (the
    main process then reads it and reports why)."""
    from ezskiros_runtime.world.scene import SceneError, read_scene

    try:
        text = Path(path).read_text(encoding="utf-8")
        return text, read_scene(path, text)
    except (OSError, UnicodeError, SceneError):
        return None


Reading = tuple[FileFacts, FileResult | None]
"""A file's facts, and the codemod's own reading of it when the plain reader declined it."""


TAKES_ON = 6
"""Declined files a worker meets before it reads them with the codemod itself. Until then
it leaves them to the main process, which imports libcst once for all (a second import
costs a worker 0.1 s of a core, the codemod about 0.01 s a file: the 21 public
repositories decline 4 files in all); from the sixth on, a tree that declines many files
keeps both cores on them, and the worker reads the ones it left too."""

_SETTINGS: Settings | None = None
_LEFT: list[tuple[Candidate, bytes]] = []  # the declined files this worker left so far
_CAUGHT_UP: list[tuple[str, FileResult]] = []  # their readings, once it read them after all
_READS = False  # this worker reads declined files itself now


def _init_worker(settings: Settings | None, parent: int | None = None) -> None:
    """A worker's start: the codemod's settings, inherited (the index is never pickled),
    its index the active ontology (``FileFacts.loaded`` is checked against it), and its
    end with the run's (``lifetime.exit_with_parent``)."""
    global _SETTINGS
    exit_with_parent(parent)
    _SETTINGS = settings
    if settings is not None and settings.index is not None:
        from ezskiros_runtime.ontology import use_ontology

        use_ontology(settings.index)


ReadDeclined = Callable[["Candidate", bytes], "FileResult | None"]
"""The codemod's reading of a file the plain reader declines (None: someone else's)."""


def _declined(facts: FileFacts) -> bool:
    """Whether the codemod must read the file (``own_reading``)."""
    return facts.described and facts.settled is None and isinstance(facts.static, Declined)


def _read_files(items: list[tuple[Candidate, bytes, bool | None]], compounds: bool,
                declined: ReadDeclined | None, statically: bool = False) -> list[Reading]:
    """Each file's facts and, for each file the plain reader declines, ``declined``'s
    reading of it alone, taken while the file is at hand instead of after every file is
    read (the cross-file pass still runs after)."""
    found: list[Reading] = []
    for candidate, data, verdict in items:
        facts = file_facts(candidate, data, compounds, verdict, statically)
        found.append((facts, declined(candidate, data)
                      if declined is not None and _declined(facts) else None))
    return found


def _here(settings: Settings, candidate: Candidate, data: bytes) -> FileResult:
    """The main process's reading of a declined file."""
    return own_reading(candidate.relative, data, settings)


def _in_worker(candidate: Candidate, data: bytes) -> FileResult | None:
    """A worker's reading of a declined file: none until it has met ``TAKES_ON`` of them
    (the main process reads those), then its own, and those of the files it left before
    (``_CAUGHT_UP``)."""
    global _READS
    if _SETTINGS is None:
        return None
    if not _READS and len(_LEFT) + 1 < TAKES_ON:
        _LEFT.append((candidate, data))
        return None
    if not _READS:
        _READS = True
        _CAUGHT_UP.extend((str(c.path), own_reading(c.relative, d, _SETTINGS)) for c, d in _LEFT)
        _LEFT.clear()
    return own_reading(candidate.relative, data, _SETTINGS)


def _read_in_worker(items: list[tuple[Candidate, bytes, bool | None]], compounds: bool,
                    statically: bool) -> tuple[list[Reading], list[tuple[str, FileResult]]]:
    """A worker's chunk (``_read_files`` with ``_in_worker``), and by path the readings of
    the files it left before and read in this chunk."""
    found = _read_files(items, compounds, _in_worker, statically)
    caught_up = list(_CAUGHT_UP)
    _CAUGHT_UP.clear()
    return found, caught_up


class ReadingPool:
    """Forked readers for one run: ``workers`` processes read, the main one among them
    (so one fewer is forked; ``workers`` under two: none, the main reads alone). ``settings``:
    what the codemod reads declined files with (None: they are left to ``settle``)."""

    def __init__(self, workers: int, settings: Settings | None = None) -> None:
        self.workers = workers
        self.settings = settings
        self._pool: ProcessPoolExecutor | None = None
        self._scenes: list[tuple[Path, Future[tuple[str, Scene] | None]]] = []
        self._waiting: list[Path] = []

    def _executor(self) -> ProcessPoolExecutor | None:
        if self.workers < 2 or "fork" not in multiprocessing.get_all_start_methods():
            return None
        if self._pool is None:  # forked: the settings' index is inherited, never pickled
            self._pool = ProcessPoolExecutor(max_workers=max(1, self.workers - 1),
                                             mp_context=multiprocessing.get_context("fork"),
                                             initializer=_init_worker,
                                             initargs=(self.settings, os.getpid()))
        return self._pool

    def parse_scenes(self, paths: Sequence[Path]) -> None:
        """Parse ``paths`` in the workers (``seed_scenes`` hands the parses to
        ``read_scene``): they start after the files' readings, which the run needs first."""
        self._waiting += paths

    def _start_scenes(self) -> None:
        pool = self._executor() if self._waiting else None
        if pool is not None:
            self._scenes += [(path, pool.submit(_parse_scene, str(path)))
                             for path in self._waiting]
        self._waiting = []

    def seed_scenes(self) -> None:
        """Hand ``read_scene`` every scene parsed in the workers. The main process, done
        with its own work by now, parses from the end the scenes no worker has started
        (as it does the files' chunks): it does its share instead of waiting for the
        workers' last ones."""
        from ezskiros_runtime.world.scene import seed_scene

        self._start_scenes()
        for path, future in reversed(self._scenes):
            if not future.cancel():
                break
            parsed = _parse_scene(str(path))
            if parsed is not None:
                seed_scene(path, *parsed)
        for path, future in self._scenes:
            if future.cancelled():
                continue
            try:
                parsed = future.result()
            except (BrokenProcessPool, OSError):  # read_scene parses it when asked
                continue
            if parsed is not None:
                seed_scene(path, *parsed)
        self._scenes = []

    def read_files(self, items: list[tuple[Candidate, bytes, bool | None]], compounds: bool,
                   statically: bool = False) -> list[Reading]:
        """``file_facts`` of each ``(candidate, bytes, the prefilter's text verdict)``, and
        the codemod's reading of those the plain reader declines (``_read_files``), in
        order: in the workers when there are enough.

        Files of the same bytes are read once (a workspace keeps a fork beside its
        upstream, a vendored copy of a package): the copies' facts are moved from the
        first one's (``FileFacts.moved``). A copy of a file the codemod read is read itself
        (the codemod's reading is not moved), after the others."""
        firsts: dict[bytes, int] = {}
        unique: list[tuple[Candidate, bytes, bool | None]] = []
        for item in items:
            if firsts.setdefault(item[1], len(unique)) == len(unique):
                unique.append(item)
        read = self._read_all(unique, compounds, statically)
        if len(unique) == len(items):
            return read
        found: list[Reading] = []
        again: list[int] = []
        for index, (candidate, data, _) in enumerate(items):
            facts, own = read[firsts[data]]
            if unique[firsts[data]][0] is candidate:
                found.append((facts, own))
            elif own is None and not facts.depends:
                found.append((facts.moved(candidate), None))
            else:
                found.append((facts, own))  # a placeholder, read again below
                again.append(index)
        for index, reading in zip(again, self._read_all([items[i] for i in again], compounds,
                                                        statically), strict=True):
            found[index] = reading
        return found

    def _read_all(self, items: list[tuple[Candidate, bytes, bool | None]], compounds: bool,
                  statically: bool) -> list[Reading]:
        """``read_files`` of files whose bytes all differ."""
        here = None if self.settings is None else functools.partial(_here, self.settings)
        pool = self._executor() if len(items) >= SHARED_FROM else None
        if pool is None:
            self._start_scenes()
            return _read_files(items, compounds, here, statically)
        size = max(4, len(items) // (self.workers * 12))
        starts = list(range(0, len(items), size))
        futures = {start: pool.submit(_read_in_worker, items[start:start + size], compounds,
                                      statically)
                   for start in starts}
        self._start_scenes()
        mine: dict[int, list[Reading]] = {}
        for start in reversed(starts):  # the main takes chunks from the end, while no
            if not futures[start].cancel():  # worker has started them: the share each
                break  # does is what it gets through, whatever a chunk costs
            mine[start] = _read_files(items[start:start + size], compounds, here, statically)
        theirs: dict[int, list[Reading]] = {}
        caught_up: dict[str, FileResult] = {}
        for start in starts:
            if start in mine:
                continue
            try:
                theirs[start], late = futures[start].result()
                caught_up.update(late)
            except (BrokenProcessPool, OSError):  # a worker died: read here what it had
                mine[start] = _read_files(items[start:start + size], compounds, here, statically)
        found: list[Reading] = []
        for start in starts:
            if start in mine:
                found += mine[start]
                continue
            for (candidate, data, _), (facts, own) in zip(items[start:start + size],
                                                         theirs[start], strict=True):
                if own is None and here is not None and _declined(facts):
                    own = caught_up.get(str(candidate.path)) or here(candidate, data)
                found.append((facts, own))
        return found

    def close(self) -> None:
        if self._pool is not None:
            self._pool.shutdown(wait=True, cancel_futures=True)
            self._pool = None
