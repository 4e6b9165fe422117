"""``ezskiros_runtime.world`` on real files: the fixture scenes parsed by rdflib, checked
against the real SkiROS2 OWL files plus the fixture lab's ontology, post-conditions, and the
hand-worked grounding example. Runs on the robot's Python 3.8 with rdflib 4.2.2 too
(no ezmigrate import here)."""

from __future__ import annotations

from pathlib import Path

import pytest
from shared_data import skiros2

from ezskiros_runtime.legacy.abstract_skill import SkillDescription
from ezskiros_runtime.legacy.params import ParamTypes
from ezskiros_runtime.legacy.world_element import Element
from ezskiros_runtime.model import Condition, Param, SkillModel
from ezskiros_runtime.ontology.load import load_index
from ezskiros_runtime.world import (
    RelationUse,
    SceneError,
    can_start,
    check_scene,
    check_scene_file,
    double_places,
    read_scene,
    single_valued,
)
from ezskiros_runtime.world.postconditions import retraction

ROOT = Path(__file__).resolve().parents[3]
REPO = ROOT / "fixtures" / "world_repo"
SCENES = REPO / "owl" / "scenes"
SAVED = SCENES / "cell.turtle"
EDITED = SCENES / "cell_two_stations.turtle"


@pytest.fixture(scope="module")
def index():
    """The real SkiROS2 core files and the lab's own ontology, as the world model loads them."""
    return load_index([skiros2(), REPO / "owl"], cache=False)


def _codes(found):
    return sorted((f.line, f.code) for f in found)


def _marked(path: Path):
    """``(line, code)`` of every ``# expect: EZ4xx`` in a scene."""
    found = []
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if "# expect: " in line:
            found += [(number, c.strip()) for c in line.split("# expect: ")[1].split(",")]
    return sorted(found)


def test_a_scene_saved_by_skiros2_reads_with_its_generated_prefixes_and_skills(index):
    scene = read_scene(SAVED)
    assert scene.prefixes["default1"] == "http://lab.example.org/ontologies/cell.owl#"
    robot = scene.elements["http://lab.example.org/ontologies/cell.owl#Ur5-3"]
    assert robot.label == "cell_robot" and robot.line == 46
    assert robot.types == ["http://lab.example.org/ontologies/cell.owl#Ur5"]
    assert scene.compact(robot.iri) == "default1:Ur5-3"
    gear = [v for v in scene.values if v.subject.endswith("Part-8") and "Inspected" in v.property]
    assert gear[0].value is False and gear[0].line == 83
    # its skills, parameters and their templates are SkiROS2's own: no finding at all
    assert check_scene(scene, index) == []


def test_every_mistake_of_the_hand_edited_scene_is_found_on_its_line(index):
    assert _codes(check_scene_file(EDITED, index)) == _marked(EDITED)


def test_the_findings_say_what_is_wrong(index):
    found = {f.code: f for f in check_scene_file(EDITED, index)}
    assert "rparts:ArmDevice-4 has two spatial parents: skiros:Scene-0 and cell:Ur5-3" in \
        found["EZ403"].message
    assert "cell:Part-9 is defined nowhere" in found["EZ404"].message
    assert "outside the range rparts:ArmDevice" in found["EZ405"].message
    assert found["EZ405"].severity == "info" and found["EZ407"].severity == "info"
    # the arm has no pose of its own: a second GUI node, not a misplaced frame
    assert found["EZ403"].severity == "info" and "no pose of its own" in found["EZ403"].message


def test_a_scene_that_does_not_parse_is_one_finding_at_rdflibs_line(tmp_path: Path, index):
    broken = ROOT / "fixtures" / "world" / "broken_scene.turtle"
    with pytest.raises(SceneError) as caught:
        read_scene(broken)
    assert caught.value.line == 7
    found = check_scene_file(broken, index)
    assert [(f.code, f.line) for f in found] == [("EZ402", 7)]


SCENE = """\
@prefix skiros: <http://rvmi.aau.dk/ontologies/skiros.owl#> .
@prefix rparts: <http://www.inf.ufrgs.br/phi-group/ontologies/RParts.owl#> .
@prefix cell: <http://lab.example.org/ontologies/cell.owl#> .
@prefix xsd: <http://www.w3.org/2001/XMLSchema#> .

skiros:Scene-0 a skiros:Scene ;
    skiros:contain skiros:Location-1, rparts:ArmDevice-2 .

skiros:Location-1 a skiros:Location ;
    skiros:PositionX "{x}"^^xsd:float .

rparts:ArmDevice-2 a rparts:ArmDevice .

skiros:DepthCamera-3 a {camera} ;
    {relation} .
"""


