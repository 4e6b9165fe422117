"""Each compound check on a minimal tree: one that triggers it and a near miss that does not.

Trees are built as models (the checks' input) against a small index; the ontology is the
bundled SkiROS2 core. The runtime's entry point ``check_compound`` is exercised on real
legacy-backend classes, traced.
"""

from __future__ import annotations

import pytest

from ezskiros_runtime import CompoundSkillError, check_compound
from ezskiros_runtime.codes import code_for
from ezskiros_runtime.compound import index_of
from ezskiros_runtime.compound.checks import check_model
from ezskiros_runtime.compound.library import DescriptionInfo, SkillIndex
from ezskiros_runtime.compound.model import (
    CallProblem,
    CompoundModel,
    ProcessorNode,
    SkillNode,
)
from ezskiros_runtime.compound.trace import Unanalysable
from ezskiros_runtime.legacy.abstract_skill import SkillDescription
from ezskiros_runtime.legacy.params import ParamTypes
from ezskiros_runtime.legacy.skill import SerialStar, SkillBase
from ezskiros_runtime.legacy.world_element import Element
from ezskiros_runtime.ontology.index import bundled_ontology_path
from ezskiros_runtime.ontology.load import load_index

ONTOLOGY = load_index([bundled_ontology_path()])


def _index() -> SkillIndex:
    index = SkillIndex.with_standard_library()
    for info in (
        DescriptionInfo("Kit", {"Part": "skiros:Product", "Shelf": "skiros:Location",
                                "Box": "skiros:LargeBox", "Camera": "skiros:DepthCamera"}),
        DescriptionInfo("Navigate", {"Target": "skiros:Location"}),
        DescriptionInfo("Pick", {"Object": "skiros:Product", "Speed": None}),
        DescriptionInfo("Fetch", {"Shelf": "skiros:Location"}),
        DescriptionInfo("Place", {"Where": "skiros:LargeBox"}),
    ):
        index.add_description(info)
    index.add_implementation("pick_ur5", "Pick")
    index.add_implementation("navigate_base", "Navigate")
    index.add_compound(CompoundModel("fetch", "Fetch", "fetch", "Sequential", (
        SkillNode("Navigate", "", (("Target", "Shelf"),)), SkillNode("Pick", ""))))
    return index


def _codes(*children: object, processor: str = "Sequential") -> list[str]:
    model = CompoundModel("kit", "Kit", "kit", processor, tuple(children))  # type: ignore[arg-type]
    return [code_for(f.kind) for f in check_model(model, _index(), ONTOLOGY)]


CASES = [  # (code, triggering node, near miss)
    ("EZ301", SkillNode("PickPart"), SkillNode("Pick")),
    ("EZ302", SkillNode("Pi.k"), SkillNode("skiros:Pick")),
    ("EZ303", SkillNode("Pick", "navigate_base"), SkillNode("Pick", "pick_ur5")),
    ("EZ304", SkillNode("Navigate", "", (("Goal", "Shelf"),)),
     SkillNode("Navigate", "", (("Target", "Shelf"),))),
    ("EZ305", SkillNode("Fetch", "", (("Object", "Part"),)),
     SkillNode("Fetch", "", (("Shelf", "Shelf"),))),
    ("EZ314", SkillNode("Fetch", "", (("Target", "Part"),)),  # Fetch's Navigate remapped it
     SkillNode("Fetch", "", (("Shelf", "Shelf"),))),
    ("EZ306", SkillNode("Pick", "", (("Object", "Speed"),)),
     SkillNode("Pick", "", (("Object", "Part"),))),
    ("EZ307", SkillNode("Wait", "", (), (("Time", 1.0),)),
     SkillNode("Wait", "", (), (("Duration", 1.0),))),
    ("EZ307", SkillNode("Pick", "", (("Object", "Part"),), (("Object", None),)),
     SkillNode("Pick", "", (("Object", "Part"),), (("Part", None),))),
    ("EZ308", SkillNode("Navigate", "", (("Target", "Station"),)),
     SkillNode("Navigate", "", (("Target", "Shelf"),))),
    ("EZ309", CallProblem("self.skill(self.skill(...))"), SkillNode("Navigate")),
    ("EZ310", ProcessorNode("RetryOnFail", (SkillNode("Pick"),)),
     ProcessorNode("NoFail(Serial)", (SkillNode("Pick"),))),
    ("EZ311", SkillNode("Place", "", (("Where", "Camera"),)),
     SkillNode("Place", "", (("Where", "Box"),))),
    ("EZ312", SkillNode("Place", "", (("Where", "Shelf"),)),
     SkillNode("Place", "", (("Where", "Box"),))),
]


