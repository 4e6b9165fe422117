"""Run the pure core over many files: read, prefilter, migrate in parallel workers.

The main process reads every candidate and drops those the prefilter rules out, so workers
only ever see files that may hold descriptions. Workers are forked with the ontology index
already loaded (one load per run, not per file) and return picklable ``FileResult``s.
"""

from __future__ import annotations

import multiprocessing
import os
import traceback
from collections.abc import Iterator, Sequence
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass
from typing import TYPE_CHECKING

from .discover import Candidate
from .migrate import Settings, migrate
from .prefilter import may_hold_descriptions
from .results import FileResult
from .writing import digest

if TYPE_CHECKING:
    from ezskiros_runtime.ontology.index import OntologyIndex

_SETTINGS: Settings | None = None


@dataclass
class Migrated:
    """One file after the core ran: what it was, its verdict, and the hash it was read with."""

    candidate: Candidate
    original: bytes
    digest: str
    result: FileResult


def _init_worker(settings: Settings) -> None:
    global _SETTINGS
    _SETTINGS = settings


def _migrate_one(item: tuple[str, bytes]) -> FileResult:
    relative, data = item
    assert _SETTINGS is not None
    try:
        return migrate(data, _SETTINGS, relative)
    except Exception:  # a bug of ours must not stop the run nor lose the other files
        return FileResult(path=relative, error="internal error while migrating:\n"
                          + traceback.format_exc(limit=6))


def default_jobs() -> int:
    """One worker per CPU this process may use."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # not on Linux
        return max(1, os.cpu_count() or 1)


def read_candidates(candidates: Sequence[Candidate]) -> Iterator[tuple[Candidate, bytes | None,
                                                                       str | None]]:
    """Each candidate with its bytes, or an error message when it cannot be read."""
    for candidate in candidates:
        try:
            yield candidate, candidate.path.read_bytes(), None
        except OSError as error:
            yield candidate, None, f"cannot read: {error.strerror or error}"


def migrate_all(candidates: Sequence[Candidate], index: OntologyIndex | None,
                jobs: int) -> list[Migrated]:
    """Migrate every candidate; files the prefilter rules out get an empty result."""
    settings = Settings(index=index)
    done: list[Migrated] = []
    work: list[tuple[int, tuple[str, bytes]]] = []
    for candidate, data, error in read_candidates(candidates):
        if data is None:
            done.append(Migrated(candidate, b"", "", FileResult(candidate.relative, error=error)))
            continue
        done.append(Migrated(candidate, data, digest(data), FileResult(candidate.relative)))
        if may_hold_descriptions(data):
            work.append((len(done) - 1, (candidate.relative, data)))
    if not work:
        return done
    items = [item for _, item in work]
    if jobs <= 1 or len(work) < 4:
        _init_worker(settings)
        results = [_migrate_one(item) for item in items]
    else:
        context = multiprocessing.get_context(
            "fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn")
        with ProcessPoolExecutor(max_workers=min(jobs, len(work)), mp_context=context,
                                 initializer=_init_worker, initargs=(settings,)) as pool:
            chunk = max(1, len(items) // (jobs * 8))
            results = list(pool.map(_migrate_one, items, chunksize=chunk))
    for (position, _), result in zip(work, results, strict=True):
        done[position].result = result
    return done
