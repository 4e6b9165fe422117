"""The index of SkiROS2's public OWL files (read from ../shared, never copied).

Expected facts are either stated by the brief and the shared README (counts, domains,
ranges) or read from the files with plain rdflib here, independently of the index code.
"""

from __future__ import annotations

from pathlib import Path

import pytest
import rdflib
from rdflib.namespace import RDFS
from shared_data import skiros2

from ezskiros_runtime.ontology.expressions import ComplementOf, IntersectionOf, Named
from ezskiros_runtime.ontology.index import OntologyIndex
from ezskiros_runtime.ontology.load import load_index

SKIROS = "http://rvmi.aau.dk/ontologies/skiros.owl#"
SUMO = "http://www.inf.ufrgs.br/phi-group/ontologies/sumo.owl#"
CORA = "http://www.inf.ufrgs.br/phi-group/ontologies/cora.owl#"
CORAX = "http://www.inf.ufrgs.br/phi-group/ontologies/coraX.owl#"
RPARTS = "http://www.inf.ufrgs.br/phi-group/ontologies/RParts.owl#"
XSD = "http://www.w3.org/2001/XMLSchema#"


@pytest.fixture(scope="module")
def real() -> OntologyIndex:
    return load_index([skiros2()], cache=False)


@pytest.fixture(scope="module")
def raw_graph() -> rdflib.Graph:
    graph = rdflib.Graph()
    for path in sorted(skiros2().rglob("*.owl")):
        graph.parse(str(path), format="xml")
    return graph


def test_counts_match_the_files(real: OntologyIndex) -> None:
    kinds = [p.kind for p in real.properties.values()]
    assert len(real.classes) == 93  # 100 owl:Class nodes, 7 of them anonymous
    assert kinds.count("object") == 44
    assert kinds.count("data") == 69
    assert kinds.count("annotation") == 0


def test_folder_loads_the_six_owl_files_and_skips_the_readme(real: OntologyIndex) -> None:
    names = sorted(Path(s).name for s in real.sources)
    assert names == [
        "RParts.owl",
        "cora.owl",
        "coraX.owl",
        "skiros.owl",
        "skirosExtra.owl",
        "sumo.owl",
    ]


def test_prefixes_are_derived_like_skiros2(real: OntologyIndex) -> None:
    assert real.prefixes["skiros"] == SKIROS
    assert real.prefixes["cora"] == CORA
    assert real.prefixes["corax"] == CORAX  # coraX.owl, lower-cased
    assert real.prefixes["rparts"] == RPARTS
    assert real.prefixes["sumo"] == SUMO
    assert "coraX" not in real.prefixes
    assert real.default_prefix == "skiros"


def test_robot_part_domain_and_range(real: OntologyIndex) -> None:
    robot_part = real.property(CORA + "robotPart")
    assert robot_part is not None
    assert robot_part.kind == "object"
    assert robot_part.domains == (Named(SUMO + "Device"), Named(SUMO + "Object"))  # + sumo:part
    assert robot_part.ranges == (Named(CORA + "Robot"), Named(SUMO + "Object"))
    assert robot_part.super_properties == {SUMO + "part"}


def test_datatype_ranges(real: OntologyIndex) -> None:
    position_x = real.property(SKIROS + "PositionX")
    publish_tf = real.property(SKIROS + "PublishTf")
    assert position_x is not None and publish_tf is not None
    assert position_x.kind == "data"
    assert position_x.ranges == (Named(XSD + "float"),)
    assert publish_tf.ranges == (Named(XSD + "boolean"),)
    assert position_x.super_properties == {
        SKIROS + "Position",
        SKIROS + "TransformationProperty",
        SKIROS + "PhysicalObjectProperty",
    }


def test_skiros_relations_have_no_domain_or_range(real: OntologyIndex) -> None:
    # As the shared README says: the public files leave contain/hasA open.
    for name in ("contain", "hasA", "at"):
        info = real.property(SKIROS + name)
        assert info is not None
        assert (info.domains, info.ranges) == ((), ())


