"""Picklable result types that workers return and reports read.

Like LibCST's codemod results: a file is changed, unchanged, or failed with a message, and
each skill in it is converted, skipped (with a reason a user can act on and its finding
code), failed (with the difference or the error), or unchanged. Frozen dataclasses of
builtins: they cross process boundaries cheaply and serialize to the JSON report directly,
and a verdict, once given, is never edited: a later step (verification, a refused write)
makes a new result with ``dataclasses.replace`` and puts it in the old one's place.
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Literal

from ezskiros_runtime.codes import code_for, rule_for
from ezskiros_runtime.diagnostics import Finding

if TYPE_CHECKING:
    from .static_facts import StaticDescription

SkillStatus = Literal["converted", "skipped", "failed", "unchanged"]


def review_finding(kind: str, skill: str, line: int, message: str, subject: str = ""
                   ) -> Finding:
    """Something a reviewer should see that migration keeps as it was (a latent bug...),
    as the runtime's one ``Finding`` at its rule's severity: ``line`` 0 is the skill as a
    whole; ``subject`` the prefix no loaded ontology defines when that is the cause, which
    the report says once for the whole migration (as ``check`` does). After a rewrite the
    report moves ``line`` to the written file and keeps the legacy one in ``legacy_line``
    (``written_lines``)."""
    return Finding(kind, rule_for(kind).severity, message, None, line, skill, subject=subject)


@dataclass(frozen=True)
class SkillResult:
    """The verdict on one description class."""

    name: str
    line: int
    status: SkillStatus
    reason: str | None = None
    findings: list[Finding] = field(default_factory=list)
    """What the reviewer should see (``review_finding``), with the runtime's findings of the
    migrated skill once it is loaded (``verdicts.with_findings``)."""
    model: dict[str, Any] | None = None
    equivalent: bool | None = None
    diff: list[dict[str, Any]] | None = None
    static: StaticDescription | None = None
    """What a converted legacy description declares, for ``check``'s static early checks."""
    legacy_line: int | None = None
    """The line in the legacy file when ``line`` is the written file's (``written_lines``)."""

    @property
    def code(self) -> str | None:
        """The catalogue code of a verdict that needs a reader's eye (kept, not equivalent)."""
        return code_for(self.status) if self.status in ("skipped", "failed") else None


def source_digest(data: bytes) -> str:
    """The SHA-1 a map of a new source's lines names it by (a checksum, not a secret)."""
    return hashlib.sha1(data).hexdigest()


@dataclass(frozen=True)
class ClassLines:
    """Each top-level class of one new source and the line of its ``class`` statement, as
    the parse that checked the migrated code read them (``digest``: the source's
    ``source_digest``, None while it is text: a changed source never meets them)."""

    digest: str | None
    classes: dict[str, int]


@dataclass(frozen=True)
class WrittenLines:
    """Legacy line -> written line, and each top-level class's line, of one new source
    (``digest``: its SHA-1, so that a changed source never meets an old map), and the
    hunks of its diff for ``--dry-run``."""

    digest: str
    lines: dict[int, int]
    classes: dict[str, int]
    diff: str | None = None
    """The hunks of its diff (``diffs.diff_body``), when the run shows diffs."""


@dataclass(frozen=True)
class FileResult:
    """What happened to one file. ``new_source`` is set only when it should change."""

    path: str
    skills: list[SkillResult] = field(default_factory=list)
    new_source: bytes | str | None = None
    error: str | None = None
    error_line: int | None = None
    error_kind: str = "unreadable"
    """The catalogue kind of ``error``: ``unreadable`` (EZ905), or ``lossy-rewrite`` (EZ906)
    for a file the line guard (``core/guard.py``) kept from being written."""
    python2: bool = False
    """``error`` is Python 2 syntax no Python 3 grammar has (``codemod/core/python2``): a
    Python 2 robot imports the file (``lint/skill_library`` judges it so)."""
    notes: list[str] = field(default_factory=list)
    python: str = ""
    """The interpreter that loaded the file when verifying, when it was not the run's own
    (said once in the summary and the report's header, not per file)."""
    exports: list[str] = field(default_factory=list)
    """Description classes that convert (or inherit a conversion): bases for other files."""
    foreign_bases: list[tuple[str, str]] = field(default_factory=list)
    """``(base, module)`` of class bases imported from user modules (maybe descriptions)."""
    depends_on: list[str] = field(default_factory=list)
    """Files whose migrated descriptions this file's migrated classes derive from."""
    written: WrittenLines | None = None
    """Where the lines of ``new_source`` came from, worked out where it was made
    (``written_lines``): valid only for the new source whose digest it names."""
    new_classes: ClassLines | None = None
    """The top-level classes of ``new_source`` as the migration's own check parsed it
    (``written_lines`` takes them instead of parsing it again)."""
    refusals: dict[str, list[str]] | None = None
    """Skill -> the runtime's early-check refusals of it, worked out in the worker that
    made this result (``static_refusal.with_refusals``); None: not worked out. A result
    made again (``replace`` of its skills or source) must not keep it."""

    @property
    def error_code(self) -> str | None:
        """The catalogue code of ``error``, if any."""
        return code_for(self.error_kind) if self.error else None

    @property
    def changed(self) -> bool:
        return self.new_source is not None

    def count(self, status: str) -> int:
        return sum(1 for s in self.skills if s.status == status)


def unparsable(path: str, message: str, line: int, column: int, advice: str = "") -> FileResult:
    """The result for a file no parser reads: ``message`` where (``advice``: what to do)."""
    return FileResult(path, error=f"cannot parse: {message} (line {line}, column {column})"
                      + (f"; {advice}" if advice else ""), error_line=line)
