"""On the robot, the robot's ontology: the files the SkiROS2 world model server loads.

A stand-in package layout (``skiros2/owl`` and a workspace ``owl/`` folder in a temporary
folder) and a stand-in parameter source: no ROS. The last test runs a real process with
the recording SkiROS2 stand-in (so the SkiROS2 backend is active) and stand-in ``rospkg``
and ``rospy`` modules that answer from the temporary layout.
"""

from __future__ import annotations

import logging
import os
import subprocess
import sys
from pathlib import Path

from ezskiros_runtime.ontology.active import robot_source
from ezskiros_runtime.ontology.robot import robot_ontology_files

LAB = "http://lab.example.org/ontologies/lab.owl#"
CORE = """<?xml version="1.0"?>
<rdf:RDF xmlns:rdf="http://www.w3.org/1999/02/22-rdf-syntax-ns#"
         xmlns:rdfs="http://www.w3.org/2000/01/rdf-schema#"
         xmlns:owl="http://www.w3.org/2002/07/owl#">
  <owl:Class rdf:about="http://rvmi.aau.dk/ontologies/skiros.owl#Location"/>
  <owl:Class rdf:about="http://rvmi.aau.dk/ontologies/skiros.owl#Product"/>
</rdf:RDF>
"""
PROJECT = f"""<?xml version="1.0"?>
<rdf:RDF xmlns:rdf="http://www.w3.org/1999/02/22-rdf-syntax-ns#"
         xmlns:rdfs="http://www.w3.org/2000/01/rdf-schema#"
         xmlns:owl="http://www.w3.org/2002/07/owl#">
  <owl:Class rdf:about="{LAB}Workstation">
    <rdfs:subClassOf rdf:resource="http://rvmi.aau.dk/ontologies/skiros.owl#Location"/>
  </owl:Class>
</rdf:RDF>
"""


def _layout(root: Path) -> tuple[Path, Path]:
    package, workspace = root / "share" / "skiros2", root / "lab_ws" / "owl"
    (package / "owl" / "IEEE-1872-2015").mkdir(parents=True)
    (package / "owl" / "skiros.owl").write_text(CORE, encoding="utf-8")
    (package / "owl" / "IEEE-1872-2015" / "sumo.owl").write_text(CORE, encoding="utf-8")
    workspace.mkdir(parents=True)
    (workspace / "lab.owl").write_text(PROJECT, encoding="utf-8")
    return package, workspace


def test_the_core_package_files_then_the_workspace_files(tmp_path):
    package, workspace = _layout(tmp_path)
    files = robot_ontology_files(lambda name: package if name == "skiros2" else None,
                                 {"/wm/workspace_dir": str(workspace)}.get)
    assert files == (package / "owl" / "IEEE-1872-2015" / "sumo.owl",
                     package / "owl" / "skiros.owl", workspace / "lab.owl")
    assert robot_source(lambda name: package, {"workspace_dir": str(workspace)}.get).paths \
        == files


def test_an_unreadable_workspace_leaves_the_core_files_and_says_so(tmp_path, caplog):
    package, _ = _layout(tmp_path)
    with caplog.at_level(logging.WARNING, logger="ezskiros_runtime"):
        files = robot_ontology_files(lambda name: package, lambda name: None)
    assert files == (package / "owl" / "IEEE-1872-2015" / "sumo.owl",
                     package / "owl" / "skiros.owl")
    assert [r.getMessage() for r in caplog.records] == [
        "ezskiros_runtime: the world model's workspace_dir could not be read: checking skills "
        "against the skiros2 core files only"]


def test_without_the_package_the_bundled_core_with_one_line(tmp_path, caplog):
    with caplog.at_level(logging.WARNING, logger="ezskiros_runtime"):
        source = robot_source(lambda name: None, lambda name: None)
    assert (source.origin, source.paths) == ("bundled", ())
    assert len(caplog.records) == 1 and "bundled SkiROS2 core" in caplog.records[0].getMessage()


PROBE = """
from ezskiros_runtime.ontology.active import active_index, active_source
from ezskiros_runtime.dsl.backend import select_backend
index = active_index()
print(select_backend().name, active_source().origin,
      index.is_class("{lab}Workstation"))
"""


def test_a_launch_with_the_skiros2_backend_checks_against_the_robot_files(tmp_path):
    package, workspace = _layout(tmp_path / "ros")
    fakes = tmp_path / "fakes"
    fakes.mkdir()
    (fakes / "rospkg.py").write_text(
        "class RosPack:\n    def get_path(self, name):\n"
        f"        return {str(package)!r}\n", encoding="utf-8")
    (fakes / "rospy.py").write_text(
        f"def get_param(name, default=None):\n    return {str(workspace)!r} "
        "if name == '/wm/workspace_dir' else default\n", encoding="utf-8")
    recording = Path(__file__).resolve().parents[1] / "dsl" / "recording_skiros2"
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(recording), str(fakes)]),
               EZSKIROS_CACHE_DIR=str(tmp_path / "cache"))
    env.pop("EZSKIROS_ONTOLOGY", None)
    run = subprocess.run([sys.executable, "-c", PROBE.format(lab=LAB)], cwd=tmp_path, env=env,
                         capture_output=True, text=True, check=False, timeout=300)
    assert run.returncode == 0, run.stderr
    assert run.stdout.split() == ["skiros2", "robot", "True"], run.stderr
