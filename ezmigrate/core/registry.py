"""Rule registries: each legacy construct registers its extraction and emission here.

A rule module under ``ezmigrate/rules/`` owns one construct family end to end; the core
only walks statements and asks the registered rules in order. Adding a construct is adding
a module, not editing a dispatcher.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, TypeVar

import libcst as cst

if TYPE_CHECKING:
    from .context import ExtractContext
    from .ir import CondSpec, Operation
    from .writer import EmitContext

StatementRule = Callable[[cst.BaseSmallStatement, "ExtractContext"],
                         "Sequence[Operation] | None"]
ConditionRule = Callable[[cst.BaseExpression, "ExtractContext"], "CondSpec | None"]
ConditionEmitter = Callable[["CondSpec", "EmitContext"], str]

STATEMENT_RULES: list[StatementRule] = []
CONDITION_RULES: list[ConditionRule] = []
CONDITION_EMITTERS: dict[str, ConditionEmitter] = {}

F = TypeVar("F")


def statement_rule(fn: StatementRule) -> StatementRule:
    """Register a rule that turns one small statement of ``createDescription`` into IR.

    A rule returns ``None`` when the statement is not its construct, a list of operations
    (possibly empty) when it handled it, or raises ``Unsupported`` with a reason.
    """
    STATEMENT_RULES.append(fn)
    return fn


def condition_rule(fn: ConditionRule) -> ConditionRule:
    """Register a rule that turns an expression building a condition into a ``CondSpec``."""
    CONDITION_RULES.append(fn)
    return fn


def condition_emitter(*kinds: str) -> Callable[[ConditionEmitter], ConditionEmitter]:
    """Register the EzSkiROS writer for condition ``kinds``."""

    def register(fn: ConditionEmitter) -> ConditionEmitter:
        for kind in kinds:
            if kind in CONDITION_EMITTERS:
                raise RuntimeError(f"two emitters for condition kind {kind!r}")
            CONDITION_EMITTERS[kind] = fn
        return fn

    return register


def load_rules() -> None:
    """Import every rule module once so that their decorators have run."""
    from .. import rules  # noqa: F401  (import for the registration side effect)
