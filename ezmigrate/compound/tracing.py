"""Tracing a run's compound trees in the sandbox, and starting it as the files are read.

A tree the syntax cannot read is traced: its module is imported in a sandboxed child and
``expand`` run against recording stand-ins (``LoadJob.trace``). ``trace_all`` traces a
list of files in batches, one child per batch.

Which files need it is known as soon as the files are read (``TreeFacts.to_trace``); the
compound pass, which used to start the tracing, comes after the codemod's readings and the
legacy checks, while the tracing worker sat ready and idle. ``EarlyTraces`` starts them in
one go when the reading ends, in a thread of its own, and the pass takes their outcomes
(``outcomes``). One go, not file by file as they are read: each go costs a child's start,
and while the files are read both cores are busy already. Every load restores
``sys.modules``, so an outcome does not depend on the files that shared its batch: the
run reports the same bytes.
"""

from __future__ import annotations

import threading
from collections.abc import Sequence
from dataclasses import replace

from ..files.discover import Candidate
from ..verify.pool import PoolConfig, Standby, job_for, run_batched
from ..verify.protocol import LoadJob, LoadOutcome
from .static import NeedsTrace

TRACE_BATCH = 32
"""Files traced by one child at most: a hang costs one batch's timeout, then each of its
files is traced alone."""

TRACED_PER_WORKER = 64
"""Files one tracing worker takes before a second is worth starting. A worker's start costs
about 0.1 s of a core, a file's trace about 4 ms in a warm worker; when the tracing starts,
the run is still busy on every core (scenes, its own checks), so a second worker's start is
time taken from the rest of the run. The 21 public repositories (41 files to trace) as one
run: 1.14 s with one worker, 1.19 s with two (medians of ten)."""


def trace_workers(count: int, pool: PoolConfig) -> int:
    """The tracing workers for ``count`` files: one per ``TRACED_PER_WORKER``, at most the
    pool's."""
    return max(1, min(pool.workers, -(-count // TRACED_PER_WORKER)))


def trace_job(candidate: Candidate, pending: Sequence[NeedsTrace]) -> LoadJob:
    """The job that traces ``pending`` in ``candidate``: a load only to trace."""
    return replace(job_for(candidate.path, None, candidate.root,
                           tuple(n.implementation for n in pending)), collect=False)


def trace_all(jobs: Sequence[LoadJob], pool: PoolConfig,
              standby: Standby | None = None) -> list[LoadOutcome]:
    """Trace ``jobs`` in batches of ``TRACE_BATCH``, one child each, on ``trace_workers``
    workers; a batch that did not finish (a file hung or crashed its child) is traced again
    one file per child, so the verdict lands on the file that caused it (``run_batched``)."""
    workers = trace_workers(len(jobs), pool)
    size = min(TRACE_BATCH, max(1, -(-len(jobs) // workers)))
    return run_batched(jobs, replace(pool, workers=workers), size, standby=standby)


def _key(job: LoadJob) -> tuple[str, tuple[str, ...]]:
    return job.path, tuple(job.trace)


class EarlyTraces:
    """The traces a run started when its reading ended (``start``), for the compound pass
    to take (``outcomes``). ``close`` stops them when the run ends before the pass (an
    interrupt, an error)."""

    def __init__(self, pool: PoolConfig) -> None:
        self.pool = pool
        self._done: dict[tuple[str, tuple[str, ...]], LoadOutcome] = {}
        self._thread: threading.Thread | None = None
        self._standby: Standby | None = None
        self._failed: BaseException | None = None

    def start(self, files: Sequence[tuple[Candidate, Sequence[NeedsTrace]]],
              standby: Standby) -> None:
        """Trace ``files`` now, in the background, on ``standby``'s worker (once a run)."""
        jobs = [trace_job(candidate, pending) for candidate, pending in files if pending]
        if self._thread is not None or not jobs:
            return
        self._standby = standby

        def run() -> None:
            try:
                for job, outcome in zip(jobs, trace_all(jobs, self.pool, standby),
                                        strict=True):
                    self._done[_key(job)] = outcome
            except BaseException as error:  # said in the main thread, by ``outcomes``
                self._failed = error

        self._thread = threading.Thread(target=run, daemon=True)
        self._thread.start()

    def outcomes(self) -> dict[tuple[str, tuple[str, ...]], LoadOutcome]:
        """The outcomes by ``(path, classes)``, once every trace started is done."""
        if self._thread is not None:
            self._thread.join()
        if self._failed is not None:
            raise self._failed
        return self._done

    def close(self) -> None:
        """Stop the traces still running (their worker and its child); never raises."""
        if self._thread is not None and self._thread.is_alive():
            assert self._standby is not None
            self._standby.crew.stop()
            self._thread.join()


def traced(jobs: Sequence[LoadJob], pool: PoolConfig, standby: Standby | None,
           early: EarlyTraces | None) -> list[LoadOutcome]:
    """The outcome of each job: from ``early`` when it traced the job already, the others
    traced now."""
    done = dict(early.outcomes()) if early is not None else {}
    rest = [job for job in jobs if _key(job) not in done]
    if rest:
        done.update(zip((_key(job) for job in rest), trace_all(rest, pool, standby),
                        strict=True))
    return [done[_key(job)] for job in jobs]
