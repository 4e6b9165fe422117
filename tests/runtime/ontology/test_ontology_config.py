"""Where the ontology comes from: argument > environment > pyproject.toml > bundled."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from ezskiros_runtime.ontology.config import (
    OntologySource,
    find_tool_config,
    resolve_ontology_paths,
)
from ezskiros_runtime.ontology.errors import OntologyConfigError, OntologyError


@pytest.fixture
def project(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A project folder with ontology files, a configured pyproject.toml, and a subfolder."""
    root = tmp_path / "project"
    (root / "onto").mkdir(parents=True)
    (root / "src" / "skills").mkdir(parents=True)
    for name in ("a.ttl", "b.owl", "env.ttl", "arg.ttl"):
        (root / "onto" / name).write_text("")
    (root / "pyproject.toml").write_text(
        '[project]\nname = "robot"\n\n[tool.ezmigrate]\nontology = ["onto/a.ttl", "onto/b.owl"]\n'
    )
    monkeypatch.chdir(root / "src")
    return root


def test_pyproject_paths_relative_to_its_folder(project: Path) -> None:
    source = resolve_ontology_paths(environ={}, start=project / "src" / "skills")
    assert source.origin == f"pyproject:{project / 'pyproject.toml'}"
    assert source.paths == (project / "onto" / "a.ttl", project / "onto" / "b.owl")


def test_start_defaults_to_the_working_directory(project: Path) -> None:
    source = resolve_ontology_paths(environ={})
    assert source.origin.startswith("pyproject:")


def test_start_may_be_a_file(project: Path) -> None:
    skill = project / "src" / "skills" / "pick.py"
    skill.write_text("")
    assert resolve_ontology_paths(environ={}, start=skill).origin.startswith("pyproject:")


def test_environment_beats_pyproject_and_splits_on_pathsep(project: Path) -> None:
    value = os.pathsep.join([str(project / "onto" / "env.ttl"), "../onto/a.ttl", ""])
    source = resolve_ontology_paths(environ={"EZSKIROS_ONTOLOGY": value}, start=project)
    assert source.origin == "environment"
    # relative entries are relative to the working directory (project/src)
    assert source.paths == (project / "onto" / "env.ttl", project / "src" / ".." / "onto" / "a.ttl")


def test_argument_beats_environment(project: Path) -> None:
    env = {"EZSKIROS_ONTOLOGY": str(project / "onto" / "env.ttl")}
    source = resolve_ontology_paths(["../onto/arg.ttl", project / "onto"], environ=env)
    assert source.origin == "argument"
    assert source.paths == (project / "src" / ".." / "onto" / "arg.ttl", project / "onto")


def test_a_single_argument_string(project: Path) -> None:
    source = resolve_ontology_paths(str(project / "onto"), environ={})  # type: ignore[arg-type]
    assert source.paths == (project / "onto",)


def test_empty_argument_and_blank_environment_fall_through(project: Path) -> None:
    source = resolve_ontology_paths([], environ={"EZSKIROS_ONTOLOGY": "  "}, start=project)
    assert source.origin.startswith("pyproject:")


def test_bundled_when_nothing_is_configured(tmp_path: Path) -> None:
    source = resolve_ontology_paths(environ={}, start=tmp_path)
    assert source == OntologySource((), "bundled")
    assert "bundled" in source.describe()


def test_nearest_configured_pyproject_wins(project: Path) -> None:
    inner = project / "src"
    (inner / "pyproject.toml").write_text('[tool.ezmigrate]\nontology = "../onto/env.ttl"\n')
    source = resolve_ontology_paths(environ={}, start=inner / "skills")
    assert source.origin == f"pyproject:{inner / 'pyproject.toml'}"
    assert source.paths == (inner / ".." / "onto" / "env.ttl",)


def test_nearest_pyproject_is_the_project_even_without_our_table(project: Path) -> None:
    # Same rule as ezmigrate.cli.config: all [tool.ezmigrate] settings come from one file.
    (project / "src" / "pyproject.toml").write_text("[tool.ruff]\nline-length = 100\n")
    source = resolve_ontology_paths(environ={}, start=project / "src" / "skills")
    assert source.origin == "bundled"
    assert find_tool_config(project / "src" / "skills") == (project / "src" / "pyproject.toml", {})
    assert find_tool_config(project.parent) is None


def test_table_without_ontology_key_means_bundled(project: Path) -> None:
    (project / "src" / "pyproject.toml").write_text("[tool.ezmigrate]\nstrict = true\n")
    source = resolve_ontology_paths(environ={}, start=project / "src")
    assert source.origin == "bundled"
    found = find_tool_config(project / "src")
    assert found is not None and found[1] == {"strict": True}


def test_missing_paths_name_their_origin(project: Path) -> None:
    with pytest.raises(OntologyConfigError, match=r"nope\.ttl.*--ontology"):
        resolve_ontology_paths(["nope.ttl"], environ={})
    with pytest.raises(OntologyConfigError, match=r"gone\.owl.*EZSKIROS_ONTOLOGY"):
        resolve_ontology_paths(environ={"EZSKIROS_ONTOLOGY": "gone.owl"})
    (project / "pyproject.toml").write_text('[tool.ezmigrate]\nontology = ["onto/missing.ttl"]\n')
    with pytest.raises(OntologyConfigError) as caught:
        resolve_ontology_paths(environ={}, start=project)
    assert "missing.ttl" in str(caught.value)
    assert str(project / "pyproject.toml") in str(caught.value)


def test_bad_pyproject_is_a_config_error(project: Path) -> None:
    (project / "pyproject.toml").write_text("[tool.ezmigrate\nontology = 1\n")
    with pytest.raises(OntologyConfigError, match="invalid TOML"):
        resolve_ontology_paths(environ={}, start=project)
    (project / "pyproject.toml").write_text("[tool.ezmigrate]\nontology = 1\n")
    with pytest.raises(OntologyConfigError, match="path or a list of paths"):
        resolve_ontology_paths(environ={}, start=project)
    assert issubclass(OntologyConfigError, OntologyError)