@pytest.mark.parametrize(("code", "mistake", "near_miss"), CASES,
                         ids=[f"{c}-{i}" for i, (c, _, _) in enumerate(CASES)])
def test_the_mistake_is_found_and_the_near_miss_is_not(code: str, mistake: object,
                                                       near_miss: object) -> None:
    assert code in _codes(mistake)
    assert _codes(near_miss) == []


def test_blackboard_idioms_stay_silent() -> None:
    assert _codes(
        SkillNode("Pick", "", (("Object", "Found"),)),   # Pick writes "Found"...
        SkillNode("Navigate", "", (("Target", "Found"),)),  # ...a later sibling reads it
        SkillNode("WmSetRelation", "", (("Src", "Shelf"), ("Dst", "Part")),
                  (("Relation", "skiros:contain"), ("RelationState", True))),
    ) == []


def test_a_remap_below_an_unknown_tree_is_not_judged() -> None:
    index = _index()
    index.unknown_compounds.add("Fetch")
    model = CompoundModel("kit", "Kit", "kit", "Sequential",
                          (SkillNode("Fetch", "", (("Gripper", "Part"),)),))
    assert [f.kind for f in check_model(model, index, ONTOLOGY)] == []


def test_an_unanalysable_tree_is_reported_not_clean() -> None:
    [finding] = check_model(Unanalysable("kit", "it asks the world model", 7), _index())
    assert (code_for(finding.kind), finding.line) == ("EZ313", 7)


def test_a_base_description_resolves_to_nothing_and_says_why() -> None:
    index = _index()
    index.add_description(DescriptionInfo("NavigateFast", {"Target": "skiros:Location"}))
    index.bases.add("Navigate")
    assert index.resolve("Navigate") == ([], False)
    assert [d.name for d in index.resolve("Navigate.*")[0]] == ["NavigateFast"]
    model = CompoundModel("kit", "Kit", "kit", "Sequential", (SkillNode("Navigate"),))
    [finding] = check_model(model, index, ONTOLOGY)
    assert code_for(finding.kind) == "EZ301" and "leaf descriptions" in finding.message


def test_the_root_processor_is_checked_too() -> None:
    assert _codes(SkillNode("Pick"), processor="Loop") == ["EZ310"]


class Task(SkillDescription):
    def createDescription(self):
        self.addParam("Pause", 1.0, ParamTypes.Optional)
        self.addParam("Shelf", Element("skiros:Location"), ParamTypes.Required)


class task(SkillBase):
    def createDescription(self):
        self.setDescription(Task(), "task")

    def expand(self, skill):
        skill.setProcessor(SerialStar())
        for seconds in (self.params["Pause"].value,):
            skill(self.skill("Wait", "", specify={"Time": seconds}),
                  self.skill("Navigate", "", remap={"Target": "Shelf"}))


def test_check_compound_traces_and_returns_findings_as_data() -> None:
    index = index_of([Task])
    index.add_description(DescriptionInfo("Navigate", {"Target": "skiros:Location"}))
    findings = check_compound(task, index, ontology=ONTOLOGY, strict=False)
    assert [(code_for(f.kind), f.subject, f.fix) for f in findings] == [
        ("EZ307", "Wait", "Did you mean 'Duration'?")]
    with pytest.raises(CompoundSkillError, match="EZ307 task"):
        check_compound(task, index, strict=True)


class SlowTask(Task):
    """A leaf below ``Task``: from here on ``"Task"`` names nothing loadable."""


def test_index_of_knows_which_classes_are_bases() -> None:
    assert index_of([Task]).resolve("Task")[1]
    index = index_of([Task, SlowTask], standard_library=False)
    assert index.bases == {"Task"} and list(index.names()) == ["SlowTask"]
