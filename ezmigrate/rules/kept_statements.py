"""Statements that stay exactly as written inside ``description`` (ezskiros-dsl.md, last row).

``self.setAvailableForPlanning(False)`` and plain attribute assignments such as
``self.note = "..."`` run unchanged while the description is traced; ``pass`` and a bare
trailing ``return`` carry no meaning and are dropped.
"""

from __future__ import annotations

import libcst as cst

from ..core.context import ExtractContext
from ..core.ir import KeptStatement, Operation
from ..core.registry import statement_rule

KEPT_SELF_CALLS = frozenset({"setAvailableForPlanning"})


@statement_rule
def kept_statement(stmt: cst.BaseSmallStatement, ctx: ExtractContext) -> list[Operation] | None:
    """Keep whitelisted self-calls and attribute assignments; drop ``pass``/``return``."""
    if isinstance(stmt, cst.Pass) or (isinstance(stmt, cst.Return) and stmt.value is None):
        return []
    if isinstance(stmt, cst.Expr) and ctx.self_method(stmt.value) in KEPT_SELF_CALLS:
        return [KeptStatement(stmt, ctx.line(stmt))]
    if isinstance(stmt, (cst.Assign, cst.AnnAssign)):
        targets = ([t.target for t in stmt.targets] if isinstance(stmt, cst.Assign)
                   else [stmt.target])
        if all(isinstance(t, cst.Attribute) and isinstance(t.value, cst.Name)
               and t.value.value == ctx.self_name for t in targets):
            return [KeptStatement(stmt, ctx.line(stmt))]
    return None
