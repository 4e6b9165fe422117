"""The code written is code the robot runs: the target Python.

``list[float]`` raises ``TypeError`` when a class is defined under ROS Noetic's Python 3.8,
so a ROS 1 package (or ``target-version = "py38"``) gets the DSL's ``LIST[float]``; every
other line is the same. The line ``package.xml`` gains is tested in
``tests/files/test_package_xml.py``.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from ezmigrate.cli.config import ConfigError, load_project_config
from ezmigrate.codemod.migrate import Settings, migrate
from ezmigrate.project.target import parse_target, ros_flavour, target_for

LEGACY = b'''from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes


class Sweep(SkillDescription):
    def createDescription(self):
        self.addParam("Speeds", [0.1, 0.2], ParamTypes.Optional)
        self.addParam("Name", "arm", ParamTypes.Optional)
'''


def _migrated(target: tuple[int, int]) -> str:
    result = migrate(LEGACY, Settings(target=target), "sweep.py")
    assert isinstance(result.new_source, bytes), result
    return result.new_source.decode()


def test_python_3_8_gets_the_dsl_list_and_its_import():
    code = _migrated((3, 8))
    assert "Speeds: OPTIONAL[LIST[float]] = [0.1, 0.2]" in code
    assert "list[float]" not in code
    assert "LIST" in code.split("class Sweep")[0]  # imported from ezskiros_runtime
    namespace: dict[str, object] = {}
    exec(compile(code, "sweep.py", "exec"), namespace)  # defines the class here too


def test_python_3_9_and_newer_keep_the_builtin_list():
    code = _migrated((3, 10))
    assert "Speeds: OPTIONAL[list[float]] = [0.1, 0.2]" in code
    assert "LIST" not in code
    assert _migrated((3, 8)).replace("LIST", "list").replace(", list", "") == code


@pytest.mark.parametrize(("value", "expected"), [
    ("py38", (3, 8)), ("py310", (3, 10)), ("py313", (3, 13)),
    ("py37", None), ("3.8", None), (38, None), ("py3", None)])
def test_target_versions_are_spelled_as_ruff_spells_them(value, expected):
    assert parse_target(value) == expected


def test_a_bad_target_version_in_pyproject_is_a_usage_error(tmp_path):
    (tmp_path / "pyproject.toml").write_text('[tool.ezmigrate]\ntarget-version = "3.8"\n')
    with pytest.raises(ConfigError, match="target-version"):
        load_project_config(tmp_path)
    (tmp_path / "pyproject.toml").write_text('[tool.ezmigrate]\ntarget-version = "py38"\n')
    assert load_project_config(tmp_path).target_version == (3, 8)


def _package(folder: Path, tool: str) -> Path:
    folder.mkdir(parents=True)
    (folder / "package.xml").write_text(
        f"<package format=\"3\">\n  <name>{folder.name}</name>\n"
        f"  <buildtool_depend>{tool}</buildtool_depend>\n</package>\n")
    return folder


def test_the_repository_says_which_robot(tmp_path):
    noetic = _package(tmp_path / "ws" / "cell_ros1", "catkin")
    humble = _package(tmp_path / "ws" / "cell_ros2", "ament_python")
    assert ros_flavour(noetic / "package.xml") == "ros1"
    assert ros_flavour(humble / "package.xml") == "ros2"
    assert target_for([humble], None).version == (3, 10)
    inside = target_for([noetic / "src"], None) if (noetic / "src").mkdir() is None else None
    assert inside is not None and (inside.version, inside.flavour) == ((3, 8), "ros1")
    both = target_for([tmp_path / "ws"], None)  # the oldest Python among the packages
    assert both.version == (3, 8) and "cell_ros1/package.xml" in both.why
    assert target_for([tmp_path / "ws"], (3, 12)).version == (3, 12)  # configured wins
    plain = tmp_path / "plain"
    plain.mkdir()
    assert (target_for([plain], None).version, target_for([plain], None).flavour) == (
        (3, 10), None)


AMENT_PYTHON = """<?xml version="1.0"?>
<package format="3">
  <name>lab_skills</name>
  <version>0.1.0</version>
  <description>skills</description>
  <maintainer email="lab@example.org">lab</maintainer>
  <license>MIT</license>
  <export>
    <build_type>ament_python</build_type>
  </export>
</package>
"""


def test_an_ament_python_package_in_a_subfolder_is_named_as_the_run_names_files(
        tmp_path, monkeypatch):
    """Issue 43: an ament_python package says what it is by its build type alone; the note
    names its manifest relative to the working directory, and asks for what the run did
    not look for (a ROS 2 robot's Python) rather than for a PATH entry."""
    from ezmigrate.project.target import target_for, verified_with

    (tmp_path / "src" / "lab_skills").mkdir(parents=True)
    (tmp_path / "src" / "lab_skills" / "package.xml").write_text(AMENT_PYTHON)
    monkeypatch.chdir(tmp_path)
    target = target_for([tmp_path], None)
    assert (target.flavour, target.python) == ("ros2", "3.10")
    assert target.why.startswith("src/lab_skills/package.xml is a ")
    line = verified_with(None, target)
    if not line.split(" (")[0].endswith("3.10"):
        assert "pass --python naming a python3.10" in line and "PATH" not in line
