"""``ezmigrate check``: what a repository keeps in CI after its migration.

Two questions, answered without writing anything: is any legacy description left that
``rewrite`` would convert (it should have been migrated), and do the EzSkiROS descriptions
pass their early checks against the configured ontology (the runtime's checks, run by
loading each module in an isolated child, exactly as ``verify`` does)? Legacy descriptions
that cannot be migrated (reported as skipped by ``rewrite``) are listed, not failed: they
were reviewed and kept.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .discover import discover
from .package import RUNTIME_MARKER, migrate_package
from .verify.pool import PoolConfig, job_for, run_jobs

if TYPE_CHECKING:
    from ezskiros_runtime.ontology.index import OntologyIndex


@dataclass
class CheckMessage:
    """One line of the check's output."""

    path: str
    line: int
    skill: str
    severity: str
    message: str

    def __str__(self) -> str:
        return f"{self.path}:{self.line}: {self.skill}: {self.severity}: {self.message}"


@dataclass
class CheckOutcome:
    """Everything ``check`` found; ``exit_code`` follows the CLI conventions."""

    files: int = 0
    skills: int = 0
    messages: list[CheckMessage] = field(default_factory=list)
    unloadable: list[str] = field(default_factory=list)

    @property
    def errors(self) -> int:
        return sum(1 for m in self.messages if m.severity == "error")

    @property
    def exit_code(self) -> int:
        return 2 if self.unloadable else 1 if self.errors else 0


def run_check(paths: list[Path], index: OntologyIndex | None, pool: PoolConfig,
              exclude: tuple[str, ...] = ()) -> CheckOutcome:
    """Static pass for leftover legacy descriptions, then the runtime's checks."""
    candidates, _ = discover(paths, exclude)
    outcome = CheckOutcome(files=len(candidates))
    loadable = []
    for item in migrate_package(candidates, index, pool.workers):
        path = str(item.candidate.path)
        for skill in item.result.skills:
            if skill.status == "converted":
                outcome.messages.append(CheckMessage(
                    path, skill.line, skill.name, "error",
                    "legacy description not migrated yet (run `ezmigrate rewrite`)"))
            elif skill.status == "skipped":
                outcome.messages.append(CheckMessage(
                    path, skill.line, skill.name, "info",
                    f"legacy description kept: {(skill.reason or '').splitlines()[0]}"))
        if item.result.error:
            outcome.messages.append(CheckMessage(path, item.result.error_line or 0, "-",
                                                 "error", item.result.error))
        if RUNTIME_MARKER in item.original:
            loadable.append(item)
    outcomes = run_jobs([job_for(i.candidate.path, None, i.candidate.root) for i in loadable],
                        pool) if loadable else []
    for item, loaded in zip(loadable, outcomes, strict=True):
        path = str(item.candidate.path)
        if not loaded.loaded:
            outcome.unloadable.append(path)
            outcome.messages.append(CheckMessage(path, loaded.line or 0, "-", "error",
                                                 f"{loaded.status}: {loaded.message}"))
            continue
        outcome.skills += len(loaded.models)
        for error in loaded.errors:
            outcome.messages.append(_class_error(path, error))
        for finding in loaded.findings:
            outcome.messages.append(CheckMessage(
                path, int(finding.get("line") or 0), str(finding.get("skill", "-")),
                str(finding.get("severity", "warning")), str(finding.get("message", ""))))
    return outcome


def _class_error(path: str, error: dict[str, Any]) -> CheckMessage:
    return CheckMessage(path, int(error.get("line") or 0), str(error.get("name", "-")), "error",
                        str(error.get("message", "")))
