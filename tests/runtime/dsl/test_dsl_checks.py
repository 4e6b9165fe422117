"""The early checks: one test per check, asserting the finding's fields and message, plus
the policy around them (findings as data, warnings, strict mode, per-kind severity)."""

from __future__ import annotations

import os
import warnings
from pathlib import Path

import pytest
from dsl_support import PAPER, line_of, paper  # noqa: F401 - paper is a fixture
from shared_data import skiros2

from ezskiros_runtime import (
    ELEMENT,
    INFERRED,
    REQUIRED,
    EzSkirosWarning,
    Finding,
    Lock,
    SkillDescription,
    SkillTypeError,
    check,
    is_strict,
    set_severity,
    strict,
)
from ezskiros_runtime.ontology import active_index, rparts, skiros, use_ontology

pytestmark = pytest.mark.usefixtures("paper")
HERE = Path(__file__)


def only(cls: type) -> Finding:
    """The single finding ``check`` reports for ``cls``."""
    (finding,) = check(cls)
    return finding


def test_unknown_class_in_a_verbatim_element_type_warns_with_a_suggestion():
    class Skill(SkillDescription):
        def description(self, Box: ELEMENT("skiros:Prodcut")):
            pass

    finding = only(Skill)
    assert (finding.kind, finding.severity, finding.param) == ("unknown-vocabulary", "warning",
                                                               "Box")
    assert finding.message == ("parameter Box: class skiros:Prodcut is not in the loaded "
                               "ontology (did you mean skiros:Product?)")
    assert finding.line == line_of('Box: ELEMENT("skiros:Prodcut")', HERE)
    assert finding.suggestions[0] == "skiros:Product"


def test_unknown_prefix_is_named_as_such():
    class Skill(SkillDescription):
        def description(self, Arm: ELEMENT("scalable:Ur5")):
            pass

    finding = only(Skill)
    assert finding.message == ("parameter Arm: class scalable:Ur5: prefix 'scalable' is not "
                               "defined by the loaded ontology")
    # the lab's ontology may just not be loaded here: info, silent on the robot, not raised
    # under strict (issue 28, part 4)
    assert finding.severity == "info"
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with strict():
            assert [f.severity for f in Skill().findings] == ["info"]


def test_unknown_relation_name_falls_back_to_the_default_prefix_and_warns():
    class Skill(SkillDescription):
        def description(self, A: skiros.Location, B: skiros.Product):
            self.pre_conditions += A.contian(B)

    with pytest.warns(EzSkirosWarning) as caught:
        built = Skill()
    assert built._pre_conditions[0].relation == "skiros:contian"
    (finding,) = built.findings
    assert finding.message == ("A.contian: no object or datatype property named 'contian' in "
                               "the loaded ontology; lowered as skiros:contian (did you mean "
                               "skiros:contain?)")
    line = line_of("A.contian(B)", HERE)
    assert (finding.kind, finding.line, finding.relation) == ("unknown-vocabulary", line,
                                                              "skiros:contian")
    assert [(Path(w.filename).name, w.lineno) for w in caught] == [(HERE.name, line)]
    assert str(caught[0].message).startswith("Skill: A.contian: no object or datatype")


def test_unknown_verbatim_relation_warns_with_a_suggestion():
    class Skill(SkillDescription):
        def description(self, G: rparts.GripperEffector, R: ELEMENT("cora:Robot")):
            self.pre_conditions += G.relation("cora:robotPrt", R)

    finding = only(Skill)
    assert finding.message == ("relation cora:robotPrt is not in the loaded ontology (did you "
                               "mean cora:robotPart?)")


@pytest.mark.parametrize(("condition", "start"), [
    ("A.has(skiros.Product)", "property skiros:Product: skiros:Product is a class in the "
                              "loaded ontology, not a property"),
    ('A.relation("skiros:Location", A)', "relation skiros:Location: skiros:Location is a class"),
    ("A.is_a(skiros.contain)", "class skiros:contain: skiros:contain is an object property"),
    ('A.has("skiros:PublishTf")', None),  # a datatype property: right where it is
])
def test_vocabulary_of_the_wrong_kind_says_what_it_is(condition, start):
    namespace: dict[str, object] = {"skiros": skiros}
    exec(f"def build(A):\n    return {condition}\n", namespace)

    class Skill(SkillDescription):
        def description(self, A: skiros.Location):
            self.pre_conditions += namespace["build"](A)

    found = check(Skill)
    if start is None:
        assert found == []
        return
    assert (found[0].kind, found[0].severity) == ("unknown-vocabulary", "warning")
    assert found[0].message.startswith(start)


