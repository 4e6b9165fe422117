"""The rule table's shape, and the registries of what is dispatched by condition kind.

A rule module under ``ezmigrate/codemod/rules/`` owns one construct family end to end: how it is
read (a statement or condition rule), written (an emitter) and replayed through the legacy
backend (a replayer). The core walks statements and asks the rules of a ``RuleTable`` in
its order; the table itself is written out in ``ezmigrate/codemod/rules/__init__.py``, with the
catch-all last by construction, so the order never depends on which module imports which.
The core never imports a rule: the table reaches it through the extraction and emission
contexts, and the kind-keyed registries below are filled by the rules' decorators.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

from .context import CompoundRule, ConditionRule, ReadPass, StatementRule
from .emit import ConditionEmitter, EmitContext
from .ir import AddCondition, CondSpec, ParamOp

ConditionReplayer = Callable[[Any, CondSpec], object]
"""Builds the legacy condition object for a ``CondSpec`` on a legacy description."""


@dataclass(frozen=True)
class RuleTable:
    """Every rule of the codemod, in the order it is asked."""

    statements: tuple[StatementRule, ...]
    fallback: StatementRule
    """Asked last, whatever ``statements`` holds: it explains why a statement blocks an
    exact translation (``rules/unsupported.py``)."""
    conditions: tuple[ConditionRule, ...]
    compound_rules: tuple[CompoundRule, ...]
    """Asked for a compound statement (a loop); one none claims is refused."""
    read_passes: tuple[ReadPass, ...]
    param_annotation: Callable[[ParamOp, str, EmitContext], tuple[str, str | None]]
    """A parameter's annotation and default in the ``description`` signature."""
    condition_statement: Callable[[AddCondition, EmitContext], str]
    """The statement that adds a condition to its list in ``description``."""
    condition_emitters: Mapping[str, ConditionEmitter]
    condition_replayers: Mapping[str, ConditionReplayer]

    @property
    def statement_rules(self) -> tuple[StatementRule, ...]:
        return (*self.statements, self.fallback)


CONDITION_EMITTERS: dict[str, ConditionEmitter] = {}
CONDITION_REPLAYERS: dict[str, ConditionReplayer] = {}


def _register(registry: dict[str, Any], what: str, kinds: tuple[str, ...]) -> Callable[[Any],
                                                                                         Any]:
    def register(fn: Any) -> Any:
        for kind in kinds:
            if kind in registry:
                raise RuntimeError(f"two {what}s for condition kind {kind!r}")
            registry[kind] = fn
        return fn

    return register


def condition_emitter(*kinds: str) -> Callable[[ConditionEmitter], ConditionEmitter]:
    """Register the EzSkiROS writer for condition ``kinds``."""
    return _register(CONDITION_EMITTERS, "emitter", kinds)


def condition_replayer(*kinds: str) -> Callable[[ConditionReplayer], ConditionReplayer]:
    """Register how condition ``kinds`` are rebuilt on the legacy backend (for the model)."""
    return _register(CONDITION_REPLAYERS, "replayer", kinds)
