"""The paper's Listing 4 (Pick) against paper.ttl: loads, equals legacy, fails precisely.

No ``from __future__ import annotations`` here on purpose: annotations are evaluated when the
class is defined, which is when a misspelt class name must fail. Classes are built inside
functions so that they are defined while paper.ttl is the active ontology.
"""

import pytest
from dsl_support import line_of, model, named, paper  # noqa: F401 - paper is a fixture

from ezskiros_runtime import INFERRED, EzSkirosWarning, SkillDescription, SkillTypeError
from ezskiros_runtime.compare import compare
from ezskiros_runtime.diagnostics import UnknownVocabularyError
from ezskiros_runtime.legacy.abstract_skill import SkillDescription as LegacyDescription
from ezskiros_runtime.legacy.params import ParamTypes
from ezskiros_runtime.legacy.world_element import Element
from ezskiros_runtime.ontology import cora, rparts, skiros

pytestmark = pytest.mark.usefixtures("paper")


def pick_class() -> type:
    @named("Pick")
    class Pick(SkillDescription):
        def description(self,
                        Robot: INFERRED[cora.Robot],
                        ObjectLocation: INFERRED[skiros.Location],
                        Object: skiros.Product,
                        Gripper: rparts.GripperEffector,
                        GraspingPose: INFERRED[skiros.GraspingPose]):
            self.pre_conditions += ObjectLocation.contain(Object)
            self.pre_conditions += ~ Gripper.contain(Object)
            self.pre_conditions += Object.hasA(GraspingPose)
            self.post_conditions += Gripper.contain(Object)

    return Pick


def bad_pick_class() -> type:
    @named("Pick")
    class Pick(SkillDescription):
        def description(self,
                        Robot: INFERRED[cora.Robot],
                        ObjectLocation: INFERRED[skiros.Location],
                        Object: skiros.Product,
                        Gripper: rparts.GripperEffector,
                        GraspingPose: INFERRED[skiros.GraspingPose]):
            self.pre_conditions += ObjectLocation.contain(Object)
            self.pre_conditions += ~ Gripper.contain(Object)
            self.pre_conditions += Object.hasA(Gripper)  # <- the paper's rejected condition
            self.post_conditions += Gripper.contain(Object)

    return Pick


@named("Pick")
class LegacyPick(LegacyDescription):
    def createDescription(self):
        self.addParam("Robot", Element("cora:Robot"), ParamTypes.Inferred)
        self.addParam("ObjectLocation", Element("skiros:Location"), ParamTypes.Inferred)
        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)
        self.addParam("Gripper", Element("rparts:GripperEffector"), ParamTypes.Required)
        self.addParam("GraspingPose", Element("skiros:GraspingPose"), ParamTypes.Inferred)
        self.addPreCondition(self.getRelationCond(
            "ObjectLocationContainObject", "skiros:contain", "ObjectLocation", "Object", True))
        self.addPreCondition(self.getRelationCond(
            "NotGripperContainObject", "skiros:contain", "Gripper", "Object", False))
        self.addPreCondition(self.getRelationCond(
            "ObjectHasAGraspingPose", "skiros:hasA", "Object", "GraspingPose", True))
        self.addPostCondition(self.getRelationCond(
            "GripperContainObject", "skiros:contain", "Gripper", "Object", True))


def test_listing4_loads_clean_and_equals_its_legacy_twin():
    pick = pick_class()()
    assert pick.findings == []
    ez, legacy = model(type(pick)), model(LegacyPick)
    assert [p.key for p in ez.params] == ["Robot", "ObjectLocation", "Object", "Gripper",
                                          "GraspingPose"]
    assert [p.element_type for p in ez.params][:2] == ["cora:Robot", "skiros:Location"]
    assert ez.type == "skiros:Pick"
    assert ez == legacy
    assert compare(legacy, ez) == []


def test_the_papers_hasA_mistake_names_file_line_skill_parameter_and_classes():
    cls = bad_pick_class()
    # GraspingPose is now mentioned by no pre-condition: warned first, then the error.
    with pytest.warns(EzSkirosWarning, match="INFERRED parameter GraspingPose"), \
            pytest.raises(SkillTypeError) as raised:
        cls()
    line = line_of("Object.hasA(Gripper)  # <-", __file__)
    message = str(raised.value)
    assert f"test_dsl_pick.py:{line}: Pick: skiros:hasA expects object of class " \
           "skiros:TransformationPose, but parameter Gripper is rparts:GripperEffector" \
           in message
    (finding,) = raised.value.findings
    assert (finding.kind, finding.severity, finding.line) == ("range", "error", line)
    assert finding.file == __file__
    assert (finding.skill, finding.param, finding.relation) == ("Pick", "Gripper",
                                                                "skiros:hasA")
    assert (finding.expected, finding.actual) == ("skiros:TransformationPose",
                                                  "rparts:GripperEffector")


def test_a_misspelt_term_fails_when_the_class_is_defined_with_a_suggestion():
    reached_end_of_class = False
    with pytest.raises(UnknownVocabularyError) as raised:
        class Pick(SkillDescription):
            def description(self, Pose: INFERRED[skiros.GrASPingPose]):
                pass

        reached_end_of_class = True
    assert not reached_end_of_class
    assert "skiros.GrASPingPose" in str(raised.value)
    assert "did you mean skiros.GraspingPose?" in str(raised.value)
    assert raised.value.suggestions[0] == "skiros.GraspingPose"


def test_the_paper_listing_verbatim_loads_and_subclassing_mirrors_the_ontology():
    @named("Pick")
    class Pick(SkillDescription):
        def description(self,
                        Robot: INFERRED[cora.Robot],
                        ObjectLocation: INFERRED[skiros.Location],
                        Object: skiros.Product,
                        Gripper: rparts.GripperEffector):
            self.pre_conditions += ObjectLocation.contain(Object)
            self.pre_conditions += ~ Gripper.contain(Object)
            self.post_conditions += Gripper.contain(Object)

    built = model(Pick)
    assert [c.label for c in built.pre] == ["ObjectLocationContainObject",
                                            "NotGripperContainObject"]
    assert [c.label for c in built.post] == ["GripperContainObject"]
    assert issubclass(skiros.GraspingPose, skiros.TransformationPose)
    assert not issubclass(rparts.GripperEffector, skiros.TransformationPose)
