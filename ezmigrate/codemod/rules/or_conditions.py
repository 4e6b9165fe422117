"""``getOrCond`` + ``addCondition`` <-> ``c1 | c2``.

Legacy (legacy-skiros2-api.md §4, §8.7)         EzSkiROS (docs/dsl.md)
``o = self.getOrCond(True)``                     ``self.pre_conditions += A.contain(B) | C.at(D)``
``o.addCondition(self.getRelationCond(...))``
``o.addCondition(self.getRelationCond(...))``
``self.addPreCondition(o)``
``getOrCond(False)``                             ``~(c1 | c2)``
an or whose first child is itself an or         ``any_of(any_of(c1, c2), c3)`` (no flattening)
Or-conditions are always labelled "or", so no ``.named`` is ever written for them.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    import libcst as cst
else:
    from ..core.lazy_cst import cst

from ..core.context import ExtractContext, bind_arguments
from ..core.emit import EmitContext
from ..core.ir import CommentOnly, CondSpec, Literal, Unsupported
from ..core.registry import condition_emitter, condition_replayer
from ..core.replay import literal_value, replay_condition
from .condition_lists import (
    condition_of,
    emit_condition,
    statement_comments,
    strip_outer_parentheses,
)


def or_condition(node: cst.BaseExpression, ctx: ExtractContext) -> CondSpec | None:
    """``self.getOrCond(desired)`` or ``ConditionOr(desired)``: an empty disjunction."""
    if not isinstance(node, cst.Call):
        return None
    if ctx.self_method(node) != "getOrCond" and ctx.names.symbol(node.func) != "ConditionOr":
        return None
    args = bind_arguments(node, ("desired_state",), 0, "getOrCond", ctx)
    desired = Literal(True, "True")
    if "desired_state" in args:
        found = ctx.literal(args["desired_state"])
        if found is None:
            raise Unsupported(f"getOrCond at line {ctx.line(node)} has a computed desired state")
        desired = found
    return CondSpec(kind="or", label=Literal("or", '"or"'), line=ctx.line(node), desired=desired)


def add_child(stmt: cst.BaseSmallStatement, ctx: ExtractContext) -> list[CommentOnly] | None:
    """``o.addCondition(cond)`` on a local or-condition."""
    if not (isinstance(stmt, cst.Expr) and isinstance(stmt.value, cst.Call)
            and isinstance(stmt.value.func, cst.Attribute)
            and stmt.value.func.attr.value == "addCondition"):
        return None
    call = stmt.value
    target = call.func.value  # type: ignore[attr-defined]
    holder = ctx.locals.get(target.value) if isinstance(target, cst.Name) else None
    if not isinstance(holder, CondSpec) or holder.kind != "or":
        raise Unsupported(f"addCondition at line {ctx.line(stmt)} is not called on a local "
                          "or-condition", stmt)
    args = bind_arguments(call, ("condition",), 1, "addCondition", ctx)
    holder.children.append(condition_of(args["condition"], ctx))
    return [CommentOnly(statement_comments(stmt, ctx))]


def _parts(spec: CondSpec, ctx: EmitContext) -> tuple[str, list[str], str]:
    """Opening text, children, and separator of an or-condition's expression."""
    if len(spec.children) < 1:
        raise Unsupported(f"the or-condition made at line {spec.line} has no children; "
                          "EzSkiROS has no form for an empty disjunction")
    desired = spec.desired.value if spec.desired is not None else True
    if desired not in (True, False) or type(desired) is not bool:
        raise Unsupported(f"the or-condition at line {spec.line} has desired state {desired!r}")
    negation = "" if desired else "~"
    children = [emit_condition(child, ctx) for child in spec.children]
    if spec.children[0].kind == "or" or len(children) == 1:
        bare = [strip_outer_parentheses(child) for child in children]
        return f"{negation}{ctx.use('any_of')}(", bare, ","
    return f"{negation}(", children, " |"


@condition_emitter("or")
def emit_or(spec: CondSpec, ctx: EmitContext) -> str:
    opening, children, separator = _parts(spec, ctx)
    joiner = ", " if separator == "," else " | "
    return opening + joiner.join(children) + ")"


def wrapped_or(spec: CondSpec, ctx: EmitContext, offset: int) -> str:
    """The or-condition over several lines, children aligned after the opening bracket.

    ``offset`` is the column of the expression relative to the statement's indentation
    (continuation lines are written relative to it, and libcst re-indents them).
    """
    opening, children, separator = _parts(spec, ctx)
    pad = " " * (offset + len(opening))
    if separator == ",":
        return opening + (",\n" + pad).join(children) + ")"
    return opening + ("\n" + pad + "| ").join(children) + ")"


@condition_replayer("or")
def replay_or(desc: Any, spec: CondSpec) -> object:
    condition = desc.getOrCond(literal_value(spec.desired))
    for child in spec.children:
        condition.addCondition(replay_condition(desc, child))
    return condition