def test_a_local_name_two_prefixes_define_is_an_error_pointing_to_the_verbatim_form(tmp_path):
    extra = tmp_path / "extra.ttl"
    extra.write_text(
        "@prefix owl: <http://www.w3.org/2002/07/owl#> .\n"
        "@prefix skiros: <http://rvmi.aau.dk/ontologies/skiros.owl#> .\n"
        "skiros:robotPart a owl:ObjectProperty .\n")
    use_ontology([PAPER, extra])

    class Skill(SkillDescription):
        def description(self, G: rparts.GripperEffector, R: ELEMENT("cora:Robot")):
            self.pre_conditions += G.robotPart(R)

    finding = only(Skill)
    assert (finding.kind, finding.severity) == ("ambiguous-vocabulary", "error")
    assert finding.message == (
        "G.robotPart: 'robotPart' is defined under several prefixes (cora:robotPart, "
        'skiros:robotPart); write G.relation("cora:robotPart", ...) or '
        'G.relation("skiros:robotPart", ...)')


def test_relation_domain_violation_names_subject_union_and_actual_class():
    class Skill(SkillDescription):
        def description(self, B: skiros.Product, Pose: skiros.GraspingPose):
            self.pre_conditions += B.contain(Pose)

    with pytest.raises(SkillTypeError) as raised:
        Skill()
    (finding,) = raised.value.findings
    assert finding.message == ("skiros:contain expects subject of class (skiros:Location | "
                               "rparts:GripperEffector), but parameter B is skiros:Product")
    assert (finding.kind, finding.param, finding.actual) == ("domain", "B", "skiros:Product")
    assert finding.expected == "(skiros:Location | rparts:GripperEffector)"


def test_subclass_closure_union_and_the_automatic_robot_are_used():
    class Fine(SkillDescription):
        def description(self, P: skiros.Product, Pose: skiros.GraspingPose,
                        G: rparts.GripperEffector):
            self.pre_conditions += P.hasA(Pose)     # GraspingPose below TransformationPose
            self.pre_conditions += G.contain(Pose)  # union domain and union range

    assert check(Fine) == []

    class RobotOnly(SkillDescription):
        def description(self, P: skiros.Product):
            self.pre_conditions += self.param("Robot").hasA(P)

    assert [(f.kind, f.param, f.actual) for f in check(RobotOnly)] == [
        ("domain", "Robot", "sumo:Agent"), ("range", "P", "skiros:Product")]


def test_sub_properties_inherit_domain_and_range(tmp_path):
    extra = tmp_path / "holds.ttl"
    extra.write_text(
        "@prefix owl: <http://www.w3.org/2002/07/owl#> .\n"
        "@prefix rdfs: <http://www.w3.org/2000/01/rdf-schema#> .\n"
        "@prefix skiros: <http://rvmi.aau.dk/ontologies/skiros.owl#> .\n"
        "skiros:holdsPose a owl:ObjectProperty ; rdfs:subPropertyOf skiros:hasA .\n")
    use_ontology([PAPER, extra])

    class Skill(SkillDescription):
        def description(self, P: skiros.Product, L: skiros.Product):
            self.pre_conditions += P.holdsPose(L)

    finding = only(Skill)
    assert finding.message == ("skiros:holdsPose expects object of class "
                               "skiros:TransformationPose, but parameter L is skiros:Product")


def test_a_wider_class_is_advice_a_disjoint_one_an_error():
    """An element declared as a superclass of what the relation expects may be bound to an
    element of the expected class at run time: not provably wrong, so only a warning that
    names a class that would do. A class nothing below which fits can never hold: an error.
    """
    use_ontology([PAPER])

    class Wider(SkillDescription):
        def description(self, P: skiros.Product, L: skiros.Location):
            self.pre_conditions += P.hasA(L)

    class Disjoint(SkillDescription):
        def description(self, P: skiros.Product, Q: skiros.Product):
            self.pre_conditions += P.hasA(Q)

    wider = only(Wider)
    assert (wider.kind, wider.severity, wider.param) == ("range-unproven", "info", "L")
    assert "skiros:TransformationPose" in wider.message and "narrow" in wider.message
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        Wider()  # loads, silently: modelling advice is info (docs/rules.md, EZ204)
    disjoint = only(Disjoint)
    assert (disjoint.kind, disjoint.severity) == ("range", "error")
    with pytest.raises(SkillTypeError):
        Disjoint()
    with strict():
        assert only(Wider).severity == "error"


