"""The line guard: outside the migrated code, every line of a file reaches the output.

A migration changes three kinds of lines: the converted ``createDescription`` methods
(with the comments that trail them), the headers of their classes (the base), and import
statements. Every other line must be in the output, byte for byte and in the same order;
new lines may come between them. This is the promise the stand-in reading
(``holes.py``) and libcst's own printing are meant to keep; the guard checks it on every
migrated text before anything is written, shown as a diff or counted by ``--check``, so
a mistake of either costs a refused file (EZ906) instead of a lost comment.

Lines are compared on the decoded text, in the file's own encoding: that is how Python
and ``ast`` count them (a coding cookie such as utf-7 can make newlines out of bytes that
hold none). A line ends at ``\\n``, ``\\r\\n`` or ``\\r``, as Python's tokenizer splits
them; a form feed does not end a line.
"""

from __future__ import annotations

import ast
import difflib
import io
import re
import tokenize
from collections.abc import Collection, Iterable, Iterator
from dataclasses import replace

import libcst as cst
from libcst.metadata import CodeRange

from ...report.results import FileResult
from .context import positions_of
from .holes import first_line

_LINE = re.compile(r"[^\r\n]*(?:\r\n|\n|\r)?")
CREATE = "createDescription"
LOSSY = "lossy-rewrite"
"""The finding kind of a refused file (EZ906 in ``ezskiros_runtime.codes``)."""


def lost_line(source: bytes | str, result: FileResult, tree: ast.Module | None) -> int | None:
    """The first line outside the migration that ``result``'s new text would change
    (``None`` if none, or nothing changes). ``tree``: ``source`` as ``ast`` read it, or
    ``None`` when only libcst could."""
    if result.new_source is None:
        return None
    encoding = encoding_of(source)
    original, new = decoded(source, encoding), decoded(result.new_source, encoding)
    converted = {s.line for s in result.skills if s.status == "converted"}
    count = len(split_lines(original))
    protected = protected_lines(tree, converted, count) if tree is not None else \
        protected_lines_cst(cst.parse_module(source), converted, count)
    return first_changed(original, new, protected)


def refuse(result: FileResult, line: int) -> FileResult:
    """``result`` not to be written: its converted skills fail, the file reports EZ906."""
    message = (f"not migrated: line {line} would change although it is outside the migrated "
               "code (a bug of ezmigrate: please report it with this file); the file is left "
               "as it is")
    return replace(result, new_source=None, error=message, error_line=line,
                   error_kind=LOSSY, skills=[
                       replace(s, status="failed", reason=message)
                       if s.status == "converted" else s for s in result.skills])


def split_lines(text: str) -> list[str]:
    """``text``'s lines with their endings, as Python counts them (not ``str.splitlines``,
    which also ends a line at a form feed)."""
    found = _LINE.findall(text)
    return found[:-1] if found and not found[-1] else found


def decoded(source: bytes | str, encoding: str) -> str:
    """The text Python reads from ``source`` in ``encoding``; bytes that do not decode map
    one to one onto characters, so the guard still compares every byte."""
    if isinstance(source, str):
        return source
    try:
        return source.decode(encoding)
    except (LookupError, UnicodeDecodeError):
        return source.decode("latin-1")


def encoding_of(source: bytes | str) -> str:
    """The encoding Python reads ``source`` in: its BOM or coding cookie, else UTF-8."""
    if isinstance(source, str):
        return "utf-8"
    try:
        return tokenize.detect_encoding(io.BytesIO(source).readline)[0]
    except SyntaxError:  # an unknown cookie: libcst refused the file before this
        return "latin-1"


def first_changed(original: str, new: str, protected: Collection[int]) -> int | None:
    """The first line (1-based) of ``original`` outside ``protected`` that ``new`` loses,
    changes or moves; ``None`` when every such line is in ``new`` in order.

    The check is a subsequence test (greedy, so exact); the line named comes from an
    alignment of the two texts when it finds one, since greedy matching of a lost blank
    line against a later blank one would name a line after the loss.
    """
    old_lines, new_lines = split_lines(original), split_lines(new)
    at = 0
    for number, line in enumerate(old_lines, 1):
        if number in protected:
            continue
        try:
            at = new_lines.index(line, at) + 1
        except ValueError:
            return _aligned(old_lines, new_lines, protected) or number
    return None


