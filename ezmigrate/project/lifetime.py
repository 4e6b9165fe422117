"""A worker process of a run ends when the run does, however the run ends.

``rewrite`` and ``check`` read files in forked pool workers. When the run is killed
(SIGKILL: no handler runs), a worker waiting for its next task would wait forever, since
its siblings, forked from the same parent, hold the task queue's pipe open. Each worker
therefore watches its parent through a pidfd (Linux 5.3, Python 3.9): a thread that
blocks until the parent is gone, then ends the process. ``prctl(PR_SET_PDEATHSIG)`` would
not do: it fires when the *thread* that forked ends, and a pool may fork its workers from a
short-lived thread. (The verification children are held otherwise: ``verify/sandbox``.)
"""

from __future__ import annotations

import os
import select
import threading


def exit_with_parent(parent: int | None) -> None:
    """End this process as soon as ``parent`` has ended (at once when it already has);
    nothing where pidfds are missing (the run's own shutdown still ends the workers)."""
    if parent is None or not hasattr(os, "pidfd_open"):
        return
    try:
        handle = os.pidfd_open(parent)
    except OSError:  # already gone
        os._exit(0)
    if os.getppid() != parent:  # it died before the pidfd was taken, and its pid reused
        os._exit(0)

    def watch() -> None:
        select.select([handle], [], [])
        os._exit(0)

    threading.Thread(target=watch, name="exit-with-parent", daemon=True).start()
