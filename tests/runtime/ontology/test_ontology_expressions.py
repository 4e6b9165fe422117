"""Anonymous classes in domains and ranges, `satisfies`, and sub-property inheritance."""

from __future__ import annotations

import pickle
from pathlib import Path

import pytest

from ezskiros_runtime.ontology.expressions import (
    ComplementOf,
    IntersectionOf,
    Named,
    UnionOf,
    Unsupported,
)
from ezskiros_runtime.ontology.index import OntologyIndex, PropertyInfo
from ezskiros_runtime.ontology.load import load_index

REPO = Path(__file__).resolve().parents[3]
FIXTURES = REPO / "fixtures" / "ontology"

EX = "http://example.org/ontologies/shapes.owl#"
WC = "http://example.org/ontologies/workcell.owl#"
XSD = "http://www.w3.org/2001/XMLSchema#"
SKIROS = "http://rvmi.aau.dk/ontologies/skiros.owl#"
RPARTS = "http://www.inf.ufrgs.br/phi-group/ontologies/RParts.owl#"
CORA = "http://www.inf.ufrgs.br/phi-group/ontologies/cora.owl#"


@pytest.fixture(scope="module")
def shapes() -> OntologyIndex:
    return load_index([FIXTURES / "expressions.ttl"], cache=False)


@pytest.fixture(scope="module")
def workcell() -> OntologyIndex:
    return load_index([FIXTURES / "inheritance.ttl"], cache=False)


@pytest.fixture(scope="module")
def paper() -> OntologyIndex:
    return load_index([FIXTURES / "paper.ttl"], cache=False)


def _prop(index: OntologyIndex, iri: str) -> PropertyInfo:
    info = index.property(iri)
    assert info is not None, iri
    return info


def _only_range(index: OntologyIndex, iri: str):  # type: ignore[no-untyped-def]
    ranges = _prop(index, iri).ranges
    assert len(ranges) == 1, ranges
    return ranges[0]


def test_union_intersection_complement_are_read(shapes: OntologyIndex) -> None:
    assert _only_range(shapes, EX + "roundOrRed") == UnionOf(
        (Named(EX + "Round"), Named(EX + "Red"))
    )
    assert _prop(shapes, EX + "roundAndRed").domains == (
        IntersectionOf((Named(EX + "Round"), Named(EX + "Red"))),
    )
    assert _only_range(shapes, EX + "notRound") == ComplementOf(Named(EX + "Round"))
    assert _only_range(shapes, EX + "nested") == UnionOf(
        (IntersectionOf((Named(EX + "Round"), Named(EX + "Red"))), Named(EX + "Cube"))
    )
    assert _prop(shapes, EX + "twoRanges").ranges == (Named(EX + "Red"), Named(EX + "Round"))


@pytest.mark.parametrize(
    ("prop", "cls", "expected"),
    [
        ("roundOrRed", "Wheel", True),
        ("roundOrRed", "Brick", True),
        ("roundOrRed", "Cube", False),
        ("notRound", "Cube", True),
        ("notRound", "Ball", False),
        ("nested", "Ball", True),  # Round and Red
        ("nested", "Cube", True),
        ("nested", "Wheel", False),  # Round but not Red, not a Cube
        ("nested", "Cherry", True),  # subclass of an anonymous Round ⊓ Red
    ],
)
def test_satisfies_ranges(shapes: OntologyIndex, prop: str, cls: str, expected: bool) -> None:
    assert shapes.satisfies(EX + cls, _only_range(shapes, EX + prop)) is expected


@pytest.mark.parametrize(("cls", "expected"), [("Ball", True), ("Wheel", False), ("Brick", False)])
def test_satisfies_intersection_domain(shapes: OntologyIndex, cls: str, expected: bool) -> None:
    (domain,) = _prop(shapes, EX + "roundAndRed").domains
    assert shapes.satisfies(EX + cls, domain) is expected


@pytest.mark.parametrize(
    "prop",
    ["restricted", "enumerated", "notAList", "twoOperators", "empty", "literal", "cyclicList"],
)
def test_odd_blank_nodes_are_unsupported_and_undecidable(shapes: OntologyIndex, prop: str) -> None:
    expr = _only_range(shapes, EX + prop)
    assert isinstance(expr, Unsupported)
    assert expr.text  # something to show in a message
    assert shapes.satisfies(EX + "Ball", expr) is None


def test_unsupported_text_describes_the_node(shapes: OntologyIndex) -> None:
    expr = _only_range(shapes, EX + "restricted")
    assert isinstance(expr, Unsupported)
    assert "owl:Restriction" in expr.text and "shapes:nested" in expr.text


def test_three_valued_logic_with_unsupported_members(shapes: OntologyIndex) -> None:
    mixed = _only_range(shapes, EX + "unionWithRestriction")
    assert isinstance(mixed, UnionOf) and isinstance(mixed.members[1], Unsupported)
    assert shapes.satisfies(EX + "Cube", mixed) is True  # one known member suffices
    assert shapes.satisfies(EX + "Ball", mixed) is None  # cannot rule the restriction out
    unknown = Unsupported("?")
    assert shapes.satisfies(EX + "Ball", IntersectionOf((Named(EX + "Cube"), unknown))) is False
    assert shapes.satisfies(EX + "Ball", IntersectionOf((Named(EX + "Red"), unknown))) is None
    assert shapes.satisfies(EX + "Ball", ComplementOf(unknown)) is None


