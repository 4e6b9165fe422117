"""Findings about the world model (scenes, the lab's ontology): the runtime's one
``Finding`` type (``ezskiros_runtime.diagnostics``), made here with a catalogue kind
(``ezskiros_runtime.codes``), where, what, the element it is about and a suggested fix.
The linter turns them into its diagnostics; a lab's test can read them directly."""

from __future__ import annotations

from ..codes import rule_for
from ..diagnostics import Finding


def finding(kind: str, path: str, line: int, message: str, subject: str = "",
            fix: str | None = None, severity: str | None = None) -> Finding:
    """A finding of a catalogue kind (the catalogue test reads the kinds passed here) at
    its rule's severity; ``severity`` lowers it to info where the rule's condition for its
    own severity does not hold (docs/rules.md, severity contract)."""
    if severity not in (None, "info"):
        raise ValueError(f"a finding is only ever lowered to info, not to {severity!r}")
    return Finding(kind, severity or rule_for(kind).severity, message, path, line, "",
                   subject=subject, fix=fix)


__all__ = ["finding"]
