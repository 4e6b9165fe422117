"""``colcon build`` without ROS sourced takes the runtime package for a catkin one (issue
43): its ``package.xml`` chooses the build type by ``ROS_VERSION``, as a package built on
ROS 1 and ROS 2 must. The README's colcon steps source ROS 2 first and say why; this holds
the package and the README to that, with catkin_pkg's own reading of the manifest (the
parser colcon-ros uses)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from catkin_pkg.package import parse_package

pytestmark = pytest.mark.filterwarnings(  # catkin_pkg's conditions use pyparsing's old names
    "ignore::DeprecationWarning:catkin_pkg.condition", "ignore::DeprecationWarning:pyparsing")

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize(("environment", "build_type"), [
    ({}, "catkin"), ({"ROS_VERSION": "1"}, "catkin"), ({"ROS_VERSION": "2"}, "ament_python")])
def test_the_build_type_follows_ros_version(environment: dict[str, str],
                                            build_type: str) -> None:
    package = parse_package(str(ROOT / "ros" / "ezskiros_runtime" / "package.xml"))
    package.evaluate_conditions(environment)
    assert package.get_build_type() == build_type


def test_the_readme_sources_ros_2_before_colcon_build() -> None:
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    block = next(b for b in re.findall(r"```bash\n(.*?)```", text, re.S) if "colcon build" in b)
    lines = [line.split("#")[0].strip() for line in block.splitlines()]
    build = next(i for i, line in enumerate(lines) if line.startswith("colcon build"))
    assert any(re.fullmatch(r"source /opt/ros/\w+/setup\.bash", line)
               for line in lines[:build]), block
    after = text.split(block, 1)[1]
    assert "with `ROS_VERSION` unset colcon takes it for\na catkin package" in after
