"""Statements that stay exactly as written inside ``description`` (ezskiros-dsl.md, last row).

``self.setAvailableForPlanning(False)`` and plain attribute assignments such as
``self.note = "..."`` run unchanged while the description is traced; ``pass`` and a bare
trailing ``return`` carry no meaning and are dropped.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import libcst as cst
else:
    from ..core.lazy_cst import cst

from ..core.context import ExtractContext
from ..core.ir import CondSpec, KeptStatement, Operation, Unsupported

KEPT_SELF_CALLS = frozenset({"setAvailableForPlanning"})


def kept_statement(stmt: cst.BaseSmallStatement, ctx: ExtractContext) -> list[Operation] | None:
    """Keep whitelisted self-calls and attribute assignments; drop ``pass``/``return``."""
    if isinstance(stmt, cst.Pass) or (isinstance(stmt, cst.Return) and stmt.value is None):
        return []
    if isinstance(stmt, cst.Expr) and ctx.self_method(stmt.value) in KEPT_SELF_CALLS:
        return [keep(stmt, ctx)]
    if isinstance(stmt, (cst.Assign, cst.AnnAssign)):
        targets = ([t.target for t in stmt.targets] if isinstance(stmt, cst.Assign)
                   else [stmt.target])
        if all(isinstance(t, cst.Attribute) and isinstance(t.value, cst.Name)
               and t.value.value == ctx.self_name for t in targets):
            return [keep(stmt, ctx)]
    return None


def keep(stmt: cst.BaseSmallStatement, ctx: ExtractContext) -> KeptStatement:
    """A statement kept as written, unless it reads a local holding a condition.

    Such locals are inlined into the ``+=`` that adds them and their assignment goes away,
    so a kept ``self.cond = c`` would fail with a NameError in the migrated skill.
    """
    class _Reads(cst.CSTVisitor):
        found: str | None = None

        def visit_Name(self, node: cst.Name) -> None:
            if self.found is None and isinstance(ctx.locals.get(node.value), CondSpec):
                self.found = node.value

    reads = _Reads()
    stmt.visit(reads)
    if reads.found is not None:
        raise Unsupported(f"`{ctx.code(stmt).strip()}` at line {ctx.line(stmt)} uses the "
                          f"condition stored in `{reads.found}` for more than adding it; "
                          "EzSkiROS adds conditions with `+=` and keeps no such variable "
                          "(drop that use by hand, then migrate)", stmt)
    return KeptStatement(stmt, ctx.line(stmt))
