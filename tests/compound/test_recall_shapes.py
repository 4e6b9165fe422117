"""Shapes of public trees that hid mistakes from the compound checks (issue 42, recall):
a type whose compound implementation runs the same type under a primitive's label, and
processors behind star imports of SkiROS2's other modules and of the lab's own modules.
Real files in a temporary folder, the real check core."""

from __future__ import annotations

from pathlib import Path

from ezmigrate.checking.pipeline import run_check
from ezmigrate.verify.pool import PoolConfig

MOVE = '''\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.primitive import PrimitiveBase
from skiros2_common.core.world_element import Element
from skiros2_skill.core.skill import SkillBase, Sequential


class MoveArm(SkillDescription):
    def createDescription(self):
        self.addParam("Target", Element("sumo:Object"), ParamTypes.Required)


class move_arm(SkillBase):
    def createDescription(self):
        self.setDescription(MoveArm(), self.__class__.__name__)

    def expand(self, skill):
        skill(self.skill("MoveArm", "move_joint"))


class move_joint(PrimitiveBase):
    def createDescription(self):
        self.setDescription(MoveArm(), self.__class__.__name__)


class Press(SkillDescription):
    def createDescription(self):
        self.addParam("Pose", Element("sumo:Object"), ParamTypes.Required)


class press(SkillBase):
    def createDescription(self):
        self.setDescription(Press(), self.__class__.__name__)

    def expand(self, skill):
        skill(self.skill("MoveArm", "{label}", remap={{"{key}": "Pose"}}))
'''


def codes(folder: Path, files: dict[str, str]) -> set[str]:
    folder.mkdir(parents=True)
    for name, text in files.items():
        (folder / name).write_text(text, encoding="utf-8")
    found = run_check([folder], None, PoolConfig(workers=1)).diagnostics
    return {d.code for d in found if d.severity != "info"}


def test_a_label_of_a_primitive_ends_the_walk_below_a_self_containing_type(tmp_path):
    assert "EZ304" in codes(tmp_path / "typo", {"arm.py": MOVE.format(
        label="move_arm", key="Tarrget")})
    assert "EZ304" not in codes(tmp_path / "fine", {"arm.py": MOVE.format(
        label="move_arm", key="Target")})


TREE = '''\
from skiros2_common.core.abstract_skill import SkillDescription
from tools import *


class Tidy(SkillDescription):
    def createDescription(self):
        pass


class tidy(SkillBase):
    def createDescription(self):
        self.setDescription(Tidy(), self.__class__.__name__)

    def expand(self, skill):
        skill.setProcessor({processor}())
        skill(self.skill("Wait", "", specify={{"Duration": 1.0}}))
'''
TOOLS = '''\
from skiros2_common.core.primitive import *
from skiros2_skill.core.skill import {imported}


def helper():
    return 1
'''


def test_a_processor_behind_star_imports_of_known_modules_is_judged(tmp_path):
    tools = TOOLS.format(imported="SkillBase, ParallelFs")
    assert "EZ317" in codes(tmp_path / "typo", {
        "tree.py": TREE.format(processor="ParalleFs"), "tools.py": tools})
    assert "EZ317" not in codes(tmp_path / "fine", {
        "tree.py": TREE.format(processor="ParallelFs"), "tools.py": tools})
    # a star import of a module the run cannot find may bind any name: not judged
    assert "EZ317" not in codes(tmp_path / "unknown", {
        "tree.py": TREE.format(processor="ParalleFs").replace("tools", "elsewhere"),
        "tools.py": tools})
