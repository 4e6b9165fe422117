"""The early checks carried into implementation code (issue 30: "the same checks inside a
skill implementation").

Read from the syntax of each implementation class (a class whose ``createDescription``
calls ``setDescription(Desc(), ...)``), against what the repository declares:

- ``self.params["Key"]`` with a key the implemented description does not declare: not its
  own ``addParam``, not what an implementation adds to the wrapper or itself in
  ``modifyDescription``, not the ``Robot`` SkiROS2 adds to every skill. SkiROS2's
  ``ParamHandler.__getitem__`` logs "Param ... is not in the map" and returns None, so the
  ``.value`` after it raises when the line runs (EZ109, error). A fork's tuple keys are not
  strings and are left alone; a description this run could not read is not judged.
- ``Element("p:Class")`` with a class no loaded ontology, owl file or scene defines that is
  one edit away from one that is (EZ214, warning, with the did-you-mean): the world model
  matches element types verbatim, so a query or a new element of that type finds or makes
  the wrong thing. A class far from every known one is more likely the lab's own
  vocabulary from a file this run cannot see, and is left alone.
- ``getProperty("p:Name")``/``hasProperty`` of a property that nothing in the repository
  sets (``setProperty``, a property condition) and no loaded ontology or scene declares
  (EZ215, info). Property names are made at run time on purpose (``skiros:Mean``, a lab's
  calibration values), so this is worth saying only when nothing makes it, and then as
  advice.
"""

from __future__ import annotations

import ast
import bisect
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import TYPE_CHECKING

from ezskiros_runtime.codes import code_for, rule_for
from ezskiros_runtime.diagnostics import Finding

from ..codemod.core.ast_walk import nodes, walk

if TYPE_CHECKING:  # the compound library: not for ``IMPLEMENTATION`` alone
    from ezskiros_runtime.compound.library import SkillIndex

IMPLEMENTATION = (code_for("implementation-unknown-key"), code_for("implementation-element-typo"),
                  code_for("implementation-unknown-property"))
"""The codes of these checks, which need the skill index the compound pass builds."""

def _found(kind: str, line: int, message: str, cls: str, fix: str | None, name: str
           ) -> Finding:
    """A finding of these checks: the runtime's one type, the implementation class its
    skill, the key or name it is about its subject."""
    return Finding(kind, rule_for(kind).severity, message, None, line, cls, subject=name,
                   fix=fix)


@dataclass(frozen=True)
class ImplementationClass:
    """What the checks need of one implementation class, read once from its syntax: the
    description it sets, its literal ``self.params["Key"]`` reads and ``Element("p:C")``
    literals (``("param" | "element", name, line)``, in the order of the class's walk), its
    ``getProperty``/``hasProperty`` names, and every string literal in it (the keys it may
    read or pass on: ``uninferable.keys_read``)."""

    description: str
    name: str
    uses: tuple[tuple[str, str, int], ...]
    properties: tuple[tuple[str, int], ...]
    strings: frozenset[str]


@dataclass(frozen=True)
class ModuleFacts:
    """A module's implementation classes and the property names its code sets: all these
    checks read of a file, so a run keeps this and not the syntax tree."""

    classes: tuple[ImplementationClass, ...] = ()
    sets: frozenset[str] = frozenset()


