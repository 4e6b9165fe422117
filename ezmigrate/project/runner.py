"""Run the pure core over many files: read, prefilter, migrate in parallel workers.

One pass over the candidates, in the main process: read a file, ask the prefilter, and hand
the few files that may hold descriptions to the workers at once, so parsing overlaps the
reading of the rest. The workers are forked when the second such file turns up (one file is
migrated in this process: a pool would only add its start-up), with the ontology index and
libcst already imported, so neither is loaded again per worker. libcst itself is imported
only when some file needs parsing: a tree without legacy descriptions never pays for it.

Memory stays flat on a large tree: only the bytes of files handed to the core are kept
(the diff, the write and verification need them); for every other file ``Migrated``
re-reads the bytes from disk when someone asks for them (a copy into ``--output-dir``).
"""

from __future__ import annotations

import contextlib
import importlib
import multiprocessing
import os
import traceback
from collections.abc import Iterator, Mapping, Sequence
from concurrent.futures import Future, ProcessPoolExecutor
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass
from typing import TYPE_CHECKING

from ..files.discover import Candidate
from ..files.prefilter import by_text, marker_is_identifier
from ..files.writing import digest as content_digest
from ..report.results import FileResult
from . import holdpoint
from .frozen_heap import frozen_heap
from .import_scan import import_words
from .lifetime import exit_with_parent
from .progress import Progress

if TYPE_CHECKING:
    from ezskiros_runtime.ontology.index import OntologyIndex

    from ..codemod.settings import Settings

_SETTINGS: Settings | None = None


@dataclass(frozen=True)
class Extras:
    """What the workers add to each result for the main process, which would otherwise do
    it file by file after them: the report's line map (``with_written_lines``), the diff's
    hunks (``--dry-run``), the runtime's early-check refusals (``rewrite --no-verify``:
    ``static_refusal``)."""

    written_lines: bool = False
    diffs: bool = False
    refusals: bool = False


NO_EXTRAS = Extras()
_EXTRAS = NO_EXTRAS


class Migrated:
    """One file after the core ran: what it was, its verdict, and the hash it was read with.

    ``original`` and ``digest`` are kept from the read for every file the core looked at.
    For a file the prefilter ruled out (never parsed, never changed, never written in
    place) they are not kept: the first access reads the file again, as it is then.
    """

    __slots__ = ("_digest", "_imports", "_original", "candidate", "result", "settings")

    def __init__(self, candidate: Candidate, original: bytes | None, digest: str | None,
                 result: FileResult, settings: Settings | None = None,
                 imports: frozenset[bytes] | None = None) -> None:
        self.candidate = candidate
        self._original = original
        self._digest = digest
        self._imports = imports
        self.result = result
        self.settings = settings
        """What the core migrated this file with (to migrate it again, holding classes)."""

    @property
    def original(self) -> bytes:
        if self._original is None:
            try:
                return self.candidate.path.read_bytes()
            except OSError:
                return b""
        return self._original

    @property
    def imports(self) -> frozenset[bytes]:
        """The words of the file's import statements (``import_scan``): taken at the read
        for a file the prefilter ruled out, so that no later pass reads it again."""
        if self._imports is None:
            self._imports = import_words(self.original)
        return self._imports

    @property
    def digest(self) -> str:
        if self._digest is None:
            self._digest = content_digest(self.original)
        return self._digest

    def __repr__(self) -> str:
        return f"Migrated({self.candidate.relative!r}, changed={self.result.changed})"


def _init_worker(settings: Settings, extras: Extras = NO_EXTRAS,
                 parent: int | None = None) -> None:
    """A worker's start: its settings, and its end with the run's (``lifetime.exit_with_parent``:
    a SIGKILL of ``rewrite`` leaves no worker behind)."""
    global _SETTINGS, _EXTRAS
    exit_with_parent(parent)
    _SETTINGS = settings
    _EXTRAS = extras


