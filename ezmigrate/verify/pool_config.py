"""How verification workers run (``PoolConfig``), apart from the pool itself: every command
settles it from its options, and a ``check`` its cache answers starts no worker, so it
need not import the pool (its protocol and the runtime's diagnostics) to say how one
would run."""

from __future__ import annotations

import os
from dataclasses import dataclass


def default_jobs() -> int:
    """One worker per CPU this process may use (every command's default ``--jobs``)."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # not on Linux
        return max(1, os.cpu_count() or 1)


@dataclass(frozen=True)
class PoolConfig:
    """How verification workers run: count, per-file timeout, memory cap, ontology."""

    workers: int = 2
    timeout: float = 20.0
    memory_mb: int = 2048
    ontology: tuple[str, ...] = ()
    python: str | None = None
    """The interpreter to load files with (``--python``, or the robot's); None: ours."""
    python_given: bool = False
    """``python`` is the user's choice (``--python``, ``[tool.ezmigrate] python``): kept
    for every file. Otherwise a file with syntax newer than it is loaded again under the
    oldest ``python3.X`` that compiles it (``interpreters.oldest_that_compiles``)."""
