"""The catch-all: a statement no rule claimed, explained so the user can act on it.

Anything here could declare parameters or conditions at run time (a helper method, a loop),
so translating around it would risk changing the skill's meaning; the skill is skipped and
the reason names the line.
"""

from __future__ import annotations

import libcst as cst

from ..core.context import ExtractContext
from ..core.ir import Operation, Unsupported
from ..core.registry import statement_rule


@statement_rule
def unsupported(stmt: cst.BaseSmallStatement, ctx: ExtractContext) -> list[Operation] | None:
    """Always raises: explains why the statement blocks an exact translation."""
    line = ctx.line(stmt)
    code = ctx.code(stmt).strip().splitlines()[0]
    if isinstance(stmt, cst.Expr) and isinstance(stmt.value, cst.Call):
        method = ctx.self_method(stmt.value)
        if method is not None:
            raise Unsupported(f"self.{method}(...) at line {line} is not part of the SkiROS2 "
                              "description API; it may declare parameters or conditions at run "
                              "time (inline it by hand, then migrate)", stmt)
    raise Unsupported(f"`{code}` at line {line} is not a declarative description statement; "
                      "parameters or conditions could depend on it at run time", stmt)