def _migrate_one(relative: str, data: bytes, ambiguous: bool = False) -> FileResult:
    """``migrate_file`` in a worker, with the settings and extras it was started with."""
    assert _SETTINGS is not None
    return migrate_file(relative, data, _SETTINGS, ambiguous, _EXTRAS)


def migrate_file(relative: str, data: bytes, settings: Settings, ambiguous: bool = False,
                 extras: Extras = NO_EXTRAS) -> FileResult:
    """One file's migration, with what the run's ``Extras`` ask for besides (the report's
    line map, the diff's hunks, the early-check refusals: in the worker, rather than for
    every file in the main process afterwards).
    ``ambiguous``: the prefilter's text could not rule the file out; its parse
    (``marker_is_identifier``) is taken here too, and an empty result is what the
    prefilter would have given."""
    from ..codemod.migrate import migrate
    from ..report.written_lines import with_written_lines
    from .refusals import with_refusals

    if ambiguous and not marker_is_identifier(data):
        return FileResult(relative)
    try:
        result = migrate(data, settings, relative)
        if extras.refusals:
            result = with_refusals(result, relative, settings.index)
        if extras.written_lines:
            result = with_written_lines(result, data, extras.diffs)
        return result
    except Exception:  # a bug of ours must not stop the run nor lose the other files
        return FileResult(path=relative, error="internal error while migrating:\n"
                          + traceback.format_exc(limit=6))


def own_reading(relative: str, data: bytes, settings: Settings) -> FileResult:
    """What ``migrate_all`` makes, before the cross-file pass and without extras, of a file
    the prefilter keeps (the caller took its verdict, its parse included when the text
    could not tell: ``file_facts.described``): taken early by a pool that has the file at
    hand (``reading_pool``) and handed to ``migrate_all`` as ``known``."""
    return migrate_file(relative, data, settings)


def read_candidates(candidates: Sequence[Candidate]) -> Iterator[tuple[Candidate, bytes | None,
                                                                       str | None]]:
    """Each candidate with its bytes, or an error message when it cannot be read."""
    for candidate in candidates:
        try:
            with open(candidate.path, "rb") as handle:
                data = handle.read()
        except OSError as error:
            yield candidate, None, f"cannot read: {error.strerror or error}"
        else:
            yield candidate, data, None


