"""A finding about the world model: a catalogue kind (``ezskiros_runtime.codes``), where,
what, and a suggested fix. The linter turns these into its diagnostics; a lab's test can
read them directly."""

from __future__ import annotations

from dataclasses import dataclass

from ..codes import rule_for


@dataclass(frozen=True)
class WorldFinding:
    """One finding; ``subject`` is the element or skill it is about (for highlighting)."""

    kind: str
    path: str
    line: int
    message: str
    subject: str = ""
    fix: str | None = None
    lowered: str | None = None
    """``info`` when the rule's condition for its own severity does not hold here (the
    catalogue's severity is the most a finding gets; docs/rules.md, severity contract)."""

    @property
    def code(self) -> str:
        return rule_for(self.kind).code

    @property
    def severity(self) -> str:
        return self.lowered or rule_for(self.kind).severity

    def __str__(self) -> str:
        return f"{self.path}:{self.line}: {self.code} {self.message}"


def finding(kind: str, path: str, line: int, message: str, subject: str = "",
            fix: str | None = None, severity: str | None = None) -> WorldFinding:
    """A finding of a catalogue kind (the catalogue test reads the kinds passed here);
    ``severity`` lowers it to info (see ``WorldFinding.lowered``)."""
    if severity not in (None, "info"):
        raise ValueError(f"a finding is only ever lowered to info, not to {severity!r}")
    return WorldFinding(kind, path, line, message, subject, fix, severity)


__all__ = ["WorldFinding", "finding"]
