"""EZ105 is a warning only where grounding by type can pick the wrong element (issue 30):
the parameter is read, a run can leave it unset, and the scenes hold two or more elements
of its class. Each condition has its trigger and its near miss, in a real repository
checked by the real CLI."""

from __future__ import annotations

import json
import subprocess
import textwrap
from pathlib import Path

from check_support import cli

DESCRIPTION = """\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element
from skiros2_skill.core.skill import SkillBase
from skiros2_skill.core.primitive import PrimitiveBase


class Detect(SkillDescription):
    def createDescription(self):
        self.addParam("Pose", Element("skiros:TransformationPose"), ParamTypes.Inferred)
        self.addParam("Gripper", Element("rparts:GripperEffector"), ParamTypes.Inferred)


class detect(PrimitiveBase):
    def createDescription(self):
        self.setDescription(Detect(), self.__class__.__name__)

    def execute(self):
        pose = self.params["Pose"].value
        return self.success(str(pose))
"""

PARENT = """\


class Task(SkillDescription):
    def createDescription(self):
        self.addParam("Goal", Element("skiros:TransformationPose"), ParamTypes.Required)


class task(SkillBase):
    def createDescription(self):
        self.setDescription(Task(), self.__class__.__name__)

    def expand(self, skill):
        skill(self.skill("Detect", "", remap={"Pose": "Goal"}))
"""

SCENE = """\
@prefix owl: <http://www.w3.org/2002/07/owl#> .
@prefix skiros: <http://rvmi.aau.dk/ontologies/skiros.owl#> .
@prefix rparts: <http://www.inf.ufrgs.br/phi-group/ontologies/RParts.owl#> .
skiros:Scene-0 a skiros:Scene, owl:NamedIndividual ;
    skiros:contain skiros:TransformationPose-1, rparts:GripperEffector-3{more} .
skiros:TransformationPose-1 a skiros:TransformationPose, owl:NamedIndividual .
rparts:GripperEffector-3 a rparts:GripperEffector, owl:NamedIndividual .
{extra}"""


def _ez105(tmp_path: Path, files: dict[str, str]) -> dict[str, str]:
    """``{parameter: severity}`` of the EZ105 findings of ``check`` on a new repository."""
    for name, text in files.items():
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text(textwrap.dedent(text), encoding="utf-8")
    subprocess.run(["git", "init", "-q", str(tmp_path)], check=True)
    run = cli(".", "--output-format", "json", "--select", "EZ105", cwd=tmp_path)
    assert run.returncode in (0, 1), run.stderr
    return {str(d["message"]).split("INFERRED parameter ")[1].split(" ")[0]: str(d["severity"])
            for d in json.loads(run.stdout)}


def test_a_parameter_the_implementation_reads_warns_one_nothing_reads_is_info(tmp_path):
    assert _ez105(tmp_path, {"pkg/skills.py": DESCRIPTION}) == {"Pose": "warning",
                                                               "Gripper": "info"}


def test_a_value_every_parent_passes_is_info(tmp_path):
    found = _ez105(tmp_path, {"pkg/skills.py": DESCRIPTION + PARENT})
    assert found == {"Pose": "info", "Gripper": "info"}


def test_one_element_of_the_class_in_the_scenes_is_info_two_warn(tmp_path):
    one = _ez105(tmp_path / "one", {"pkg/skills.py": DESCRIPTION,
                                    "scenes/cell.turtle": SCENE.format(more="", extra="")})
    assert one == {"Pose": "info", "Gripper": "info"}
    two = _ez105(tmp_path / "two", {
        "pkg/skills.py": DESCRIPTION,
        "scenes/cell.turtle": SCENE.format(
            more=", skiros:TransformationPose-2",
            extra="skiros:TransformationPose-2 a skiros:TransformationPose, "
                  "owl:NamedIndividual .\n")})
    assert two == {"Pose": "warning", "Gripper": "info"}


TYPO = DESCRIPTION.replace('self.addParam("Pose", Element("skiros:TransformationPose"), '
                           'ParamTypes.Inferred)',
                           'self.addParam("Pose", Element("skiros:TransformationPoze"), '
                           'ParamTypes.Required)')


def _ez209(tmp_path: Path, source: str) -> list[str]:
    (tmp_path / "pkg").mkdir(parents=True)
    (tmp_path / "pkg" / "skills.py").write_text(source, encoding="utf-8")
    subprocess.run(["git", "init", "-q", str(tmp_path)], check=True)
    run = cli(".", "--output-format", "json", "--select", "EZ209", cwd=tmp_path)
    return [str(d["severity"]) for d in json.loads(run.stdout)]


UNKNOWN_CLASS = TYPO.replace("skiros:TransformationPoze", "skiros:GraspTarget")


def test_an_unknown_class_every_tree_passes_a_value_to_is_info(tmp_path):
    """SkiROS2 matches a parameter's class only to ground it: with the value always passed
    (the parent remaps its own Goal onto Pose), a class the ontology lacks (the lab's own,
    perhaps) changes nothing the run can see."""
    assert _ez209(tmp_path / "alone", UNKNOWN_CLASS) == ["warning"]
    assert _ez209(tmp_path / "passed", UNKNOWN_CLASS + PARENT) == ["info"]


def test_a_class_one_edit_from_a_known_one_stays_a_warning(tmp_path):
    """A typo of a class of a loaded namespace (TransformationPoze) is a mistake even where
    every tree passes a value: the task planner types the parameter by its class, the GUI
    lists no element for it, and the migrated module fails to import (issue 42)."""
    assert _ez209(tmp_path / "alone", TYPO) == ["warning"]
    assert _ez209(tmp_path / "passed", TYPO + PARENT) == ["warning"]
