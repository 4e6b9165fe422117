"""What emission rules consult: which names to import, how a key or a term is spelled.

The short forms (``Object: skiros.Product``, ``A.contain(B)``) are used only when the
ontology given to the migration knows the term under exactly that prefix and, for a
relation or property, under no other prefix and in the default ``skiros`` prefix (the one a
short name unknown at run time falls back to); otherwise the verbatim string forms are written
(``ELEMENT(":Location")``, ``A.relation("turtlebot:docked", B)``), which lower to the same
legacy strings whatever ontology is loaded later. Class and namespace forms (``cora.Robot``,
``O.has(cora.Position)``) name their prefix, so they cannot change meaning either.

One dependence remains, in the runtime rather than here: a short relation or property name
resolves to the one property of that local name in the ontology loaded at run time, so
``A.contain(B)`` means ``foo:contain`` on a robot whose ontology has ``foo:contain`` and no
``skiros:contain`` (ezskiros_runtime/dsl/vocabulary.py, ``resolve_property``).
"""

from __future__ import annotations

import json
import keyword
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Protocol

if TYPE_CHECKING:
    import libcst as cst
else:
    from .lazy_cst import cst

from ..settings import DEFAULT_TARGET
from .ir import AddCondition, CondSpec, ParamOp
from .tree_walk import walk

if TYPE_CHECKING:
    from ezskiros_runtime.ontology.index import OntologyIndex


SYMBOL_METHODS = frozenset(
    {"relation", "property", "has", "is_specified", "generated", "is_a", "named", "key"})
"""Methods of a symbolic parameter: never usable as a short relation/property name."""

DSL_NAMES = frozenset({
    "SkillDescription", "Annotated", "INFERRED", "OPTIONAL", "REQUIRED", "ELEMENT", "KEY", "DESC",
    "LIST", "abstract", "any_of", "Lock", "Consume", "Unspecify", "RespectType", "Output"})

LINE_LIMIT = 99
"""Longest line the emitter writes when it has a choice (ruff's and black's spirit)."""

_QNAME = re.compile(r"([A-Za-z][A-Za-z0-9_]*):([A-Za-z][A-Za-z0-9_]*)\Z")


def quote(text: str, quotes: str = '"') -> str:
    """A Python string literal for ``text``, in ``quotes`` (``"`` or ``'``) unless the text
    holds that quote and not the other (black's rule: the fewer escapes)."""
    double = json.dumps(text, ensure_ascii=False)
    if quotes != "'" or "'" in text:
        return double
    return "'" + double[1:-1].replace('\\"', '"') + "'"


def quote_style(node: cst.CSTNode) -> str:
    """The quote the code under ``node`` uses most for one-line strings (``'`` or ``"``; a
    tie is ``"``): the emitted strings follow the file's own style, not ours. Why per class:
    the strings a migration writes replace those of its ``createDescription``."""
    counts = {"'": 0, '"': 0}
    for found in walk(node):
        if isinstance(found, cst.SimpleString) and found.quote in counts:
            counts[found.quote] += 1
    return "'" if counts["'"] > counts['"'] else '"'


ConditionEmitter = Callable[[CondSpec, "EmitContext"], str]
"""Writes the EzSkiROS expression of one condition kind."""


class EmissionRules(Protocol):
    """The part of the rule table (``registry.RuleTable``) that writing consults. Declared
    here, not imported, so that the table may name this context in its rules' signatures
    without the two modules importing each other."""

    @property
    def param_annotation(self) -> Callable[[ParamOp, str, EmitContext],
                                           tuple[str, str | None]]: ...

    @property
    def condition_statement(self) -> Callable[[AddCondition, EmitContext], str]: ...

    @property
    def condition_emitters(self) -> Mapping[str, ConditionEmitter]: ...


@dataclass
class EmitContext:
    """Per-skill emission state: key names, and what the file must import."""

    index: OntologyIndex | None
    rules: EmissionRules
    self_name: str = "self"
    param_names: dict[str, str] = field(default_factory=dict)
    runtime_names: set[str] = field(default_factory=set)
    prefixes: set[str] = field(default_factory=set)
    reserved: set[str] = field(default_factory=set)
    aliases: dict[str, str] = field(default_factory=dict)
    column: int = 8
    """Width of the body's indentation, for wrapping long lines."""
    target: tuple[int, int] = DEFAULT_TARGET
    """The oldest Python the written code must run on (see ``list_type``)."""
    quotes: str = '"'
    """The quote the file uses (``quote_style``): every string written is spelt with it."""

    def quote(self, text: str) -> str:
        """A string literal for ``text`` in the file's own quote style."""
        return quote(text, self.quotes)

    def use(self, name: str) -> str:
        """Note that ``name`` must be imported from ``ezskiros_runtime``; its local name."""
        self.runtime_names.add(name)
        return self.aliases.get(name, name)

    def list_type(self, item: str) -> str:
        """The annotation of a list of ``item``: ``list[float]`` where the target Python
        runs it (3.9 and newer), else the DSL's ``LIST[float]`` (``typing.List``), since
        ``list[float]`` raises ``TypeError`` when the class is defined under Python 3.8."""
        return f"list[{item}]" if self.target >= (3, 9) else f"{self.use('LIST')}[{item}]"

    def namespace(self, prefix: str) -> str:
        """Note that the namespace ``prefix`` must be imported; its local name."""
        self.prefixes.add(prefix)
        return self.aliases.get(prefix, prefix)

    def subject(self, key: str) -> str:
        """The expression for a key inside ``description``: its parameter, else ``self.param``."""
        name = self.param_names.get(key)
        return name if name is not None else f"{self.self_name}.param({self.quote(key)})"

    def _qname(self, text: str) -> tuple[str, str, str] | None:
        """``(prefix, local, iri)`` when ``text`` is a plain ``prefix:Local`` the index knows."""
        match = _QNAME.match(text)
        if match is None or self.index is None:
            return None
        prefix, local = match.groups()
        if keyword.iskeyword(prefix) or keyword.iskeyword(local):
            return None
        if prefix not in self.index.prefixes:
            return None
        iri = self.index.expand(text)
        return None if iri is None else (prefix, local, iri)

    def class_ref(self, type_string: str) -> str | None:
        """``skiros.Product`` for ``"skiros:Product"`` when the ontology has that class."""
        found = self._qname(type_string)
        if found is None or not self.index or not self.index.is_class(found[2]):
            return None
        return f"{self.namespace(found[0])}.{found[1]}"

    def property_ref(self, vocabulary: str) -> str | None:
        """``skiros.Position`` for a property the ontology has under that prefix."""
        found = self._qname(vocabulary)
        if found is None or not self.index or self.index.property(found[2]) is None:
            return None
        return f"{self.namespace(found[0])}.{found[1]}"

    def short_property(self, vocabulary: str) -> str | None:
        """``contain`` for ``"skiros:contain"`` when that local name is unambiguous.

        Only for the default prefix: the runtime reads a short name it does not know as the
        default prefix's (SkiROS2's ``:name``), so ``A.robotPart(B)`` would silently become
        ``skiros:robotPart`` on a robot whose ontology lacks ``cora:robotPart``.
        """
        found = self._qname(vocabulary)
        if found is None or not self.index or found[0] != self.index.default_prefix:
            return None
        _, local, iri = found
        if local in SYMBOL_METHODS or local.startswith("_"):
            return None
        if self.index.property(iri) is None or self.index.properties_named(local) != [iri]:
            return None
        return local
