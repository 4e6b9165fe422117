"""The ontology index: what the DSL and the migrator need to know about the vocabulary.

The index is plain data (strings, frozensets, small frozen dataclasses), not an rdflib
graph, for two reasons: it can be cached on disk (``cache``, as JSON) and loaded without
importing rdflib (whose import alone costs more than the whole warm load), and every
question the checks ask ("is this a class?", "what is the range of contain?") becomes a
dictionary lookup instead of a graph query. Subclass and sub-property questions walk the
direct edges (``closure.Hierarchy``): the closures are never stored, since a long chain
makes them quadratic.

`load_index` (in `load.py`) is the only entry point that touches files; everything here is
queries.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field, replace

from .bundled import bundled_ontology_path
from .closure import Hierarchy
from .expressions import (
    ClassExpr,
    ComplementOf,
    IntersectionOf,
    Named,
    UnionOf,
    Unsupported,
)
from .naming import DEFAULT_PREFIX, OWL, local_name, looks_like_iri, split_iri

OWL_THING = OWL + "Thing"
PROPERTY_KINDS = ("object", "data", "annotation")
NAME_KINDS = ("class", *PROPERTY_KINDS)

@dataclass(frozen=True)
class PropertyInfo:
    """One object, datatype or annotation property, with its effective domain and range.

    `domains` and `ranges` are the property's own plus those of all its super-properties
    (RDFS rdfs7 with rdfs2/rdfs3: `x P y` entails `x Q y` for every super-property `Q`);
    `domain_sources` / `range_sources` name where they were declared, so a message can say
    "inherited from ...". Several entries mean all of them must hold, as several
    rdfs:domain triples do in OWL.
    """

    iri: str
    kind: str
    domains: tuple[ClassExpr, ...]
    ranges: tuple[ClassExpr, ...]
    parents: frozenset[str]
    """The direct super-properties (``rdfs:subPropertyOf``), itself excluded."""
    domain_sources: tuple[str, ...] = ()
    range_sources: tuple[str, ...] = ()
    lineage: Hierarchy | None = field(default=None, compare=False, repr=False, hash=False)
    """The sub-property hierarchy of all properties, shared, for ``super_properties``."""

    @property
    def super_properties(self) -> frozenset[str]:
        """All super-properties, transitively (itself excluded), walked when asked: stored
        for every property, a chain of them would be quadratic."""
        if self.lineage is None:
            return self.parents
        return self.lineage.ancestors(self.iri) - {self.iri}


@dataclass(frozen=True)
class ClassGraph:
    """The named classes and the edges asserted between them, as the builder or the cache
    read them: one argument of `OntologyIndex`, since the three only mean something
    together (the index builds its ``Hierarchy`` from them and never stores a closure)."""

    names: Iterable[str]
    direct_superclasses: Mapping[str, Iterable[str]] = field(default_factory=dict)
    """Each class's named ``rdfs:subClassOf`` targets (and intersection members)."""
    equivalent_classes: Mapping[str, Iterable[str]] = field(default_factory=dict)
    """Each class's named ``owl:equivalentClass`` partners, both directions."""


