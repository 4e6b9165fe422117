"""The second core during ``check``'s reading: scenes and file readings in a forked worker.

Parsing a file or a scene needs nothing but its path and bytes and gives a picklable
reading (``file_facts.FileFacts``, ``world.scene.Scene``), so both go to one worker,
forked when the run first has work for it: its scenes, as soon as the run knows it must
read (``parse_scenes``, before the files' bytes are read), else its files. The scenes
come first, while the main process still reads bytes and sets up;
the files' readings, split into small chunks once the misses of the cache are known, take
over as soon as they are handed over: the worker takes chunks from the start and the main
process from the end until they meet (``worker_channel.Claims``: a chunk of costly files
slows nobody more than its share); the worker then parses the scenes left while the main
process goes on with the files' findings. Results are taken in the order they were asked
for, so a run reports the same bytes as one without the worker (``--jobs 1``, or too little
to share). ``worker_channel`` says why there is no executor between the two.

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
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ..lint.plain_reader import Declined
from ..project.lifetime import exit_with_parent
from ..project.runner import own_reading
from ..report.results import FileResult
from .file_facts import FileFacts, file_facts
from .worker_channel import Channel, Claims

if TYPE_CHECKING:
    from multiprocessing.process import BaseProcess

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
    """A worker's start: the codemod's settings, inherited (forked, never pickled), its
    index the active ontology (``FileFacts.loaded`` is checked against it), and its end
    with the run's (``lifetime.exit_with_parent``)."""
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


SCENES, FILES = 0, 1
"""The worker's two task lists (``Claims``): the run's scenes, and the chunks of the batch
of files at hand."""


def _serve(channel: Channel, claims: Claims, scenes: list[str], settings: Settings | None,
           parent: int) -> None:
    """The worker: the chunks of the batch at hand first (the run waits for them), scenes
    otherwise; it ends when the main process closes the channel. A task that fails is
    recorded as None: the main process then does it itself, and says why if it fails."""
    channel.as_worker()
    _init_worker(settings, parent)
    try:
        _take_tasks(channel, claims, scenes)
    except (OSError, EOFError):  # the main process has gone, or closed the channel
        return


def _take_tasks(channel: Channel, claims: Claims, scenes: list[str]) -> None:
    """``_serve``'s loop, until the main process closes the channel."""
    batch: tuple[list[tuple[Candidate, bytes, bool | None]], bool, bool, int] | None = None
    number = -1
    scenes_left = bool(scenes)
    while True:
        if batch is None:
            batch = channel.next_batch(block=not scenes_left)
            number += 0 if batch is None else 1
        if batch is not None:
            chunk = claims.front(FILES)
            if chunk is None:
                channel.say(b"f")
                batch = None
                continue
            items, compounds, statically, size = batch
            channel.record(FILES, number, chunk, _attempt(
                _read_in_worker, items[chunk * size:(chunk + 1) * size], compounds,
                statically))
            continue
        scene = claims.front(SCENES)
        if scene is None:
            channel.say(b"s")
            scenes_left = False
            continue
        channel.record(SCENES, 0, scene, _attempt(_parse_scene, scenes[scene]))


def _attempt(task: Callable[..., Any], *args: Any) -> Any:
    """``task(*args)``, or None when it raises (the main process does it again)."""
    try:
        return task(*args)
    except Exception:  # the main process's own attempt reports it
        return None


