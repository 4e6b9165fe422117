"""Shared helpers of the check tests: a small ontology with known domains and ranges, and
running the real check core (or the real CLI) on files written to a temporary folder."""

from __future__ import annotations

import subprocess
import sys
import textwrap
from pathlib import Path

from ezmigrate.checking.pipeline import run_check
from ezmigrate.lint.diagnostic import Diagnostic
from ezmigrate.lint.select import Selection, apply
from ezmigrate.verify.pool import PoolConfig
from ezskiros_runtime.ontology.load import load_index

ONTOLOGY = """\
@prefix rdf: <http://www.w3.org/1999/02/22-rdf-syntax-ns#> .
@prefix rdfs: <http://www.w3.org/2000/01/rdf-schema#> .
@prefix owl: <http://www.w3.org/2002/07/owl#> .
@prefix xsd: <http://www.w3.org/2001/XMLSchema#> .
@prefix skiros: <http://rvmi.aau.dk/ontologies/skiros.owl#> .
@prefix lab: <http://example.org/lab#> .

skiros:Thing a owl:Class .
skiros:Location a owl:Class ; rdfs:subClassOf skiros:Thing .
skiros:LargeBox a owl:Class ; rdfs:subClassOf skiros:Location .
skiros:Product a owl:Class ; rdfs:subClassOf skiros:Thing .
skiros:Gripper a owl:Class ; rdfs:subClassOf skiros:Thing .
skiros:contain a owl:ObjectProperty ; rdfs:domain skiros:Location ; rdfs:range skiros:Product .
skiros:Label a owl:DatatypeProperty ; rdfs:range xsd:string .
skiros:Open a owl:DatatypeProperty ; rdfs:range xsd:boolean .
skiros:near a owl:ObjectProperty .
lab:near a owl:ObjectProperty .
"""

LEGACY_HEADER = """\
from skiros2_common.core.abstract_skill import SkillDescription, ParamOptions
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


class Skill(SkillDescription):
    def createDescription(self):
"""

EZ_HEADER = """\
from ezskiros_runtime import SkillDescription, INFERRED, OPTIONAL
from ezskiros_runtime.ontology import skiros


class Skill(SkillDescription):
"""


def legacy(body: str) -> str:
    """A legacy module whose one description has ``body`` as its ``createDescription``."""
    return LEGACY_HEADER + textwrap.indent(textwrap.dedent(body).strip() + "\n", " " * 8)


def ezskiros(body: str) -> str:
    """An EzSkiROS module whose one description class has ``body``."""
    return EZ_HEADER + textwrap.indent(textwrap.dedent(body).strip() + "\n", " " * 4)


def ontology_file(folder: Path) -> Path:
    path = folder / "lab.ttl"
    path.write_text(ONTOLOGY, encoding="utf-8")
    return path


def lint(folder: Path, source: str, selection: Selection | None = None,
         name: str = "skill.py") -> list[Diagnostic]:
    """The diagnostics ``check`` reports for one file (every rule selected by default)."""
    folder.mkdir(parents=True, exist_ok=True)
    owl = ontology_file(folder.parent)
    (folder / name).write_text(source, encoding="utf-8")
    index = load_index([owl])
    outcome = run_check([folder / name], index, PoolConfig(workers=1, ontology=(str(owl),)))
    return apply(outcome.diagnostics, outcome.sources,
                 selection or Selection(select=("ALL",)))


def cli(*args: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    """``python -m ezmigrate check ARGS`` in a fresh process."""
    return subprocess.run([sys.executable, "-m", "ezmigrate", "check", *args], cwd=cwd,
                          capture_output=True, text=True, stdin=subprocess.DEVNULL,
                          timeout=300, check=False)