def module_facts(tree: ast.Module, data: bytes) -> ModuleFacts:
    """One walk of the module: its implementation classes' reads, and the property names
    any of its code sets (only when its text holds a setter at all)."""
    from ..compound.static import described_classes

    setters = _setter_lines(data)
    described = {id(cls): description for description, cls in described_classes(tree)}
    classes = []
    sets: set[str] = set()
    for stmt in tree.body:
        description = described.get(id(stmt))
        if description is None:
            if _spans(stmt, setters):
                sets |= properties_set((stmt,))
            continue
        uses: list[tuple[str, str, int]] = []
        properties: list[tuple[str, int]] = []
        strings: set[str] = set()
        for node in walk(stmt):
            kind = type(node)
            if kind is ast.Constant:
                if isinstance(node.value, str):  # type: ignore[attr-defined]
                    strings.add(node.value)  # type: ignore[attr-defined]
            elif kind is ast.Subscript:
                key = _params_key(node)
                if key is not None:
                    uses.append(("param", *key))
            elif kind is ast.Call:
                if setters:
                    _set_by(node, sets)
                read = _property_call(node, ("getProperty", "hasProperty"))
                if read is not None:
                    properties.append(read)
                literal = _element_class(node)
                if literal is not None:
                    uses.append(("element", *literal))
        assert isinstance(stmt, ast.ClassDef)
        classes.append(ImplementationClass(description, stmt.name, tuple(uses),
                                           tuple(properties), frozenset(strings)))
    return ModuleFacts(tuple(classes), frozenset(sets))


_SETTERS = (b"setProperty", b"PropCond")
"""Text every property-setting call holds (``setProperty``, ``getPropCond``,
``getHasPropCond``): a module without it sets none."""


def _setter_lines(data: bytes) -> list[int]:
    """The lines (1-based, as ``ast`` counts them) whose text holds a setter's name: a
    statement that spans none of them sets no property, and is not walked (most of a
    large module)."""
    if not any(m in data for m in _SETTERS):
        return []
    return [number for number, line in enumerate(data.splitlines(), start=1)
            if any(m in line for m in _SETTERS)]


def _spans(stmt: ast.stmt, lines: list[int]) -> bool:
    """Whether ``stmt`` (with its decorators, written above it) spans one of ``lines``."""
    if not lines:
        return False
    first = min([stmt.lineno, *(d.lineno for d in getattr(stmt, "decorator_list", ()))])
    last = stmt.end_lineno or stmt.lineno
    at = bisect.bisect_left(lines, first)
    return at < len(lines) and lines[at] <= last


def properties_set(trees: Iterable[ast.AST]) -> set[str]:
    """Every literal property name the code sets (``setProperty("p:N", v)``,
    ``getPropCond(..., "p:N", ...)`` conditions, which SkiROS2 sets on post-conditions)."""
    found: set[str] = set()
    for tree in trees:
        for node in nodes(tree):
            if type(node) is ast.Call:
                _set_by(node, found)
    return found


def _set_by(node: ast.AST, found: set[str]) -> None:
    """Add the property name ``node`` sets, if it is a setter call with a literal name."""
    name = _property_call(node, ("setProperty",))
    if name is not None:
        found.add(name[0])
    elif isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) \
            and node.func.attr in ("getPropCond", "getHasPropCond") \
            and len(node.args) > 1 and isinstance(node.args[1], ast.Constant) \
            and isinstance(node.args[1].value, str):
        found.add(node.args[1].value)


def implementation_findings(facts: ModuleFacts, path: str, skills: SkillIndex,
                            known_class: Callable[[str], bool],
                            classes: Iterable[str],
                            known_property: Callable[[str], bool] = lambda _name: True,
                            ) -> list[Finding]:
    """Every finding of the implementation classes of the module in ``path`` (see the
    module doc); ``known_class`` answers for a ``prefix:Name``, ``classes`` lists the known
    ones; ``known_property`` for a property name the ontology, a scene or the code
    defines."""
    found: list[Finding] = []
    known = sorted(set(classes))
    for cls in facts.classes:
        for name, line in cls.properties:
            if not known_property(name):
                found.append(_found("implementation-unknown-property", line,
                              f"{name}: nothing in the repository sets this property and "
                              "no loaded ontology or scene declares it, so every element "
                              "SkiROS2 holds lacks it (Element.hasProperty is False)",
                              cls.name, None, name))
        declared = _declared(cls.description, skills, path)
        for kind, name, line in cls.uses:
            if kind == "param" and declared is not None and name not in declared:
                found.append(_found("implementation-unknown-key", line,
                              f"self.params[{name!r}]: {cls.description} declares no such "
                              "parameter, so SkiROS2's ParamHandler returns None (\"Param "
                              "... is not in the map\") and the line raises when it runs",
                              cls.name, _closest(name, sorted(declared)), name))
            elif kind == "element" and not known_class(name):
                near = [c for c in known if _one_edit(name, c)]
                if near:
                    found.append(_found("implementation-element-typo", line,
                                  f"Element({name!r}): no loaded ontology, owl file or "
                                  f"scene defines {name}; did you mean {near[0]}? The "
                                  "world model matches types verbatim", cls.name,
                                  f"Element({near[0]!r})", name))
    return found


