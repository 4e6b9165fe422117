"""Holding skills back: what a run does with a skill it will not write.

A skill that did not verify (``settle``) or that the runtime's early checks refuse
(``static_refusal``) is held: its file is migrated again leaving it as it was. A file that
is not written keeps its converted skills as failures with the reason. Both the settle loop
and the static refusal do this, so it lives below both of them.
"""

from __future__ import annotations

from dataclasses import replace

from ..codemod.settings import Settings
from ..report.results import FileResult, SkillResult
from ..verify.verdicts import failed
from .runner import Migrated


def hold_back(item: Migrated, culprits: dict[str, SkillResult]) -> bool:
    """Migrate ``item`` again leaving ``culprits`` as they are; True when something still
    changes (and so must be verified again)."""
    from ..codemod.migrate import migrate  # libcst: only when something is held

    settings = item.settings or Settings()
    held = {**settings.held, **{name: skill.reason or "held" for name, skill in culprits.items()}}
    item.settings = replace(settings, held=held)
    result = migrate(item.original, item.settings, item.candidate.relative)
    item.result = replace(result, skills=[culprits.get(s.name, s) for s in result.skills],
                          notes=[*item.result.notes, *result.notes])
    return result.changed


def not_written(result: FileResult, reason: str) -> FileResult:
    """``result`` kept as it was on disk: its converted skills failed for ``reason``."""
    return replace(result, new_source=None, skills=[
        failed(s, reason) if s.status == "converted" else s for s in result.skills])
