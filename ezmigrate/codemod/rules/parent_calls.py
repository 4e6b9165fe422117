"""Calls to a base description's ``createDescription``: the base's declarations are inlined.

Legacy                                          EzSkiROS
``class Child(Base):``                          ``class Child(Base):``
``    def createDescription(self):``            ``    def description(self, <Base's params>,``
``        Base.createDescription(self)``        ``                    <Child's params>):``
``        self.addParam("Extra", ...)``         ``        <Base's conditions> <Child's>``
``super().createDescription()`` and ``super(Child, self).createDescription()`` likewise.
Only bases whose description was extracted (same module or package) can be inlined.
"""

from __future__ import annotations

import copy
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import libcst as cst
else:
    from ..core.lazy_cst import cst

from ..core.context import ExtractContext
from ..core.ir import CommentOnly, Comments, Operation, Unsupported


def _called_base(call: cst.Call, ctx: ExtractContext) -> str | None:
    func = call.func
    if not (isinstance(func, cst.Attribute) and func.attr.value == "createDescription"):
        return None
    owner = func.value
    if isinstance(owner, cst.Call) and isinstance(owner.func, cst.Name) \
            and owner.func.value == "super":
        if len(ctx.base_names) != 1:
            raise Unsupported(f"super().createDescription() at line {ctx.line(call)} with "
                              "several base classes", call)
        return ctx.base_names[0]
    if isinstance(owner, cst.Name) and len(call.args) == 1 \
            and isinstance(call.args[0].value, cst.Name) \
            and call.args[0].value.value == ctx.self_name:
        return owner.value
    return None


def parent_call(stmt: cst.BaseSmallStatement, ctx: ExtractContext) -> list[Operation] | None:
    """Inline the operations of the base description whose ``createDescription`` is called."""
    if not (isinstance(stmt, cst.Expr) and isinstance(stmt.value, cst.Call)):
        return None
    base = _called_base(stmt.value, ctx)
    if base is None:
        return None
    if base not in ctx.base_names or ctx.parent_operations is None:
        raise Unsupported(f"createDescription of {base} is called at line {ctx.line(stmt)}, "
                          "but it is not a base class of this description", stmt)
    inlined = copy.deepcopy(ctx.parent_operations(base))
    kept: list[Operation] = [op for op in inlined if not isinstance(op, CommentOnly)]
    for op in kept:  # the base keeps its comments; the child must not repeat them
        op.comments = Comments()
        ctx.skill.inlined_at[id(op)] = ctx.line(stmt)
    return kept
