"""The bundled default vocabulary states the facts of the real SkiROS2 core, and no more.

Loads the bundled Turtle file and the public SkiROS2 OWL files (``../shared/ontology/
skiros2``, RDF/XML) with rdflib and compares, fact by fact: the named classes, the
subclass closure between them, and for every property its kind, domains, ranges and
super-properties. An axiom of our own (such as the EzSkiROS paper's domain and range of
``skiros:hasA``, which lives in ``fixtures/ontology/paper.ttl``) makes it fail: the default
must never reject a skill that SkiROS2 loads.
"""

from __future__ import annotations

from rdflib import OWL, RDF, RDFS, BNode, Graph, URIRef
from shared_data import skiros2

from ezskiros_runtime.ontology.index import bundled_ontology_path


def _real() -> Graph:
    graph = Graph()
    for path in sorted(skiros2().rglob("*.owl")):
        graph.parse(str(path), format="xml")
    return graph


def _bundled() -> Graph:
    return Graph().parse(str(bundled_ontology_path()), format="turtle")


def _classes(graph: Graph) -> set[URIRef]:
    return {c for c in graph.subjects(RDF.type, OWL.Class) if isinstance(c, URIRef)}


def _closure(graph: Graph) -> set[tuple[URIRef, URIRef]]:
    """Every (sub, super) pair between named classes, transitively."""
    direct: dict[URIRef, set[URIRef]] = {}
    for sub, sup in graph.subject_objects(RDFS.subClassOf):
        if isinstance(sub, URIRef) and isinstance(sup, URIRef):
            direct.setdefault(sub, set()).add(sup)
    pairs = set()
    for start in direct:
        todo, seen = list(direct[start]), set()
        while todo:
            node = todo.pop()
            if node not in seen:
                seen.add(node)
                todo.extend(direct.get(node, ()))
        pairs |= {(start, sup) for sup in seen}
    return pairs


def _named(graph: Graph, subject: URIRef, predicate: URIRef) -> frozenset[str]:
    """Named objects as IRIs; an anonymous class (``owl:unionOf``) by its members."""
    found = set()
    for value in graph.objects(subject, predicate):
        if isinstance(value, BNode):
            members = graph.value(value, OWL.unionOf)
            items = sorted(str(m) for m in graph.items(members)) if members else ["?"]
            found.add("union(" + ",".join(items) + ")")
        else:
            found.add(str(value))
    return frozenset(found)


def _properties(graph: Graph) -> dict[str, tuple[str, frozenset[str], ...]]:
    facts = {}
    for kind in (OWL.ObjectProperty, OWL.DatatypeProperty):
        for prop in graph.subjects(RDF.type, kind):
            if isinstance(prop, URIRef):
                facts[str(prop)] = (str(kind), _named(graph, prop, RDFS.domain),
                                    _named(graph, prop, RDFS.range),
                                    _named(graph, prop, RDFS.subPropertyOf))
    return facts


def test_the_same_classes():
    real, bundled = _classes(_real()), _classes(_bundled())
    assert sorted(real - bundled) == [], "classes of the core missing from the default"
    assert sorted(bundled - real) == [], "classes the core does not have"


def test_the_same_subclass_closure():
    real, bundled = _closure(_real()), _closure(_bundled())
    assert sorted(real - bundled) == []
    assert sorted(bundled - real) == []


def test_the_same_properties_with_the_same_domains_ranges_and_parents():
    real, bundled = _properties(_real()), _properties(_bundled())
    assert sorted(set(real) ^ set(bundled)) == []
    differing = {name: (real[name], bundled[name]) for name in real
                 if real[name] != bundled[name]}
    assert differing == {}


def test_has_a_is_left_open_as_in_the_core():
    """The paper's axiom rejected about 7% of real skills (``Robot hasA Gripper``)."""
    has_a = URIRef("http://rvmi.aau.dk/ontologies/skiros.owl#hasA")
    bundled = _bundled()
    assert list(bundled.objects(has_a, RDFS.domain)) == []
    assert list(bundled.objects(has_a, RDFS.range)) == []