def test_subclass_closure_follows_the_files(real: OntologyIndex, raw_graph: rdflib.Graph) -> None:
    gripper = rdflib.URIRef(RPARTS + "GripperEffector")
    expected = {
        str(node)
        for node in raw_graph.transitive_objects(gripper, RDFS.subClassOf)
        if isinstance(node, rdflib.URIRef)
    }
    assert expected >= {RPARTS + "EndEffector", SUMO + "Device", SUMO + "Entity"}
    assert real.superclasses(RPARTS + "GripperEffector") == expected
    assert real.is_subclass(RPARTS + "GripperEffector", SUMO + "Device")
    assert not real.is_subclass(SUMO + "Device", RPARTS + "GripperEffector")
    assert real.is_subclass(CORA + "Robot", SUMO + "Agent")


def test_every_named_superclass_in_the_files_is_in_the_closure(
    real: OntologyIndex, raw_graph: rdflib.Graph
) -> None:
    for sub, sup in raw_graph.subject_objects(RDFS.subClassOf):
        if isinstance(sub, rdflib.URIRef) and isinstance(sup, rdflib.URIRef):
            assert real.is_subclass(str(sub), str(sup)), (sub, sup)


def test_intersection_superclass_and_equivalence(real: OntologyIndex) -> None:
    # sumo:Group ⊑ (sumo:Agent ⊓ sumo:Collection) in sumo.owl.
    assert real.is_subclass(SUMO + "Group", SUMO + "Agent")
    assert real.is_subclass(SUMO + "Group", SUMO + "Collection")
    assert real.direct_superclasses(SUMO + "Group") == {SUMO + "Agent", SUMO + "Collection"}
    # skiros:Scene ≡ corax:PhysicalEnvironment in skiros.owl: both directions.
    assert real.is_subclass(SKIROS + "Scene", CORAX + "PhysicalEnvironment")
    assert real.is_subclass(CORAX + "PhysicalEnvironment", SKIROS + "Scene")
    assert CORAX + "PhysicalEnvironment" not in real.direct_superclasses(SKIROS + "Scene")


def test_sub_property_inherits_domain_and_range(real: OntologyIndex) -> None:
    # cora:automatedRobot declares nothing; cora:robotprocesslink has Robot -> Process, and
    # its own parent sumo:agent Process -> Agent. RDFS entails all of them (rdfs7 + rdfs2/3),
    # all must hold; that the IEEE files declare robotprocesslink against sumo:agent's
    # direction shows here, and no skill condition we know of uses either. Stable order.
    info = real.property(CORA + "automatedRobot")
    assert info is not None
    assert info.domains == (Named(CORA + "Robot"), Named(SUMO + "Process"))
    assert info.ranges == (Named(SUMO + "Agent"), Named(SUMO + "Process"))
    assert info.domain_sources == (CORA + "robotprocesslink", SUMO + "agent")
    assert info.super_properties == {CORA + "robotprocesslink", SUMO + "agent", SUMO + "CaseRole"}


def test_anonymous_domain_of_sumo_member(real: OntologyIndex) -> None:
    member = real.property(SUMO + "member")
    assert member is not None
    domain = IntersectionOf((Named(SUMO + "Object"), ComplementOf(Named(SUMO + "Collection"))))
    assert member.domains == (domain,)
    assert real.satisfies(SUMO + "Agent", domain) is True
    assert real.satisfies(SUMO + "Group", domain) is False  # a Group is a Collection
    assert real.satisfies(SKIROS + "Skill", domain) is False  # not an Object
    assert real.render(domain) == "(sumo:Object & ~sumo:Collection)"


def test_paper_check_on_real_hierarchy(real: OntologyIndex) -> None:
    pose = Named(SKIROS + "TransformationPose")
    assert real.satisfies(RPARTS + "GripperEffector", pose) is False
    assert real.satisfies(SKIROS + "GraspingPose", pose) is True
    assert real.satisfies(SKIROS + "NoSuchClass", pose) is None
