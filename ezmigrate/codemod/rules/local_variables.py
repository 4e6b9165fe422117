"""Local variables inside ``createDescription``: inlined where that is exact.

Legacy                                           EzSkiROS
``c = self.getRelationCond(...)``                 (inlined into the ``+=`` that uses it)
``o = self.getOrCond(True)``                      (inlined, with its ``addCondition`` children)
``key = "Object"`` then ``addParam(key, ...)``    ``Object: ...`` (the constant is inlined,
                                                  its assignment dropped once nothing reads it)
Other assignments to locals stay as written; a parameter or condition that depends on them
cannot be written statically and makes the skill skipped.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import libcst as cst
else:
    from ..core.lazy_cst import cst

from ..core.context import ExtractContext
from ..core.ir import CommentOnly, KeptStatement, Operation
from .condition_lists import statement_comments
from .kept_statements import keep


def local_assignment(stmt: cst.BaseSmallStatement, ctx: ExtractContext) -> list[Operation] | None:
    """``name = <condition | literal | anything>`` with one plain name as target."""
    if not (isinstance(stmt, cst.Assign) and len(stmt.targets) == 1
            and isinstance(stmt.targets[0].target, cst.Name)):
        return None
    name = stmt.targets[0].target.value
    for rule in ctx.rules.conditions:
        spec = rule(stmt.value, ctx)
        if spec is not None:
            ctx.locals[name] = spec
            return [CommentOnly(statement_comments(stmt, ctx))]
    literal = ctx.literal(stmt.value)
    ctx.locals.pop(name, None)
    kept = keep(stmt, ctx)
    if literal is not None:
        ctx.locals[name] = literal
        kept.literal_local = name
    else:
        ctx.opaque_locals.add(name)
    return [kept]


def drop_dead_literal_locals(operations: list[Operation]) -> list[Operation]:
    """``operations`` without the literal assignments no kept statement reads any more.

    Keys, labels and values read from such a local were inlined while extracting, so the
    assignment would stay behind as dead code (ruff F841). Dropping one can make another
    dead (``b = a`` read nothing else), hence the loop. Their comments stay in place.
    """
    while True:
        read: set[str] = set()
        for op in operations:
            if isinstance(op, KeptStatement):
                node = op.node.value if isinstance(op.node, cst.Assign) else op.node
                read |= _names_read(node)
        dead = [i for i, op in enumerate(operations) if isinstance(op, KeptStatement)
                and op.literal_local is not None and op.literal_local not in read]
        if not dead:
            return operations
        operations = [CommentOnly(op.comments) if i in dead else op
                      for i, op in enumerate(operations)]


def _names_read(node: cst.CSTNode) -> set[str]:
    names: set[str] = set()

    class _Names(cst.CSTVisitor):
        def visit_Name(self, name: cst.Name) -> None:
            names.add(name.value)

    node.visit(_Names())
    return names
