"""Run extracted IR through the legacy backend to get the static model of a skill.

The legacy backend is the one place where SkiROS2's semantics are written down (option
expansion, duplicate keys, the automatic ``Robot``); replaying calls through it instead of
re-deriving the model here keeps that rule in one place. Nothing of the user's code runs:
only the literal arguments extraction found.
"""

from __future__ import annotations

import builtins
from collections.abc import Iterable
from typing import Any

from ezskiros_runtime.legacy import abstract_skill
from ezskiros_runtime.legacy.extract import model_of
from ezskiros_runtime.legacy.params import ParamTypes
from ezskiros_runtime.legacy.world_element import Element
from ezskiros_runtime.model import SkillModel

from .ir import AddCondition, CondSpec, ElementValue, Literal, OpaqueValue, Operation, ParamOp


class Unknown:
    """A value only known at run time (a module constant), kept by its source text."""

    def __init__(self, code: str) -> None:
        self.code = code

    def __repr__(self) -> str:
        return self.code


def _value(op: ParamOp) -> object:
    value = op.value
    if isinstance(value, ElementValue):
        return Element if value.is_class else Element(value.type_string or "Unknown")
    if isinstance(value, Literal):
        return value.value
    if isinstance(value, OpaqueValue):
        return value.known.value if value.known is not None else Unknown(value.code)
    return getattr(builtins, value.name)


def _condition(desc: abstract_skill.SkillDescription, spec: CondSpec) -> object:
    def lit(x: Literal | None) -> Any:
        return None if x is None else x.value

    label = lit(spec.label)
    if spec.kind == "or":
        cond = desc.getOrCond(lit(spec.desired))
        for child in spec.children:
            cond.addCondition(_condition(desc, child))
        return cond
    vocabulary, subject, obj = spec.vocabulary or "", spec.subject or "", spec.object or ""
    desired = lit(spec.desired)
    if spec.kind == "relation":
        return desc.getRelationCond(label, vocabulary, subject, obj, desired)
    if spec.kind == "abstract_relation":
        return desc.getAbstractRelationCond(label, vocabulary, subject, obj, desired)
    if spec.kind == "property":
        return desc.getPropCond(label, vocabulary, subject, spec.operator or "", lit(spec.value),
                                desired)
    if spec.kind == "has_property":
        return desc.getHasPropCond(label, vocabulary, subject, desired)
    if spec.kind == "is_specified":
        return desc.getIsSpecifiedCond(label, subject, desired)
    if spec.kind == "generate":
        return desc.getGenerateCond(label, subject, desired)
    return desc.getOnTypeCond(label, subject, vocabulary)


_ADD = {"pre": "addPreCondition", "hold": "addHoldCondition", "post": "addPostCondition"}


def replay(name: str, operations: Iterable[Operation]) -> SkillModel:
    """The model SkiROS2 would build from these calls, in this order."""
    ops = list(operations)

    def create_description(self: abstract_skill.SkillDescription) -> None:
        for op in ops:
            if isinstance(op, ParamOp):
                options = [abstract_skill.ParamOptions[o] for o in op.options]
                self.addParam(op.key, _value(op), ParamTypes[op.kind],
                              op.options_text if op.options_text is not None else options,
                              op.description or "")
            elif isinstance(op, AddCondition):
                getattr(self, _ADD[op.which])(_condition(self, op.condition))

    cls = type(name, (abstract_skill.SkillDescription,), {"createDescription": create_description})
    return model_of(cls())

