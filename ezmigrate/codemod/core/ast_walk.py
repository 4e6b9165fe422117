"""Walks of an ``ast`` tree for the fast readers, without ``ast.walk``'s generator per
node, and without looking into what is never a node of interest: the shared
``Load``/``Store`` context nodes (a third of a module's nodes) and the fields that hold a
name or a number. ``check`` walks most of a repository's code several times (the compound
pass, the implementation checks, the codemod's facts), so these are its inner loops.
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


def _fields(kind: type[ast.AST]) -> tuple[str, ...]:
    """The fields of ``kind`` that may hold nodes (a ``Constant``'s value never does)."""
    names = _NODE_FIELDS[kind] = () if kind is ast.Constant else tuple(
        f for f in kind._fields if f not in _NOT_NODES)
    return names


def nodes(tree: ast.AST) -> Iterator[ast.AST]:
    """Every node under ``tree`` (``tree`` too) but the context nodes, in no particular
    order: for a reader that collects a set or asks whether any node is so."""
    todo = [tree]
    pop, push, extend = todo.pop, todo.append, todo.extend
    known = _NODE_FIELDS
    while todo:
        node = pop()
        yield node
        kind = type(node)
        names = known.get(kind)
        for name in names if names is not None else _fields(kind):
            value = getattr(node, name, None)
            if type(value) is list:
                extend([item for item in value if isinstance(item, ast.AST)])
            elif isinstance(value, ast.AST):
                push(value)


def walk(tree: ast.AST) -> Iterator[ast.AST]:
    """``ast.walk``'s nodes in ``ast.walk``'s order (breadth first, fields in order), but
    the context nodes: for a reader whose findings follow the code's order."""
    known = _NODE_FIELDS
    level = [tree]
    while level:
        below: list[ast.AST] = []
        push, extend = below.append, below.extend
        for node in level:
            yield node
            kind = type(node)
            names = known.get(kind)
            for name in names if names is not None else _fields(kind):
                value = getattr(node, name, None)
                if type(value) is list:
                    extend([item for item in value if isinstance(item, ast.AST)])
                elif isinstance(value, ast.AST):
                    push(value)
        level = below


def walk_lines(tree: ast.AST, lines: Sequence[int]) -> Iterator[ast.AST]:
    """``walk`` of what may stand on ``lines`` (sorted, 1-based): a node whose span holds
    none of them is neither given nor entered (nor anything in it). For a reader that
    looks for what a word on a line names (``self.post_conditions += ...``): most of a
    module holds no such line and is not walked."""
    known = _NODE_FIELDS
    level = [tree]
    while level:
        below: list[ast.AST] = []
        push = below.append
        for node in level:
            first = getattr(node, "lineno", None)
            if first is not None:
                at = bisect.bisect_left(lines, first)
                if at == len(lines) or lines[at] > (getattr(node, "end_lineno", None) or first):
                    continue
            yield node
            kind = type(node)
            names = known.get(kind)
            for name in names if names is not None else _fields(kind):
                value = getattr(node, name, None)
                if type(value) is list:
                    for item in value:
                        if isinstance(item, ast.AST):
                            push(item)
                elif isinstance(value, ast.AST):
                    push(value)
        level = below
