"""Prefixed names: expand, compact, lookups by local name, and "did you mean"."""

from __future__ import annotations

from pathlib import Path

import pytest

from ezskiros_runtime.ontology.index import OntologyIndex
from ezskiros_runtime.ontology.load import load_index
from ezskiros_runtime.ontology.naming import derive_prefix, split_iri
from ezskiros_runtime.ontology.suggest import closest_names

REPO = Path(__file__).resolve().parents[3]
FIXTURES = REPO / "fixtures" / "ontology"

SKIROS = "http://rvmi.aau.dk/ontologies/skiros.owl#"
CORA = "http://www.inf.ufrgs.br/phi-group/ontologies/cora.owl#"
XSD = "http://www.w3.org/2001/XMLSchema#"


@pytest.fixture(scope="module")
def paper() -> OntologyIndex:
    return load_index([FIXTURES / "paper.ttl"], cache=False)


@pytest.mark.parametrize(
    ("namespace", "prefix"),
    [
        ("http://rvmi.aau.dk/ontologies/skiros.owl#", "skiros"),
        ("http://www.inf.ufrgs.br/phi-group/ontologies/coraX.owl#", "corax"),
        ("http://www.inf.ufrgs.br/phi-group/ontologies/RParts.owl#", "rparts"),
        ("http://example.org/onto/Workcell/", "workcell"),
        ("http://example.org/my.onto.ttl#", "my.onto"),
        ("urn:example:Gear#", "gear"),
        ("http://#", None),
    ],
)
def test_derive_prefix(namespace: str, prefix: str | None) -> None:
    assert derive_prefix(namespace) == prefix


def test_split_iri() -> None:
    assert split_iri(SKIROS + "Product") == (SKIROS, "Product")
    assert split_iri("http://example.org/a/b") == ("http://example.org/a/", "b")
    assert split_iri("http://example.org/a#b/c") == ("http://example.org/a#", "b/c")
    assert split_iri("Product") == ("", "Product")


@pytest.mark.parametrize("name", ["skiros:Product", ":Product", "Product", " skiros:Product "])
def test_expand_default_prefix_forms(paper: OntologyIndex, name: str) -> None:
    assert paper.expand(name) == SKIROS + "Product"


def test_expand_other_cases(paper: OntologyIndex) -> None:
    assert paper.expand("cora:Robot") == CORA + "Robot"
    assert paper.expand("nope:Robot") is None
    assert paper.expand("coraX:Robot") is None  # SkiROS2 only knows `corax`
    assert paper.expand("skiros:NotDefined") == SKIROS + "NotDefined"  # no existence check
    assert paper.expand(CORA + "Robot") == CORA + "Robot"
    assert paper.expand(f"<{CORA}Robot>") == CORA + "Robot"
    assert paper.expand("") is None
    assert paper.expand("skiros:") is None


def test_compact(paper: OntologyIndex) -> None:
    assert paper.compact(SKIROS + "Product") == "skiros:Product"  # never the bare `:` form
    assert paper.compact(CORA + "Robot") == "cora:Robot"
    assert paper.compact(XSD + "float") == "xsd:float"
    assert paper.compact("http://elsewhere.org/x#Y") == "http://elsewhere.org/x#Y"
    for name in ("skiros:hasA", "cora:robotPart", "rparts:GripperEffector"):
        expanded = paper.expand(name)
        assert expanded is not None and paper.compact(expanded) == name


def test_skiros_prefix_exists_even_without_skiros_files() -> None:
    index = load_index([FIXTURES / "inheritance.ttl"], cache=False)
    assert index.expand(":Product") == SKIROS + "Product"
    assert index.prefixes["workcell"] == "http://example.org/ontologies/workcell.owl#"


def test_first_file_keeps_a_contested_prefix(tmp_path: Path) -> None:
    first = tmp_path / "a.ttl"
    second = tmp_path / "b.ttl"
    first.write_text("<http://one.org/parts.owl#Gear> a <http://www.w3.org/2002/07/owl#Class> .\n")
    second.write_text("<http://two.org/parts.owl#Axle> a <http://www.w3.org/2002/07/owl#Class> .\n")
    index = load_index([first, second], cache=False)
    assert index.prefixes["parts"] == "http://one.org/parts.owl#"
    assert index.compact("http://two.org/parts.owl#Axle") == "http://two.org/parts.owl#Axle"
    swapped = load_index([second, first], cache=False)
    assert swapped.prefixes["parts"] == "http://two.org/parts.owl#"


