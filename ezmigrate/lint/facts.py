"""What a legacy description declares, as plain picklable data with source lines.

Extraction (``core/reader.py``) already turns ``createDescription`` into IR; the IR holds
libcst nodes (comments) that are heavy to send between processes. These facts keep only
what the early checks need — keys, values, types, conditions and the line of each — so a
worker can return them with the ``FileResult`` and the linter can check them without
importing the user's code.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from ..core.ir import (
    AddCondition,
    CondSpec,
    ElementValue,
    ExtractedSkill,
    Literal,
    OpaqueValue,
    ParamOp,
    TypeValue,
)


@dataclass(frozen=True)
class ParamFact:
    """One ``addParam``: ``mode`` is ``element``, ``type`` or ``literal`` (as ``ParamSpec``).

    ``own`` is False for a parameter inlined from a base class's ``createDescription``.
    """

    key: str
    kind: str
    mode: str
    line: int
    value: Any = None
    type_name: str | None = None
    element_type: str | None = None
    options: tuple[str, ...] = ()
    own: bool = True


@dataclass(frozen=True)
class CondFact:
    """One condition as its factory's arguments; children for or-conditions."""

    kind: str
    line: int
    subject: str | None = None
    vocabulary: str | None = None
    object: str | None = None
    operator: str | None = None
    value: Any = None
    desired: bool = True
    label: str | None = None
    children: tuple[CondFact, ...] = ()


@dataclass(frozen=True)
class StaticDescription:
    """The parameters and the ``(which, condition)`` additions of one description."""

    params: tuple[ParamFact, ...] = ()
    conditions: tuple[tuple[str, CondFact], ...] = field(default_factory=tuple)


def _literal(value: Literal | None) -> Any:
    return value.value if value is not None else None


def _param(op: ParamOp, line: int, own: bool) -> ParamFact:
    value = op.value
    common: dict[str, Any] = {"key": op.key, "kind": op.kind, "line": line,
                              "options": tuple(op.options), "own": own}
    if isinstance(value, ElementValue):
        return ParamFact(mode="element", element_type=value.type_string, **common)
    if isinstance(value, TypeValue):
        return ParamFact(mode="type", type_name=value.name, **common)
    if isinstance(value, OpaqueValue):
        return ParamFact(mode="literal", value=_literal(value.known), **common)
    return ParamFact(mode="literal", value=value.value, **common)


def _condition(spec: CondSpec, inlined: int | None) -> CondFact:
    desired = _literal(spec.desired)
    return CondFact(kind=spec.kind, line=inlined or spec.line, subject=spec.subject,
                    vocabulary=spec.vocabulary, object=spec.object, operator=spec.operator,
                    value=_literal(spec.value),
                    desired=True if desired is None else bool(desired),
                    label=_literal(spec.label) if spec.label is not None else None,
                    children=tuple(_condition(c, inlined) for c in spec.children))


def static_description(skill: ExtractedSkill) -> StaticDescription:
    """The facts of an extracted skill; inlined operations get the line of the call."""
    params: list[ParamFact] = []
    conditions: list[tuple[str, CondFact]] = []
    for op in skill.operations:
        inlined = skill.inlined_at.get(id(op))
        if isinstance(op, ParamOp):
            params.append(_param(op, inlined or op.line, inlined is None))
        elif isinstance(op, AddCondition):
            conditions.append((op.which, _condition(op.condition, inlined)))
    return StaticDescription(tuple(params), tuple(conditions))
