"""Tracing a run's compound trees in the sandbox (``check --trace``, ``rewrite``'s report).

A tree the syntax cannot read is traced: its module is imported in a sandboxed child and
``expand`` run against recording stand-ins (``LoadJob.trace``). ``trace_all`` traces a
list of files in batches, one child per batch. Every load restores ``sys.modules``, so an
outcome does not depend on the files that shared its batch: the run reports the same
bytes.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from ..files.discover import Candidate
from ..verify.pool import PoolConfig, job_for, run_batched
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


def trace_all(jobs: Sequence[LoadJob], pool: PoolConfig) -> list[LoadOutcome]:
    """Trace ``jobs`` in batches of ``TRACE_BATCH``, one child each, on ``trace_workers``
    workers; a batch that did not finish (a file hung or crashed its child) is traced again
    one file per child, so the verdict lands on the file that caused it (``run_batched``)."""
    workers = trace_workers(len(jobs), pool)
    size = min(TRACE_BATCH, max(1, -(-len(jobs) // workers)))
    return run_batched(jobs, replace(pool, workers=workers), size)