@pytest.mark.parametrize(("code", "trigger", "near_miss"), [
    ("EZ403", {"relation": "skiros:contain rparts:ArmDevice-2"},
     {"relation": "skiros:at rparts:ArmDevice-2"}),  # at is no spatial parent
    ("EZ404", {"relation": "cell:mountedOn rparts:ArmDevice-9"},
     {"relation": "cell:mountedOn cell:spare_gripper"}),  # declared by owl/robot.owl
    ("EZ405", {"relation": "cell:mountedOn skiros:Location-1"},
     {"relation": "cell:mountedOn rparts:ArmDevice-2"}),
    ("EZ406", {"x": "0,5"}, {"x": "-0.5"}),
    ("EZ407", {"camera": "cell:Kinect"}, {"camera": "skiros:DepthCamera"}),
    ("EZ408", {"relation": "skiros:FrameId \"cam\""},
     {"camera": "skiros:Parameter", "relation": "skiros:FrameId \"cam\""}),  # SkiROS2's own
])
def test_each_scene_code_fires_on_its_trigger_and_not_on_its_near_miss(
        tmp_path: Path, index, code: str, trigger: dict, near_miss: dict) -> None:
    def codes(values: dict) -> set:
        text = SCENE.format(**{"x": "0.5", "camera": "skiros:DepthCamera",
                               "relation": "skiros:FrameId \"cam\" ; "
                                           "skiros:hasA rparts:ArmDevice-2", **values})
        path = tmp_path / "scene.turtle"
        path.write_text(text, encoding="utf-8")
        return {f.code for f in check_scene_file(path, index)}

    assert code in codes(trigger)
    assert code not in codes(near_miss)


# -- post-conditions ----------------------------------------------------------------------

def _use(which, relation, subject, obj, desired=True, line=0):
    return RelationUse(which, relation, subject, obj, desired, line)


@pytest.mark.parametrize(("uses", "found"), [
    # the official planning example's Pick: never retracted
    ([_use("pre", "skiros:contain", "Container", "Object"),
      _use("post", "skiros:contain", "Gripper", "Object", line=9)], [9]),
    # the retraction is there (Drive: NoRobotAt StartLocation)
    ([_use("pre", "skiros:at", "Robot", "Start"),
      _use("post", "skiros:at", "Robot", "Start", False),
      _use("post", "skiros:at", "Robot", "Target", line=9)], []),
    # at: one place per subject, written with another spelling of the relation
    ([_use("pre", ":at", "Robot", "Start"), _use("post", "skiros:at", "Robot", "Target",
                                                 line=4)], [4]),
    # the same key at both ends: no second parent
    ([_use("pre", "skiros:contain", "Gripper", "Part"),
      _use("post", "skiros:contain", "Gripper", "Part")], []),
    # the first relation is required NOT to hold
    ([_use("pre", "skiros:contain", "Fixture", "Part", False),
      _use("post", "skiros:contain", "Tray", "Part")], []),
    # any spatial sub-property counts: contained before, held by hasA after
    ([_use("pre", "skiros:contain", "Table", "Tool"),
      _use("post", "skiros:hasA", "Arm", "Tool", line=3)], [3]),
    # one parent per object, not one child per parent: a robot has many parts
    ([_use("pre", "skiros:hasA", "Robot", "Arm"),
      _use("post", "skiros:hasA", "Robot", "Camera")], []),
])
def test_post_conditions_that_leave_two_parents_or_two_places(index, uses, found):
    assert [d.second.line for d in double_places(uses, single_valued(index), index)] == found


def test_the_single_valued_list_is_configurable(index):
    uses = [_use("pre", "skiros:contain", "Container", "Object"),
            _use("post", "skiros:contain", "Gripper", "Object", line=9),
            _use("pre", "cell:mountedOn", "Camera", "Arm"),
            _use("post", "cell:mountedOn", "Camera", "Wrist", line=11)]
    assert [d.second.line for d in double_places(uses, single_valued(index), index)] == [9]
    only = single_valued(index, ["skiros:at", "cell:mountedOn"])
    assert [d.second.line for d in double_places(uses, only, index)] == [11]


