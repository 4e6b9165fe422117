"""Walks of an ``ast`` tree for the fast readers, without ``ast.walk``'s generator per
node and without the shared ``Load``/``Store`` context nodes no reader asks for (a third
of a module's nodes). ``check`` walks most of a repository's code several times (the
compound pass, the implementation checks, the codemod's facts), so these are its inner
loops.
"""

from __future__ import annotations

import ast
from collections.abc import Iterator

_NODE_FIELDS: dict[type[ast.AST], tuple[str, ...]] = {}


def _fields(kind: type[ast.AST]) -> tuple[str, ...]:
    names = _NODE_FIELDS.get(kind)
    if names is None:
        names = _NODE_FIELDS[kind] = tuple(f for f in kind._fields if f != "ctx")
    return names


def nodes(tree: ast.AST) -> Iterator[ast.AST]:
    """Every node under ``tree`` (``tree`` too) but the context nodes, in no particular
    order: for a reader that collects a set or asks whether any node is so."""
    todo = [tree]
    pop, push, extend = todo.pop, todo.append, todo.extend
    while todo:
        node = pop()
        yield node
        for name in _fields(type(node)):
            value = getattr(node, name, None)
            if type(value) is list:
                extend([item for item in value if isinstance(item, ast.AST)])
            elif isinstance(value, ast.AST):
                push(value)


def walk(tree: ast.AST) -> Iterator[ast.AST]:
    """``ast.walk``'s nodes in ``ast.walk``'s order (breadth first, fields in order), but
    the context nodes: for a reader whose findings follow the code's order."""
    level = [tree]
    while level:
        below: list[ast.AST] = []
        push, extend = below.append, below.extend
        for node in level:
            yield node
            for name in _fields(type(node)):
                value = getattr(node, name, None)
                if type(value) is list:
                    extend([item for item in value if isinstance(item, ast.AST)])
                elif isinstance(value, ast.AST):
                    push(value)
        level = below
