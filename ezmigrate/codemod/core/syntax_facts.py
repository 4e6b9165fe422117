"""What Python's own parser tells about a module, in one walk: the cheap facts.

libcst keeps every byte, which the rewrite needs, but each full visit of its tree costs
about as much as parsing the file; ``ast`` parses at C speed and walks ten times faster.
So the facts that need the whole module (the names it uses, how often each name is bound,
its legacy imports, the lines of its classes) come from one ``ast`` walk here, and libcst
is walked only where code is rewritten. ``check``'s fast reader uses the same facts.

``names`` counts the references to names, outside import statements: every name read or
bound as a variable (``ast.Name``), and the names of ``global`` and ``nonlocal``. These are
what an import's binding can be used by. An attribute (``wmi.Element``), a keyword of a call
(``f(Element=...)``), a parameter or a definition's own name merely spells the same word:
counting them kept legacy imports the migration had left unused (ruff's F401). ``True``,
``False`` and ``None`` are constants here, and no import binds them.

A file written for a newer Python than this one (``f"{d["key"]}"``, Python 3.12) parses
with libcst but not with ``ast``: ``core/cst_facts.py`` then gives the same facts, slowly.
"""

from __future__ import annotations

import ast
from collections import Counter
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from functools import cached_property

from .ast_walk import nodes
from .legacy_names import LegacyNames

Span = tuple[int, int]
"""First and last line of a statement (each small statement of a line on its own)."""


@dataclass(frozen=True)
class FunctionFacts:
    """What the migration needs of one ``createDescription`` besides its libcst tree."""

    column: int
    """Column of its ``def``: the new method's body is indented one level further."""
    spans: list[Span]
    """Its body's statements in order (``StatementLines`` gives its nodes lines)."""
    names: Counter[str]
    """Name references of the whole method: what replacing it removes from the module."""
    bound: frozenset[str]
    """Names its body binds: Python makes them local throughout, so none reads the module
    constant of the same name."""


class ClassFacts:
    """A top-level class: the line of its ``class`` keyword, its body's statement spans,
    and its own ``createDescription`` (the last one), read when the migration asks."""

    def __init__(self, line: int, spans: list[Span],
                 create: Callable[[], FunctionFacts | None]) -> None:
        self.line, self.spans, self._create = line, spans, create

    @cached_property
    def create(self) -> FunctionFacts | None:
        return self._create()


@dataclass
class SyntaxFacts:
    """The whole-module facts of one module."""

    classes: list[ClassFacts]
    """The top-level classes in order: the k-th is libcst's k-th top-level ``ClassDef``."""
    names: Counter[str] = field(default_factory=Counter)
    """Name -> how often the module refers to it outside imports (see the module's
    docstring: attributes, keywords and parameters are no references)."""
    bindings: dict[str, int] = field(default_factory=dict)
    """Name -> weight of its bindings anywhere: 1 per plain assignment, 2 per augmented
    assignment or ``global`` (a name bound more than once is no constant)."""
    legacy: LegacyNames = field(default_factory=LegacyNames)
    """The SkiROS2 names imported anywhere (legacy files import inside ``try`` too)."""
    python_parses: bool = True
    """Whether this Python's parser read the module (else libcst alone could)."""

    @classmethod
    def of(cls, tree: ast.Module) -> SyntaxFacts:
        facts = cls([_class(node) for node in tree.body if isinstance(node, ast.ClassDef)])
        _walk(tree, facts.names, facts.legacy, facts.bindings)
        return facts


_BODIES = frozenset({"body", "handlers", "orelse", "finalbody", "cases"})
"""The fields that hold statements (an ``except``'s and a ``case``'s ``body`` too)."""


def legacy_names(tree: ast.Module) -> LegacyNames:
    """``SyntaxFacts.of(tree).legacy`` alone, walking the statements only (imports are
    statements), in the order ``nodes`` meets them: the EzSkiROS reader needs no more."""
    legacy = LegacyNames()
    todo: list[ast.AST] = [tree]
    while todo:
        node = todo.pop()
        if type(node) is ast.Import or type(node) is ast.ImportFrom:
            note_import(node, legacy)
            continue
        for name in node._fields:
            if name in _BODIES:
                value = getattr(node, name, None)
                if type(value) is list:
                    todo.extend(value)
    return legacy