def _aligned(old_lines: list[str], new_lines: list[str],
             protected: Collection[int]) -> int | None:
    """The first unprotected line a diff of the two texts deletes or replaces."""
    matcher = difflib.SequenceMatcher(None, old_lines, new_lines, autojunk=False)
    for tag, first, last, _, _ in matcher.get_opcodes():
        if tag in ("delete", "replace"):
            lost = [n for n in range(first + 1, last + 1) if n not in protected]
            if lost:
                return lost[0]
    return None


def protected_lines(tree: ast.Module, converted: Collection[int], count: int) -> set[int]:
    """The lines a migration may change in a file of ``count`` lines: every import
    statement, and of each top-level class whose ``class`` line is in ``converted``, its
    header and its ``createDescription`` up to the next statement (its trailing
    comments)."""
    found: set[int] = set()
    for node in _statements(tree.body):
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            found.update(range(node.lineno, (node.end_lineno or node.lineno) + 1))
    body = tree.body
    for at, node in enumerate(body):
        if isinstance(node, ast.ClassDef) and node.lineno in converted:
            after = first_line(body[at + 1]) if at + 1 < len(body) else count + 1
            found |= _class_lines(node.lineno, [first_line(s) for s in node.body], [
                first_line(s) for s in node.body if _creates(s)], after)
    return found


def protected_lines_cst(module: cst.Module, converted: Collection[int], count: int) -> set[int]:
    """``protected_lines`` from libcst's reading, for a file written for a newer Python
    than this one (``ast`` cannot read it; slow, and rare)."""
    wrapped, positions = positions_of(module)
    found: set[int] = set()

    def first(node: cst.CSTNode) -> int:
        """A statement's first line, its decorators included, not its leading comments."""
        decorators = getattr(node, "decorators", ())
        place = positions[decorators[0] if decorators else node]
        assert isinstance(place, CodeRange)
        return place.start.line

    class _Imports(cst.CSTVisitor):
        def visit_Import(self, node: cst.Import) -> None:
            self._add(node)

        def visit_ImportFrom(self, node: cst.ImportFrom) -> None:
            self._add(node)

        def _add(self, node: cst.CSTNode) -> None:
            place = positions[node]
            assert isinstance(place, CodeRange)
            found.update(range(place.start.line, place.end.line + 1))

    wrapped.visit(_Imports())
    body = wrapped.body
    for at, stmt in enumerate(body):
        if isinstance(stmt, cst.ClassDef) and isinstance(stmt.body, cst.IndentedBlock) \
                and {first(stmt), first(stmt.name)} & set(converted):
            after = first(body[at + 1]) if at + 1 < len(body) else count + 1
            statements = stmt.body.body
            found |= _class_lines(first(stmt.name), [first(s) for s in statements], [
                first(s) for s in statements
                if isinstance(s, cst.FunctionDef) and s.name.value == CREATE], after)
    return found


def _class_lines(line: int, starts: list[int], creates: Iterable[int], after: int) -> set[int]:
    """A converted class's header (its ``class`` line up to its first statement, ``starts``
    being the first lines of its statements) and each ``createDescription`` from its
    first line up to the next statement of the class, or ``after`` (the first line of
    the next top-level statement)."""
    found = set(range(line, max(line + 1, starts[0] if starts else line + 1)))
    for first in creates:
        end = next((s for s in starts if s > first), after)
        found.update(range(first, end))
    return found


def _statements(body: list[ast.stmt]) -> Iterator[ast.stmt]:
    """Every statement in ``body`` and in the blocks nested in it (no expression is
    walked: an import is a statement)."""
    todo = list(body)
    while todo:
        node = todo.pop()
        yield node
        for name in _BLOCKS:
            block = getattr(node, name, None)
            if block:
                todo += block
        for handler in getattr(node, "handlers", ()):  # try, try*
            todo += handler.body
        for case in getattr(node, "cases", ()):  # match
            todo += case.body


_BLOCKS = ("body", "orelse", "finalbody")


def _creates(node: ast.stmt) -> bool:
    return isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and node.name == CREATE
