"""Compound skills: the behaviour trees implementations build in ``expand``, checked early.

``check_compound(Implementation, index=...)`` is what a launch script calls: it traces the
class's ``expand`` with recording stand-ins (nothing reaches a skill manager or the world
model), checks the tree against the skill index, and returns the findings as data; with
``strict=True`` (or ``ezskiros_runtime.strict()``) an error-severity finding raises
``CompoundSkillError``, like the description checks.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING

from ..codes import rule_for
from ..diagnostics import Finding
from .checks import check_model, compound_finding
from .library import DescriptionInfo, SkillIndex
from .model import CompoundModel, ProcessorNode, SkillNode
from .trace import Unanalysable, trace

if TYPE_CHECKING:
    from ..ontology.index import OntologyIndex


class CompoundSkillError(TypeError):
    """A compound skill's tree has a mistake SkiROS2 would only log when it runs."""

    def __init__(self, findings: list[Finding]) -> None:
        self.findings = findings
        super().__init__("; ".join(f"{rule_for(f.kind).code} {f.skill}: {f.message}"
                                   for f in findings))


def index_of(descriptions: Iterable[type], *, standard_library: bool = True) -> SkillIndex:
    """A skill index of description classes (legacy or EzSkiROS), plus the standard
    library's unless ``standard_library=False``. A class another one of them derives from
    is a base: the skill manager loads leaves only."""
    from ..legacy.extract import model_of

    index = SkillIndex.with_standard_library() if standard_library else SkillIndex()
    classes = list(descriptions)
    for cls in classes:
        params = model_of(cls()).params
        index.add_description(DescriptionInfo(cls.__name__,
                                              {p.key: p.element_type for p in params}))
    index.bases |= {base.__name__ for base in classes for cls in classes
                    if cls is not base and issubclass(cls, base)}
    return index


def check_compound(implementation: type, index: SkillIndex | None = None, *,
                   ontology: OntologyIndex | None = None,
                   strict: bool | None = None) -> list[Finding]:
    """The findings of one compound skill implementation's tree (see the module doc)."""
    from ..dsl.policy import is_strict

    found = trace(implementation)
    if isinstance(found, CompoundModel) and index is not None:
        index.add_compound(found)
    findings = check_model(found, index or SkillIndex.with_standard_library(), ontology)
    errors = [f for f in findings if rule_for(f.kind).severity == "error"]
    if errors and (is_strict() if strict is None else strict):
        raise CompoundSkillError(errors)
    return findings


__all__ = [
    "CompoundModel",
    "CompoundSkillError",
    "DescriptionInfo",
    "Finding",
    "ProcessorNode",
    "SkillIndex",
    "SkillNode",
    "Unanalysable",
    "check_compound",
    "compound_finding",
    "index_of",
    "trace",
]