def test_the_suggested_retraction_is_written_in_the_files_own_form():
    first = _use("pre", "skiros:contain", "Container", "Object")
    assert retraction(first, "legacy") == (
        'self.addPostCondition(self.getRelationCond("NotContainerContainObject", '
        '"skiros:contain", "Container", "Object", False))')
    assert retraction(first, "ezskiros") == "self.post_conditions += ~ Container.contain(Object)"
    odd = _use("pre", "cora:robotPart", "Target Location", "Object")
    assert retraction(odd, "ezskiros") == \
        'self.post_conditions += ~ self.param("Target Location").robotPart(Object)'


# -- grounding: the hand-worked example -----------------------------------------------------

class Drive(SkillDescription):
    def createDescription(self):
        self.addParam("Start", Element("skiros:Location"), ParamTypes.Inferred)
        self.addParam("Target", Element("skiros:Location"), ParamTypes.Required)
        self.addPreCondition(self.getRelationCond("RobotAtStart", "skiros:at", "Robot",
                                                  "Start", True))


class Inspect(SkillDescription):
    def createDescription(self):
        self.addParam("Camera", Element("skiros:DepthCamera"), ParamTypes.Inferred)
        self.addParam("Part", Element("cell:Part"), ParamTypes.Inferred)
        self.addParam("Table", Element("skiros:Location"), ParamTypes.Inferred)
        self.addPreCondition(self.getRelationCond("RobotHasCamera", "skiros:hasA", "Robot",
                                                  "Camera", True))
        self.addPreCondition(self.getRelationCond("TableContainPart", "skiros:contain",
                                                  "Table", "Part", True))
        self.addPreCondition(self.getPropCond("NotInspected", "cell:Inspected", "Part", "=",
                                              False, True))


class Place(SkillDescription):
    def createDescription(self):
        self.addParam("Gripper", Element("rparts:GripperEffector"), ParamTypes.Required)
        self.addParam("Object", Element("skiros:Product"), ParamTypes.Inferred)
        self.addPreCondition(self.getRelationCond("Holding", "skiros:contain", "Gripper",
                                                  "Object", True))


class LoadFixture(SkillDescription):
    def createDescription(self):
        self.addParam("Fixture", Element("cell:Fixture"), ParamTypes.Required)


CELL = "http://lab.example.org/ontologies/cell.owl#"
SKIROS = "http://rvmi.aau.dk/ontologies/skiros.owl#"


def test_which_skills_can_start_from_the_demo_cell_and_why_not(index):
    """Worked by hand on cell.turtle: the robot stands at the table (Location-1), which
    holds the bracket (Part-7, inspected) and the gear (Part-8, not yet); the robot has a
    camera; the gripper holds nothing; there is no fixture."""
    drive = can_start(Drive, SAVED, index)
    assert drive and drive.assignment["Start"] == SKIROS + "Location-1"
    assert drive.assignment["Robot"] == CELL + "Ur5-3"  # cell:Ur5 < cora:Robot < sumo:Agent
    inspect = can_start(Inspect, SAVED, index)
    assert inspect and inspect.assignment["Part"] == CELL + "Part-8"  # the bracket is done
    place = can_start(Place, SAVED, index)
    assert not place and place.blocking is not None and place.blocking.label == "Holding"
    assert "'Holding' (Gripper skiros:contain Object)" in place.reason
    fixture = can_start(LoadFixture, SAVED, index)
    assert not fixture and fixture.blocking is None
    assert fixture.reason == ("no element of class cell:Fixture for parameter Fixture in the "
                              "scene")


def test_grounding_takes_a_model_and_judges_or_and_negated_conditions(index):
    def model(*pre: Condition) -> SkillModel:
        return SkillModel("M", "skiros:M", params=(
            Param("Part", "Inferred", "Element", "cell:Part"),
            Param("Where", "Inferred", "Element", "skiros:Location"),
            Param("Speed", "Optional", "float")), pre=pre)

    contain = Condition("relation", "In", "skiros:contain", "Where", "Part",
                        desired_state=("bool", True))
    shelf = Condition("on_type", "OnShelf", "cell:Shelf", "Where")
    assert can_start(model(contain), SAVED, index)
    assert not can_start(model(contain, shelf), SAVED, index)  # the shelf is empty
    either = Condition("or", "or", children=(contain, shelf), desired_state=("bool", True))
    assert can_start(model(either), SAVED, index)
    nowhere = Condition("relation", "NotIn", "skiros:contain", "Where", "Part",
                        desired_state=("bool", False))
    # the first choice (IRIs in order) where the part is not: the shelf, not the table
    assert can_start(model(nowhere), SAVED, index).assignment == {
        "Part": CELL + "Part-7", "Where": CELL + "Shelf-2"}
    assert can_start(model(contain, nowhere), SAVED, index).reason.startswith(
        "no choice of elements satisfies the pre-condition 'NotIn'")


