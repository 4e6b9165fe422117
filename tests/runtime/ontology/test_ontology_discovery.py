"""With nothing configured, a command loads the core plus the repository's own ``owl/`` files.

Real files in a temporary repository made with ``git init``; the CLI runs as a subprocess.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from ezskiros_runtime.ontology.config import resolve_ontology_paths
from ezskiros_runtime.ontology.index import bundled_ontology_path
from ezskiros_runtime.ontology.load import load_index

LAB = "http://lab.example.org/ontologies/lab.owl#"
PROJECT = f"""\
@prefix owl: <http://www.w3.org/2002/07/owl#> .
@prefix rdfs: <http://www.w3.org/2000/01/rdf-schema#> .
@prefix skiros: <http://rvmi.aau.dk/ontologies/skiros.owl#> .
@prefix lab: <{LAB}> .

<http://lab.example.org/ontologies/lab.owl> a owl:Ontology .
lab:Workstation a owl:Class ; rdfs:subClassOf skiros:Location .
lab:Paint a owl:Class ; rdfs:subClassOf skiros:Product .
"""
ROBOT = f"""\
<?xml version="1.0"?>
<rdf:RDF xmlns:rdf="http://www.w3.org/1999/02/22-rdf-syntax-ns#"
         xmlns:owl="http://www.w3.org/2002/07/owl#"
         xmlns:lab="{LAB}">
  <owl:NamedIndividual rdf:about="{LAB}station_1">
    <rdf:type rdf:resource="{LAB}Workstation"/>
  </owl:NamedIndividual>
  <owl:NamedIndividual rdf:about="{LAB}red_paint">
    <rdf:type rdf:resource="{LAB}Paint"/>
  </owl:NamedIndividual>
</rdf:RDF>
"""
VENDORED_CORE = """\
@prefix owl: <http://www.w3.org/2002/07/owl#> .
@prefix skiros: <http://rvmi.aau.dk/ontologies/skiros.owl#> .

skiros:Location a owl:Class .
skiros:Product a owl:Class .
"""
SKILL = """\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


class Paint(SkillDescription):
    def createDescription(self):
        self.addParam("Station", Element("lab:Workstation"), ParamTypes.Required)
        self.addParam("Color", Element("lab:Paint"), ParamTypes.Required)
