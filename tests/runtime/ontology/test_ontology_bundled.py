"""The bundled default vocabulary: complete with respect to SkiROS2's public files.

The names are compared with what plain rdflib reads from ../shared/ontology/skiros2, so a
class or property missing from skiros-core.ttl fails here.
"""

from __future__ import annotations

import pytest
import rdflib
from rdflib.namespace import OWL, RDF, RDFS
from shared_data import REPO, skiros2

from ezskiros_runtime.ontology.expressions import Named
from ezskiros_runtime.ontology.index import OntologyIndex, bundled_ontology_path
from ezskiros_runtime.ontology.load import load_index

SKIROS = "http://rvmi.aau.dk/ontologies/skiros.owl#"
SUMO = "http://www.inf.ufrgs.br/phi-group/ontologies/sumo.owl#"
CORA = "http://www.inf.ufrgs.br/phi-group/ontologies/cora.owl#"
XSD = "http://www.w3.org/2001/XMLSchema#"


@pytest.fixture(scope="module")
def bundled() -> OntologyIndex:
    return load_index(None, cache=False)


@pytest.fixture(scope="module")
def public() -> rdflib.Graph:
    graph = rdflib.Graph()
    for path in sorted(skiros2().rglob("*.owl")):
        graph.parse(str(path), format="xml")
    return graph


def _named(graph: rdflib.Graph, rdf_type: rdflib.URIRef) -> set[str]:
    return {str(s) for s in graph.subjects(RDF.type, rdf_type) if isinstance(s, rdflib.URIRef)}


def _named_pairs(graph: rdflib.Graph, predicate: rdflib.URIRef) -> set[tuple[str, str]]:
    return {
        (str(s), str(o))
        for s, o in graph.subject_objects(predicate)
        if isinstance(s, rdflib.URIRef) and isinstance(o, rdflib.URIRef)
    }


def test_default_is_the_bundled_file(bundled: OntologyIndex) -> None:
    path = bundled_ontology_path()
    assert path.name == "skiros-core.ttl" and path.is_file()
    assert bundled.sources == (str(path.resolve()),)
    assert load_index([], cache=False).fingerprint == bundled.fingerprint


def test_has_every_class_and_property_of_the_public_files(
    bundled: OntologyIndex, public: rdflib.Graph
) -> None:
    public_classes = _named(public, OWL.Class) | {
        iri for pair in _named_pairs(public, RDFS.subClassOf) for iri in pair
    }
    assert bundled.classes == public_classes
    kinds = {iri: info.kind for iri, info in bundled.properties.items()}
    assert {i for i, k in kinds.items() if k == "object"} == _named(public, OWL.ObjectProperty)
    assert {i for i, k in kinds.items() if k == "data"} == _named(public, OWL.DatatypeProperty)


def test_has_the_public_hierarchies_and_datatype_ranges(
    bundled: OntologyIndex, public: rdflib.Graph
) -> None:
    for sub, sup in _named_pairs(public, RDFS.subClassOf):
        assert sup in bundled.direct_superclasses(sub), (sub, sup)
    for sub, sup in _named_pairs(public, RDFS.subPropertyOf):
        info = bundled.property(sub)
        assert info is not None and sup in info.super_properties, (sub, sup)
    for prop, datatype in _named_pairs(public, RDFS.range):
        if datatype.startswith(XSD):
            info = bundled.property(prop)
            assert info is not None and info.ranges == (Named(datatype),), prop


def test_has_a_is_open_in_the_default_and_narrow_only_in_the_paper_fixture(
        bundled: OntologyIndex) -> None:
    """Real skills say ``Robot hasA Gripper``: only the paper's demo ontology forbids it."""
    has_a = bundled.property(SKIROS + "hasA")
    assert has_a is not None
    assert (has_a.domains, has_a.ranges) == ((), ())
    paper = load_index([REPO / "fixtures" / "ontology" / "paper.ttl"], cache=False)
    has_a = paper.property(SKIROS + "hasA")
    assert has_a is not None
    assert has_a.domains == (Named(SKIROS + "Product"),)
    assert has_a.ranges == (Named(SKIROS + "TransformationPose"),)
    assert paper.satisfies(SKIROS + "TransformationPose", has_a.ranges[0]) is True


def test_robot_part_agent_and_state_property(bundled: OntologyIndex) -> None:
    robot_part = bundled.property(CORA + "robotPart")
    assert robot_part is not None
    assert robot_part.domains == (Named(SUMO + "Device"), Named(SUMO + "Object"))  # + sumo:part
    assert robot_part.ranges == (Named(CORA + "Robot"), Named(SUMO + "Object"))
    assert bundled.is_class(SUMO + "Agent")  # type of SkiROS2's automatic Robot parameter
    state = bundled.property(SKIROS + "StateProperty")
    assert state is not None and state.kind == "data"


def test_prefixes_of_the_bundle(bundled: OntologyIndex) -> None:
    assert {"skiros", "sumo", "cora", "corax", "rparts"} <= set(bundled.prefixes)
    assert bundled.expand(":Product") == SKIROS + "Product"


def test_file_says_what_it_is() -> None:
    text = bundled_ontology_path().read_text(encoding="utf-8")
    header = text.split("@prefix", 1)[0]
    assert "SkiROS2" in header and "Nothing is added" in header
    assert "<?xml" not in text and "rdf:RDF" not in text  # Turtle, not copied OWL