RANGES_TTL = """
@prefix ex: <http://example.org/ex#> .
@prefix owl: <http://www.w3.org/2002/07/owl#> .
@prefix rdfs: <http://www.w3.org/2000/01/rdf-schema#> .
ex:P a owl:Class .
ex:A a owl:Class ; rdfs:subClassOf ex:P .
ex:B a owl:Class ; rdfs:subClassOf ex:P .
ex:wide a owl:ObjectProperty ; rdfs:range ex:A .
ex:narrow a owl:ObjectProperty ; rdfs:subPropertyOf ex:wide ; rdfs:range ex:B .
ex:odd a owl:ObjectProperty ; rdfs:range [ a owl:Class ; owl:intersectionOf ( ex:A
    [ a owl:Restriction ; owl:onProperty ex:wide ; owl:someValuesFrom ex:B ] ) ] .
"""


@pytest.mark.parametrize(("relation", "expected"), [
    ("ex:wide", [("range-unproven", "info")]),  # ex:A, below ex:P, fits
    ("ex:narrow", [("range", "error")]),  # must be ex:A and ex:B: no class below ex:P is both
    ("ex:odd", []),  # ex:A may fit, the restriction is undecidable: no guessing
])
def test_several_ranges_must_fit_one_class_and_undecidable_ones_report_nothing(
        tmp_path: Path, relation: str, expected: list[tuple[str, str]]) -> None:
    """Whether a wider parameter *can* fit is asked of one class for all ranges at once
    (a subclass fitting each range separately is no witness), and a subclass the index
    cannot decide keeps an impossible-looking condition from becoming an error."""
    (tmp_path / "ranges.ttl").write_text(RANGES_TTL)
    use_ontology([tmp_path / "ranges.ttl"])

    class Skill(SkillDescription):
        def description(self, X: ELEMENT("ex:P"), Y: ELEMENT("ex:P")):
            self.pre_conditions += X.relation(relation, Y)

    assert [(f.kind, f.severity) for f in check(Skill)] == expected


def test_the_automatic_robot_may_be_a_device(tmp_path: Path) -> None:
    """The legacy pattern the rule is for: the automatic ``Robot: INFERRED[sumo.Agent]``
    with ``cora:robotPart`` (domain ``sumo:Device``) may hold, since ``cora:Robot`` is both;
    the warning names the file, line, parameter and a class to narrow it to."""
    use_ontology([skiros2()])

    class Skill(SkillDescription):
        def description(self, Robot: INFERRED[ELEMENT("sumo:Agent")],
                        Other: ELEMENT("cora:Robot")):
            self.pre_conditions += Robot.relation("cora:robotPart", Other)

    finding = only(Skill)
    assert (finding.kind, finding.severity, finding.param) == ("domain-unproven", "info",
                                                               "Robot")
    assert finding.line == line_of('relation("cora:robotPart", Other)', HERE)
    assert finding.message == (
        "cora:robotPart expects subject of class sumo:Device, but parameter Robot is "
        "sumo:Agent, which only some elements are (cora:Robot is): narrow the parameter's "
        "type (e.g. to cora:Robot) to be sure")
    assert str(finding).startswith(f"{finding.location}: Skill: cora:robotPart expects")


NO_ELEMENT_TTL = """
@prefix ex: <http://example.org/ex#> .
@prefix owl: <http://www.w3.org/2002/07/owl#> .
ex:Thing a owl:Class .
ex:near a owl:ObjectProperty .
ex:Size a owl:DatatypeProperty .
"""