def test_lookups_by_local_name(tmp_path: Path) -> None:
    extra = tmp_path / "other.ttl"
    extra.write_text(
        "@prefix owl: <http://www.w3.org/2002/07/owl#> .\n"
        "<http://example.org/lab.owl#contain> a owl:ObjectProperty .\n"
        "<http://example.org/lab.owl#Robot> a owl:Class .\n"
    )
    index = load_index([FIXTURES / "paper.ttl", extra], cache=False)
    assert index.properties_named("contain") == [
        "http://example.org/lab.owl#contain",
        SKIROS + "contain",
    ]
    assert index.properties_named("hasA") == [SKIROS + "hasA"]
    assert index.properties_named("Open") == []
    assert index.classes_named("Robot") == ["http://example.org/lab.owl#Robot", CORA + "Robot"]
    assert index.classes_named("contain") == []


def test_local_names_of_a_prefix(paper: OntologyIndex) -> None:
    assert paper.local_names("cora") == ["Robot", "robotPart"]
    assert paper.local_names("nope") == []


@pytest.mark.parametrize(
    ("typo", "kinds", "best"),
    [
        ("GrASPingPose", ("class",), "skiros:GraspingPose"),
        ("skiros:GrASPingPose", ("class", "object", "data"), "skiros:GraspingPose"),
        ("conatin", ("object",), "skiros:contain"),
        ("conatin", ("class", "object", "data"), "skiros:contain"),
        (":hasa", ("object",), "skiros:hasA"),
        ("skirso:Product", ("class",), "skiros:Product"),
        ("coraX:Robot", ("class",), "cora:Robot"),
        ("GripperEfector", ("class",), "rparts:GripperEffector"),
        ("PositonX", ("data",), "skiros:PositionX"),
    ],
)
def test_suggestions(paper: OntologyIndex, typo: str, kinds: tuple[str, ...], best: str) -> None:
    suggestions = paper.suggest(typo, kinds=kinds)
    assert suggestions and suggestions[0] == best, suggestions


def test_suggestions_respect_kinds_and_limit(paper: OntologyIndex) -> None:
    assert paper.suggest("robot", limit=5) == ["cora:Robot", "cora:robotPart"]
    assert paper.suggest("robot", limit=1) == ["cora:Robot"]
    assert paper.suggest("robot", kinds=("object",)) == ["cora:robotPart"]
    assert paper.suggest("xyzzy") == []
    assert paper.suggest("conatin", kinds=("data",)) == []
    with pytest.raises(ValueError, match="unknown name kinds"):
        paper.suggest("x", kinds=("klass",))


def test_closest_names_never_suggests_the_name_itself() -> None:
    assert closest_names("skiros:Product", ["skiros:Product", "skiros:Products"]) == [
        "skiros:Products"
    ]
    assert closest_names("x", ["a", "b"], limit=0) == []


@pytest.mark.parametrize(("a", "b", "apart"), [
    ("Location", "Lcoation", True),   # two neighbours swapped
    ("Location", "Locaton", True),    # one dropped
    ("Location", "Locattion", True),  # one doubled
    ("Location", "Lokation", True),   # one changed
    ("Location", "Location", False),  # the same name is no typo
    ("Location", "Lcoaiton", False),  # two edits
    ("Product", "Location", False),
])
def test_one_edit_apart_is_the_typos_a_hand_makes(a: str, b: str, apart: bool) -> None:
    from ezskiros_runtime.ontology.suggest import one_edit_apart

    assert one_edit_apart(a, b) is apart
    assert one_edit_apart(b, a) is apart


def test_a_misspelt_term_is_matched_within_its_own_prefix() -> None:
    from ezskiros_runtime.ontology.suggest import misspelt_term

    classes = ["skiros:Location", "rparts:Locator"]
    assert misspelt_term("skiros:Lcoation", classes) == "skiros:Location"
    assert misspelt_term("cora:Lcoation", classes) is None
    assert misspelt_term("skiros:Location", classes) is None
