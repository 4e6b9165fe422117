"""Descriptions deriving from descriptions in sibling files of the same package."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

from ezmigrate.project.cross_file import dotted, target_module

BASE = '''\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


class ArmMotion(SkillDescription):
    def createDescription(self):
        self.addParam("Arm", Element("rparts:ArmDevice"), ParamTypes.Required)
        self.addPreCondition(self.getRelationCond("ArmRobotPartRobot", "cora:robotPart", "Arm", "Robot", True))
'''
MOVES = '''\
from skiros2_common.core.params import ParamTypes
from {source} import ArmMotion


class MoveLinear(ArmMotion):
    def createDescription(self):
        ArmMotion.createDescription(self)
        self.addParam("Speed", 0.1, ParamTypes.Optional)


class MoveHome(ArmMotion):
    pass
'''


def _package(root: Path, source: str) -> Path:
    pkg = root / "robot_skills"
    (pkg / "arm").mkdir(parents=True)
    (pkg / "__init__.py").write_text("")
    (pkg / "arm" / "__init__.py").write_text("")
    (pkg / "base.py").write_text(BASE)
    (pkg / "arm" / "moves.py").write_text(MOVES.format(source=source))
    return pkg


def _ezmigrate(*args: str | Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "ezmigrate", *map(str, args)],
                          capture_output=True, text=True, check=False)


def test_module_names_of_relative_and_absolute_imports():
    assert dotted("robot_skills/arm/moves.py") == "robot_skills.arm.moves"
    assert dotted("robot_skills/__init__.py") == "robot_skills"
    assert target_module("robot_skills/arm/moves.py", "..base") == "robot_skills.base"
    assert target_module("robot_skills/arm/moves.py", ".util") == "robot_skills.arm.util"
    assert target_module("robot_skills/arm/moves.py", "robot_skills.base") == "robot_skills.base"


def test_child_in_sibling_file_is_converted_and_verified(tmp_path: Path):
    for source in ("..base", "robot_skills.base"):
        root = tmp_path / source.strip(".").replace(".", "_")
        pkg = _package(root, source)
        before = root.parent / (root.name + "_before")
        shutil.copytree(root, before)
        proc = _ezmigrate("rewrite", root)
        assert proc.returncode == 0, proc.stderr
        moves = (pkg / "arm" / "moves.py").read_text()
        assert "class MoveLinear(ArmMotion):\n    def description(self," in moves
        assert "Arm: rparts.ArmDevice" in moves and "Speed: OPTIONAL[float] = 0.1" in moves
        assert "class MoveHome(ArmMotion):\n    pass" in moves
        assert "def description" in (pkg / "base.py").read_text()
        proved = _ezmigrate("verify", before, root)
        assert proved.returncode == 0, proved.stderr


def test_child_is_not_written_when_its_base_file_is_not(tmp_path: Path):
    pkg = _package(tmp_path, "..base")
    # A constant rebound after the class: legacy code reads it when the skill is created,
    # a Python default is evaluated when the class is defined. Verification must catch it,
    # keep base.py, and therefore keep moves.py (its migrated form needs the new base).
    base = BASE.replace("ParamTypes.Required)\n", "ParamTypes.Required)\n"
                        "        self.addParam(\"Speed\", SPEED, ParamTypes.Optional)\n", 1)
    (pkg / "base.py").write_text("SPEED = 0.5\n" + base + "\nSPEED = 1.0\n")
    before = {p: p.read_bytes() for p in pkg.rglob("*.py")}
    proc = _ezmigrate("rewrite", tmp_path)
    assert proc.returncode == 1
    assert "not equivalent" in proc.stderr and "robot_skills/base.py" in proc.stderr
    assert "robot_skills/arm/moves.py" in proc.stderr
    assert {p: p.read_bytes() for p in pkg.rglob("*.py")} == before