class _Workers:
    """Migrates the files it is given: here for the first, in forked workers from the second."""

    def __init__(self, index: OntologyIndex | None, jobs: int,
                 progress: Progress | None = None,
                 target: tuple[int, int] | None = None, extras: Extras = NO_EXTRAS) -> None:
        self.index = index
        self.target = target
        self.extras = extras
        self.jobs = jobs
        self.progress = progress
        self._settings: Settings | None = None
        self.pool: ProcessPoolExecutor | None = None
        self.first: tuple[Migrated, bytes, bool] | None = None
        self.futures: list[tuple[Migrated, Future[FileResult]]] = []
        self._frozen = contextlib.ExitStack()  # the heap, frozen while the pool runs

    @property
    def settings(self) -> Settings:
        if self._settings is None:  # no libcst yet: ``_start`` imports it before the fork
            from ..codemod.settings import Settings

            self._settings = (Settings(index=self.index) if self.target is None
                              else Settings(index=self.index, target=self.target))
        return self._settings

    def add(self, item: Migrated, data: bytes, ambiguous: bool = False) -> None:
        item.settings = self.settings
        if self.jobs <= 1:
            _init_worker(self.settings, self.extras)
            item.result = _migrate_one(item.candidate.relative, data, ambiguous)
            self.finished(item)
            return
        if self.pool is None and self.first is None:
            self.first = (item, data, ambiguous)
            return
        if self.pool is None:
            self.pool = self._start()
            assert self.first is not None
            self._submit(*self.first)
            self.first = None
        self._submit(item, data, ambiguous)

    def _start(self) -> ProcessPoolExecutor:
        # the core (and libcst) imported once, here, before the fork: the workers inherit
        # it instead of each importing it while the tree is still being read
        importlib.import_module("ezmigrate.codemod.migrate")
        self._frozen.enter_context(frozen_heap())  # the workers inherit it frozen
        context = multiprocessing.get_context(
            "fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn")
        return ProcessPoolExecutor(max_workers=self.jobs, mp_context=context,
                                   initializer=_init_worker,
                                   initargs=(self.settings, self.extras, os.getpid()))

    def _submit(self, item: Migrated, data: bytes, ambiguous: bool) -> None:
        assert self.pool is not None
        try:
            future = self.pool.submit(_migrate_one, item.candidate.relative, data, ambiguous)
        except BrokenProcessPool as error:  # a worker died while files were still read:
            future = Future()  # this file gets the verdict the files in flight get
            future.set_exception(error)
        self.futures.append((item, future))

    def finish(self) -> None:
        if self.first is not None:  # only one file needed the core: no pool for it
            _init_worker(self.settings, self.extras)
            item, data, ambiguous = self.first
            item.result = _migrate_one(item.candidate.relative, data, ambiguous)
            self.finished(item)
        if self.pool is None:
            return
        try:
            for item, future in self.futures:
                try:
                    item.result = future.result()
                except Exception as error:  # the worker process died (killed, out of memory)
                    item.result = FileResult(
                        item.candidate.relative,
                        error=f"internal error: the migration worker died ({error})")
                self.finished(item)
        finally:
            self.close()

    def finished(self, item: Migrated | None = None) -> None:
        """One more file done (``item``: one the core migrated, whose skills count)."""
        if self.progress is not None:
            self.progress.advance(1, 0 if item is None else sum(
                1 for s in item.result.skills if s.status == "converted"),
                skill_file=item is not None)

    def close(self) -> None:
        if self.pool is not None:
            self.pool.shutdown(wait=True, cancel_futures=True)
            self.pool = None
        self._frozen.close()


def migrate_all(candidates: Sequence[Candidate], index: OntologyIndex | None,
                jobs: int, progress: Progress | None = None,
                target: tuple[int, int] | None = None,
                extras: Extras = NO_EXTRAS,
                known: Mapping[str, tuple[bytes, FileResult]] | None = None
                ) -> list[Migrated]:
    """Migrate every candidate; files the prefilter rules out get an empty result.
    ``target``: the Python the migrated code must run on (None: the default); ``extras``:
    what each result carries besides (``Extras``). ``known``: by path, files already
    migrated as this would (``own_reading``, default target, no extras) and the bytes they
    were read with: taken as they are."""
    assert not known or (target is None and extras == NO_EXTRAS), "known: default readings"
    workers = _Workers(index, jobs, progress, target, extras)
    done: list[Migrated] = []
    try:
        for candidate, data, error in read_candidates(candidates):
            taken = known.get(str(candidate.path)) if known else None
            if taken is not None and taken[0] == data:
                item = Migrated(candidate, data, content_digest(data), taken[1],
                                workers.settings)
                done.append(item)
                workers.finished(item)
            elif data is None:
                done.append(Migrated(candidate, b"", "",
                                     FileResult(candidate.relative, error=error)))
                workers.finished()
            elif (verdict := by_text(data)) is not False:
                item = Migrated(candidate, data, content_digest(data),
                                FileResult(candidate.relative))
                done.append(item)
                if progress is not None:  # the estimate is weighted by skill files
                    progress.queued()
                workers.add(item, data, ambiguous=verdict is None)
                if workers.pool is not None:  # forked workers are busy with the others
                    holdpoint.reach("migrating")
            else:
                done.append(Migrated(candidate, None, None, FileResult(candidate.relative),
                                     imports=import_words(data)))
                workers.finished()
        workers.finish()
    finally:
        workers.close()
    return done
