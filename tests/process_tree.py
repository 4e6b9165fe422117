"""A process's descendants, and whether they ended: what the tests of process lifetimes
watch (nothing a run starts may outlive it). Linux only: ``/proc`` and ``pidfd_open``."""

from __future__ import annotations

import contextlib
import os
import select
from pathlib import Path


def descendants(pid: int) -> set[int]:
    """Every process below ``pid`` now (children, their children, ...)."""
    found: set[int] = set()
    todo = [pid]
    while todo:
        for task in Path(f"/proc/{todo.pop()}/task").glob("*/children"):
            with contextlib.suppress(OSError):
                children = {int(c) for c in task.read_text().split()} - found
                todo += children
                found |= children
    return found


def ends(pid: int, seconds: float = 30) -> bool:
    """Whether ``pid`` ends within ``seconds`` (a bound on failure: an ended process
    answers at once), a zombie counting as ended."""
    try:
        handle = os.pidfd_open(pid)
    except ProcessLookupError:
        return True
    try:
        if select.select([handle], [], [], seconds)[0]:
            return True
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
        return state in ("Z", "X")
    except OSError:
        return True
    finally:
        os.close(handle)
