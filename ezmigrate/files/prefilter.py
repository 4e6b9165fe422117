"""A cheap text test that lets files with no legacy description skip parsing entirely.

On a lab monorepo most files are ordinary modules; parsing them with libcst would dominate
the run. A legacy description needs ``SkillDescription`` in its code (as a base, or in the
import that binds the base's name: aliases and module imports keep the word) or
``createDescription`` (a subclass of a description from a sibling module). Files with
neither word are never parsed.

Files that mention a marker only in comments, docstrings or strings ("unlike a
SkillDescription subclass...") are ruled out too, in three steps from cheap to exact:

1. every occurrence sits on a line whose first non-blank character is ``#``: such a line is
   a comment or lies inside a string, never code -> no description;
2. some occurrence sits on a line that starts with ``class``, ``def``, ``from`` or
   ``import`` -> maybe a description (parse it; a docstring line is a harmless false alarm);
3. otherwise ``ast`` (C speed, no code runs) says whether a marker is an identifier
   anywhere: a name, an attribute, an imported name or alias, a function or class name.

Any doubt (the file does not parse for ``ast``, cannot be decoded, nests too deep) means
"maybe": the core then parses the file and reports what it finds, exactly as before.
"""

from __future__ import annotations

import re

MARKERS = (b"SkillDescription", b"createDescription")
_TEXT_MARKERS = tuple(m.decode() for m in MARKERS)
_ANY_MARKER = re.compile(b"|".join(re.escape(m) for m in MARKERS))
_STATEMENT = re.compile(rb"(?:class|def|from|import)\b")


def may_hold_descriptions(data: bytes) -> bool:
    """False only when the file certainly has nothing to migrate."""
    verdict = by_text(data)
    return marker_is_identifier(data) if verdict is None else verdict


def by_text(data: bytes) -> bool | None:
    """Steps 1 and 2 of the module doc: True or False when the text decides, None when
    only step 3 (``marker_is_identifier``, a parse) can; a migration's workers take that
    step for the file, so that the process reading the tree does not parse it."""
    if not any(marker in data for marker in MARKERS):
        return False
    in_code = False
    for match in _ANY_MARKER.finditer(data):
        line = _line_head(data, match.start())
        if line.startswith(b"#"):
            continue  # a comment, or text inside a multi-line string
        if _STATEMENT.match(line):
            return True
        in_code = True
    return None if in_code else False


def _line_head(data: bytes, position: int) -> bytes:
    """The line holding ``position``, from its first non-blank character to ``position``."""
    start = max(data.rfind(b"\n", 0, position), data.rfind(b"\r", 0, position)) + 1
    return data[start:position].lstrip(b" \t\f")


def marker_is_identifier(data: bytes) -> bool:
    """Whether a marker is part of an identifier in the module's syntax tree."""
    import ast  # here: most runs never get this far

    try:
        tree = ast.parse(data)
    except (SyntaxError, ValueError, UnicodeError, LookupError, MemoryError, RecursionError):
        return True  # the core decides, and reports why the file cannot be read
    for node in ast.walk(tree):
        if isinstance(node, ast.Name):
            names: tuple[str | None, ...] = (node.id,)
        elif isinstance(node, ast.Attribute):
            names = (node.attr,)
        elif isinstance(node, ast.alias):
            names = (node.name, node.asname)
        elif isinstance(node, ast.ImportFrom):
            names = (node.module,)
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            names = (node.name,)
        elif isinstance(node, (ast.arg, ast.keyword)):
            names = (node.arg,)
        elif isinstance(node, (ast.Global, ast.Nonlocal)):
            names = tuple(node.names)
        else:
            continue
        if any(name and marker in name for name in names for marker in _TEXT_MARKERS):
            return True
    return False
