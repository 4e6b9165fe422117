"""Code the migration never reads, stood in for while libcst parses a module.

A skill file is mostly code the migration never reads: helper functions, callbacks,
implementation classes (``PrimitiveBase``, ``SkillBase``). libcst parses and prints every
byte at Python speed (about 13 ms for a 300-line file), while ``ast`` has already told
where each top-level statement starts and ends. So before libcst parses the module, each
top-level function, the body of each class that cannot be a description
(``classes.inert_classes``) and the methods of the others (below), is replaced by a
placeholder of the same lines: one string token holding the original's line endings and a
mark, ``def name(): '''<mark>...'''`` for a function, ``'''<mark>...'''`` at the body's
indentation for a class body (its header stays, bases and all). The placeholder binds the
same name with the same kind of statement, so every whole-module reading (bindings,
imports, classes and their bases, where new imports go) sees what it would see in the
original, and every line keeps its number. After the rewrite each placeholder, found
verbatim in the printed code, gets its original text back: those bytes are never parsed,
printed or touched.

The lines after the last statement (blank lines, comments, form feeds: the tail of the
file) are kept out of libcst's reading and put back after it: libcst does not always
print back what it files in a module's footer (a blank line before a form feed at the end
of a file, comments after a one-line placeholder).

``source`` must count its lines as Python does: a file whose coding cookie can make a
newline out of other bytes (utf-7, raw-unicode-escape) is stood in for in its decoded text
(``migrate._readings``), or the placeholders of ``ast``'s lines would swallow statements.

The methods of the other classes (those that may be descriptions) are stood in for the same
way, at their indentation, except ``createDescription`` and ``description``, the two the
migration reads and writes: a class is read by the names its body binds. libcst drops a
form feed in the indentation of a line it prints, so no line that holds one is printed by
libcst when it can be stood in for.

A statement stays whole when its first line does not plainly start it (a backslash, a
body on the header's line); a form feed in its indentation does not count (Python counts
the columns after it). Nothing is stood in for in a file with a lone carriage
return (Python and a line split could count its lines differently) or one that already
holds the mark. New imports only ever go after imports or the docstring, never between a
stood-in statement and the comments that follow it, so where libcst files those comments
does not change the output.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Collection, Iterator
from dataclasses import dataclass

MARK = b"__ezmigrate_stood_in_"
_LINE = re.compile(rb"[^\r\n]*(?:\r\n|\n|\r)?")
_LONE_CR = re.compile(rb"\r(?!\n)")
_BLANK = b" \t\f"


@dataclass(frozen=True)
class Holes:
    """A module's bytes with some statements stood in for, and how to undo it."""

    text: bytes
    """What libcst parses: the original with each stood-in part replaced by its placeholder,
    without its tail."""
    filled: tuple[tuple[bytes, bytes], ...]
    """``(placeholder, original text)`` per stood-in part, in file order."""
    tail: bytes = b""
    """The lines after the last statement, which ``fill`` puts back at the end."""

    def fill(self, code: bytes) -> bytes | None:
        """``code`` (printed from the module parsed from ``text``) with every part back;
        ``None`` if a placeholder is not where it must be (the caller then migrates the
        original without holes)."""
        parts: list[bytes] = []
        at = 0
        for placeholder, original in self.filled:
            found = code.find(placeholder, at)
            if found < 0:
                return None
            parts += (code[at:found], original)
            at = found + len(placeholder)
        parts += (code[at:], self.tail)
        if MARK in parts[-2] or any(MARK in part for part in parts[:-2:2]):
            return None  # a placeholder printed twice
        return b"".join(parts)


def stand_in(source: bytes, tree: ast.Module, inert: Collection[int] = ()) -> Holes | None:
    """``source`` with its top-level functions, the bodies of the classes whose ``id`` is
    in ``inert`` and the methods of the others stood in for, and its tail kept apart (see
    the module docstring); ``None`` when there is nothing to do, or the file is one this
    must leave whole."""
    if not tree.body or MARK in source or _LONE_CR.search(source):
        return None
    lines = _LINE.findall(source)
    cut = _tail_start(lines, tree.body[-1])
    filled: list[tuple[bytes, bytes]] = []
    for node, body in _parts(tree, inert):
        number = len(filled)
        last = (node.end_lineno or node.lineno) - 1
        first = first_line(body[0] if body else node) - 1
        lead, indent = _indentation(lines[first])
        if not _starts(lines[first][lead:], lead, body[0] if body else node):
            continue
        if body:  # a class body: its header stays
            if first <= node.lineno - 1 or not indent:
                continue
            opening = b"%s'''%s%d_" % (indent, MARK, number)
        else:
            assert isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef))
            if not node.name.isascii():
                continue
            opening = b"%sdef %s(): '''%s%d_" % (indent, node.name.encode(), MARK, number)
        if first and lines[first - 1].rstrip().endswith(b"\\"):
            continue
        ends = [line[len(line.rstrip(b"\r\n")):] for line in lines[first:last + 1]]
        original = b"".join(lines[first:last + 1])[:-len(ends[-1]) or None]
        placeholder = opening + b"".join(ends[:-1]) + b"'''"
        lines[first] = placeholder + ends[-1]
        lines[first + 1:last + 1] = [b""] * (last - first)
        filled.append((placeholder, original))
    tail = b"".join(lines[cut:])
    if not filled and not tail:
        return None
    return Holes(b"".join(lines[:cut]), tuple(filled), tail)


def _tail_start(lines: list[bytes], last: ast.stmt) -> int:
    """Index of the first line after the statement ``last`` (the lines a backslash at the
    end of its lines continues belong to it)."""
    at = last.end_lineno or last.lineno
    while at < len(lines) and lines[at - 1].rstrip(b"\r\n").endswith(b"\\"):
        at += 1
    return at


def _parts(tree: ast.Module, inert: Collection[int]) -> Iterator[tuple[ast.stmt,
                                                                     list[ast.stmt]]]:
    """What to stand in for, in file order: ``(function, [])`` for a top-level function or
    a method of a class that may be a description (its ``createDescription`` and
    ``description`` excepted: the migration reads and writes them), ``(class, body)`` for
    an inert class's body."""
    for node in tree.body:
        if isinstance(node, _FUNCTIONS):
            yield node, []
        elif isinstance(node, ast.ClassDef) and id(node) in inert and node.body:
            yield node, node.body
        elif isinstance(node, ast.ClassDef):
            yield from ((stmt, []) for stmt in node.body
                        if isinstance(stmt, _FUNCTIONS) and stmt.name not in _READ)


_FUNCTIONS = (ast.FunctionDef, ast.AsyncFunctionDef)
_READ = frozenset({"createDescription", "description"})


def _indentation(line: bytes) -> tuple[int, bytes]:
    """The length of ``line``'s leading whitespace, and the indentation Python counts in
    it: what follows its last form feed (a form feed sets the column back to 0)."""
    lead = len(line) - len(line.lstrip(_BLANK))
    return lead, line[:lead].rpartition(b"\f")[2]


def first_line(node: ast.stmt) -> int:
    """The first line of a statement (1-based), its decorators included."""
    decorators = getattr(node, "decorator_list", [])
    return min([node.lineno, *(d.lineno for d in decorators)])


def _starts(line: bytes, column: int, node: ast.stmt) -> bool:
    """Whether ``line`` (its ``column`` bytes of indentation removed) plainly begins the
    statement ``node``."""
    if getattr(node, "decorator_list", None):
        return line.startswith(b"@")
    if node.col_offset != column:
        return False
    return not isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) \
        or line.startswith((b"def ", b"async "))
