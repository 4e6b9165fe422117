"""The runtime is a ROS package a lab builds in its own workspace, beside its skills.

A lab puts a checkout of ezmigrate in its workspace's ``src/``; catkin, colcon and rosdep
must then find exactly one package in it, ``ros/ezskiros_runtime`` (the lab repositories
under ``fixtures/`` are test data), which installs the Python package ``ezskiros_runtime``
with its data and nothing of the command. Each test works on a copy of the checkout as a
clone has it (the files git tracks or would track, links kept), never on this one.

ROS 2 is built for real: colcon (from PyPI, with the ROS extensions) builds the runtime and
a skill package ``rewrite`` migrated, and the skill is imported from the install space, as
the skill manager would. catkin's CMake half is not on PyPI (it comes with ROS Noetic), so
the ROS 1 build runs its Python half: the ``setup.py`` install catkin's install step runs.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from catkin_pkg.package import Package, parse_package
from catkin_pkg.packages import find_packages

import ezskiros_runtime
from ezmigrate.files.package_xml import RUNTIME_PACKAGE, packages_of
from ezskiros_runtime.pyproject import read_toml

pytestmark = pytest.mark.filterwarnings(  # catkin_pkg's conditions use pyparsing's old names
    "ignore::DeprecationWarning:catkin_pkg.condition", "ignore::DeprecationWarning:pyparsing")

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = Path("ros") / RUNTIME_PACKAGE
COLCON = Path(sys.executable).with_name("colcon")
"""Installed with the ``test`` extra (colcon-core, colcon-ros, colcon-python-setup-py)."""

SKILL_XML = """<?xml version="1.0"?>
<package format="3">
  <name>lab_skills</name>
  <version>0.0.1</version>
  <description>A lab's skills</description>
  <maintainer email="lab@example.org">Lab</maintainer>
  <license>BSD</license>

  <exec_depend>skiros2</exec_depend>

  <export>
    <build_type>ament_python</build_type>
  </export>
</package>
"""
SKILL_SETUP = """from setuptools import setup

setup(name="lab_skills", version="0.0.1", packages=["lab_skills"],
      data_files=[("share/ament_index/resource_index/packages", ["resource/lab_skills"]),
                  ("share/lab_skills", ["package.xml"])])
"""
SKILL = """from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


class Place(SkillDescription):
    def createDescription(self):
        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)
        self.addParam("Location", Element("skiros:Location"), ParamTypes.Required)
        self.addPostCondition(self.getRelationCond(
            "LocationContainObject", "skiros:contain", "Location", "Object", True))
"""
IMPORT = """import ezskiros_runtime, lab_skills.descriptions as skills
print(ezskiros_runtime.__file__)
print(skills.__file__)
print(sorted(skills.Place().params))
"""


def _checkout(into: Path) -> Path:
    """A copy of what a clone of this repository holds, at ``into``."""
    listed = subprocess.run(["git", "ls-files", "-z", "--cached", "--others",
                             "--exclude-standard"], cwd=ROOT, capture_output=True,
                            check=True, timeout=60).stdout.decode().split("\0")
    for name in filter(None, listed):
        source = ROOT / name
        if not source.is_symlink() and not source.is_file():
            continue  # deleted in the work tree
        (into / name).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(source, into / name, follow_symlinks=False)
    return into


def _files(folder: Path) -> set[str]:
    """Every file below ``folder`` (links not followed), to see that a build wrote none."""
    return {os.path.relpath(os.path.join(here, name), folder)
            for here, dirs, names in os.walk(folder) for name in names
            if "__pycache__" not in here}


def _environment(**extra: str) -> dict[str, str]:
    """This environment without any ROS workspace or ezskiros setting of the caller's."""
    dropped = ("AMENT_", "COLCON_", "CMAKE_PREFIX_PATH", "ROS_", "PYTHONPATH", "EZSKIROS_")
    env = {k: v for k, v in os.environ.items() if not k.startswith(dropped)}
    return {**env, **extra}


def _manifest(ros_version: str) -> Package:
    package = parse_package(str(ROOT / PACKAGE / "package.xml"))
    package.evaluate_conditions({"ROS_VERSION": ros_version})
    return package


def test_the_manifest_is_catkin_on_ros_1_and_ament_python_on_ros_2():
    ros1, ros2 = _manifest("1"), _manifest("2")
    assert (ros1.name, ros1.package_format) == (RUNTIME_PACKAGE, 3)
    assert ros1.get_build_type() == "catkin"
    assert [d.name for d in ros1.buildtool_depends if d.evaluated_condition] == ["catkin"]
    assert ros2.get_build_type() == "ament_python"
    assert [d.name for d in ros2.buildtool_depends if d.evaluated_condition] == []
    for package in (ros1, ros2):  # a key rosdep knows: apt's python3-rdflib on Ubuntu
        assert [d.name for d in package.exec_depends if d.evaluated_condition] == [
            "python3-rdflib"]
    project = read_toml(ROOT / "pyproject.toml")["project"]
    assert ros1.version == project["version"] == ezskiros_runtime.__version__
    assert (ROOT / PACKAGE / RUNTIME_PACKAGE).resolve() == ROOT / RUNTIME_PACKAGE


def test_a_checkout_in_a_workspace_is_one_ros_package_and_changes_nothing_else(tmp_path):
    checkout = _checkout(tmp_path / "src" / "ezmigrate")
    found = find_packages(str(tmp_path / "src"))  # what catkin and rosdep --from-paths see
    assert {path: package.name for path, package in found.items()} == {
        f"ezmigrate/{PACKAGE.as_posix()}": RUNTIME_PACKAGE}
    assert (checkout / "fixtures" / "CATKIN_IGNORE").is_file()
    # ezmigrate's own files are in no ROS package: its discovery sees the checkout as before
    assert packages_of([checkout / "ezskiros_runtime" / "__init__.py",
                        checkout / "ezmigrate" / "__init__.py"]) == []