class OntologyIndex:
    """Classes, properties and prefixes of the loaded ontology files, ready for lookups.

    Build it with `load_index`; treat it as read-only. `sources` lists the files it came
    from (for messages); `fingerprint` identifies their content.
    """

    prefixes: Mapping[str, str]
    default_prefix: str
    classes: frozenset[str]
    properties: Mapping[str, PropertyInfo]
    sources: tuple[str, ...]
    fingerprint: str
    individuals: Mapping[str, list[str]] | None = None
    """``{iri: [classes]}`` of the individuals the files declare (``individuals``), kept
    from the build; None for an index made otherwise (``world.scene.individuals_of`` then
    parses the files)."""

    def __init__(
        self,
        *,
        prefixes: Mapping[str, str],
        classes: ClassGraph,
        properties: Mapping[str, PropertyInfo],
        sources: Iterable[str] = (),
        fingerprint: str = "",
        default_prefix: str = DEFAULT_PREFIX,
        individuals: Mapping[str, list[str]] | None = None,
    ) -> None:
        self.prefixes = dict(prefixes)
        self.individuals = None if individuals is None else {
            iri: list(types) for iri, types in individuals.items()}
        self.default_prefix = default_prefix
        self.classes = frozenset(classes.names)
        self.sources = tuple(sources)
        self.fingerprint = fingerprint
        direct = {c: frozenset(s) for c, s in classes.direct_superclasses.items()}
        self._direct_superclasses: dict[str, frozenset[str]] = direct
        self._equivalent_classes: dict[str, frozenset[str]] = {
            c: frozenset(same) for c, same in classes.equivalent_classes.items()}
        edges: dict[str, set[str]] = {c: set(s) for c, s in direct.items()}
        for cls, same in self._equivalent_classes.items():
            edges.setdefault(cls, set()).update(same)
        self._hierarchy = Hierarchy(self.classes, edges)
        lineage = Hierarchy(properties, {iri: info.parents for iri, info in properties.items()})
        self.properties = {iri: _with_lineage(info, lineage)
                           for iri, info in properties.items()}
        self._namespace_prefix: dict[str, str] = {}
        for prefix, namespace in self.prefixes.items():
            self._namespace_prefix.setdefault(namespace, prefix)
        self._classes_by_local = _group_by_local_name(self.classes)
        self._properties_by_local = _group_by_local_name(self.properties)
        self._below: dict[str, frozenset[str]] = {}

    # -- names ---------------------------------------------------------------------------

    def expand(self, name: str) -> str | None:
        """`skiros:Product`, `:Product` or `Product` -> the full IRI; unknown prefix -> None.

        A bare or `:`-prefixed name means the default prefix, as in SkiROS2. Whether the
        IRI names anything is not checked here (use `is_class` / `property`). Absolute IRIs
        are returned unchanged.
        """
        name = name.strip()
        if name.startswith("<") and name.endswith(">"):
            name = name[1:-1]
        if not name:
            return None
        if looks_like_iri(name):
            return name
        prefix, colon, local = name.partition(":")
        if not colon:
            prefix, local = self.default_prefix, name
        elif not prefix:
            prefix = self.default_prefix
        namespace = self.prefixes.get(prefix)
        if namespace is None or not local:
            return None
        return namespace + local

    def compact(self, iri: str) -> str:
        """IRI -> `prefix:Local` (always with the prefix); unchanged if no prefix matches."""
        namespace, local = split_iri(iri)
        prefix = self._namespace_prefix.get(namespace)
        if prefix is not None and local:
            return f"{prefix}:{local}"
        for candidate_ns, candidate_prefix in sorted(
            self._namespace_prefix.items(), key=lambda item: -len(item[0])
        ):
            if iri.startswith(candidate_ns) and len(iri) > len(candidate_ns):
                return f"{candidate_prefix}:{iri[len(candidate_ns) :]}"
        return iri

    def render(self, expr: ClassExpr) -> str:
        """A class expression with compact names, for messages: `(skiros:A | ~cora:B)`."""
        return expr.render(self.compact)

    def local_names(self, prefix: str) -> list[str]:
        """Local names of the classes and properties in a prefix's namespace, sorted.

        Namespace objects use it for `dir()` and completion.
        """
        namespace = self.prefixes.get(prefix)
        if namespace is None:
            return []
        found = {
            local
            for iri in (*self.classes, *self.properties)
            for ns, local in [split_iri(iri)]
            if ns == namespace and local
        }
        return sorted(found)

    def sub_properties(self, iri: str) -> frozenset[str]:
        """``iri`` and every loaded property below it. Kept by the index: the world checks
        ask it of the same few properties for each relation of each scene."""
        found = self._below.get(iri)
        if found is None:
            found = self._below[iri] = frozenset(
                {iri} | {p for p, info in self.properties.items() if iri in info.super_properties})
        return found

    # -- classes -------------------------------------------------------------------------

    def is_class(self, iri: str) -> bool:
        """True when `iri` is a named class of the loaded files."""
        return iri in self.classes

    def superclasses(self, iri: str) -> frozenset[str]:
        """`iri` and all its named superclasses (rdfs:subClassOf, equivalences, intersections).

        For an IRI the index does not know, just `{iri}`: reflexivity holds for anything.
        """
        return self._hierarchy.ancestors(iri)

    def direct_superclasses(self, iri: str) -> frozenset[str]:
        """The named superclasses asserted for `iri` (no closure, no equivalences).

        This is the shape to mirror as Python base classes. Odd ontologies can make it
        cyclic; callers building class hierarchies must guard against that.
        """
        return self._direct_superclasses.get(iri, frozenset())

    def is_subclass(self, sub: str, sup: str) -> bool:
        """Reflexive, transitive subclass test; everything is a subclass of owl:Thing."""
        return sup == OWL_THING or self._hierarchy.reaches(sub, sup)

    def direct_superclass_map(self) -> Mapping[str, frozenset[str]]:
        """Every class's asserted superclasses (read-only): the hierarchy's direct edges."""
        return self._direct_superclasses

    def equivalent_class_map(self) -> Mapping[str, frozenset[str]]:
        """Every class's asserted equivalents (read-only)."""
        return self._equivalent_classes

    def equivalent_classes(self, iri: str) -> frozenset[str]:
        """The named classes asserted equivalent to `iri` (both directions, no closure)."""
        return self._equivalent_classes.get(iri, frozenset())

    def classes_named(self, local: str) -> list[str]:
        """IRIs of the classes with this local name, across all prefixes (sorted)."""
        return list(self._classes_by_local.get(local, ()))

    def witness(self, class_iri: str, expr: ClassExpr) -> str | None:
        """A named class at or below `class_iri` all of whose instances belong to `expr`.

        A parameter declared as `class_iri` is bound at run time to an individual of some
        class below it, so when such a class exists (`sumo:Agent` where `sumo:Device` is
        expected: `cora:Robot` is both) the condition may hold: a checker that calls only
        impossible conditions errors needs the difference. None when no class qualifies.
        """
        for candidate in self._at_or_below(class_iri):
            if self._satisfies(candidate, expr) is True:
                return candidate
        return None

    def can_satisfy(self, class_iri: str, expr: ClassExpr) -> bool | None:
        """Can an element of class `class_iri` belong to `expr`? None when undecidable.

        True when some class at or below `class_iri` satisfies `expr` (a `witness`), False
        only when every one certainly does not: then the condition can never hold, which is
        the one case a checker may call an error. An undecidable subclass (an `Unsupported`
        member) or a class the index does not know gives None: no guessing.
        """
        below = self._at_or_below(class_iri)
        if not below:
            return None
        results = {self._satisfies(candidate, expr) for candidate in below}
        if True in results:
            return True
        return None if None in results else False

    def _at_or_below(self, class_iri: str) -> list[str]:
        """The known classes at or below `class_iri`, fewest superclasses (most general)
        first so that `witness` names the simplest fix; everything is below owl:Thing."""
        if class_iri == OWL_THING:
            below = list(self.classes)
        elif class_iri in self.classes:
            below = [c for c in self._hierarchy.descendants(class_iri) if c in self.classes]
        else:
            return []
        count = self._hierarchy.ancestor_count
        return sorted(below, key=lambda c: (count(c), c))

    def satisfies(self, class_iri: str, expr: ClassExpr) -> bool | None:
        """Does every instance of `class_iri` belong to `expr`? None when undecidable.

        Named classes use the subclass closure; unions, intersections and complements use
        three-valued logic, reading the hierarchy closed-world (a class that is not below
        `B` counts as outside `B`), which is what the EzSkiROS paper's Python-subclass check
        does. Unknown classes and `Unsupported` expressions give None, and callers then
        report nothing rather than a false error.
        """
        if class_iri != OWL_THING and class_iri not in self.classes:
            return None
        return self._satisfies(class_iri, expr)

    def _satisfies(self, class_iri: str, expr: ClassExpr) -> bool | None:
        if isinstance(expr, Named):
            if expr.iri == OWL_THING:
                return True
            if expr.iri not in self.classes:
                return None
            return self._hierarchy.reaches(class_iri, expr.iri)
        if isinstance(expr, UnionOf):
            results = [self._satisfies(class_iri, m) for m in expr.members]
            if any(r is True for r in results):
                return True
            return False if all(r is False for r in results) else None
        if isinstance(expr, IntersectionOf):
            results = [self._satisfies(class_iri, m) for m in expr.members]
            if any(r is False for r in results):
                return False
            return True if all(r is True for r in results) else None
        if isinstance(expr, ComplementOf):
            inner = self._satisfies(class_iri, expr.expr)
            return None if inner is None else not inner
        if isinstance(expr, Unsupported):
            return None
        return None

    # -- properties ----------------------------------------------------------------------

    def property(self, iri: str) -> PropertyInfo | None:
        """The property with this IRI, or None when no loaded file declares it."""
        return self.properties.get(iri)

    def properties_named(self, local: str) -> list[str]:
        """IRIs of the properties with this local name, across all prefixes (sorted)."""
        return list(self._properties_by_local.get(local, ()))

    # -- suggestions ---------------------------------------------------------------------

    def suggest(
        self,
        name: str,
        kinds: Iterable[str] = ("class", "object", "data"),
        limit: int = 3,
    ) -> list[str]:
        """Closest existing compact names to `name` ("did you mean"), best first.

        `kinds` picks the vocabulary: "class", "object", "data", "annotation". Answers are
        remembered per index: a repository repeats its misspellings in many skills, and
        each answer compares the name with the whole vocabulary.
        """
        wanted = set(kinds)
        unknown = wanted.difference(NAME_KINDS)
        if unknown:
            raise ValueError(f"unknown name kinds {sorted(unknown)}; use {NAME_KINDS}")
        memo: dict[tuple[str, frozenset[str], int], list[str]] = self.__dict__.setdefault(
            "_suggested", {})
        key = (name, frozenset(wanted), limit)
        if key not in memo:
            memo[key] = self._suggest(name, wanted, limit)
        return list(memo[key])

    def _suggest(self, name: str, wanted: set[str], limit: int) -> list[str]:
        from .suggest import closest_names

        candidates: list[str] = []
        if "class" in wanted:
            candidates.extend(self.compact(iri) for iri in self.classes)
        candidates.extend(
            self.compact(iri) for iri, info in self.properties.items() if info.kind in wanted
        )
        return closest_names(name, candidates, limit)

    # -- plumbing ------------------------------------------------------------------------

    def with_sources(self, sources: Iterable[str]) -> OntologyIndex:
        """The same index, reporting other file paths (a cached index loaded from elsewhere)."""
        clone = object.__new__(OntologyIndex)
        clone.__dict__.update(self.__dict__)
        clone.sources = tuple(sources)
        return clone

    def __repr__(self) -> str:
        kinds = {k: sum(1 for p in self.properties.values() if p.kind == k) for k in PROPERTY_KINDS}
        return (
            f"<OntologyIndex {len(self.classes)} classes, {kinds['object']} object / "
            f"{kinds['data']} data / {kinds['annotation']} annotation properties, "
            f"prefixes {sorted(self.prefixes)}, {len(self.sources)} file(s)>"
        )


def _with_lineage(info: PropertyInfo, lineage: Hierarchy) -> PropertyInfo:
    """``info`` sharing the hierarchy of its index. A fresh `PropertyInfo` (from the
    builder or the cache, with none yet) gets it in place: ``dataclasses.replace`` for every
    property was a third of the warm load."""
    if info.lineage is None:
        object.__setattr__(info, "lineage", lineage)
        return info
    return info if info.lineage is lineage else replace(info, lineage=lineage)


def _group_by_local_name(iris: Iterable[str]) -> dict[str, tuple[str, ...]]:
    grouped: dict[str, list[str]] = {}
    for iri in iris:
        grouped.setdefault(local_name(iri), []).append(iri)
    return {local: tuple(sorted(found)) for local, found in grouped.items()}


__all__ = [
    "ClassExpr",
    "ClassGraph",
    "ComplementOf",
    "IntersectionOf",
    "Named",
    "OntologyIndex",
    "PropertyInfo",
    "UnionOf",
    "Unsupported",
    "bundled_ontology_path",
]