class ReadingPool:
    """The forked reader of one run: ``workers`` processes read, the main one among them (so
    one is forked, as the run needs it; ``workers`` under two: none, the main reads alone).
    ``settings``: what the codemod reads declined files with (None: they are left to
    ``settle``)."""

    def __init__(self, workers: int, settings: Settings | None = None) -> None:
        self.workers = workers
        self.settings = settings
        self._worker: BaseProcess | None = None
        self._channel: Channel | None = None
        self._claims: Claims | None = None
        self._scenes: list[Path] = []
        self._parsed: dict[int, tuple[str, Scene] | None] = {}
        self._batches = 0

    def _start(self, scenes: Sequence[Path]) -> bool:
        """Fork the worker, given ``scenes`` to parse, unless it runs already; False when
        the run reads alone (one worker asked for, no ``fork``, or the worker has ended)."""
        if self._channel is not None:
            return not self._channel.gone
        if self.workers < 2 or "fork" not in multiprocessing.get_all_start_methods():
            return False
        if scenes:  # the parser, imported once for both processes (the run needs it too)
            import ezskiros_runtime.world.scene  # noqa: F401
        context = multiprocessing.get_context("fork")
        try:
            self._claims = Claims(2, context.Lock())
            self._channel = Channel()
        except (OSError, ImportError):  # no shared semaphore, no temporary folder, no pipe:
            self.workers = 1  # the run reads alone, as with --jobs 1
            return False
        self._claims.open(SCENES, len(scenes))
        self._scenes = list(scenes)
        self._worker = context.Process(  # forked: the arguments are inherited, not pickled
            target=_serve, name="ezmigrate-reader", daemon=True,
            args=(self._channel, self._claims, [str(p) for p in scenes], self.settings,
                  os.getpid()))
        try:
            self._worker.start()
        except OSError:  # no process to be had (a limit on processes, on memory)
            self._channel.gone, self._worker = True, None
            return False
        finally:
            self._channel.as_main()
        return True

    def parse_scenes(self, paths: Sequence[Path]) -> None:
        """Parse ``paths`` in the worker, forked now (``seed_scenes`` hands the parses to
        ``read_scene``). Scenes named after the worker started are parsed where they are
        asked for."""
        if paths and self._channel is None:
            self._start(paths)

    def seed_scenes(self) -> None:
        """Hand ``read_scene`` every scene the worker parsed, once it has parsed them all
        (those it could not, or could not finish, ``read_scene`` parses when asked)."""
        from ezskiros_runtime.world.scene import seed_scene

        if self._channel is None or not self._scenes:
            return
        self._channel.wait(b"s")
        self._take_records()
        for index, path in enumerate(self._scenes):
            parsed = self._parsed.get(index)
            if parsed is not None:
                seed_scene(path, *parsed)
        self._scenes = []

    def _take_records(self, batch: int = -1) -> dict[int, Any]:
        """The worker's records so far: its scenes kept, its chunks of ``batch`` returned."""
        assert self._channel is not None
        chunks: dict[int, Any] = {}
        for kind, number, index, value in self._channel.records():
            if kind == SCENES:
                self._parsed[index] = value
            elif number == batch and value is not None:
                chunks[index] = value
        return chunks

    def read_files(self, items: list[tuple[Candidate, bytes, bool | None]], compounds: bool,
                   statically: bool = False) -> list[Reading]:
        """``file_facts`` of each ``(candidate, bytes, the prefilter's text verdict)``, and
        the codemod's reading of those the plain reader declines (``_read_files``), in
        order: shared with the worker when there are enough.

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
        if len(items) < SHARED_FROM or not self._start(()):
            return _read_files(items, compounds, here, statically)
        assert self._channel is not None and self._claims is not None
        size = max(4, len(items) // (self.workers * 12))
        chunks = -(-len(items) // size)
        number, self._batches = self._batches, self._batches + 1
        self._claims.open(FILES, chunks)
        self._channel.send((items, compounds, statically, size))
        mine: dict[int, list[Reading]] = {}
        while (chunk := self._claims.back(FILES)) is not None:  # from the end, until the
            mine[chunk] = _read_files(items[chunk * size:(chunk + 1) * size], compounds,
                                      here, statically)  # worker's share meets this one
        self._channel.wait(b"f")
        theirs = self._take_records(number)
        caught_up: dict[str, FileResult] = {}
        for _, late in theirs.values():
            caught_up.update(late)
        found: list[Reading] = []
        for chunk in range(chunks):
            part = items[chunk * size:(chunk + 1) * size]
            if chunk in mine:
                found += mine[chunk]
            elif chunk not in theirs:  # the worker ended, or failed on it: read it here
                found += _read_files(part, compounds, here, statically)
            else:
                for (candidate, data, _), (facts, own) in zip(part, theirs[chunk][0],
                                                             strict=True):
                    if own is None and here is not None and _declined(facts):
                        own = caught_up.get(str(candidate.path)) or here(candidate, data)
                    found.append((facts, own))
        return found

    def close(self) -> None:
        """End the worker (whatever it was doing: the run needs nothing more of it)."""
        if self._worker is not None:
            self._worker.kill()
            self._worker.join()
            self._worker = None
        if self._channel is not None:
            self._channel.close()
            self._channel = None