def _declared(description: str, skills: SkillIndex, path: str) -> set[str] | None:
    """The keys ``self.params`` holds in an implementation of ``description`` in ``path``
    (None when the description could not be read: nothing is judged then).

    Packages reuse description names (two labs' ``ChangeStiffness`` side by side in one
    checkout): the implementation gets the nearest definition, as a compound's child does
    (``SkillIndex.nearest``); when several are equally near, a key any of them declares
    is not judged."""
    info = skills.descriptions.get(description)
    if info is None:
        return None
    nearest = skills.nearest(info, path)
    if not all(d.complete for d in nearest):
        return None
    return (set().union(*(d.declared() for d in nearest))
            | set(skills.modified_by.get(description, {}))
            | skills.self_added.get(description, set()))


def _params_key(node: ast.AST) -> tuple[str, int] | None:
    """``("Key", line)`` for ``self.params["Key"]`` (any first-argument name)."""
    if isinstance(node, ast.Subscript) and isinstance(node.value, ast.Attribute) \
            and node.value.attr == "params" and isinstance(node.value.value, ast.Name) \
            and node.value.value.id == "self" and isinstance(node.slice, ast.Constant) \
            and isinstance(node.slice.value, str):
        return node.slice.value, node.lineno
    return None


def _element_class(node: ast.AST) -> tuple[str, int] | None:
    """``("p:Class", line)`` for ``Element("p:Class")`` with a literal ``prefix:Name``."""
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) \
            and node.func.id == "Element" and node.args \
            and isinstance(node.args[0], ast.Constant) and isinstance(node.args[0].value, str):
        value = node.args[0].value
        prefix, _, local = value.partition(":")
        if prefix and local and " " not in value:
            return value, node.lineno
    return None


def _property_call(node: ast.AST, methods: tuple[str, ...]) -> tuple[str, int] | None:
    """``("p:Name", line)`` for ``anything.method("p:Name", ...)`` with a literal name."""
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) \
            and node.func.attr in methods and node.args \
            and isinstance(node.args[0], ast.Constant) and isinstance(node.args[0].value, str):
        name = node.args[0].value
        if ":" in name and " " not in name:
            return name, node.lineno
    return None


def _one_edit(a: str, b: str) -> bool:
    """Whether ``a`` becomes ``b`` by one insertion, deletion, substitution or swap of two
    neighbouring characters (and not when they are equal)."""
    if a == b or abs(len(a) - len(b)) > 1:
        return False
    if len(a) == len(b):
        diff = [i for i, (x, y) in enumerate(zip(a, b, strict=True)) if x != y]
        return len(diff) == 1 or (len(diff) == 2 and diff[1] == diff[0] + 1
                                  and a[diff[0]] == b[diff[1]] and a[diff[1]] == b[diff[0]])
    short, long = (a, b) if len(a) < len(b) else (b, a)
    i = next((i for i, (x, y) in enumerate(zip(short, long, strict=False)) if x != y), len(short))
    return short[i:] == long[i + 1:]


def _closest(key: str, declared: list[str]) -> str | None:
    """A declared key one edit away, as the fix (None when there is none)."""
    near = [d for d in declared if _one_edit(key, d) or key.lower() == d.lower()]
    return f"self.params[{near[0]!r}]" if near else None
