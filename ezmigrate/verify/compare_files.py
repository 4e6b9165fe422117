"""Compare what two versions of one file loaded into: a verdict per description class."""

from __future__ import annotations

import ast
from dataclasses import dataclass, field
from typing import Any, Literal

from ezskiros_runtime.compare import compare
from ezskiros_runtime.diagnostics import Finding
from ezskiros_runtime.model import SkillModel

from ..report.diffs import decode
from .protocol import LoadOutcome

Verdict = Literal["equivalent", "different", "missing-after", "added-after", "error",
                  "unverified"]
"""``unverified``: the class fails to load in both versions, so nothing was compared."""


@dataclass
class ClassVerdict:
    """How one class compares; ``diff`` holds ``Difference.to_json()`` dicts."""

    name: str
    verdict: Verdict
    message: str = ""
    diff: list[dict[str, Any]] = field(default_factory=list)
    line_before: int | None = None
    line_after: int | None = None

    @property
    def equivalent(self) -> bool:
        return self.verdict == "equivalent"


def _errors(outcome: LoadOutcome) -> dict[str, Finding]:
    """The class errors of a load by the class they are about."""
    return {e.skill: e for e in outcome.errors}


def compare_outcomes(before: LoadOutcome, after: LoadOutcome, *, ignore_order: bool = False,
                     ignore_labels: bool = False) -> list[ClassVerdict]:
    """One verdict per class seen on either side (both loads must have succeeded)."""
    old = {m["name"]: SkillModel.from_json(m) for m in before.models}
    new = {m["name"]: SkillModel.from_json(m) for m in after.models}
    old_errors, new_errors = _errors(before), _errors(after)
    names = list(dict.fromkeys([*old, *old_errors, *new, *new_errors]))
    verdicts = []
    for name in names:
        line_b = _line(name, old, old_errors)
        line_a = _line(name, new, new_errors)
        verdict = _one(name, old, new, old_errors, new_errors, ignore_order, ignore_labels)
        verdict.line_before, verdict.line_after = line_b, line_a
        verdicts.append(verdict)
    return verdicts


def _line(name: str, models: dict[str, SkillModel],
          errors: dict[str, Finding]) -> int | None:
    """Where ``name`` is on one side: its model's line, its error's, or nowhere."""
    if name in models:
        return models[name].line
    return errors[name].line if name in errors else None


def _one(name: str, old: dict[str, SkillModel], new: dict[str, SkillModel],
         old_errors: dict[str, Finding], new_errors: dict[str, Finding],
         ignore_order: bool, ignore_labels: bool) -> ClassVerdict:
    if name in new_errors and name not in old_errors:
        return ClassVerdict(name, "error", "the migrated class fails to load: "
                            + new_errors[name].message)
    if name in old_errors and name in new_errors:  # no model on either side: no proof
        return ClassVerdict(name, "unverified", "fails to load in both versions, so it "
                            "cannot be verified: " + new_errors[name].message)
    if name in old_errors:
        return ClassVerdict(name, "error", "the legacy class fails to load: "
                            + old_errors[name].message)
    if name not in new:
        return ClassVerdict(name, "missing-after", "the class is missing after migration")
    if name not in old:
        return ClassVerdict(name, "added-after", "the class only exists after migration")
    diffs = compare(old[name], new[name], ignore_order=ignore_order, ignore_labels=ignore_labels)
    if diffs:
        return ClassVerdict(name, "different", f"{len(diffs)} difference(s)",
                            [d.to_json() for d in diffs])
    return ClassVerdict(name, "equivalent")


def load_failure(side: str, outcome: LoadOutcome) -> str:
    """A one-line reason for a version that did not load."""
    line = f" (line {outcome.line})" if outcome.line else ""
    return f"the {side} version could not be loaded: {outcome.status}{line}: {outcome.message}"


def class_sources(data: bytes) -> dict[str, str]:
    """Top-level class name -> its exact source text (empty when the file does not parse)."""
    text = decode(data)
    try:
        tree = ast.parse(text)
    except (SyntaxError, ValueError):
        return {}
    lines = text.splitlines(keepends=True)  # once: get_source_segment splits per call
    return {node.name: "".join(lines[node.lineno - 1:node.end_lineno or node.lineno])
            for node in tree.body if isinstance(node, ast.ClassDef)}
