"""The fast readers' walks (``codemod/core/ast_walk``) against ``ast.walk``: the same
nodes in the same order, less the context nodes; a ``walk`` of some lines, less what spans
none of them."""

from __future__ import annotations

import ast
import collections
from pathlib import Path

from ezmigrate.codemod.core.ast_walk import nodes, walk

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures"


def _modules() -> list[ast.Module]:
    found = []
    for path in sorted(FIXTURES.rglob("*.py")):
        try:
            found.append(ast.parse(path.read_bytes()))
        except (SyntaxError, ValueError):
            continue
    assert len(found) > 20
    return found


def _plain(tree: ast.AST) -> list[ast.AST]:
    return [n for n in ast.walk(tree) if not isinstance(n, ast.expr_context)]


def test_walk_is_ast_walk_without_the_context_nodes() -> None:
    for tree in _modules():
        assert list(walk(tree)) == _plain(tree)


def test_nodes_are_the_same_nodes_in_any_order() -> None:
    for tree in _modules():
        assert {id(n) for n in nodes(tree)} == {id(n) for n in _plain(tree)}


def _spans(node: ast.AST, lines: list[int]) -> bool:
    first: int | None = getattr(node, "lineno", None)
    if first is None:
        return True
    last: int = getattr(node, "end_lineno", None) or first
    return any(first <= line <= last for line in lines)


def test_walk_of_lines_is_walk_pruned_at_what_spans_none_of_them() -> None:
    """``ast.walk``'s breadth-first order, where a node that spans none of the lines is
    dropped with everything below it (a node without a position spans them all)."""
    for tree in _modules():
        lines = sorted({n.lineno for n in ast.walk(tree)
                        if isinstance(n, ast.AugAssign | ast.Return)})

        expected: list[ast.AST] = []
        todo: collections.deque[ast.AST] = collections.deque([tree])
        while todo:
            node = todo.popleft()
            if not isinstance(node, ast.expr_context) and _spans(node, lines):
                expected.append(node)
                todo.extend(ast.iter_child_nodes(node))
        assert list(walk(tree, lines)) == expected
        assert len(expected) < len(_plain(tree)) or not lines
