"""``ezmigrate check``: the linter a SkiROS2 repository keeps in CI, before and after migrating.

Legacy descriptions are checked statically: the codemod's reader extracts what each
``createDescription`` declares (no user code runs) and the runtime's early checks run on
it, plus the checks only legacy code needs (``lint/legacy.py``). EzSkiROS files are loaded
in an isolated child, exactly as ``verify`` does, and report the runtime's own findings.
Every finding gets its catalogue code (``ezskiros_runtime.codes``); selection and
suppression happen afterwards (``lint/select.py``), so this module reports everything.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .discover import discover
from .lint.diagnostic import Diagnostic, Positions, diagnostic
from .lint.legacy import legacy_hits
from .package import RUNTIME_MARKER, migrate_package
from .runner import Migrated
from .verify.pool import PoolConfig, job_for, run_jobs

if TYPE_CHECKING:
    from ezskiros_runtime.ontology.index import OntologyIndex

KEPT_FROM_CODEMOD = frozenset({"description-in-options", "options-ignored"})
"""Codemod findings ``check`` keeps; the others are found again by the runtime's checks."""


@dataclass
class CheckOutcome:
    """Every finding of a run (before selection), and the source of each file read."""

    files: int = 0
    skills: int = 0
    diagnostics: list[Diagnostic] = field(default_factory=list)
    sources: dict[str, str] = field(default_factory=dict)


def _text(data: bytes) -> str:
    return data.decode("utf-8", errors="replace")


def _legacy(item: Migrated, positions: Positions, index: OntologyIndex | None
            ) -> list[Diagnostic]:
    path = str(item.candidate.path)
    found: list[Diagnostic] = []
    if item.result.error:
        found.append(diagnostic(path, positions, "unreadable", item.result.error_line or 0,
                                item.result.error.splitlines()[0]))
    for skill in item.result.skills:
        if skill.status == "converted":
            found.append(diagnostic(path, positions, "not-migrated", skill.line,
                                    "legacy description not migrated yet (run `ezmigrate "
                                    "rewrite`)", skill.name))
            for f in skill.findings:
                if f.kind in KEPT_FROM_CODEMOD:
                    found.append(diagnostic(path, positions, f.kind, f.line or skill.line,
                                            f.message, skill.name))
            if skill.static is not None:
                for hit in legacy_hits(skill.name, path, skill.static, index):
                    found.append(diagnostic(path, positions, hit.kind, hit.line or skill.line,
                                            hit.message, skill.name, hit.fix))
        elif skill.status == "skipped":
            reason = (skill.reason or "").splitlines()[0] if skill.reason else ""
            found.append(diagnostic(path, positions, "kept-legacy", skill.line,
                                    f"legacy description kept, not checked: {reason}",
                                    skill.name))
    return found


def run_check(paths: list[Path], index: OntologyIndex | None, pool: PoolConfig,
              exclude: tuple[str, ...] = (),
              progress: Callable[[str], None] | None = None) -> CheckOutcome:
    """Static pass over legacy descriptions, then the runtime's checks of EzSkiROS files."""
    candidates, _ = discover(paths, exclude)
    outcome = CheckOutcome(files=len(candidates))
    if progress is not None:
        progress(f"checking {len(candidates)} files")
    loadable = []
    positions: dict[str, Positions] = {}
    for item in migrate_package(candidates, index, pool.workers):
        path = str(item.candidate.path)
        outcome.sources[path] = _text(item.original)
        positions[path] = Positions(outcome.sources[path])
        outcome.skills += sum(1 for s in item.result.skills if s.status != "unchanged")
        outcome.diagnostics += _legacy(item, positions[path], index)
        if RUNTIME_MARKER in item.original:
            loadable.append(item)
    if loadable and progress is not None:
        progress(f"loading {len(loadable)} EzSkiROS files")
    outcomes = run_jobs([job_for(i.candidate.path, None, i.candidate.root) for i in loadable],
                        pool) if loadable else []
    for item, loaded in zip(loadable, outcomes, strict=True):
        path = str(item.candidate.path)
        where = positions[path]
        if not loaded.loaded:
            outcome.diagnostics.append(diagnostic(path, where, "unloadable", loaded.line or 0,
                                                  f"{loaded.status}: {loaded.message}"))
            continue
        outcome.skills += len(loaded.models)
        for error in loaded.errors:
            outcome.diagnostics.append(_class_error(path, where, error))
        for data in loaded.findings:
            suggestions = data.get("suggestions") or []
            outcome.diagnostics.append(diagnostic(
                path, where, str(data.get("kind", "description")),
                int(data.get("line") or 0), str(data.get("message", "")),
                str(data.get("skill", "")),
                f"Did you mean {suggestions[0]}?" if suggestions else None))
    outcome.diagnostics.sort(key=lambda d: (d.path, d.line, d.column, d.code))
    return outcome


def _class_error(path: str, where: Positions, error: dict[str, Any]) -> Diagnostic:
    return diagnostic(path, where, "description", int(error.get("line") or 0),
                      str(error.get("message", "")), str(error.get("name", "")))
