"""``rewrite --no-verify`` never writes code that cannot load (issue 22, item 4).

Without verification nothing loads the migrated module, but the runtime's early checks
raise when the class is defined; the static pass runs them and holds such a skill back
just as the verified run does. ``check`` on the written tree then finds no module that
fails to import (EZ904) and no error at all.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

SKILLS = '''from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


class OpenDoor(SkillDescription):
    def createDescription(self):
        self.addParam("Door", Element("skiros:Location"), ParamTypes.Required)
        self.addPreCondition(self.getPropCond("Open", "skiros:Open", "Door", "=", True, True))
        self.addPreCondition(self.getPropCond("Shut", "skiros:Open", "Door", "=", True, False))


class OpenDoorFast(OpenDoor):
    pass


class Fine(SkillDescription):
    def createDescription(self):
        self.addParam("Door", Element("skiros:Location"), ParamTypes.Required)
'''


def ezmigrate(cwd: Path, *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "ezmigrate", *args], cwd=cwd,
                          capture_output=True, text=True, stdin=subprocess.DEVNULL,
                          timeout=300, check=False)


def statuses(report: Path) -> dict[str, tuple[str, str]]:
    data = json.loads(report.read_text(encoding="utf-8"))
    return {s["class"]: (s["status"], (s["reason"] or "").split(":")[0])
            for s in data["skills"]}


@pytest.mark.parametrize("verify", ["--verify", "--no-verify"])
def test_a_skill_the_runtime_rejects_is_held_with_or_without_verification(
        tmp_path: Path, verify: str):
    folder = tmp_path / "pkg"
    folder.mkdir()
    (folder / "__init__.py").write_text("", encoding="utf-8")
    (folder / "skills.py").write_text(SKILLS, encoding="utf-8")
    run = ezmigrate(tmp_path, "rewrite", verify, "--report", "r.json", "pkg")
    assert run.returncode == 0, run.stderr
    assert statuses(tmp_path / "r.json") == {
        "OpenDoor": ("skipped", "EzSkiROS rejects this skill when it loads"),
        "OpenDoorFast": ("skipped", "its base class OpenDoor was not converted"),
        "Fine": ("converted", "")}
    written = (folder / "skills.py").read_text(encoding="utf-8")
    assert "class OpenDoor(SkillDescription):\n    def createDescription(self):" in written
    assert "def description(self,\n                    Door: skiros.Location):" in written
    checked = ezmigrate(tmp_path, "check", "--select", "EZ9,EZ107", "pkg")
    assert "EZ904" not in checked.stdout  # the written module loads
    assert "OpenDoor" in checked.stdout and "EZ107" in checked.stdout  # still said, as legacy
