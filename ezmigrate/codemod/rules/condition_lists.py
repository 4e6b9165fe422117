"""``self.addPreCondition(c)`` and friends <-> ``self.pre_conditions += c``.

Legacy                                        EzSkiROS
``self.addPreCondition(self.getRelationCond(...))``  ``self.pre_conditions += A.contain(B)``
``self.addHoldCondition(c)``                  ``self.hold_conditions += ...``
``self.addPostCondition(c)``                  ``self.post_conditions += ...``
``c = self.getRelationCond(...)`` then ``self.addPreCondition(c)``: the local is inlined.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import libcst as cst
else:
    from ..core.lazy_cst import cst

from ..core.context import ExtractContext, bind_arguments
from ..core.emit import EmitContext
from ..core.ir import AddCondition, Comments, CondSpec, Unsupported
from ..core.registry import CONDITION_EMITTERS

LISTS = {"addPreCondition": "pre", "addHoldCondition": "hold", "addPostCondition": "post"}


def add_condition(stmt: cst.BaseSmallStatement, ctx: ExtractContext) -> list[AddCondition] | None:
    """One ``add*Condition`` statement."""
    if not isinstance(stmt, cst.Expr):
        return None
    method = ctx.self_method(stmt.value)
    if method not in LISTS:
        return None
    call = stmt.value
    assert isinstance(call, cst.Call)
    args = bind_arguments(call, ("condition",), 1, method, ctx)
    cond = condition_of(args["condition"], ctx)
    return [AddCondition(LISTS[method], cond, ctx.line(call), statement_comments(stmt, ctx))]


def condition_of(node: cst.BaseExpression, ctx: ExtractContext) -> CondSpec:
    """The condition an expression builds, or the one a local variable holds."""
    if isinstance(node, cst.Name):
        held = ctx.locals.get(node.value)
        if isinstance(held, CondSpec):
            return held
    for rule in ctx.rules.conditions:
        spec = rule(node, ctx)
        if spec is not None:
            return spec
    raise Unsupported(f"`{ctx.code(node).strip()}` at line {ctx.line(node)} does not build a "
                      "condition with a SkiROS2 factory or condition class", node)


def statement_comments(stmt: cst.BaseSmallStatement, ctx: ExtractContext) -> Comments:
    """Comments inside a statement (a multi-line call); the line's own are added by the reader."""
    found: list[str] = []
    if ctx.lines.one_line():  # a comment would end the line: the reader has it
        return Comments(inner=found)

    class _Collect(cst.CSTVisitor):  # a visitor: it goes in source order
        def visit_Comment(self, node: cst.Comment) -> None:
            found.append(node.value)

    stmt.visit(_Collect())
    return Comments(inner=found)


def emit_condition(spec: CondSpec, ctx: EmitContext) -> str:
    """The EzSkiROS expression for a condition (dispatch on its kind)."""
    emitter = CONDITION_EMITTERS.get(spec.kind)
    if emitter is None:
        raise Unsupported(f"no EzSkiROS form for a {spec.kind} condition (line {spec.line})")
    return emitter(spec, ctx)


def strip_outer_parentheses(text: str) -> str:
    """``(a == b)`` -> ``a == b`` when one pair encloses everything (for ``+=``)."""
    if not text.startswith("("):
        return text
    node = cst.parse_expression(text)
    if not node.lpar:
        return text
    return cst.Module([]).code_for_node(node.with_changes(lpar=[], rpar=[]))
