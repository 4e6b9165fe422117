"""A hostile ``.owl`` file in a repository's ``owl/`` folder neither hangs ``check`` nor
``rewrite``: it is skipped with one warning naming it, and named explicitly it is an error
naming its file and line (issue 28, part 5).

The real command in a subprocess, on a ``git init`` repository in a temporary folder. The
timeout is only a safety net should the guard be lost (the file would never finish
parsing); what the tests hold is the output.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
from hostile_ontology import FLAT, HOSTILE, NESTED_LINE, chain_turtle

SKILL = """\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


class Paint(SkillDescription):
    def createDescription(self):
        self.addParam("Station", Element("lab:Workstation"), ParamTypes.Required)
"""
SAFETY_NET = 120
"""Seconds: far above a run's few, far below a parse that never ends."""


def _repository(root: Path) -> Path:
    (root / "owl").mkdir(parents=True)
    (root / "owl" / "hostile.owl").write_text(HOSTILE, encoding="utf-8")
    (root / "owl" / "lab.owl").write_text(FLAT, encoding="utf-8")
    (root / "pkg").mkdir()
    (root / "pkg" / "paint.py").write_text(SKILL, encoding="utf-8")
    subprocess.run(["git", "init", "-q", str(root)], check=True)
    return root


def _ezmigrate(repo: Path, *args: str,
               env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    env = {**{k: v for k, v in os.environ.items() if not k.startswith("EZSKIROS_ONTOLOGY")},
           "EZSKIROS_CACHE_DIR": str(repo.parent / "cache"), **(env or {})}
    return subprocess.run([sys.executable, "-m", "ezmigrate", *args], cwd=repo,
                          capture_output=True, text=True, env=env, timeout=SAFETY_NET,
                          check=False)


@pytest.mark.parametrize("command", [["check", "."], ["rewrite", "--dry-run", "."]])
def test_a_discovered_hostile_file_is_skipped_with_one_warning(tmp_path: Path,
                                                               command: list[str]) -> None:
    repo = _repository(tmp_path / "repo")
    run = _ezmigrate(repo, *command)
    assert run.returncode == 0, run.stderr
    warnings = [line for line in run.stderr.splitlines() if "warning" in line]
    assert len(warnings) == 1, run.stderr
    assert f"owl/hostile.owl:{NESTED_LINE}: refused before parsing" in warnings[0]
    assert "skipped" in warnings[0]
    described = next(line for line in run.stderr.splitlines() if "ontology:" in line)
    assert "owl/lab.owl" in described and "unreadable, skipped: owl/hostile.owl" in described
    assert "EZ209" not in run.stdout and "prefix 'lab'" not in run.stderr, run.stdout
    if command[0] == "rewrite":  # lab:Workstation is known: the flat file beside it loaded
        assert "Station: lab.Workstation" in run.stdout


def test_the_hostile_file_named_explicitly_is_an_error_with_its_file_and_line(
        tmp_path: Path) -> None:
    repo = _repository(tmp_path / "repo")
    run = _ezmigrate(repo, "check", "--ontology", "owl/hostile.owl", ".")
    assert run.returncode == 2, run.stderr
    hostile = (repo / "owl" / "hostile.owl").resolve()
    assert f"ezmigrate: error: {hostile}:{NESTED_LINE}: refused before parsing" in run.stderr
    assert "billion laughs" in run.stderr


OUTSIDE_LAB = """\
@prefix lab: <http://lab.example.org/ontologies/lab.owl#> .
@prefix owl: <http://www.w3.org/2002/07/owl#> .
@prefix rdfs: <http://www.w3.org/2000/01/rdf-schema#> .
lab:Outside a owl:Class ; rdfs:subClassOf <http://rvmi.aau.dk/ontologies/skiros.owl#Location> .
"""
OUTSIDE_SKILL = SKILL.replace("lab:Workstation", "lab:Outside") + \
    '        self.addParam("Inside", Element("lab:Workstation"), ParamTypes.Required)\n'


def test_an_ontology_symlink_leading_outside_the_repository_is_not_loaded(
        tmp_path: Path) -> None:
    """Issue 41: ``owl/lab.ttl`` linked to a file elsewhere was said to be skipped, yet
    its classes were loaded. Now using its class is unknown vocabulary (EZ209)."""
    outside = tmp_path / "elsewhere"
    outside.mkdir()
    (outside / "lab.ttl").write_text(OUTSIDE_LAB, encoding="utf-8")
    repo = tmp_path / "repo"
    (repo / "owl").mkdir(parents=True)
    (repo / "owl" / "workstation.owl").write_text(FLAT, encoding="utf-8")
    (repo / "owl" / "lab.ttl").symlink_to(outside / "lab.ttl")
    (repo / "pkg").mkdir()
    (repo / "pkg" / "paint.py").write_text(OUTSIDE_SKILL, encoding="utf-8")
    subprocess.run(["git", "init", "-q", str(repo)], check=True)
    run = _ezmigrate(repo, "check", ".")
    assert "owl/lab.ttl: symlink leads outside the given paths, skipped" in run.stderr
    assert "Traceback" not in run.stderr
    unknown = [line for line in run.stdout.splitlines() if "lab:Outside" in line]
    assert len(unknown) == 1 and "EZ209" in unknown[0], run.stdout + run.stderr
    assert "not in the loaded ontology" in unknown[0]
    assert "lab:Workstation" not in run.stdout.replace("did you mean lab:Workstation", "")


def test_a_discovered_file_over_a_limit_is_skipped_and_the_run_goes_on(
        tmp_path: Path) -> None:
    """Issue 41: a file over a limit is refused with its name, the limit and the variable
    that raises it; the other files load (``lab:Workstation`` is known)."""
    repo = _repository(tmp_path / "repo")
    (repo / "owl" / "hostile.owl").unlink()
    (repo / "owl" / "chain.ttl").write_text(chain_turtle(3000), encoding="utf-8")
    run = _ezmigrate(repo, "check", ".", env={"EZSKIROS_ONTOLOGY_MAX_TRIPLES": "2000"})
    assert run.returncode == 0, run.stderr
    warnings = [line for line in run.stderr.splitlines() if "warning" in line]
    assert len(warnings) == 1, run.stderr
    assert "owl/chain.ttl: refused: it holds more than 2,000 triples" in warnings[0]
    assert "EZSKIROS_ONTOLOGY_MAX_TRIPLES" in warnings[0] and "skipped" in warnings[0]
    assert "lab:Workstation" not in run.stdout  # the other file's class is known
