"""The statement that adds a condition to its list: ``self.pre_conditions += <expr>``.

Why a module of its own: the statement is written for every kind of condition, and a long
disjunction wraps over lines the way ``or_conditions`` lays it out, while ``or_conditions``
builds on the condition helpers of ``condition_lists``; here both are below, so neither
rule imports the other back.
"""

from __future__ import annotations

from ..core.emit import LINE_LIMIT, EmitContext
from ..core.ir import AddCondition
from .condition_lists import emit_condition, strip_outer_parentheses
from .or_conditions import wrapped_or


def condition_statement(add: AddCondition, ctx: EmitContext) -> str:
    """``self.pre_conditions += <expr>`` for one ``add*Condition``; long disjunctions wrap."""
    head = f"{ctx.self_name}.{add.which}_conditions += "
    line = head + strip_outer_parentheses(emit_condition(add.condition, ctx))
    if ctx.column + len(line) <= LINE_LIMIT or add.condition.kind != "or":
        return line
    return head + wrapped_or(add.condition, ctx, len(head))