def test_unknown_classes_are_undecidable(shapes: OntologyIndex) -> None:
    assert shapes.satisfies(EX + "Ball", _only_range(shapes, EX + "undeclared")) is None
    assert shapes.satisfies(EX + "Nope", Named(EX + "Shape")) is None
    thing = Named("http://www.w3.org/2002/07/owl#Thing")
    assert shapes.satisfies(EX + "Ball", thing) is True


def test_data_ranges_and_untyped_properties(shapes: OntologyIndex) -> None:
    assert _prop(shapes, EX + "size").kind == "data"
    assert _only_range(shapes, EX + "size") == UnionOf((Named(XSD + "int"), Named(XSD + "float")))
    assert isinstance(_only_range(shapes, EX + "colourName"), Unsupported)
    assert _prop(shapes, EX + "label").kind == "data"  # rdf:Property with an xsd range
    assert _prop(shapes, EX + "touches").kind == "object"
    assert _prop(shapes, EX + "note").kind == "annotation"


def test_paper_union_domain(paper: OntologyIndex) -> None:
    contain = _prop(paper, SKIROS + "contain")
    (domain,) = contain.domains
    assert domain == UnionOf((Named(SKIROS + "Location"), Named(RPARTS + "GripperEffector")))
    assert paper.satisfies(RPARTS + "GripperEffector", domain) is True
    assert paper.satisfies(SKIROS + "GraspingPose", domain) is True  # a pose is a Location
    assert paper.satisfies(CORA + "Robot", domain) is False
    (has_a_range,) = _prop(paper, SKIROS + "hasA").ranges
    assert paper.satisfies(RPARTS + "GripperEffector", has_a_range) is False
    assert paper.render(domain) == "(skiros:Location | rparts:GripperEffector)"


# -- sub-property inheritance ----------------------------------------------------------------


def test_inherits_domain_and_range_when_declaring_none(workcell: OntologyIndex) -> None:
    near = _prop(workcell, WC + "near")
    assert near.domains == (Named(WC + "Station"),)
    assert near.ranges == (Named(WC + "Part"),)
    assert near.domain_sources == (WC + "related",)


def test_inherits_through_two_levels(workcell: OntologyIndex) -> None:
    touches = _prop(workcell, WC + "touches")
    assert touches.super_properties == {WC + "near", WC + "related"}
    assert touches.domains == (Named(WC + "Station"),)
    assert touches.ranges == (Named(WC + "Part"),)


def test_own_domain_adds_to_the_inherited_ones(workcell: OntologyIndex) -> None:
    """RDFS: ``x holds y`` entails ``x related y``, so related's domain binds holds too."""
    holds = _prop(workcell, WC + "holds")
    related = _prop(workcell, WC + "related")
    assert holds.domains == (Named(WC + "Hand"), *related.domains)
    assert holds.domain_sources == (WC + "holds", WC + "related")
    assert holds.ranges == (Named(WC + "Part"),)


def test_inherits_from_every_annotated_parent(workcell: OntologyIndex) -> None:
    uses = _prop(workcell, WC + "uses")
    assert set(uses.domains) == {Named(WC + "Station"), Named(WC + "Tool")}
    assert set(uses.domain_sources) == {WC + "related", WC + "operatedBy"}
    assert uses.ranges == (Named(WC + "Part"),)


def test_property_cycles_terminate(workcell: OntologyIndex) -> None:
    loop_a = _prop(workcell, WC + "loopA")
    assert loop_a.super_properties == {WC + "loopB"}  # excluding itself
    assert loop_a.domains == ()


def test_datatype_range_is_inherited(workcell: OntologyIndex) -> None:
    width = _prop(workcell, WC + "width")
    assert width.kind == "data"
    assert width.ranges == (Named(XSD + "float"),)


def test_index_is_plain_picklable_data(shapes: OntologyIndex) -> None:
    copy = pickle.loads(pickle.dumps(shapes))
    assert copy.properties == shapes.properties
    assert copy.classes == shapes.classes
    assert copy.superclasses(EX + "Cherry") == shapes.superclasses(EX + "Cherry")
    modules = {type(v).__module__ for v in _walk(copy.__dict__)}
    assert not any(m.startswith("rdflib") for m in modules), modules


def _walk(value: object) -> list[object]:
    found: list[object] = [value]
    if isinstance(value, dict):
        for key, item in value.items():
            found += _walk(key) + _walk(item)
    elif isinstance(value, (list, tuple, set, frozenset)):
        for item in value:
            found += _walk(item)
    elif hasattr(value, "__dataclass_fields__"):
        for name in value.__dataclass_fields__:
            found += _walk(getattr(value, name))
    return found
