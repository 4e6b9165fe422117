"""Turning parsed RDF into an `OntologyIndex` (the cache-miss path; imports rdflib).

Everything rdflib-specific stays in this module: the result holds only strings and the
dataclasses of `expressions`, so it can be cached (as JSON) and queried without rdflib.
Nothing here computes a closure per class or property: the index keeps direct edges, and
inherited domains and ranges are shared along single-parent chains (``_Inheritance``), so
time and memory grow linearly with a chain of 10,000 ``subClassOf`` or ``subPropertyOf``.

What counts, and why:
- classes: URIRefs typed owl:Class or rdfs:Class, plus every URIRef on either side of
  rdfs:subClassOf (files often use a class without declaring it);
- superclasses: named rdfs:subClassOf targets, the named members of an intersection a
  class is a subclass of (or equivalent to) since A ⊑ B ⊓ C entails A ⊑ B, and named
  owl:equivalentClass partners (kept apart, they make the hierarchy cyclic);
- properties: owl:ObjectProperty / DatatypeProperty / AnnotationProperty, the OWL
  characteristics that imply an object property, and plain rdf:Property (kind guessed
  from its range); domains and ranges inherited from super-properties when a property
  declares none itself;
- prefixes: derived from the namespaces of those IRIs as SkiROS2 does; when two namespaces
  derive the same prefix, the one from the earlier file keeps it.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from typing import Tuple

from rdflib import BNode, Graph, Literal, URIRef
from rdflib.namespace import OWL, RDF, RDFS, XSD

from .expressions import ClassExpr, ComplementOf, IntersectionOf, Named, UnionOf, Unsupported
from .index import ClassGraph, OntologyIndex, PropertyInfo
from .individuals import add_individuals
from .naming import (
    DEFAULT_PREFIX,
    SKIROS_NAMESPACE,
    WELL_KNOWN_PREFIXES,
    derive_prefix,
    split_iri,
)
from .parsing import OntologyFile, parse_ontology_file

_CLASS_TYPES = (OWL.Class, RDFS.Class)
_KIND_BY_TYPE = {
    OWL.ObjectProperty: "object",
    OWL.DatatypeProperty: "data",
    OWL.AnnotationProperty: "annotation",
}
_OBJECT_CHARACTERISTICS = (
    OWL.TransitiveProperty,
    OWL.SymmetricProperty,
    OWL.AsymmetricProperty,
    OWL.ReflexiveProperty,
    OWL.IrreflexiveProperty,
    OWL.InverseFunctionalProperty,
)
_KIND_PRIORITY = ("object", "data", "annotation")
_SET_OPERATORS = (OWL.unionOf, OWL.intersectionOf, OWL.complementOf)


def build_index(files: Sequence[OntologyFile], fingerprint: str) -> OntologyIndex:
    """Parse `files` (in order) and index them."""
    graphs = [parse_ontology_file(entry) for entry in files]
    merged = Graph()
    for graph in graphs:
        merged += graph
    classes = _named_classes(merged)
    kinds = _property_kinds(merged)
    prefixes = _derive_prefixes(graphs, classes | set(kinds))
    reader = _ExpressionReader(merged, _compactor(prefixes))
    direct, equivalent = _class_hierarchy(merged, reader)
    properties = _properties(merged, kinds, reader)
    individuals: dict[str, list[str]] = {}
    for graph in graphs:
        add_individuals(graph, individuals)
    return OntologyIndex(
        prefixes=prefixes,
        classes=ClassGraph(classes, direct, equivalent),
        properties=properties,
        sources=[str(entry.path) for entry in files],
        fingerprint=fingerprint,
        default_prefix=DEFAULT_PREFIX,
        individuals=individuals,
    )


# -- classes -------------------------------------------------------------------------------


def _named_classes(graph: Graph) -> set[str]:
    classes = {
        str(node)
        for class_type in _CLASS_TYPES
        for node in graph.subjects(RDF.type, class_type)
        if isinstance(node, URIRef)
    }
    for sub, sup in graph.subject_objects(RDFS.subClassOf):
        for node in (sub, sup):
            if isinstance(node, URIRef):
                classes.add(str(node))
    return classes


def _named_parts(expr: ClassExpr) -> set[str]:
    """Named classes every instance of `expr` belongs to (a name, or an intersection's)."""
    if isinstance(expr, Named):
        return {expr.iri}
    if isinstance(expr, IntersectionOf):
        return set().union(*(_named_parts(member) for member in expr.members))
    return set()


def _class_hierarchy(
    graph: Graph, reader: _ExpressionReader
) -> tuple[dict[str, set[str]], dict[str, set[str]]]:
    direct: dict[str, set[str]] = {}
    for sub, sup in graph.subject_objects(RDFS.subClassOf):
        if isinstance(sub, URIRef) and sup != sub:
            parts = _named_parts(reader.read(sup)) - {str(sub)}
            direct.setdefault(str(sub), set()).update(parts)
    equivalent: dict[str, set[str]] = {}
    for left, right in graph.subject_objects(OWL.equivalentClass):
        if isinstance(left, URIRef) and isinstance(right, URIRef):
            if left != right:
                equivalent.setdefault(str(left), set()).add(str(right))
                equivalent.setdefault(str(right), set()).add(str(left))
            continue
        for named, anonymous in ((left, right), (right, left)):
            if isinstance(named, URIRef) and not isinstance(anonymous, URIRef):
                parts = _named_parts(reader.read(anonymous)) - {str(named)}
                direct.setdefault(str(named), set()).update(parts)
    return direct, equivalent


# -- properties ----------------------------------------------------------------------------


def _property_kinds(graph: Graph) -> dict[str, str]:
    found: dict[str, set[str]] = {}
    for rdf_type, kind in _KIND_BY_TYPE.items():
        for node in graph.subjects(RDF.type, rdf_type):
            if isinstance(node, URIRef):
                found.setdefault(str(node), set()).add(kind)
    for characteristic in _OBJECT_CHARACTERISTICS:
        for node in graph.subjects(RDF.type, characteristic):
            if isinstance(node, URIRef):
                found.setdefault(str(node), set()).add("object")
    for node in graph.subjects(RDF.type, RDF.Property):
        if isinstance(node, URIRef) and str(node) not in found:
            found[str(node)] = {_guess_kind(graph, node)}
    return {
        iri: next(kind for kind in _KIND_PRIORITY if kind in kinds) for iri, kinds in found.items()
    }


def _guess_kind(graph: Graph, node: URIRef) -> str:
    """rdf:Property says nothing about its kind: a literal range makes it a data property."""
    for range_node in graph.objects(node, RDFS.range):
        if isinstance(range_node, URIRef) and (
            str(range_node).startswith(str(XSD)) or range_node == RDFS.Literal
        ):
            return "data"
    return "object"


def _properties(
    graph: Graph, kinds: dict[str, str], reader: _ExpressionReader
) -> dict[str, PropertyInfo]:
    parents: dict[str, set[str]] = {}
    for sub, sup in graph.subject_objects(RDFS.subPropertyOf):
        if isinstance(sub, URIRef) and isinstance(sup, URIRef) and sub != sup:
            parents.setdefault(str(sub), set()).add(str(sup))
    domains = _Inheritance(_own_expressions(graph, RDFS.domain, reader), parents)
    ranges = _Inheritance(_own_expressions(graph, RDFS.range, reader), parents)
    properties: dict[str, PropertyInfo] = {}
    for iri, kind in sorted(kinds.items()):
        own_domains, domain_sources = domains.effective(iri)
        own_ranges, range_sources = ranges.effective(iri)
        properties[iri] = PropertyInfo(
            iri=iri,
            kind=kind,
            domains=own_domains,
            ranges=own_ranges,
            parents=frozenset(parents.get(iri, ())),
            domain_sources=domain_sources,
            range_sources=range_sources,
        )
    return properties


_Effective = Tuple[Tuple[ClassExpr, ...], Tuple[str, ...]]


class _Inheritance:
    """Each property's own expressions (domains, or ranges) plus its super-properties'.

    A property without expressions of its own and with one parent has exactly its
    parent's: the answer is shared, not copied, and found without walking up again, so a
    chain costs linear time and memory. Other properties walk up (``_walk``)."""

    def __init__(self, own: dict[str, tuple[ClassExpr, ...]],
                 parents: dict[str, set[str]]) -> None:
        self._own = own
        self._parents = parents
        self._known: dict[str, _Effective] = {}

    def effective(self, iri: str) -> _Effective:
        pending = [iri]
        while pending:  # iterative: a chain is deeper than the recursion limit
            node = pending[-1]
            if node in self._known:
                pending.pop()
                continue
            above = self._parents.get(node, set())
            if node in self._own or len(above) != 1:
                self._known[node] = self._walk(node)
                pending.pop()
                continue
            parent = next(iter(above))
            if parent in self._known:
                self._known[node] = self._known[parent]
                pending.pop()
            elif parent in pending:  # a cycle of single parents: walk it once
                self._known[node] = self._walk(node)
                pending.pop()
            else:
                pending.append(parent)
        return self._known[iri]

    def _walk(self, iri: str) -> _Effective:
        """Own expressions plus those of every super-property (in a stable order).

        RDFS: ``x P y`` with ``P subPropertyOf Q`` entails ``x Q y``, so ``Q``'s domain and
        range hold for ``P`` too (rdfs7 with rdfs2/rdfs3); like several ``rdfs:domain``,
        all must hold.
        """
        own, parents = self._own, self._parents
        collected: list[ClassExpr] = list(own.get(iri, ()))
        sources: list[str] = [iri] if iri in own else []
        seen = {iri}
        frontier = sorted(parents.get(iri, ()))
        while frontier:
            upper: list[str] = []
            for parent in frontier:
                if parent in seen:
                    continue
                seen.add(parent)
                if parent in own:
                    collected.extend(own[parent])
                    sources.append(parent)
                upper.extend(sorted(parents.get(parent, ())))
            frontier = upper
        return _ordered_unique(collected), tuple(sources)


def _own_expressions(
    graph: Graph, predicate: URIRef, reader: _ExpressionReader
) -> dict[str, tuple[ClassExpr, ...]]:
    found: dict[str, list[ClassExpr]] = {}
    for subject, value in graph.subject_objects(predicate):
        if isinstance(subject, URIRef):
            found.setdefault(str(subject), []).append(reader.read(value))
    return {iri: _ordered_unique(exprs) for iri, exprs in found.items()}


def _ordered_unique(exprs: Iterable[ClassExpr]) -> tuple[ClassExpr, ...]:
    """Duplicates dropped, in a stable order (graph iteration order is arbitrary)."""
    return tuple(sorted(set(exprs), key=lambda e: (not isinstance(e, Named), repr(e))))


# -- prefixes ------------------------------------------------------------------------------


def _derive_prefixes(graphs: Sequence[Graph], entities: set[str]) -> dict[str, str]:
    prefixes: dict[str, str] = {}
    taken_namespaces: set[str] = set()
    for graph in graphs:
        in_file = {str(node) for node in graph.all_nodes() if isinstance(node, URIRef)}
        for namespace in sorted({split_iri(iri)[0] for iri in in_file & entities}):
            if namespace in taken_namespaces:
                continue
            prefix = derive_prefix(namespace)
            if prefix is None or prefix in prefixes:
                continue
            prefixes[prefix] = namespace
            taken_namespaces.add(namespace)
    # `:Name` must always reach SkiROS2's namespace, and messages want `xsd:float`.
    for prefix, namespace in {DEFAULT_PREFIX: SKIROS_NAMESPACE, **WELL_KNOWN_PREFIXES}.items():
        if prefix not in prefixes and namespace not in taken_namespaces:
            prefixes[prefix] = namespace
            taken_namespaces.add(namespace)
    return prefixes


def _compactor(prefixes: dict[str, str]) -> Callable[[str], str]:
    by_namespace = {namespace: prefix for prefix, namespace in prefixes.items()}

    def compact(iri: str) -> str:
        namespace, local = split_iri(iri)
        prefix = by_namespace.get(namespace)
        return f"{prefix}:{local}" if prefix and local else f"<{iri}>"

    return compact


# -- class expressions ---------------------------------------------------------------------


class _ExpressionReader:
    """Reads RDF nodes as class expressions; never raises, whatever the blank node holds."""

    def __init__(self, graph: Graph, compact: Callable[[str], str]) -> None:
        self._graph = graph
        self._compact = compact

    def read(self, node: object, seen: frozenset[object] = frozenset()) -> ClassExpr:
        if isinstance(node, URIRef):
            return Named(str(node))
        if isinstance(node, Literal):
            return Unsupported(f"literal {str(node)!r} (not a class)")
        if not isinstance(node, BNode):
            return Unsupported(f"unexpected node {node!s}")
        if node in seen:
            return Unsupported(f"cyclic {self._describe(node)}")
        seen = seen | {node}
        operators = [p for p in _SET_OPERATORS if (node, p, None) in self._graph]
        if len(operators) != 1 or len(list(self._graph.objects(node, operators[0]))) != 1:
            return Unsupported(self._describe(node))
        operator = operators[0]
        value = self._graph.value(node, operator)
        if operator == OWL.complementOf:
            return ComplementOf(self.read(value, seen))
        items = self._rdf_list(value)
        if items is None:
            return Unsupported(self._describe(node))
        members = tuple(self.read(item, seen) for item in items)
        return UnionOf(members) if operator == OWL.unionOf else IntersectionOf(members)

    def _rdf_list(self, head: object) -> list[object] | None:
        """The items of a well-formed RDF list, else None (so the caller says Unsupported)."""
        items: list[object] = []
        visited: set[object] = set()
        node = head
        while node != RDF.nil:
            if not isinstance(node, BNode) or node in visited:
                return None
            visited.add(node)
            firsts = list(self._graph.objects(node, RDF.first))
            rests = list(self._graph.objects(node, RDF.rest))
            if len(firsts) != 1 or len(rests) != 1:
                return None
            items.append(firsts[0])
            node = rests[0]
        return items

    def _describe(self, node: object) -> str:
        """`anonymous owl:Restriction(owl:onProperty sumo:hasPart, ...)` for messages."""
        if not isinstance(node, BNode):
            return str(node)
        types = sorted(
            self._term(t) for t in self._graph.objects(node, RDF.type) if t not in _CLASS_TYPES
        )
        details = sorted(
            f"{self._term(p)} {self._term(o)}"
            for p, o in self._graph.predicate_objects(node)
            if p != RDF.type
        )
        kind = types[0] if types else "class"
        if not details:
            return f"anonymous {kind} (no description)"
        return f"anonymous {kind}(" + ", ".join(details) + ")"

    def _term(self, term: object) -> str:
        if isinstance(term, URIRef):
            return self._compact(str(term))
        if isinstance(term, Literal):
            return repr(str(term))
        return "[...]"