def count_names(nodes: Iterable[ast.AST]) -> Counter[str]:
    """``SyntaxFacts.names`` of some subtrees (what a rewrite removes)."""
    found: Counter[str] = Counter()
    for node in nodes:
        _walk(node, found)
    return found


def _walk(tree: ast.AST, names: Counter[str], legacy: LegacyNames | None = None,
          bindings: dict[str, int] | None = None) -> None:
    """One walk that counts names (and, when given, notes imports and bindings). Dispatch
    is on the exact type: a file has thousands of nodes and a chain of ``isinstance``
    tests was half the walk."""
    for node in nodes(tree):
        kind = type(node)
        if kind is ast.Name:
            names[node.id] += 1  # type: ignore[attr-defined]
        elif kind is ast.Import or kind is ast.ImportFrom:
            if legacy is not None:
                note_import(node, legacy)
        else:
            if kind is ast.Global or kind is ast.Nonlocal:
                names.update(node.names)  # type: ignore[attr-defined]
            if bindings is not None and kind in _BINDERS:
                note_binding(node, bindings)


def note_import(node: ast.AST, legacy: LegacyNames) -> None:
    """Record ``node`` in ``legacy`` if it is an import statement (relative ones bind no
    SkiROS2 name)."""
    if isinstance(node, ast.Import):
        for alias in node.names:
            legacy.add_import(alias.name, alias.asname)
    elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
        legacy.add_from_import(node.module, None if node.names[0].name == "*" else
                               [(a.name, a.asname or a.name) for a in node.names])


def note_binding(node: ast.AST, bindings: dict[str, int]) -> None:
    """Add ``node``'s bindings to ``bindings`` (see ``SyntaxFacts.bindings``)."""
    if isinstance(node, ast.Assign):
        for name in (n for t in node.targets for n in target_names(t)):
            bindings[name] = bindings.get(name, 0) + 1
    elif isinstance(node, ast.AugAssign):
        for name in target_names(node.target):
            bindings[name] = bindings.get(name, 0) + 2
    elif isinstance(node, ast.Global):
        for name in node.names:
            bindings[name] = bindings.get(name, 0) + 2


_BINDERS = frozenset({ast.Assign, ast.AugAssign, ast.Global})


def target_names(node: ast.expr) -> list[str]:
    """Names an assignment target binds (``a``, ``a, b``, ``[a, b]``; not ``a.b``)."""
    if isinstance(node, ast.Name):
        return [node.id]
    if isinstance(node, ast.Starred):
        return target_names(node.value)
    if isinstance(node, (ast.Tuple, ast.List)):
        return [n for e in node.elts for n in target_names(e)]
    return []


def _class(node: ast.ClassDef) -> ClassFacts:
    def create() -> FunctionFacts | None:
        func = next((stmt for stmt in reversed(node.body)
                     if isinstance(stmt, (ast.FunctionDef, ast.AsyncFunctionDef))
                     and stmt.name == "createDescription"), None)
        if func is None:
            return None
        return FunctionFacts(func.col_offset, _spans(func.body), count_names([func]),
                             bound_names(func))

    return ClassFacts(node.lineno, _spans(node.body), create)


def _spans(body: list[ast.stmt]) -> list[Span]:
    return [(stmt.lineno, stmt.end_lineno or stmt.lineno) for stmt in body]


def bound_names(func: ast.FunctionDef | ast.AsyncFunctionDef) -> frozenset[str]:
    """Every name ``func``'s body binds (assignments, walrus, loops, imports, ``as``)."""
    found: set[str] = set()
    for node in (n for stmt in func.body for n in nodes(stmt)):
        if isinstance(node, ast.Assign):
            found.update(n for t in node.targets for n in target_names(t))
        elif isinstance(node, (ast.AugAssign, ast.AnnAssign, ast.NamedExpr, ast.For,
                               ast.AsyncFor)):
            found.update(target_names(node.target))
        elif isinstance(node, ast.withitem) and node.optional_vars is not None:
            found.update(target_names(node.optional_vars))
        elif isinstance(node, ast.ExceptHandler) and node.name is not None:
            found.add(node.name)
        elif isinstance(node, ast.alias) and node.name != "*":
            found.add(node.asname or node.name.split(".")[0])
    return frozenset(found)
