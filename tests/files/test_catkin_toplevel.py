"""Every catkin workspace's ``src/CMakeLists.txt`` is catkin's symlink to
``/opt/ros/<distro>/share/catkin/cmake/toplevel.cmake``: not the lab's code, and nothing to
say about (issue 43: every run on a workspace said "symlink leads outside the given paths,
skipped" about it). Other links that lead outside are still named. Real symlinks in a
temporary workspace; the real CLI in a child process."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

SKILL = '''\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


class Pick(SkillDescription):
    def createDescription(self):
        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)
'''


@pytest.fixture()
def workspace(tmp_path: Path) -> Path:
    """``catkin_ws/src`` with catkin's top-level link and one package; an ``/opt/ros``
    stand-in outside the workspace for the links to lead to."""
    cmake = tmp_path / "opt" / "ros" / "noetic" / "share" / "catkin" / "cmake"
    cmake.mkdir(parents=True)
    (cmake / "toplevel.cmake").write_text("# catkin\n", encoding="utf-8")
    src = tmp_path / "catkin_ws" / "src"
    package = src / "lab_skills"
    (package / "src" / "lab_skills").mkdir(parents=True)
    (package / "package.xml").write_text("<package><name>lab_skills</name></package>",
                                         encoding="utf-8")
    (package / "src" / "lab_skills" / "pick.py").write_text(SKILL, encoding="utf-8")
    os.symlink(cmake / "toplevel.cmake", src / "CMakeLists.txt")
    return src


def _run(*args: str, cwd: Path) -> str:
    run = subprocess.run([sys.executable, "-m", "ezmigrate", *args], cwd=cwd,
                         capture_output=True, text=True, timeout=300,
                         env={"PATH": os.environ.get("PATH", "/usr/bin:/bin"),
                              "EZMIGRATE_CACHE_DIR": str(cwd / ".cache")})
    assert run.returncode in (0, 1), run.stderr
    return run.stderr


@pytest.mark.parametrize("command", [("check",), ("rewrite", "--dry-run", "--no-verify")])
def test_catkins_own_link_is_not_mentioned(workspace: Path, command: tuple[str, ...]) -> None:
    said = _run(*command, "src", cwd=workspace.parent)
    assert "symlink" not in said and "CMakeLists.txt" not in said, said


def test_other_links_that_lead_outside_are_still_named(workspace: Path) -> None:
    outside = workspace.parent.parent / "opt" / "ros" / "noetic" / "share" / "catkin"
    os.symlink(outside / "cmake" / "toplevel.cmake", workspace / "lab_skills" / "CMakeLists.txt")
    os.symlink(outside, workspace / "catkin")
    said = _run("check", "src", cwd=workspace.parent)
    assert "src/lab_skills/CMakeLists.txt: symlink leads outside the given paths" in said, said
    assert "src/catkin: symlink leads outside the given paths" in said, said
    assert "src/CMakeLists.txt:" not in said, said
