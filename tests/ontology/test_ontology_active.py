"""The process-wide active index: resolved once from configuration, replaceable."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest

from ezskiros_runtime.ontology import active
from ezskiros_runtime.ontology.errors import OntologyConfigError
from ezskiros_runtime.ontology.index import bundled_ontology_path, load_index

REPO = Path(__file__).resolve().parents[2]
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
