"""A read-only walk over a libcst tree, about four times faster than a visitor.

``CSTNode.visit`` rebuilds every node it leaves (visitors and transformers share the
machinery), which is most of its cost when nothing is changed. Reading the names a method
mentions, or the comments inside a statement, needs no rebuilding: this walks the nodes'
dataclass fields directly.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator
from functools import cache
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import libcst as cst
else:
    from .lazy_cst import cst


@cache
def _fields(kind: type) -> tuple[str, ...]:
    return tuple(field.name for field in dataclasses.fields(kind))


def walk(node: cst.CSTNode, prune: tuple[type, ...] = ()) -> Iterator[cst.CSTNode]:
    """Every node under ``node`` (itself included), in no particular order; the subtrees of
    ``prune`` types are yielded but not entered."""
    stack: list[cst.CSTNode] = [node]
    while stack:
        current = stack.pop()
        yield current
        if prune and isinstance(current, prune):
            continue
        for name in _fields(type(current)):
            value = getattr(current, name)
            if isinstance(value, cst.CSTNode):
                stack.append(value)
            elif type(value) in (list, tuple):
                stack.extend(value)