@pytest.mark.parametrize(("condition", "kind", "param", "what"), [
    ("P.hasA(S)", "range", "S", "float"),
    ("N.hasA(P)", "domain", "N", "str"),
    ("S.PositionX > 1.0", "domain", "S", "float"),
])
def test_a_condition_on_a_parameter_that_is_no_element_is_an_error(condition, kind, param,
                                                                    what):
    namespace: dict[str, object] = {}
    exec(f"def build(P, S, N):\n    return {condition}\n", namespace)

    class OnPlain(SkillDescription):
        def description(self, P: skiros.Product, S: float, N: str = "x"):
            self.pre_conditions += namespace["build"](P, S, N)

    (finding,) = [f for f in check(OnPlain) if f.param == param]  # P may misfit, too
    assert (finding.kind, finding.severity, finding.param) == (kind, "error", param)
    assert f"parameter {param} is a {what}, not a world element" in finding.message


def test_no_element_is_an_error_even_where_the_ontology_declares_no_domain(tmp_path: Path):
    """A property without rdfs:domain/range still applies to world elements only."""
    (tmp_path / "open.ttl").write_text(NO_ELEMENT_TTL)
    use_ontology([tmp_path / "open.ttl"])

    class Skill(SkillDescription):
        def description(self, T: ELEMENT("ex:Thing"), S: float, N: str = "x"):
            self.pre_conditions += T.relation("ex:near", S)
            self.pre_conditions += N.property("ex:Size", ">", 1.0)

    assert [(f.kind, f.param) for f in check(Skill)] == [("range", "S"), ("domain", "N")]


@pytest.mark.parametrize(("condition", "expected", "actual"), [
    ("PublishTf == 1", "xsd:boolean", "int"),
    ("PositionX == True", "xsd:float", "bool"),
    ("FrameId == 3", "xsd:string", "int"),
])
def test_property_values_must_have_the_ranges_python_type(condition, expected, actual):
    namespace: dict[str, object] = {}
    exec(f"def build(A):\n    return A.{condition}\n", namespace)

    class Skill(SkillDescription):
        def description(self, A: skiros.Location):
            self.pre_conditions += namespace["build"](A)

    finding = only(Skill)
    assert (finding.kind, finding.severity, finding.expected, finding.actual) == (
        "value-type", "error", expected, actual)
    assert finding.message.startswith(f"skiros:{condition.split()[0]} expects a {expected} "
                                      "value, but the condition compares A with ")


def test_int_values_are_fine_for_float_properties():
    class Skill(SkillDescription):
        def description(self, A: skiros.Location):
            self.pre_conditions += A.PositionX >= 1
            self.pre_conditions += A.PositionX < 2.5

    assert check(Skill) == []


def test_ordering_operators_need_a_numeric_property():
    class Skill(SkillDescription):
        def description(self, A: skiros.Location):
            self.pre_conditions += A.FrameId > "a"

    finding = only(Skill)
    assert (finding.kind, finding.severity) == ("operator", "error")
    assert finding.message == ("skiros:FrameId is xsd:string: operator '>' needs a numeric "
                               "property (xsd:int, xsd:float, ...)")


def test_object_and_datatype_properties_are_not_interchangeable():
    class Compared(SkillDescription):
        def description(self, A: skiros.Location):
            self.pre_conditions += A.contain == True

    class Related(SkillDescription):
        def description(self, A: skiros.Location, B: skiros.Location):
            self.pre_conditions += A.PositionX(B)

    assert (only(Compared).kind, only(Compared).expected) == ("property-kind", "data property")
    assert only(Related).message.startswith("skiros:PositionX is a datatype property")


def test_an_unknown_operator_is_a_warning():
    class Skill(SkillDescription):
        def description(self, A: skiros.Location):
            self.pre_conditions += A.property("skiros:PositionX", "!=", 1.0)

    finding = only(Skill)
    assert (finding.kind, finding.severity) == ("unknown-operator", "warning")
    assert "operator '!=' is none of =, >, <, >=, <=" in finding.message


def test_an_inferred_parameter_no_pre_condition_mentions_is_reported():
    class Skill(SkillDescription):
        def description(self, Robot: INFERRED[ELEMENT("cora:Robot")],
                        Place: INFERRED[skiros.Location],
                        Gripper: INFERRED[rparts.GripperEffector, Lock],
                        Used: INFERRED[skiros.Product]):
            self.pre_conditions += Used.is_specified()
            self.post_conditions += Place.contain(Used)

    finding = only(Skill)
    assert (finding.kind, finding.severity, finding.param) == ("uninferable", "warning",
                                                               "Place")
    assert finding.line == line_of("Place: INFERRED[skiros.Location],", HERE)
    assert finding.message.startswith("INFERRED parameter Place is mentioned by no "
                                      "pre-condition, so SkiROS2 grounds it by type alone")
    assert "skiros:Location" in finding.message and "several elements" in finding.message


