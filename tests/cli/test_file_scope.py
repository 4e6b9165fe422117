"""A named file's project is its git top level, else its nearest ``package.xml`` or
``pyproject.toml``, and nothing above that is read; a file in none of them is checked alone
(issue 43: ``ezmigrate check some/dir/file.py`` run from a shared folder, outside git,
loaded the ontologies and launch files of unrelated projects).

Real folders in a temporary directory outside any git checkout, the real CLI in a child
process; stderr says which ontology files and which launch file a run used."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from ezskiros_runtime.ontology.vendored import git_top

NOT_FOUND = "ontology from the bundled default (the SkiROS2 core; no owl/ folder found)"
SKILL = '''\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


class Paint(SkillDescription):
    def createDescription(self):
        self.addParam("Station", Element("skiros:Location"), ParamTypes.Required)
'''
LAUNCH = '''\
<launch>
  <include file="$(find skiros2)/launch/world_model_server.launch">
    <arg name="workspace_dir" value="$(find lab)/owl"/>
  </include>
</launch>
'''


def _ontology(folder: Path, name: str) -> None:
    folder.mkdir(parents=True, exist_ok=True)
    (folder / f"{name}.ttl").write_text(
        "@prefix owl: <http://www.w3.org/2002/07/owl#> .\n"
        f"<http://lab.example.org/{name}#Widget> a owl:Class .\n", encoding="utf-8")


@pytest.fixture()
def shared(tmp_path: Path) -> Path:
    """A shared folder outside git: a ROS package of another lab beside it, and owl/
    folders and a launch file around ``some/dir/file.py``, none of a project."""
    root = tmp_path / "shared"
    if git_top(tmp_path) is not None:
        pytest.skip("the temporary folder is inside a git checkout")
    (root / "other").mkdir(parents=True)
    (root / "other" / "package.xml").write_text("<package><name>other</name></package>",
                                               encoding="utf-8")
    _ontology(root / "other" / "owl", "other")
    _ontology(root / "owl", "around")
    _ontology(root / "some" / "dir" / "owl", "beside")
    (root / "some" / "dir" / "launch").mkdir()
    (root / "some" / "dir" / "launch" / "robot.launch").write_text(LAUNCH, encoding="utf-8")
    (root / "some" / "dir" / "file.py").write_text(SKILL, encoding="utf-8")
    (root / "elsewhere").mkdir()
    (root / "elsewhere" / "two.py").write_text(SKILL, encoding="utf-8")
    return root


def _check(*paths: str, cwd: Path) -> str:
    run = subprocess.run([sys.executable, "-m", "ezmigrate", "check", *paths], cwd=cwd,
                         capture_output=True, text=True, timeout=300,
                         env={"PATH": os.environ.get("PATH", "/usr/bin:/bin"),
                              "EZMIGRATE_CACHE_DIR": str(cwd.parent / "cache")})
    assert run.returncode in (0, 1), run.stderr
    return run.stderr


def test_a_file_alone_is_checked_alone(shared: Path) -> None:
    said = _check("some/dir/file.py", cwd=shared)
    assert f"ezmigrate: {NOT_FOUND}" in said, said
    assert "launch:" not in said and "launch files" not in said, said


def test_files_alone_do_not_make_their_common_folder_a_project(shared: Path) -> None:
    said = _check("some/dir/file.py", "elsewhere/two.py", cwd=shared)
    assert f"ezmigrate: {NOT_FOUND}" in said, said


def test_the_nearest_pyproject_is_the_project_and_nothing_above_it_is_read(
        shared: Path) -> None:
    (shared / "some" / "pyproject.toml").write_text("[project]\nname = 'some'\n",
                                                   encoding="utf-8")
    said = _check("some/dir/file.py", cwd=shared)
    line = next(x for x in said.splitlines() if x.startswith("ezmigrate: ontology"))
    assert "dir/owl/beside.ttl" in line, said
    assert "around.ttl" not in line and "other.ttl" not in line, said
    assert "launch: some/dir/launch/robot.launch" in said, said


def test_a_ros_package_is_the_project_of_its_files(shared: Path) -> None:
    (shared / "other" / "skills.py").write_text(SKILL, encoding="utf-8")
    said = _check("other/skills.py", cwd=shared)
    line = next(x for x in said.splitlines() if x.startswith("ezmigrate: ontology"))
    assert "owl/other.ttl" in line and "around.ttl" not in line, said
