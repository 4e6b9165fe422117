"""Top-level functions stood in for while libcst reads a module: it parses what it rewrites.

A skill file is mostly code the migration never reads: helper functions, callbacks,
``main``. libcst parses and prints every byte at Python speed (about 13 ms for a 300-line
file), while ``ast`` has already told where each top-level ``def`` starts and ends. So
before libcst parses the module, each such function is replaced by a placeholder of the
same lines: ``def name(): '''<mark>`` with the function's line endings inside one string
token, closed where its last line ends. The placeholder binds the same name with the same
kind of statement, so every whole-module reading (bindings, imports, classes, where new
imports go) sees what it would see in the original, and every line keeps its number. After
the rewrite each placeholder, found verbatim in the printed code, gets its original text
back: the bytes of those functions are never parsed, printed or touched.

A function stays in place when its first line is not plainly ``def``/``async``/``@`` at
column 0, or follows a backslash. Nothing is stood in for in a file with a lone carriage
return (Python and a line split could count its lines differently) or one that already
holds the mark. New imports only ever go after imports or the docstring, never between a
function and the comments that follow it, so where libcst files those comments does not
change the output.
"""

from __future__ import annotations

import ast
import re
from dataclasses import dataclass

MARK = b"__ezmigrate_stood_in_"
_LINE = re.compile(rb"[^\r\n]*(?:\r\n|\n|\r)?")
_LONE_CR = re.compile(rb"\r(?!\n)")


@dataclass(frozen=True)
class Holes:
    """A module's bytes with its top-level functions stood in for, and how to undo it."""

    text: bytes
    """What libcst parses: the original with each function replaced by its placeholder."""
    filled: tuple[tuple[bytes, bytes], ...]
    """``(placeholder, original text)`` per function, in file order."""

    def fill(self, code: bytes) -> bytes | None:
        """``code`` (printed from the module parsed from ``text``) with every function back;
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
        parts.append(code[at:])
        if MARK in parts[-1] or any(MARK in part for part in parts[:-1:2]):
            return None  # a placeholder printed twice
        return b"".join(parts)


def stand_in(source: bytes, tree: ast.Module) -> Holes | None:
    """``source`` with its top-level functions stood in for (see the module docstring);
    ``None`` when there is none, or the file is one this must leave whole."""
    functions = [node for node in tree.body
                 if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef))]
    if not functions or MARK in source or _LONE_CR.search(source):
        return None
    lines = _LINE.findall(source)
    filled = []
    for number, node in enumerate(functions):
        first = min([node.lineno, *(d.lineno for d in node.decorator_list)]) - 1
        last = (node.end_lineno or node.lineno) - 1
        if not node.name.isascii() or not lines[first].startswith((b"def ", b"async ", b"@")) \
                or (first and lines[first - 1].rstrip().endswith(b"\\")):
            continue
        ends = [line[len(line.rstrip(b"\r\n")):] for line in lines[first:last + 1]]
        original = b"".join(lines[first:last + 1])[:-len(ends[-1]) or None]
        placeholder = b"def %s(): '''%s%d_%s'''" % (
            node.name.encode(), MARK, number, b"".join(ends[:-1]))
        lines[first] = placeholder + ends[-1]
        lines[first + 1:last + 1] = [b""] * (last - first)
        filled.append((placeholder, original))
    if not filled:
        return None
    return Holes(b"".join(lines), tuple(filled))