def test_an_inferred_parameter_that_is_no_element_is_not_judged():
    class Skill(SkillDescription):
        def description(self, Place: INFERRED[skiros.Location], Speed: INFERRED[float] = 0.5):
            self.pre_conditions += Place.is_specified()

    assert [f.kind for f in check(Skill)] == []


def test_the_same_condition_wanted_and_unwanted_in_one_list_is_a_contradiction():
    class Skill(SkillDescription):
        def description(self, A: skiros.Location, B: skiros.Product):
            self.pre_conditions += A.contain(B)
            self.post_conditions += ~ A.contain(B)  # pre and post may differ
            self.pre_conditions += (~ A.contain(B)).named("Empty")

    finding = only(Skill)
    assert (finding.kind, finding.severity) == ("contradiction", "error")
    assert finding.line == line_of('.named("Empty")', HERE)
    first = line_of("self.pre_conditions += A.contain(B)", HERE)
    assert finding.message == (
        "pre-condition getRelationCond('Empty', 'skiros:contain', 'A', 'B', False) "
        f"contradicts line {first}, which requires the opposite: it can never be met")


def test_one_property_wanted_equal_to_two_values_in_one_list_is_a_contradiction():
    class Skill(SkillDescription):
        def description(self, L: skiros.Location):
            self.pre_conditions += L.PublishTf == True
            self.post_conditions += L.PublishTf == False
            self.pre_conditions += L.PublishTf == False

    finding = only(Skill)
    assert (finding.kind, finding.severity) == ("contradiction", "error")
    assert finding.line == line_of("self.pre_conditions += L.PublishTf == False", HERE)
    first = line_of("self.pre_conditions += L.PublishTf == True", HERE)
    assert f"wants skiros:PublishTf of L to be False, but line {first} wants True" in \
        finding.message

    class Fine(SkillDescription):
        def description(self, L: skiros.Location):
            self.pre_conditions += L.PublishTf == True
            self.pre_conditions += ~ (L.PublishTf == False)

    assert check(Fine) == []


@pytest.mark.parametrize(("first", "second", "contradicts"), [
    ("A.PositionX > 3.0", "A.PositionX < 1.0", True),
    ("A.PositionX >= 2.0", "A.PositionX < 2.0", True),
    ("A.PositionX >= 2", "A.PositionX <= 2.0", False),  # exactly 2 fits
    ("A.PositionX == 5", "A.PositionX < 4.5", True),
    ("A.PositionX > 1.0", "A.PositionX < 3.0", False),
    ("A.PositionX > 3.0", "~ (A.PositionX > 5.0)", False),  # 4.0 fits
])
def test_numeric_bounds_no_value_fits_are_a_contradiction(first, second, contradicts):
    namespace: dict[str, object] = {}
    exec(f"def build(A):\n    return [{first}, {second}]\n", namespace)

    class Skill(SkillDescription):
        def description(self, A: skiros.Location):
            for cond in namespace["build"](A):
                self.pre_conditions += cond
            self.post_conditions += namespace["build"](A)[0]  # other list: independent

    found = [(f.kind, f.severity) for f in check(Skill)]
    assert found == ([("contradiction", "error")] if contradicts else [])
    if contradicts:
        assert "can never both hold" in only(Skill).message


def test_a_condition_on_an_undeclared_key_is_kept_and_reported():
    class Skill(SkillDescription):
        def description(self, A: skiros.Location):
            self.pre_conditions += A.contain(self.param("Objct"))

    finding = only(Skill)
    assert (finding.kind, finding.param) == ("undeclared-parameter", "Objct")
    assert "refers to 'Objct', which the description does not declare" in finding.message


