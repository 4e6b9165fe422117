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

from ezskiros_runtime.compare import compare
from ezskiros_runtime.legacy import abstract_skill
from ezskiros_runtime.legacy.extract import model_of
from ezskiros_runtime.legacy.params import ParamTypes
from ezskiros_runtime.legacy.world_element import Element
from ezskiros_runtime.model import SkillModel

from .ir import (
    AddCondition,
    CondSpec,
    ElementValue,
    Literal,
    OpaqueValue,
    Operation,
    ParamOp,
    Unsupported,
)
from .registry import CONDITION_REPLAYERS


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


def replay_condition(desc: abstract_skill.SkillDescription, spec: CondSpec) -> object:
    """The legacy condition object for ``spec``, built by the replayer its rule registered."""
    replayer = CONDITION_REPLAYERS.get(spec.kind)
    if replayer is None:
        raise Unsupported(f"no legacy form for a {spec.kind} condition (line {spec.line})")
    return replayer(desc, spec)


def literal_value(literal: Literal | None) -> Any:
    """The value of an optional literal argument (``None`` when it was not given)."""
    return None if literal is None else literal.value


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
                getattr(self, _ADD[op.which])(replay_condition(self, op.condition))

    cls = type(name, (abstract_skill.SkillDescription,), {"createDescription": create_description})
    return model_of(cls())


def checked_model(name: str, operations: list[Operation], params: list[ParamOp]) -> SkillModel:
    """The static legacy model; refused when the EzSkiROS form would lower to another one.

    The EzSkiROS form declares ``params`` first, then the conditions in order.
    """
    legacy = replay(name, operations)
    conditions = [op for op in operations if isinstance(op, AddCondition)]
    ordered: list[Operation] = [*params, *conditions]
    if len(ordered) == len(operations) \
            and all(a is b for a, b in zip(ordered, operations, strict=True)):
        return legacy  # the very calls in the same order: the same model (most skills)
    lowered = replay(name, ordered)
    differences = compare(legacy, lowered)
    if differences:
        raise Unsupported(
            "ParamOptions expand at the point of addParam, after conditions added earlier; "
            "EzSkiROS declares all parameters first, which would reorder conditions ("
            + str(differences[0]).splitlines()[0] + "). Move the addParam calls above the "
            "conditions by hand if the order does not matter to you, then migrate")
    return legacy