def test_ros_1_installs_the_runtime_alone_as_catkins_install_step_does(tmp_path):
    checkout = _checkout(tmp_path / "src" / "ezmigrate")
    before = _files(checkout)
    source, build, root = checkout / PACKAGE, tmp_path / "build", tmp_path / "root"
    env = _environment(ROS_VERSION="1")
    build.mkdir()  # catkin's build folder exists before it runs setup.py
    version = subprocess.run([sys.executable, "setup.py", "--version"], cwd=source, env=env,
                             capture_output=True, text=True, check=True, timeout=120)
    assert version.stdout.split()[-1] == _manifest("1").version  # catkin_python_setup checks
    run = subprocess.run([sys.executable, "setup.py", "egg_info", "--egg-base", str(build),
                          "build", "--build-base", str(build), "install", "--root", str(root),
                          "--prefix", "/opt/lab_ws"], cwd=source, env=env,
                         capture_output=True, text=True, check=False, timeout=300)
    assert run.returncode == 0, run.stderr[-3000:]
    installed = sorted(root.rglob("site-packages"))
    assert len(installed) == 1, installed
    site = installed[0]
    assert {p.name for p in site.iterdir() if not p.name.endswith("-info")} == {RUNTIME_PACKAGE}
    runtime = site / RUNTIME_PACKAGE
    assert (runtime / "py.typed").is_file()
    assert sorted(p.name for p in (runtime / "ontology" / "data").iterdir()) == sorted(
        p.name for p in (ROOT / RUNTIME_PACKAGE / "ontology" / "data").glob("*.ttl"))
    assert {p.relative_to(runtime).as_posix() for p in runtime.rglob("*.py")} == {
        p.relative_to(ROOT / RUNTIME_PACKAGE).as_posix()
        for p in (ROOT / RUNTIME_PACKAGE).rglob("*.py")}
    assert not (root / "opt" / "lab_ws" / "share").exists()  # ament's marker is ROS 2's
    assert _files(checkout) == before


def _skill_package(folder: Path) -> Path:
    """A ROS 2 (ament_python) skill package with a legacy description, migrated by
    ``rewrite`` as a lab would, which declares the runtime in its package.xml."""
    (folder / "lab_skills").mkdir(parents=True)
    (folder / "resource").mkdir()
    (folder / "resource" / "lab_skills").write_text("")
    (folder / "lab_skills" / "__init__.py").write_text("")
    (folder / "lab_skills" / "descriptions.py").write_text(SKILL)
    (folder / "package.xml").write_text(SKILL_XML)
    (folder / "setup.py").write_text(SKILL_SETUP)
    run = subprocess.run([sys.executable, "-m", "ezmigrate", "rewrite", "--no-verify", "."],
                         cwd=folder, env=_environment(), capture_output=True, text=True,
                         check=False, timeout=300)
    assert run.returncode == 0, run.stderr
    assert "from ezskiros_runtime import" in (folder / "lab_skills" / "descriptions.py").read_text()
    assert "  <exec_depend>ezskiros_runtime</exec_depend>\n" in (folder / "package.xml").read_text()
    return folder


def test_colcon_builds_the_runtime_and_a_migrated_skill_that_imports_from_the_install(tmp_path):
    workspace = tmp_path / "ws"
    checkout = _checkout(workspace / "src" / "ezmigrate")
    _skill_package(workspace / "src" / "lab_skills")
    before = _files(checkout)
    env = _environment(ROS_VERSION="2", ROS_DISTRO="humble",
                       COLCON_HOME=str(tmp_path / "colcon_home"),
                       EZSKIROS_CACHE_DIR=str(tmp_path / "cache"))
    build = subprocess.run([str(COLCON), "--log-base", "log", "build", "--base-paths", "src",
                            "--build-base", "build", "--install-base", "install"],
                           cwd=workspace, env=env, capture_output=True, text=True, check=False,
                           timeout=600)
    assert build.returncode == 0, build.stdout[-3000:] + build.stderr[-3000:]
    assert "ezskiros_runtime" in build.stdout and "lab_skills" in build.stdout
    assert "doesn't explicitly install" not in build.stderr  # the ament index and manifest
    built = {p.name for p in (workspace / "build").iterdir() if p.is_dir()}
    assert built == {RUNTIME_PACKAGE, "lab_skills"}  # fixtures/ ignored, root no package
    install = workspace / "install"
    assert not list(install.glob("*/lib/python*/site-packages/ezmigrate"))
    assert (install / RUNTIME_PACKAGE / "share" / "ament_index" / "resource_index" / "packages"
            / RUNTIME_PACKAGE).is_file()
    assert (install / RUNTIME_PACKAGE / "share" / RUNTIME_PACKAGE / "package.xml").is_file()
    script = f". {install / 'setup.sh'} && exec {sys.executable} -c '{IMPORT}'"
    run = subprocess.run(["sh", "-c", script], cwd=tmp_path, env=env, capture_output=True,
                         text=True, check=False, timeout=300)
    assert run.returncode == 0, run.stderr
    runtime_file, skill_file, params = run.stdout.splitlines()
    assert Path(runtime_file).is_relative_to(install / RUNTIME_PACKAGE)
    assert Path(skill_file).is_relative_to(install / "lab_skills")
    assert params == "['Location', 'Object', 'Robot']"
    assert _files(checkout) == before  # the checkout stays clean: git status shows nothing
