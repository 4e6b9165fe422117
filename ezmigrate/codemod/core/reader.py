"""Read one description class's ``createDescription`` into IR, statement by statement.

Each small statement goes to the registered rules (``ezmigrate/codemod/rules``); compound statements
go to the compound rules (a loop over constants is unrolled, ``rules/constant_loops.py``)
and the others (conditionals, ``try``, a loop over a computed value) are refused with a
reason because what they declare depends on run time. Comments are collected with the
statement they stand above.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import libcst as cst
else:
    from .lazy_cst import cst

from .context import ExtractContext
from .ir import CommentOnly, Comments, ExtractedSkill, Operation, Unsupported

COMPOUND_REASONS: dict[str, str] = {
    "For": "a loop", "While": "a loop", "If": "a conditional", "Try": "a try block",
    "With": "a with block", "FunctionDef": "a nested function", "ClassDef": "a nested class",
}
"""What a compound statement in ``createDescription`` is, by its libcst node's name."""


def find_create_description(classdef: cst.ClassDef) -> cst.FunctionDef | None:
    """The class's own ``createDescription`` (the last one, as Python binds it)."""
    found = None
    if isinstance(classdef.body, cst.IndentedBlock):
        for stmt in classdef.body.body:
            if isinstance(stmt, cst.FunctionDef) and stmt.name.value == "createDescription":
                found = stmt
    return found


def class_bindings(classdef: cst.ClassDef) -> list[tuple[str, cst.CSTNode]]:
    """``(name, statement)`` for each name the class body binds at its top level."""
    found: list[tuple[str, cst.CSTNode]] = []
    body = classdef.body.body if isinstance(classdef.body, cst.IndentedBlock) else ()
    for stmt in body:
        if isinstance(stmt, (cst.FunctionDef, cst.ClassDef)):
            found.append((stmt.name.value, stmt))
        for small in stmt.body if isinstance(stmt, cst.SimpleStatementLine) else ():
            targets = ([t.target for t in small.targets] if isinstance(small, cst.Assign)
                       else [small.target] if isinstance(small, cst.AnnAssign) else [])
            found += [(t.value, small) for t in targets if isinstance(t, cst.Name)]
    return found


def self_parameter(func: cst.FunctionDef) -> str:
    """The name of ``createDescription``'s only parameter, or ``Unsupported``."""
    params = func.params
    if (len(params.params) != 1 or params.star_arg is not cst.MaybeSentinel.DEFAULT
            or params.kwonly_params or params.star_kwarg or params.posonly_params):
        raise Unsupported("createDescription takes parameters besides self", func)
    if func.decorators:
        raise Unsupported("createDescription is decorated", func)
    if func.asynchronous is not None:
        raise Unsupported("createDescription is async", func)
    return params.params[0].name.value


def read_operations(func: cst.FunctionDef, bound: frozenset[str], ctx: ExtractContext) -> None:
    """Fill ``ctx.skill`` with the operations of ``func``'s body (``bound``: the names the
    body binds, ``FunctionFacts.bound``)."""
    ctx.function_names = bound
    body = func.body
    if not isinstance(body, cst.IndentedBlock):  # def createDescription(self): pass
        statements: list[cst.BaseStatement] = []
        ctx.lines.enter(body)
        _read_line_statements([s for s in body.body if isinstance(s, cst.BaseSmallStatement)],
                              Comments(), ctx, body)
    else:
        statements = list(body.body)
        ctx.skill.footer = list(body.footer)
    for index, stmt in enumerate(statements):
        ctx.lines.enter(stmt)
        if index == 0 and _is_docstring(stmt):
            assert isinstance(stmt, cst.SimpleStatementLine)
            ctx.skill.docstring = stmt
            continue
        read_statement(stmt, ctx)
    for read_pass in ctx.rules.read_passes:
        ctx.skill.operations = read_pass(ctx.skill.operations)


def read_statement(stmt: cst.BaseStatement, ctx: ExtractContext) -> None:
    """Add the operations of one statement of the body (or of a block inside it, read by a
    compound rule) to ``ctx.skill``: a line goes to the statement rules, a compound
    statement to the compound rules (a loop over constants), else it is refused."""
    if not isinstance(stmt, cst.SimpleStatementLine):
        for rule in ctx.rules.compound_rules:
            ops = rule(stmt, ctx)
            if ops is not None:
                ctx.skill.operations.extend(ops)
                return
        raise Unsupported(compound_reason(stmt, ctx), stmt)
    comments = Comments(leading=list(stmt.leading_lines),
                        trailing=stmt.trailing_whitespace.comment)
    _read_line_statements(list(stmt.body), comments, ctx, stmt)


def compound_reason(stmt: cst.BaseStatement, ctx: ExtractContext, why: str = "") -> str:
    """Why a compound statement keeps the skill as it is (``why``: what a compound rule
    found that it cannot unroll)."""
    what = COMPOUND_REASONS.get(type(stmt).__name__, "a compound statement")
    because = f" ({why})" if why else ""
    return (f"{what} at line {ctx.line(stmt)}{because}: parameters or conditions made there "
            "depend on run time; unroll it by hand, then migrate")


def _read_line_statements(small: list[cst.BaseSmallStatement], comments: Comments,
                          ctx: ExtractContext, owner: cst.CSTNode) -> None:
    for position, node in enumerate(small):
        ops = _apply_rules(node, ctx)
        if position == 0:
            ops = _attach(ops, comments)
        ctx.skill.operations.extend(ops)


def _apply_rules(node: cst.BaseSmallStatement, ctx: ExtractContext) -> list[Operation]:
    for rule in ctx.rules.statement_rules:
        ops = rule(node, ctx)
        if ops is not None:
            return list(ops)
    raise Unsupported(f"no rule for the statement at line {ctx.line(node)}", node)


def _attach(ops: list[Operation], comments: Comments) -> list[Operation]:
    """Give the line's comments to the first operation (or keep them on their own)."""
    if not ops:
        return [CommentOnly(comments)] if comments.texts() or comments.leading else []
    first = ops[0]
    inner = first.comments.inner
    first.comments = Comments(leading=comments.leading, inner=inner,
                              trailing=comments.trailing)
    return ops


def _is_docstring(stmt: cst.BaseStatement) -> bool:
    return (isinstance(stmt, cst.SimpleStatementLine) and len(stmt.body) == 1
            and isinstance(stmt.body[0], cst.Expr)
            and isinstance(stmt.body[0].value, (cst.SimpleString, cst.ConcatenatedString)))


def new_skill(classdef: cst.ClassDef, line: int) -> ExtractedSkill:
    """An empty ``ExtractedSkill`` for ``classdef``."""
    return ExtractedSkill(name=classdef.name.value, line=line)
