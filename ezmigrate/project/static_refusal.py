"""``rewrite --no-verify`` refuses what the runtime's early checks know will not load.

Why: without verification nothing loads the migrated module, yet the EzSkiROS runtime runs
its early checks when a description class is defined and raises ``SkillTypeError`` for any
finding at error severity (a contradictory condition list, a relation outside its domain...).
The verified run holds such a skill back (``verify.verdicts``); a ``--no-verify`` run wrote
it, and ``check`` then found a module that does not import. The same checks run here on
what the codemod read (``lint.legacy.trace_of``, as ``check`` runs them on legacy code), no
user code executed, and a rejected skill is held as it was, with the verified run's words.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from ..verify.verdicts import rejected
from .holding import hold_back, not_written
from .refusals import static_rejections

if TYPE_CHECKING:
    from ezskiros_runtime.ontology.index import OntologyIndex

    from .runner import Migrated


def refuse_statically(migrated: Sequence[Migrated], index: OntologyIndex | None) -> None:
    """Hold back every converted skill the runtime would refuse to load, migrating its file
    again without it; a file deriving from one whose skills were held is not written (its
    classes were migrated against the base's new form)."""
    redone: set[str] = set()
    for item in migrated:
        if not item.result.changed:
            continue
        culprits = {}
        known = item.result.refusals  # made in the worker, for this very result
        for skill in item.result.skills:
            found = known.get(skill.name, []) if known is not None else \
                static_rejections(skill, item.candidate.relative, index)
            if found:
                culprits[skill.name] = rejected(skill, found)
        if culprits:
            hold_back(item, culprits)
            redone.add(item.candidate.relative)
    for item in migrated:
        held = [r for r in item.result.depends_on if r in redone]
        if held and item.result.new_source is not None:
            item.result = not_written(item.result, "not written: it derives from a "
                                      f"description in {held[0]}, where a skill was held "
                                      "back")


__all__ = ["refuse_statically"]
