"""Named points where a test can hold a run, so that a signal lands exactly there.

The interrupt tests must signal a run *while* it discovers, migrates, verifies or writes.
Sleeping for a guessed delay races the machine (a fast one finishes before the signal), so
a test holds the run by construction instead: it sets ``EZMIGRATE_HOLD_DIR`` to a folder
and ``EZMIGRATE_HOLD_AT`` to a point name; when the run reaches that point the first time,
it creates ``<point>.reached`` in the folder and waits until ``<point>.go`` appears. The
test signals in between, then releases it.

Without both variables (every real run) ``reach`` returns at once. The points, in order:
``discovered``, ``migrating`` (one file submitted, the workers busy with the rest),
``migrated``, ``writing:N`` (inside the deferred section of the N-th write, before it
starts: a signal there is recorded and the write completes) and ``written:N`` (after the
N-th file was replaced, outside any deferred section); in ``check``, ``checking`` (the
first file read, the rest to come).
"""

from __future__ import annotations

import os
import time
from pathlib import Path

FOLDER_VARIABLE = "EZMIGRATE_HOLD_DIR"
POINT_VARIABLE = "EZMIGRATE_HOLD_AT"
LONGEST_HOLD = 900.0
"""Seconds before a forgotten hold lets the run go on (a test that died must not leave a
process waiting forever)."""

_passed: set[str] = set()


def reach(point: str) -> None:
    """Hold here if a test asked for ``point`` (only the first time it is reached)."""
    folder = os.environ.get(FOLDER_VARIABLE)
    if not folder or os.environ.get(POINT_VARIABLE) != point or point in _passed:
        return
    _passed.add(point)
    Path(folder, f"{point}.reached").touch()
    release = Path(folder, f"{point}.go")
    deadline = time.monotonic() + LONGEST_HOLD
    while not release.exists() and time.monotonic() < deadline:
        time.sleep(0.005)  # a signal arriving here interrupts the sleep, as anywhere else