"""


def _repository(root: Path, git: bool = True) -> Path:
    (root / "owl").mkdir(parents=True)
    (root / "owl" / "lab.ttl").write_text(PROJECT, encoding="utf-8")
    (root / "owl" / "robot.owl").write_text(ROBOT, encoding="utf-8")
    (root / "vendor" / "skiros2" / "owl").mkdir(parents=True)
    (root / "vendor" / "skiros2" / "owl" / "skiros.owl").write_text(VENDORED_CORE,
                                                                     encoding="utf-8")
    (root / ".venv" / "owl").mkdir(parents=True)  # never searched
    (root / ".venv" / "owl" / "junk.ttl").write_text("not turtle", encoding="utf-8")
    skills = root / "lab_skills" / "src" / "lab_skills"
    skills.mkdir(parents=True)
    (skills / "paint.py").write_text(SKILL, encoding="utf-8")
    if git:
        subprocess.run(["git", "init", "-q", str(root)], check=True)
    return skills


def test_the_core_plus_every_owl_file_of_the_repository(tmp_path):
    skills = _repository(tmp_path / "repo")
    source = resolve_ontology_paths(None, environ={}, start=skills, roots=[skills])
    root = tmp_path / "repo"
    assert source.origin == f"discovered:{root.resolve()}"
    assert source.paths == (bundled_ontology_path(), (root / "owl" / "lab.ttl").resolve(),
                            (root / "owl" / "robot.owl").resolve())
    assert source.skipped == ((root / "vendor" / "skiros2" / "owl" / "skiros.owl").resolve(),)
    line = source.describe()
    assert "owl/lab.ttl, owl/robot.owl" in line and "vendored SkiROS2 copies skipped" in line


def test_project_classes_are_known_and_individuals_are_not_classes(tmp_path):
    skills = _repository(tmp_path / "repo")
    source = resolve_ontology_paths(None, environ={}, start=skills, roots=[skills])
    index = load_index(list(source.paths), cache=False)
    assert index.is_class(LAB + "Workstation") and index.is_class(LAB + "Paint")
    assert not index.is_class(LAB + "station_1") and not index.is_class(LAB + "red_paint")
    assert index.is_class("http://rvmi.aau.dk/ontologies/skiros.owl#TransformationPose")


def test_outside_git_only_the_given_paths_are_searched(tmp_path):
    skills = _repository(tmp_path / "repo", git=False)
    inside = resolve_ontology_paths(None, environ={}, start=skills, roots=[tmp_path / "repo"])
    assert inside.origin.startswith("discovered:")
    alone = resolve_ontology_paths(None, environ={}, start=skills, roots=[skills])
    assert alone.origin == "bundled" and alone.paths == ()


def test_configuration_wins_over_discovery(tmp_path):
    skills = _repository(tmp_path / "repo")
    mine = tmp_path / "mine.ttl"
    mine.write_text(PROJECT, encoding="utf-8")
    assert resolve_ontology_paths([mine], environ={}, roots=[skills]).origin == "argument"
    assert resolve_ontology_paths(None, environ={"EZSKIROS_ONTOLOGY": str(mine)},
                                  roots=[skills]).origin == "environment"
    (tmp_path / "repo" / "pyproject.toml").write_text(
        f'[tool.ezmigrate]\nontology = ["{mine}"]\n', encoding="utf-8")
    assert resolve_ontology_paths(None, environ={}, start=skills,
                                  roots=[skills]).origin.startswith("pyproject:")


@pytest.mark.parametrize("command", ["rewrite", "check"])
def test_each_run_says_once_which_files_it_used(tmp_path, command):
    skills = _repository(tmp_path / "repo")
    report = tmp_path / "report.json"
    extra = ["--dry-run", "--no-verify", "--report", str(report)] if command == "rewrite" \
        else []
    run = subprocess.run([sys.executable, "-m", "ezmigrate", command, str(skills), *extra],
                         capture_output=True, text=True, check=False, timeout=600,
                         env={"PATH": "/usr/bin:/bin", "HOME": str(tmp_path)})
    lines = [line for line in run.stderr.splitlines() if "owl/lab.ttl" in line]
    assert len(lines) == 1, run.stderr
    assert lines[0].startswith("ezmigrate: ontology: the bundled SkiROS2 core plus the owl/")
    assert "unknown" not in run.stderr, run.stderr  # lab:Workstation, lab:Paint are known
    if command == "rewrite":
        data = json.loads(report.read_text(encoding="utf-8"))
        assert "owl/robot.owl" in data["ontology"]
        assert [s["status"] for s in data["skills"]] == ["converted"]


def test_the_project_excludes_are_not_searched(tmp_path):
    """A nested repository of its own (a fixture, a vendored lab) stays out when excluded."""
    skills = _repository(tmp_path / "repo")
    (tmp_path / "repo" / "pyproject.toml").write_text(
        '[tool.ezmigrate]\nexclude = ["owl/robot.owl", "vendor"]\n', encoding="utf-8")
    run = subprocess.run([sys.executable, "-m", "ezmigrate", "check", str(skills)],
                         capture_output=True, text=True, check=False, timeout=600,
                         env={"PATH": "/usr/bin:/bin", "HOME": str(tmp_path)})
    line = next(x for x in run.stderr.splitlines() if x.startswith("ezmigrate: ontology"))
    assert line.endswith("owl/ folders of " + str((tmp_path / "repo").resolve())
                         + ": owl/lab.ttl"), line


def test_only_files_at_or_below_an_owl_folder_of_the_repository_count(tmp_path):
    """``owl/`` at any depth below the searched folder, and every folder below it; the
    searched folder's own name does not count (a repository called ``owl``)."""
    from ezskiros_runtime.ontology.discovery import discover

    root = tmp_path / "owl"
    for relative in ("top.ttl", "docs/loose.owl", "owl/a.ttl", "owl/sub/deep/b.owl",
                     "pkg/owl/c.rdf", "pkg/owlish/d.ttl", "pkg/owl/.hidden/e.ttl"):
        (root / relative).parent.mkdir(parents=True, exist_ok=True)
        (root / relative).write_text(PROJECT, encoding="utf-8")
    found = discover(root)
    assert [p.relative_to(root).as_posix() for p in found.files] == [
        "owl/a.ttl", "owl/sub/deep/b.owl", "pkg/owl/c.rdf"]