def test_grounding_searches_a_large_scene_without_trying_every_product(tmp_path: Path):
    """60 locations of 8 products each: four parameters have 60 * 480 * 60 * 480 joint
    choices; the search follows the relations instead, so both answers come at once (a
    product of the pools would run out of its budget and say ``undecided``)."""
    lines = ["@prefix skiros: <http://rvmi.aau.dk/ontologies/skiros.owl#> .",
             "@prefix xsd: <http://www.w3.org/2001/XMLSchema#> ."]
    for i in range(60):
        lines.append(f"skiros:Location-{i} a skiros:Location ; skiros:contain "
                     + ", ".join(f"skiros:Product-{i}-{j}" for j in range(8)) + " .")
        lines += [f'skiros:Product-{i}-{j} a skiros:Product ; skiros:Weight "{j}.0"^^xsd:float .'
                  for j in range(8)]
    path = tmp_path / "big.turtle"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    scene = read_scene(path)

    def weight(key: str, op: str, value: float, label: str) -> Condition:
        return Condition("property", label, "skiros:Weight", key, operator=op,
                         value=("float", value), desired_state=("bool", True))

    def contain(subject: str, obj: str, label: str) -> Condition:
        return Condition("relation", label, "skiros:contain", subject, obj,
                         desired_state=("bool", True))

    params = tuple(Param(k, "Inferred", "Element", t) for k, t in (
        ("A", "skiros:Location"), ("O", "skiros:Product"), ("B", "skiros:Location"),
        ("P", "skiros:Product")))
    pre = (contain("A", "O", "AO"), contain("B", "P", "BP"), weight("O", ">", 6.5, "Heavy"),
           weight("P", "<", 0.5, "Light"), contain("A", "P", "AP"))
    core = load_index(cache=False)
    found = can_start(SkillModel("M", "skiros:M", params=params, pre=pre), scene, core)
    assert found.ok and not found.undecided
    assert found.assignment["O"].endswith("-7") and found.assignment["P"].endswith("-0")
    blocked = can_start(SkillModel("M", "skiros:M", params=params,
                                   pre=(*pre, weight("P", ">", 100.0, "TooHeavy"))), scene,
                        core)
    assert not blocked and not blocked.undecided and blocked.blocking is not None
    assert blocked.blocking.label == "TooHeavy"


def test_an_ontology_header_and_classes_declared_in_a_scene_are_no_elements(tmp_path: Path,
                                                                           index):
    plain = SCENE.format(x="0.5", camera="cell:Kinect", relation="skiros:FrameId \"cam\"")
    schema = ("@prefix owl: <http://www.w3.org/2002/07/owl#> .\n"
              "@prefix rdfs: <http://www.w3.org/2000/01/rdf-schema#> .\n" + plain
              + "\n<http://lab.example.org/scene> a owl:Ontology ;\n"
                "    owl:imports <http://lab.example.org/ontologies/cell.owl> .\n\n"
                "cell:Kinect a owl:Class ;\n    rdfs:subClassOf skiros:DepthCamera ;\n"
                "    rdfs:label \"kinect\" .\n")
    codes = []
    for name, text in (("plain", plain), ("schema", schema)):
        path = tmp_path / f"{name}.turtle"
        path.write_text(text, encoding="utf-8")
        scene = read_scene(path)
        assert "http://lab.example.org/scene" not in scene.elements
        assert CELL + "Kinect" not in scene.elements
        codes.append(sorted(f.code for f in check_scene(scene, index)))
    # the camera of an undeclared class, outside the tree: the header and the class add
    # nothing, and a class the scene declares is still unknown to the ontology (info)
    assert codes == [["EZ407", "EZ408"], ["EZ407", "EZ408"]]
