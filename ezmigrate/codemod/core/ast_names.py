"""Dotted names read from ``ast`` nodes, without libcst.

The fast readers (``check``'s plain reader, the compound pass, the cross-file pass) never
build a libcst tree; this lives apart from ``legacy_names`` so that importing them does not
import libcst.
"""

from __future__ import annotations

import ast


def ast_dotted_name(node: object) -> str | None:
    """``legacy_names.dotted_name`` for ``ast`` nodes: ``a.b.c``, or None for anything but
    names and attributes."""
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        head = ast_dotted_name(node.value)
        return None if head is None else f"{head}.{node.attr}"
    return None