@pytest.mark.parametrize(("annotation", "default", "message"), [
    ("int", "0.5", "parameter S: default 0.5 is float, but the annotation says int"),
    ("int", "True", "parameter S: default True is bool, but the annotation says int"),
    ("REQUIRED[str]", "None", "parameter S: default None is NoneType, but the annotation says "
                              "str"),
    ("skiros.Product", "0", "parameter S: an Element parameter takes no default, got 0"),
])
def test_a_default_that_does_not_fit_its_annotation_is_a_type_error(annotation, default,
                                                                     message):
    namespace = {"SkillDescription": SkillDescription, "REQUIRED": REQUIRED, "skiros": skiros}
    exec(f"class Skill(SkillDescription):\n"
         f"    def description(self, S: {annotation} = {default}):\n"
         f"        pass\n", namespace)
    with pytest.raises(SkillTypeError) as raised:
        namespace["Skill"]()  # type: ignore[operator]
    assert str(raised.value).endswith(f"Skill: {message}")
    assert raised.value.findings[0].kind == "default-type"


class Mixed(SkillDescription):
    def description(self, A: skiros.Location, B: skiros.Product):
        self.pre_conditions += B.contain(A)
        self.pre_conditions += A.contian(B)


def test_findings_are_data_and_check_neither_raises_nor_warns():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        findings = check(Mixed)
    assert [(f.kind, f.severity) for f in findings] == [
        ("unknown-vocabulary", "warning"), ("domain", "error"), ("range-unproven", "info")]
    data = findings[1].to_json()
    assert data["kind"] == "domain" and data["param"] == "B" and data["suggestions"] == []
    line = line_of("self.pre_conditions += B.contain(A)", HERE)
    assert str(findings[1]) == (
        f"{os.path.relpath(HERE)}:{line}: Mixed: skiros:contain expects subject of class "
        "(skiros:Location | rparts:GripperEffector), but parameter B is skiros:Product")


def test_an_instance_keeps_its_findings():
    class Skill(SkillDescription):
        def description(self, A: skiros.Location, B: skiros.Product):
            self.pre_conditions += A.contian(B)

    with pytest.warns(EzSkirosWarning):
        built = Skill()
    assert [f.kind for f in built.findings] == ["unknown-vocabulary"]
    assert check(built) == built.findings


def test_strict_mode_through_the_api_makes_every_finding_an_error():
    class Skill(SkillDescription):
        def description(self, A: skiros.Location, B: skiros.Product):
            self.pre_conditions += A.contian(B)

    assert not is_strict()
    with strict():
        assert is_strict()
        with pytest.raises(SkillTypeError, match="lowered as skiros:contian"):
            Skill()
        assert [f.severity for f in check(Skill)] == ["error"]
    assert not is_strict()
    strict(True)
    try:
        assert is_strict()
    finally:
        strict(None)
    assert not is_strict()


def test_strict_mode_through_the_environment(monkeypatch):
    class Skill(SkillDescription):
        def description(self, A: skiros.Location, B: skiros.Product):
            self.pre_conditions += A.contian(B)

    monkeypatch.setenv("EZSKIROS_STRICT", "1")
    assert is_strict()
    with pytest.raises(SkillTypeError):
        Skill()
    with strict(False), pytest.warns(EzSkirosWarning):  # the API wins over the environment
        Skill()


def test_severity_of_a_kind_is_configurable():
    class Skill(SkillDescription):
        def description(self, Place: INFERRED[skiros.Location]):
            pass

    try:
        set_severity("uninferable", "off")
        assert check(Skill) == []
        set_severity("uninferable", "error")
        with pytest.raises(SkillTypeError, match="INFERRED parameter Place"):
            Skill()
    finally:
        set_severity("uninferable", None)
    assert [f.severity for f in check(Skill)] == ["warning"]
    with pytest.raises(ValueError, match="severity 'loud'"):
        set_severity("uninferable", "loud")


def test_several_errors_are_raised_together_one_line_each():
    class Skill(SkillDescription):
        def description(self, A: rparts.GripperEffector, B: skiros.Product):
            self.pre_conditions += B.contain(A)
            self.post_conditions += B.hasA(A)

    with pytest.raises(SkillTypeError) as raised:
        Skill()
    lines = str(raised.value).splitlines()
    assert len(lines) == 3  # contain: domain and range; hasA: range
    assert [f.kind for f in raised.value.findings] == ["domain", "range", "range"]


def test_the_checks_use_the_active_ontology():
    assert active_index().sources == (str(PAPER),)
