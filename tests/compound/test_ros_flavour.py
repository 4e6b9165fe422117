"""Facts of the SkiROS2 branch a package targets (issue 21, pattern 2): the standard
library's ros2 branch declares more keys on WmSetRelation, and a processor upstream's
master and ros2 branches lack is one info per project naming where it exists. Real files,
the real check core; the flavour comes from package.xml (``target.ros_flavour``) or from
rospy/rclpy imports."""

from __future__ import annotations

from pathlib import Path

from ezmigrate.checking.pipeline import run_check
from ezmigrate.lint.diagnostic import Diagnostic
from ezmigrate.verify.pool import PoolConfig

TASK = '''\
{imports}
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element
from skiros2_skill.core.skill import RetryOnFail, Sequential, SkillBase


class Stow(SkillDescription):
    def createDescription(self):
        self.addParam("Box", Element("sumo:Object"), ParamTypes.Required)
        self.addParam("Old", Element("sumo:Object"), ParamTypes.Optional)


class stow(SkillBase):
    def createDescription(self):
        self.setDescription(Stow(), self.__class__.__name__)

    def expand(self, skill):
        skill(self.skill("WmSetRelation", "", remap={{"Dst": "Box", "OldDstToRemove": "Old"}},
                         specify={{"Relation": "skiros:contain"}}))
'''
BUILDTOOL = "<package><name>lab</name><buildtool_depend>{tool}</buildtool_depend></package>"


def ez3(folder: Path, imports: str = "", tool: str | None = None) -> list[Diagnostic]:
    folder.mkdir(parents=True)
    (folder / "stow.py").write_text(TASK.format(imports=imports), encoding="utf-8")
    if tool is not None:
        (folder / "package.xml").write_text(BUILDTOOL.format(tool=tool), encoding="utf-8")
    found = run_check([folder], None, PoolConfig(workers=1)).diagnostics
    return [d for d in found if d.code.startswith("EZ3")]


def test_a_ros2_package_may_remap_what_the_ros2_standard_library_declares(tmp_path: Path):
    assert ez3(tmp_path / "ament", tool="ament_python") == []
    assert ez3(tmp_path / "rclpy", imports="import rclpy") == []
    [ros1] = ez3(tmp_path / "catkin", tool="catkin")
    assert (ros1.code, ros1.severity) == ("EZ304", "error") and "OldDstToRemove" in ros1.message
    [plain] = ez3(tmp_path / "rospy", imports="import rospy")
    assert plain.code == "EZ304"


def test_a_processor_upstream_lacks_is_one_info_per_project_naming_its_branch(tmp_path: Path):
    tree = TASK.format(imports="").replace(
        'skill(self.skill("WmSetRelation", "", remap={"Dst": "Box", "OldDstToRemove": "Old"},\n'
        '                         specify={"Relation": "skiros:contain"}))',
        'skill(self.skill(RetryOnFail(Sequential()))(self.skill("Wait", "")))')
    for name in ("a.py", "b.py"):
        (tmp_path / name).write_text(tree.replace("Stow", name[0].upper() + "Stow"),
                                     encoding="utf-8")
    found = [d for d in run_check([tmp_path], None, PoolConfig(workers=1)).diagnostics
             if d.code.startswith("EZ3")]
    [once] = found
    assert (once.code, once.severity) == ("EZ310", "info")
    assert "ros2_roscon24_workshop" in once.message and "2 uses of RetryOnFail" in once.message
    (tmp_path / "b.py").unlink()  # near miss: one use is one finding without a count
    [single] = [d for d in run_check([tmp_path], None, PoolConfig(workers=1)).diagnostics
                if d.code.startswith("EZ3")]
    assert "uses of" not in single.message
