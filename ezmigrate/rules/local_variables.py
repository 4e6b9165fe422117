"""Local variables inside ``createDescription``: inlined where that is exact.

Legacy                                           EzSkiROS
``c = self.getRelationCond(...)``                 (inlined into the ``+=`` that uses it)
``o = self.getOrCond(True)``                      (inlined, with its ``addCondition`` children)
``key = "Object"`` then ``addParam(key, ...)``    ``Object: ...`` (the constant is inlined)
Other assignments to locals stay as written; a parameter or condition that depends on them
cannot be written statically and makes the skill skipped.
"""

from __future__ import annotations

import libcst as cst

from ..core.context import ExtractContext
from ..core.ir import CommentOnly, Operation
from ..core.registry import CONDITION_RULES, statement_rule
from .condition_lists import statement_comments
from .kept_statements import keep


@statement_rule
def local_assignment(stmt: cst.BaseSmallStatement, ctx: ExtractContext) -> list[Operation] | None:
    """``name = <condition | literal | anything>`` with one plain name as target."""
    if not (isinstance(stmt, cst.Assign) and len(stmt.targets) == 1
            and isinstance(stmt.targets[0].target, cst.Name)):
        return None
    name = stmt.targets[0].target.value
    for rule in CONDITION_RULES:
        spec = rule(stmt.value, ctx)
        if spec is not None:
            ctx.locals[name] = spec
            return [CommentOnly(statement_comments(stmt, ctx))]
    literal = ctx.literal(stmt.value)
    ctx.locals.pop(name, None)
    if literal is not None:
        ctx.locals[name] = literal
    else:
        ctx.opaque_locals.add(name)
    return [keep(stmt, ctx)]
