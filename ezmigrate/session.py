"""Orchestration of ``rewrite``: discover, migrate, verify, write. No printing happens here.

The CLI turns options into a ``RewriteOptions``, calls ``run_rewrite`` and prints what the
returned outcome says, so every decision (what is written, what is refused) is testable
without a terminal.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

from .discover import Candidate, discover
from .runner import Migrated, default_jobs, migrate_all
from .writing import WriteRefused, atomic_write

if TYPE_CHECKING:
    from ezskiros_runtime.ontology.index import OntologyIndex


@dataclass
class RewriteOptions:
    """Everything ``rewrite`` was asked to do."""

    paths: list[Path]
    dry_run: bool = False
    check: bool = False
    exclude: tuple[str, ...] = ()
    jobs: int = field(default_factory=default_jobs)
    output_dir: Path | None = None
    verify: bool = True
    timeout: float = 20.0
    ignore_order: bool = False
    ignore_labels: bool = False
    ontology: tuple[str, ...] = ()
    """Resolved ontology files for verification workers (empty: the bundled default)."""

    @property
    def writes(self) -> bool:
        return not (self.dry_run or self.check)


@dataclass
class RewriteOutcome:
    """What happened: per-file results, files written, and messages for the user."""

    migrated: list[Migrated]
    notes: list[str] = field(default_factory=list)
    written: list[str] = field(default_factory=list)
    refused: list[str] = field(default_factory=list)


Verifier = Callable[[list[Migrated], RewriteOptions], None]


def run_rewrite(options: RewriteOptions, index: OntologyIndex | None,
                verifier: Verifier | None = None,
                on_written: Callable[[str], None] | None = None) -> RewriteOutcome:
    """Discover and migrate; verify converted skills; write files whose skills all verified."""
    candidates, notes = discover(options.paths, options.exclude)
    migrated = migrate_all(candidates, index, options.jobs)
    outcome = RewriteOutcome(migrated, notes)
    if options.verify and verifier is not None:
        verifier([m for m in migrated if m.result.changed], options)
    if not options.writes:
        return outcome
    for item in migrated:
        target = _target(item.candidate, options.output_dir)
        data = item.result.new_source if item.result.changed else None
        if options.output_dir is not None:
            assert target is not None
            content = data if isinstance(data, bytes) else item.original
            if item.result.error is not None and item.original == b"":
                continue
            target.parent.mkdir(parents=True, exist_ok=True)
            if not target.exists():
                target.write_bytes(b"")
            _write(target, content, None, outcome, item, on_written)
        elif isinstance(data, bytes):
            _write(item.candidate.path, data, item.digest, outcome, item, on_written)
    return outcome


def _target(candidate: Candidate, output_dir: Path | None) -> Path | None:
    return None if output_dir is None else output_dir / candidate.relative


def _write(path: Path, data: bytes, expected: str | None, outcome: RewriteOutcome,
           item: Migrated, on_written: Callable[[str], None] | None) -> None:
    try:
        atomic_write(path, data, expected)
    except WriteRefused as refused:
        outcome.refused.append(str(refused))
        item.result.notes.append(str(refused))
        return
    if item.result.changed:
        outcome.written.append(item.candidate.relative)
        if on_written is not None:
            on_written(item.candidate.relative)
