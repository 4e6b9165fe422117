"""The process-wide active index: resolved once from configuration, replaceable."""

from __future__ import annotations

import importlib
import runpy
import shutil
import textwrap
from collections.abc import Iterator
from pathlib import Path

import pytest

from ezskiros_runtime.ontology.errors import OntologyConfigError
from ezskiros_runtime.ontology.index import bundled_ontology_path
from ezskiros_runtime.ontology.load import load_index

# The module itself, without asking the package (which would load the active ontology to see
# whether a prefix named `active` shadows the module).
active = importlib.import_module("ezskiros_runtime.ontology.active")

REPO = Path(__file__).resolve().parents[3]
FIXTURES = REPO / "fixtures" / "ontology"
WC = "http://example.org/ontologies/workcell.owl#"


@pytest.fixture(autouse=True)
def isolated(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[None]:
    """Each test starts unresolved, away from any pyproject, with its own cache."""
    saved = active._active, active._source
    active._active = active._source = None
    monkeypatch.setenv("EZSKIROS_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.delenv("EZSKIROS_ONTOLOGY", raising=False)
    workdir = tmp_path / "work"
    workdir.mkdir()
    monkeypatch.chdir(workdir)
    monkeypatch.setattr(active, "_hint", [])  # no skill file has asked yet
    yield
    active._active, active._source = saved


def test_resolved_once_from_the_environment(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("EZSKIROS_ONTOLOGY", str(FIXTURES / "inheritance.ttl"))
    first = active.active_index()
    assert first.is_class(WC + "Hand")
    source = active.active_source()
    assert source is not None and source.origin == "environment"
    monkeypatch.setenv("EZSKIROS_ONTOLOGY", str(FIXTURES / "paper.ttl"))
    assert active.active_index() is first  # cached for the process


def test_bundled_when_nothing_is_configured() -> None:
    index = active.active_index()
    assert index.sources == (str(bundled_ontology_path().resolve()),)
    source = active.active_source()
    assert source is not None and source.origin == "bundled"


def test_pyproject_in_the_working_directory(tmp_path: Path) -> None:
    (tmp_path / "work" / "pyproject.toml").write_text(
        f'[tool.ezmigrate]\nontology = ["{(FIXTURES / "paper.ttl").as_posix()}"]\n'
    )
    assert active.active_index().expand("skiros:GraspingPose") in active.active_index().classes


def test_use_ontology_with_an_index_paths_or_none(monkeypatch: pytest.MonkeyPatch) -> None:
    given = load_index([FIXTURES / "paper.ttl"], cache=False)
    assert active.use_ontology(given) is given
    assert active.active_index() is given
    from_paths = active.use_ontology([FIXTURES / "inheritance.ttl"])
    assert from_paths.is_class(WC + "Hand") and active.active_index() is from_paths
    monkeypatch.setenv("EZSKIROS_ONTOLOGY", str(FIXTURES / "paper.ttl"))
    reresolved = active.use_ontology(None)
    assert not reresolved.is_class(WC + "Hand")
    assert active.active_index() is reresolved


def test_use_ontology_with_a_missing_path_keeps_the_old_index() -> None:
    before = active.use_ontology([FIXTURES / "paper.ttl"])
    with pytest.raises(OntologyConfigError, match=r"missing\.ttl"):
        active.use_ontology(["missing.ttl"])
    assert active.active_index() is before


def _robot_package(tmp_path: Path, skill_source: str) -> tuple[Path, Path]:
    """A package configuring its ontology in pyproject.toml, and one skill file in it."""
    project = tmp_path / "robot_pkg"
    (project / "src" / "skills").mkdir(parents=True)
    shutil.copy(FIXTURES / "inheritance.ttl", project / "workcell.ttl")
    (project / "pyproject.toml").write_text('[tool.ezmigrate]\nontology = ["workcell.ttl"]\n')
    skill = project / "src" / "skills" / "grip.py"
    skill.write_text(textwrap.dedent(skill_source))
    return project / "pyproject.toml", skill


@pytest.mark.parametrize("skill_source", [
    "from ezskiros_runtime.ontology import workcell\n",  # the usual first request: a prefix
    """
    from ezskiros_runtime import ELEMENT, SkillDescription

    class Grip(SkillDescription):
        def description(self, H: ELEMENT("workcell:Hand")): ...
    """,
])
def test_unconfigured_the_pyproject_above_the_first_skill_file_names_the_ontology(
        tmp_path: Path, skill_source: str) -> None:
    """On a robot the working directory is arbitrary: the skill's own package decides."""
    pyproject, skill = _robot_package(tmp_path, skill_source)
    runpy.run_path(str(skill))
    assert active.active_index().is_class(WC + "Hand")
    assert active.active_source().origin == f"pyproject:{pyproject}"


def test_the_working_directory_still_comes_first(tmp_path: Path) -> None:
    _theirs, skill = _robot_package(tmp_path, "from ezskiros_runtime.ontology import skiros\n")
    ours = Path.cwd() / "pyproject.toml"
    shutil.copy(FIXTURES / "paper.ttl", ours.parent / "paper.ttl")
    ours.write_text('[tool.ezmigrate]\nontology = ["paper.ttl"]\n')
    runpy.run_path(str(skill))
    assert active.active_source().origin == f"pyproject:{ours}"
