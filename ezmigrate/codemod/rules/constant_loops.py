"""A ``for`` loop over constants inside ``createDescription``: unrolled.

Legacy                                                   EzSkiROS
``for key, cls in (("L", "skiros:Location"),``           ``L: skiros.Location,``
``                 ("R", "skiros:Location")):``          ``R: skiros.Location``
``    self.addParam(key, Element(cls), Required)``       (one entry per turn, in loop order)

Nothing in such a loop depends on run time: the iterable is a literal tuple, list or
string (or a module constant or local bound to one), so each turn is read as if it were
written out, with the loop's names bound to that turn's literals, in the order SkiROS2
calls ``addParam``/``addPreCondition``. The names keep the last turn's values after the
loop, as in Python: a later read is inlined, and the assignment stays only if a kept
statement still reads it. ``break``, ``continue``, ``else:``, a starred target, anything
computed, and a statement that would have to be kept as written in the body keep today's
skip, with the reason.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import libcst as cst
else:
    from ..core.lazy_cst import cst

from ..core.context import ExtractContext
from ..core.ir import (
    CommentOnly,
    Comments,
    KeptStatement,
    Literal,
    Operation,
    Unsupported,
)
from ..core.reader import compound_reason, read_statement

Bindings = dict[str, Literal]
"""One turn of a loop: each name of its target and the literal it holds then."""


def constant_loop(stmt: cst.BaseStatement, ctx: ExtractContext) -> list[Operation] | None:
    """The operations of a ``for`` loop over constants, turn by turn; ``None`` for any
    other compound statement (the reader refuses those)."""
    if not isinstance(stmt, cst.For):
        return None
    turns = _turns(stmt, ctx)
    body = _body(stmt, ctx)
    operations: list[Operation] = []
    nested: set[str] = set()
    for number, bindings in enumerate(turns):
        ctx.locals.update(bindings)
        for name in bindings:
            ctx.opaque_locals.discard(name)
        produced = _read_turn(stmt, body, ctx, nested)
        operations += produced if number == 0 else _without_comments(produced)
    operations = _with_loop_comments(stmt, operations)
    names = [*(turns[-1] if turns else {}), *sorted(nested)]
    return operations + _last_values(names, ctx)


def _turns(stmt: cst.For, ctx: ExtractContext) -> list[Bindings]:
    """What the target is bound to on each turn, or ``Unsupported`` naming what is not
    known statically."""
    if stmt.asynchronous is not None:
        raise Unsupported(compound_reason(stmt, ctx, "`async for`"), stmt)
    if stmt.orelse is not None:
        raise Unsupported(compound_reason(stmt, ctx, "it has an `else:`"), stmt)
    turns: list[Bindings] = []
    for item in _items(stmt.iter, ctx, stmt):
        bindings: Bindings = {}
        _bind(stmt.target, item, ctx, stmt, bindings)
        turns.append(bindings)
    return turns


def _items(node: cst.BaseExpression, ctx: ExtractContext,
           stmt: cst.For) -> list[cst.BaseExpression]:
    """The values iterating ``node`` gives, each as an expression with its own source text
    (so ``1e-3`` stays ``1e-3``): a tuple or list written out, a string, or a name
    bound to one of those (a module constant bound once, a literal local)."""
    if isinstance(node, (cst.Tuple, cst.List)):
        items = []
        for element in node.elements:
            if not isinstance(element, cst.Element):
                raise Unsupported(compound_reason(stmt, ctx, "a starred item"), stmt)
            items.append(element.value)
        return items
    found = ctx.resolved(node)
    if found is None or isinstance(node, cst.Set):
        raise Unsupported(compound_reason(
            stmt, ctx, f"it iterates `{ctx.code(node).strip()}`, not a tuple, list or string "
            "of literals"), stmt)
    if isinstance(found.value, str):
        return [cst.SimpleString(repr(char)) for char in found.value]
    if isinstance(found.value, (tuple, list)):
        return _items(cst.parse_expression(found.code), ctx, stmt)
    raise Unsupported(compound_reason(
        stmt, ctx, f"it iterates `{ctx.code(node).strip()}`, not a tuple, list or string"),
        stmt)


def _bind(target: cst.BaseExpression, item: cst.BaseExpression, ctx: ExtractContext,
          stmt: cst.For, bindings: Bindings) -> None:
    """Bind ``target`` (a name, or a tuple or list of targets) to ``item`` as Python's
    unpacking would; what Python would refuse (a length mismatch) keeps the skill too."""
    if isinstance(target, cst.Name):
        found = ctx.resolved(item)
        if found is None:
            raise Unsupported(compound_reason(
                stmt, ctx, f"`{target.value}` takes `{ctx.code(item).strip()}`, not a "
                "literal"), stmt)
        bindings[target.value] = found
        return
    if not isinstance(target, (cst.Tuple, cst.List)) \
            or not all(isinstance(e, cst.Element) for e in target.elements):
        raise Unsupported(compound_reason(
            stmt, ctx, f"its target `{ctx.code(target).strip()}` is not names"), stmt)
    items = _items(item, ctx, stmt)
    if len(items) != len(target.elements):
        raise Unsupported(compound_reason(
            stmt, ctx, f"`{ctx.code(item).strip()}` does not unpack into "
            f"`{ctx.code(target).strip()}`"), stmt)
    for element, value in zip(target.elements, items, strict=True):
        _bind(element.value, value, ctx, stmt, bindings)


def _body(stmt: cst.For, ctx: ExtractContext) -> list[cst.BaseStatement]:
    """The loop's statements, refusing ``break`` and ``continue`` (a turn would then
    depend on what the one before it did)."""
    if isinstance(stmt.body, cst.SimpleStatementSuite):  # for k in "AB": self.addParam(...)
        return [cst.SimpleStatementLine(body=stmt.body.body)]
    assert isinstance(stmt.body, cst.IndentedBlock)
    body = list(stmt.body.body)

    class _Jumps(cst.CSTVisitor):
        found: str | None = None

        def visit_Break(self, node: cst.Break) -> None:
            self.found = self.found or "break"

        def visit_Continue(self, node: cst.Continue) -> None:
            self.found = self.found or "continue"

        def visit_FunctionDef(self, node: cst.FunctionDef) -> bool:
            return False  # refused on its own; its jumps are not the loop's

    jumps = _Jumps()
    stmt.body.visit(jumps)
    if jumps.found is not None:
        raise Unsupported(compound_reason(stmt, ctx, f"it has a `{jumps.found}`"), stmt)
    return body


def _read_turn(stmt: cst.For, body: list[cst.BaseStatement], ctx: ExtractContext,
               nested: set[str]) -> list[Operation]:
    """One turn's operations, read as if the body were written out with its literals.

    A statement the migration would keep as written (``self.x = key``) is refused: its
    text reads the loop's names, which the unrolled form no longer binds. A nested loop's
    last values are left out (``nested`` collects their names for after the loop)."""
    outer = ctx.skill.operations
    ctx.skill.operations = []
    try:
        for inner in body:
            read_statement(inner, ctx)
        produced = ctx.skill.operations
    finally:
        ctx.skill.operations = outer
    kept: list[Operation] = []
    for op in produced:
        if isinstance(op, KeptStatement) and op.line == 0 and op.literal_local is not None:
            nested.add(op.literal_local)
            continue
        if isinstance(op, KeptStatement):
            raise Unsupported(compound_reason(
                stmt, ctx, f"`{ctx.code(op.node).strip()}` at line {op.line} would be kept "
                "as written, once per turn"), stmt)
        if id(op) in ctx.skill.inlined_at:
            raise Unsupported(compound_reason(
                stmt, ctx, "it calls a base's createDescription once per turn"), stmt)
        kept.append(op)
    return kept


def _without_comments(operations: list[Operation]) -> list[Operation]:
    """A later turn's operations: the body's comments were given to the first turn."""
    for op in operations:
        op.comments = Comments()
    return [op for op in operations if not isinstance(op, CommentOnly)]


def _with_loop_comments(stmt: cst.For, operations: list[Operation]) -> list[Operation]:
    """The loop's own comments (above it, on its line, inside its header, after its last
    statement) kept with what replaces it: first with the first operation, last after it."""
    header: list[str] = []

    class _Comments(cst.CSTVisitor):
        def visit_Comment(self, node: cst.Comment) -> None:
            header.append(node.value)

    for part in (stmt.target, stmt.iter):
        part.visit(_Comments())
    body = stmt.body
    if isinstance(body, cst.IndentedBlock):
        trailing = body.header.comment
        footer = [line for line in body.footer if line.comment is not None]
    else:
        assert isinstance(body, cst.SimpleStatementSuite)
        trailing = body.trailing_whitespace.comment
        footer = []
    own = [*stmt.leading_lines, *(cst.EmptyLine(comment=cst.Comment(text)) for text in [
        *header, *([trailing.value] if trailing is not None else [])])]
    if not operations:
        operations = [CommentOnly(Comments(leading=own))]
    else:
        first = operations[0]
        first.comments = Comments(leading=[*own, *first.comments.leading],
                                  inner=first.comments.inner, trailing=first.comments.trailing)
    if footer:
        operations.append(CommentOnly(Comments(leading=footer)))
    return operations


def _last_values(names: list[str], ctx: ExtractContext) -> list[Operation]:
    """``name = <last value>`` for each name the loop (and a loop in it) bound, as Python
    leaves them after the loop; the read pass drops each one nothing kept reads."""
    kept: list[Operation] = []
    for name in dict.fromkeys(names):
        value = ctx.locals.get(name)
        if isinstance(value, Literal):
            node = cst.Assign(targets=[cst.AssignTarget(cst.Name(name))],
                              value=cst.parse_expression(value.code))
            kept.append(KeptStatement(node, 0, literal_local=name))
    return kept
