"""The catch-all: a statement no rule claimed, explained so the user can act on it.

Anything here could declare parameters or conditions at run time (a helper method, a loop),
so translating around it would risk changing the skill's meaning; the skill is skipped and
the reason names the line.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import libcst as cst
else:
    from ..core.lazy_cst import cst

from ..core.context import ExtractContext
from ..core.ir import Operation, Unsupported
from .condition_factories import FACTORIES


def unsupported(stmt: cst.BaseSmallStatement, ctx: ExtractContext) -> list[Operation] | None:
    """Always raises: explains why the statement blocks an exact translation."""
    line = ctx.line(stmt)
    code = ctx.code(stmt.with_changes(semicolon=cst.MaybeSentinel.DEFAULT)).strip()
    if isinstance(stmt, cst.Expr) and isinstance(stmt.value, cst.Call):
        method = ctx.self_method(stmt.value)
        call = f"{ctx.self_name}.{method}(...) at line {line}"
        if method in FACTORIES or method == "getOrCond":
            raise Unsupported(f"{call} builds a condition that is never added (SkiROS2 "
                              "discards it): remove it, or add it with addPreCondition, "
                              "addHoldCondition or addPostCondition, then migrate", stmt)
        if method is not None:
            raise Unsupported(f"{call} is not part of the SkiROS2 description API; it may "
                              "declare parameters or conditions at run time (inline it by "
                              "hand, then migrate)", stmt)
    raise Unsupported(f"`{code.splitlines()[0]}` at line {line} is not a declarative "
                      "description statement; parameters or conditions could depend on it at "
                      "run time", stmt)
