"""Finding and parsing ontology files: formats, folders, and errors that name the file."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from ezskiros_runtime.ontology.errors import OntologyError, OntologyLoadError
from ezskiros_runtime.ontology.load import load_index
from ezskiros_runtime.ontology.parsing import collect_ontology_files

REPO = Path(__file__).resolve().parents[3]
FIXTURES = REPO / "fixtures" / "ontology"
FORMATS = FIXTURES / "formats"
FMT = "http://example.org/ontologies/formats.owl#"


def test_folder_mixes_formats_and_skips_unknown_extensions() -> None:
    index = load_index([FORMATS], cache=False)
    names = [Path(s).name for s in index.sources]
    assert names == ["gripper.owl", "grips.nt", "tool.ttl"]  # sorted; readme/camera skipped
    assert index.classes == {FMT + "Gripper", FMT + "Tool"}
    assert index.is_subclass(FMT + "Gripper", FMT + "Tool")  # across an .owl and a .ttl
    grips = index.property(FMT + "grips")  # from N-Triples
    assert grips is not None and grips.kind == "object"
    assert index.prefixes["formats"] == FMT


def test_explicit_file_with_unknown_extension_is_guessed() -> None:
    index = load_index([FORMATS / "camera.vocab"], cache=False)
    assert index.classes == {FMT + "Camera"}


def test_explicit_xml_with_unknown_extension_is_guessed(tmp_path: Path) -> None:
    odd = tmp_path / "gripper.data"
    shutil.copy(FORMATS / "gripper.owl", odd)
    assert load_index([odd], cache=False).is_class(FMT + "Gripper")


def test_folders_are_recursive_and_sorted(tmp_path: Path) -> None:
    (tmp_path / "b").mkdir()
    (tmp_path / "a" / "deep").mkdir(parents=True)
    (tmp_path / ".hidden").mkdir()
    shutil.copy(FORMATS / "tool.ttl", tmp_path / "b" / "tool.TTL")
    shutil.copy(FORMATS / "gripper.owl", tmp_path / "a" / "deep" / "gripper.owl")
    shutil.copy(FIXTURES / "broken" / "syntax_error.ttl", tmp_path / ".hidden" / "x.ttl")
    files = collect_ontology_files([tmp_path])
    assert [f.path.relative_to(tmp_path).as_posix() for f in files] == [
        "a/deep/gripper.owl",
        "b/tool.TTL",
    ]
    assert [f.format for f in files] == ["xml", "turtle"]


def test_same_file_twice_is_loaded_once() -> None:
    files = collect_ontology_files([FORMATS, FORMATS / "tool.ttl"])
    assert [f.path.name for f in files] == ["gripper.owl", "grips.nt", "tool.ttl"]


def test_several_paths_are_merged() -> None:
    index = load_index([FIXTURES / "paper.ttl", FIXTURES / "inheritance.ttl"], cache=False)
    assert index.expand("workcell:Hand") in index.classes
    assert index.expand("skiros:GraspingPose") in index.classes
    assert len(index.sources) == 2


def test_a_single_path_string_is_not_split_into_characters() -> None:
    index = load_index(str(FIXTURES / "paper.ttl"), cache=False)  # type: ignore[arg-type]
    assert len(index.sources) == 1


def test_turtle_syntax_error_names_file_and_line() -> None:
    broken = FIXTURES / "broken" / "syntax_error.ttl"
    with pytest.raises(OntologyLoadError) as caught:
        load_index([broken], cache=False)
    assert str(broken) in str(caught.value)
    assert f"{broken}:6:" in str(caught.value)
    assert "Turtle" in str(caught.value)
    assert caught.value.path == str(broken) and caught.value.line == 6


def test_xml_error_names_file_and_line() -> None:
    broken = FIXTURES / "broken" / "not_well_formed.owl"
    with pytest.raises(OntologyLoadError, match=r"not_well_formed\.owl:6: cannot parse as RDF/XML"):
        load_index([broken], cache=False)


def test_n_triples_error_names_file_and_line(tmp_path: Path) -> None:
    broken = tmp_path / "bad.nt"
    broken.write_text(
        "<http://x.org/a#b> <http://x.org/a#c> <http://x.org/a#d> .\n"
        "<http://x.org/a#b> <http://x.org/a#c> .\n"
    )
    with pytest.raises(OntologyLoadError) as caught:
        load_index([broken], cache=False)
    assert str(broken) in str(caught.value)
    assert caught.value.line == 2


def test_broken_file_inside_a_folder_is_named(tmp_path: Path) -> None:
    shutil.copy(FORMATS / "tool.ttl", tmp_path / "good.ttl")
    shutil.copy(FIXTURES / "broken" / "syntax_error.ttl", tmp_path / "zz_bad.ttl")
    with pytest.raises(OntologyLoadError, match=r"zz_bad\.ttl:6"):
        load_index([tmp_path], cache=False)


def test_unguessable_file_reports_both_attempts(tmp_path: Path) -> None:
    junk = tmp_path / "notes.vocab"
    junk.write_text("this is neither RDF/XML nor Turtle\n")
    with pytest.raises(OntologyLoadError) as caught:
        load_index([junk], cache=False)
    message = str(caught.value)
    assert str(junk) in message and "RDF/XML" in message and "Turtle" in message


def test_missing_path_and_empty_folder(tmp_path: Path) -> None:
    with pytest.raises(OntologyLoadError, match="not found"):
        load_index([tmp_path / "missing.owl"], cache=False)
    (tmp_path / "empty").mkdir()
    (tmp_path / "empty" / "readme.txt").write_text("no ontology here")
    with pytest.raises(OntologyLoadError, match="holds no ontology files"):
        load_index([tmp_path / "empty"], cache=False)


def test_load_errors_are_ontology_errors() -> None:
    assert issubclass(OntologyLoadError, OntologyError)
