"""A cheap text test that lets files with no legacy description skip parsing entirely.

On a lab monorepo most files are ordinary modules; parsing them with libcst would dominate
the run. A legacy description needs ``SkillDescription`` in its file (as a base, or imported
for one) or ``createDescription`` (a subclass of a description from a sibling module), so
files with neither are never parsed.
"""

from __future__ import annotations

MARKERS = (b"SkillDescription", b"createDescription")


def may_hold_descriptions(data: bytes) -> bool:
    """False only when the file certainly has nothing to migrate."""
    return any(marker in data for marker in MARKERS)
