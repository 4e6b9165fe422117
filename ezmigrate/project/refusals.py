"""The runtime's early checks on a converted skill, as ``rewrite --no-verify`` asks them.

``static_refusal`` holds back what they refuse; the workers that migrate a file work them
out for its skills (``with_refusals``) so that the main process does not, file by file,
after them. Apart from ``static_refusal`` because the workers must not import what holds
skills back (``holding`` imports the runner).
"""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from ezskiros_runtime.dsl.check_context import CheckContext
from ezskiros_runtime.dsl.checking import CHECKS

from ..lint.legacy import trace_of
from ..report.results import FileResult, SkillResult
from ..verify.verdicts import rejects

if TYPE_CHECKING:
    from ezskiros_runtime.ontology.index import OntologyIndex


def static_rejections(skill: SkillResult, path: str, index: OntologyIndex | None) -> list[str]:
    """The error-level findings the runtime's early checks give for a converted skill,
    each with its (legacy) line, once each; ``[]``: it would load."""
    if skill.status != "converted" or skill.static is None or index is None:
        return []  # ``rewrite`` always has an index (the bundled core at least)
    ctx = CheckContext(trace_of(skill.name, path, skill.static), index)
    for check in CHECKS:
        check(ctx)
    return list(dict.fromkeys(
        found.message + (f" (line {found.line})" if found.line else "")
        for found in ctx.findings if rejects(found)))


def with_refusals(result: FileResult, path: str, index: OntologyIndex | None) -> FileResult:
    """``result`` carrying ``static_rejections`` of its skills, worked out in the worker
    that migrated the file (``refuse_statically`` takes them from there)."""
    if not result.changed:
        return result
    found = {skill.name: static_rejections(skill, path, index) for skill in result.skills}
    return replace(result, refusals={name: why for name, why in found.items() if why})


__all__ = ["static_rejections", "with_refusals"]
