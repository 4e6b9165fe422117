"""``SyntaxFacts`` read from the libcst tree, for a file this Python's parser refuses.

Labs run ezmigrate on the Python their CI has, not always the one their robot runs: a
skill file may use syntax newer than this interpreter (``f"{d["key"]}"`` is Python 3.12),
which libcst reads and ``ast`` does not. Such a file gets the same facts as every other
one, from full visits of its libcst tree and one position pass: correct, several times
slower, and rare.
"""

from __future__ import annotations

from collections.abc import Mapping

import libcst as cst
import libcst.helpers
from libcst.metadata import CodeRange

from .context import positions_of
from .imports import name_counts
from .legacy_names import LegacyNames, dotted_name
from .reader import find_create_description
from .syntax_facts import ClassFacts, FunctionFacts, Span, SyntaxFacts


def facts_of(module: cst.Module) -> SyntaxFacts:
    """``SyntaxFacts.of`` for a module only libcst can parse."""
    module, positions = positions_of(module)  # unsafe_skip_copy: the nodes stay the same
    names = name_counts(module)
    bindings: dict[str, int] = {}
    module.visit(_Bindings(bindings))
    classes = [_class(stmt, positions) for stmt in module.body if isinstance(stmt, cst.ClassDef)]
    return SyntaxFacts(classes, names, bindings, legacy_names_of(module),
                       python_parses=False)


def _class(node: cst.ClassDef, positions: Mapping[cst.CSTNode, object]) -> ClassFacts:
    def create() -> FunctionFacts | None:
        func = find_create_description(node)
        if func is None:
            return None
        bound: set[str] = set()
        func.body.visit(_Bound(bound))
        return FunctionFacts(_range(func, positions).start.column,
                             _spans(func.body, positions), name_counts(func), frozenset(bound))

    return ClassFacts(_range(node, positions).start.line, _spans(node.body, positions), create)


def _range(node: cst.CSTNode, positions: Mapping[cst.CSTNode, object]) -> CodeRange:
    found = positions[node]
    assert isinstance(found, CodeRange)
    return found


def _spans(block: cst.BaseSuite, positions: Mapping[cst.CSTNode, object]) -> list[Span]:
    """Statement spans as ``ast`` counts statements: each small statement on its own."""
    found: list[Span] = []
    for stmt in block.body if isinstance(block, cst.IndentedBlock) else [block]:
        parts = list(stmt.body) if isinstance(stmt, (cst.SimpleStatementLine,
                                                     cst.SimpleStatementSuite)) else [stmt]
        for part in parts:
            where = _range(part, positions)
            found.append((where.start.line, where.end.line))
    return found


class _Bindings(cst.CSTVisitor):
    """``SyntaxFacts.bindings``: 1 per assignment, 2 per augmented one or ``global``."""

    def __init__(self, bound: dict[str, int]) -> None:
        self.bound = bound

    def _add(self, names: list[str], weight: int) -> None:
        for name in names:
            self.bound[name] = self.bound.get(name, 0) + weight

    def visit_AssignTarget(self, node: cst.AssignTarget) -> None:
        self._add(_targets(node.target), 1)

    def visit_AugAssign(self, node: cst.AugAssign) -> None:
        self._add(_targets(node.target), 2)

    def visit_Global(self, node: cst.Global) -> None:
        self._add([item.name.value for item in node.names], 2)


class _Bound(cst.CSTVisitor):
    """``FunctionFacts.bound``: what a body binds (assignments, loops, ``as``, imports)."""

    def __init__(self, found: set[str]) -> None:
        self.found = found

    def visit_AssignTarget(self, node: cst.AssignTarget) -> None:
        self.found.update(_targets(node.target))

    def visit_AugAssign(self, node: cst.AugAssign) -> None:
        self.found.update(_targets(node.target))

    def visit_AnnAssign(self, node: cst.AnnAssign) -> None:
        self.found.update(_targets(node.target))

    def visit_NamedExpr(self, node: cst.NamedExpr) -> None:
        self.found.update(_targets(node.target))

    def visit_For(self, node: cst.For) -> None:
        self.found.update(_targets(node.target))

    def visit_AsName(self, node: cst.AsName) -> None:
        self.found.update(_targets(node.name))

    def visit_ImportAlias(self, node: cst.ImportAlias) -> None:
        if node.asname is None:
            self.found.add(libcst.helpers.get_full_name_for_node_or_raise(node.name)
                           .split(".")[0])


def _targets(node: cst.BaseExpression) -> list[str]:
    if isinstance(node, cst.Name):
        return [node.value]
    if isinstance(node, cst.StarredElement):
        return _targets(node.value)
    if isinstance(node, (cst.Tuple, cst.List)):
        return [n for e in node.elements for n in _targets(e.value)]
    return []


def legacy_names_of(module: cst.Module) -> LegacyNames:
    """The ``LegacyNames`` of a libcst module: its imports, anywhere in it (legacy files
    sometimes import inside ``try`` blocks)."""
    names = LegacyNames()
    module.visit(_ImportCollector(names))
    return names


class _ImportCollector(cst.CSTVisitor):
    def __init__(self, names: LegacyNames) -> None:
        self.names = names

    def visit_Import(self, node: cst.Import) -> None:
        for alias in node.names:
            asname = alias.asname
            local = None
            if asname is not None and isinstance(asname.name, cst.Name):
                local = asname.name.value
            self.names.add_import(_import_name(alias.name), local)

    def visit_ImportFrom(self, node: cst.ImportFrom) -> None:
        if node.module is None or node.relative:
            return
        module = _import_name(node.module)
        if isinstance(node.names, cst.ImportStar):
            self.names.add_from_import(module, None)
            return
        pairs = []
        for alias in node.names:
            name = _import_name(alias.name)
            local = name
            if alias.asname is not None and isinstance(alias.asname.name, cst.Name):
                local = alias.asname.name.value
            pairs.append((name, local))
        self.names.add_from_import(module, pairs)


def _import_name(node: cst.BaseExpression) -> str:
    name = dotted_name(node)
    assert name is not None
    return name
