"""The static facts of an extracted description (``report/static_facts.py``), from its IR.

Why here and not with the facts: the facts are results every room reads; deriving them
needs the IR, which only the codemod knows. Inlined operations (a base class's
``createDescription`` read into a subclass) get the line of the call that inlined them.
"""

from __future__ import annotations

from typing import Any

from ...report.static_facts import CondFact, ParamFact, StaticDescription
from .ir import (
    AddCondition,
    CondSpec,
    ElementValue,
    ExtractedSkill,
    Literal,
    OpaqueValue,
    ParamOp,
    TypeValue,
)


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
