"""Walks of an ``ast`` tree for the fast readers, without ``ast.walk``'s generator per
node, and without looking into what is never a node of interest: the shared
``Load``/``Store`` context nodes (a third of a module's nodes) and the fields that hold a
name or a number. ``check`` walks most of a repository's code several times (the compound
pass, the implementation checks, the static readers), so these are its inner loops.
"""

from __future__ import annotations

import ast
import bisect
from collections.abc import Iterator, Sequence

_NOT_NODES = frozenset({"ctx", "id", "attr", "arg", "name", "asname", "module", "level",
                        "kind", "type_comment", "is_async", "conversion"})
"""Fields no walk looks into: the context node, and fields that hold a name, a number or a
string in every Python the tool runs on (3.8 to 3.13)."""

_NODE_FIELDS: dict[type[ast.AST], tuple[str, ...]] = {}


def _children(node: ast.AST) -> list[ast.AST]:
    """The nodes right below ``node``, in field order (a ``Constant``'s value never is)."""
    kind = type(node)
    names = _NODE_FIELDS.get(kind)
    if names is None:
        names = _NODE_FIELDS[kind] = () if kind is ast.Constant else tuple(
            f for f in kind._fields if f not in _NOT_NODES)
    found: list[ast.AST] = []
    for name in names:
        value = getattr(node, name, None)
        if type(value) is list:
            found.extend([item for item in value if isinstance(item, ast.AST)])
        elif isinstance(value, ast.AST):
            found.append(value)
    return found


def nodes(tree: ast.AST) -> Iterator[ast.AST]:
    """Every node under ``tree`` (``tree`` too) but the context nodes, depth first: for a
    reader that collects a set or asks whether any node is so."""
    todo = [tree]
    while todo:
        node = todo.pop()
        yield node
        todo.extend(_children(node))


def walk(tree: ast.AST, lines: Sequence[int] | None = None) -> Iterator[ast.AST]:
    """``ast.walk``'s nodes in ``ast.walk``'s order (breadth first, fields in order), but
    the context nodes: for a reader whose findings follow the code's order.

    ``lines`` (sorted, 1-based): only what may stand on them. A node whose span holds none
    of them is neither given nor entered; for a reader looking for what a word on a line
    names (``self.post_conditions += ...``), most of a module is then never walked."""
    level = [tree]
    while level:
        below: list[ast.AST] = []
        for node in level:
            if lines is not None and not _spans(node, lines):
                continue
            yield node
            below.extend(_children(node))
        level = below


def _spans(node: ast.AST, lines: Sequence[int]) -> bool:
    """Whether ``node`` holds one of ``lines`` (a node without a position holds them all)."""
    first = getattr(node, "lineno", None)
    if first is None:
        return True
    at = bisect.bisect_left(lines, first)
    return at < len(lines) and lines[at] <= (getattr(node, "end_lineno", None) or first)
