"""One line of ``check`` output: a finding with its code, severity, position and fix hint."""

from __future__ import annotations

from dataclasses import dataclass

from ezskiros_runtime.codes import rule_for
from ezskiros_runtime.diagnostics import Finding


@dataclass(frozen=True)
class Diagnostic:
    """A finding at a position of a file; every output format is built from these fields.

    ``skill`` names the description class ("" for a file-level finding); positions are
    1-based like an editor's, and ``end_*`` close the span (the rest of the line).
    """

    path: str
    line: int
    column: int
    code: str
    severity: str
    message: str
    fix: str
    skill: str = ""
    end_line: int = 0
    end_column: int = 0
    param: str | None = None
    """The parameter the finding is about (a key of ``skill``), when it is about one."""
    term: str | None = None
    """The vocabulary it names as written (``skiros:Location``, ``skiros:contain``), when
    it names one: what later judgements read, instead of the message."""
    term_is_class: bool = False
    """``term`` is the class of ``param`` (not a relation or property)."""

    @property
    def text(self) -> str:
        """The message with the skill it concerns, as every format shows it."""
        return f"{self.skill}: {self.message}" if self.skill else self.message

    def __str__(self) -> str:
        """``path:line:col: CODE [severity] message``: the code where ruff puts it, and the
        severity beside it, so that a reader sees which lines fail the run."""
        return f"{self.path}:{self.line}:{self.column}: {self.code} [{self.severity}] {self.text}"


class Positions:
    """Columns of a file's lines: a finding points at the first non-blank character."""

    def __init__(self, source: str) -> None:
        self.lines = source.splitlines()

    def span(self, line: int) -> tuple[int, int, int]:
        """(column, end line, end column) of a 1-based line; line 0 is the file itself."""
        if not 1 <= line <= len(self.lines):
            return 1, max(line, 1), 1
        text = self.lines[line - 1]
        return len(text) - len(text.lstrip()) + 1, line, len(text.rstrip()) + 1


def check_finding(kind: str, line: int, message: str, skill: str = "",
                  lowered: bool = False) -> Finding:
    """One of ``check``'s own findings (a file it could not read, a class not migrated, an
    unused suppression) as the runtime's ``Finding``, at its rule's severity, or info when
    ``lowered`` (it rests on something the tool could not resolve: a false error costs more
    than a missed warning). Every diagnostic is made from a ``Finding`` (``from_finding``)."""
    return Finding(kind, "info" if lowered else rule_for(kind).severity, message, None, line,
                   skill)


def from_finding(path: str, positions: Positions, found: Finding, line: int | None = None,
                 lowered: bool = True) -> Diagnostic:
    """The diagnostic of a finding in the file ``path``: the catalogue's code and severity
    (info when ``lowered`` and the finding says info: its rule's condition does not hold
    here), its fix or first suggestion, else the rule's fix; its skill and parameter; the
    vocabulary it names as the term (``actual``: a class when no relation is involved).
    ``line``: where it points instead of the finding's own line (a legacy class's finding
    without a line of its own points at the class); 0 is the file itself."""
    rule = rule_for(found.kind)
    at = (found.line or 0) if line is None else line
    column, end_line, end_column = positions.span(at)
    fix = found.fix or (f"Did you mean {found.suggestions[0]}?" if found.suggestions else None)
    return Diagnostic(path, max(at, 1), column, rule.code,
                      "info" if lowered and found.severity == "info" else rule.severity,
                      found.message, fix or without_suggestion(rule.fix), found.skill,
                      end_line, end_column, found.param, found.actual,
                      found.actual is not None and found.relation is None)


def without_suggestion(fix: str) -> str:
    """A rule's fix for a finding that has no suggestion of its own: never "see the
    suggestion" when there is none to see."""
    return fix.replace(" (see the suggestion)", "")
