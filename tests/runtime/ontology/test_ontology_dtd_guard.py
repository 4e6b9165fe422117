"""Ontology files are untrusted input: a DTD that could expand without bound or reach
outside the file is refused before rdflib reads it (issue 28, part 5).

Real files in temporary folders, read by the real loader; the hostile file
(``tests/hostile_ontology.py``) is a 1 KB "billion laughs" with one external entity, which
rdflib alone does not finish parsing. The timeouts are only a safety net for a regression
(the guard gone): no test races a clock.
"""

from __future__ import annotations

import importlib
import logging
import subprocess
from collections.abc import Iterator
from pathlib import Path

import pytest
import rdflib
from hostile_ontology import FLAT, HOSTILE, LAB, NESTED_LINE
from rdflib import BNode
from shared_data import skiros2

from ezskiros_runtime.ontology.config import load_source, resolve_ontology_paths
from ezskiros_runtime.ontology.dtd_guard import FIRST_READ, MAX_ENTITY_TEXT, refusal
from ezskiros_runtime.ontology.errors import OntologyLoadError
from ezskiros_runtime.ontology.load import load_index
from ezskiros_runtime.ontology.parsing import OntologyFile, parse_ontology_file

active = importlib.import_module("ezskiros_runtime.ontology.active")


def _document(subset: str, root: str = "<r/>") -> bytes:
    return f'<?xml version="1.0"?>\n<!DOCTYPE r [\n{subset}\n]>\n{root}\n'.encode()


def test_the_hostile_file_is_refused_at_its_first_nested_entity() -> None:
    found = refusal(HOSTILE.encode())
    assert found is not None and found.line == NESTED_LINE
    assert "'lol1' refers to the entity 'lol0'" in found.reason
    assert len(HOSTILE.encode()) < 1500  # the size the issue reports: about 1 KB


@pytest.mark.parametrize(("subset", "words"), [
    ('<!ENTITY e SYSTEM "file:///etc/passwd">', "external entity 'e' (SYSTEM"),
    ('<!ENTITY e PUBLIC "-//x//EN" "http://x/e">', "external entity 'e' (PUBLIC"),
    ('<!ENTITY % p "x">', "parameter entity 'p'"),
    ("%p;", "refers to a parameter entity (%p;)"),
    ('<!ELEMENT r (%p;)>', "parameter entity inside a declaration"),
    ('<!ENTITY a "x">\n<!ENTITY b "&a;">', "'b' refers to the entity 'a'"),
    ('<!ENTITY a "x">\n<!ENTITY b "&#38;a;">', "'b' refers to the entity 'a'"),
    ('<!ENTITY a "x">\n<!ENTITY b "&#x26;a;">', "'b' refers to the entity 'a'"),
    ('<!ENTITY b "%p;">', "'b' refers to the entity 'p'"),
    (f'<!ENTITY long "{"x" * (MAX_ENTITY_TEXT + 1)}">', "expands quadratically"),
    ('<!ENTITY amp "&#38;#38;">', "redeclares the predefined entity 'amp'"),
    ('<![INCLUDE[ <!ENTITY a "x"> ]]>', "cannot vouch for"),
])
def test_each_refused_declaration_is_named_with_its_line(subset: str, words: str) -> None:
    found = refusal(_document(subset))
    assert found is not None, subset
    assert words in found.reason
    assert found.line == 2 + subset.count("\n") + 1  # the last line of the subset


def test_an_external_dtd_subset_is_refused() -> None:
    data = b'<?xml version="1.0"?>\n\n<!DOCTYPE rdf:RDF SYSTEM "http://x/rdf.dtd">\n<r/>'
    found = refusal(data)
    assert found is not None and found.line == 3 and "external DTD subset" in found.reason


@pytest.mark.parametrize("subset", [
    '<!ENTITY owl "http://www.w3.org/2002/07/owl#" >',
    "<!ENTITY q 'a &amp; b &lt; c &#38;#38; d'>",  # predefined and character references
    f'<!ENTITY long "{"x" * MAX_ENTITY_TEXT}">',
    '<!ELEMENT r ANY>\n<!ATTLIST r a CDATA "x > y">\n<!NOTATION n SYSTEM "n">',
    '<!-- <!ENTITY e SYSTEM "x"> in a comment --><?pi <!ENTITY % p "x"> ?>',
])
def test_flat_declarations_pass(subset: str) -> None:
    assert refusal(_document(subset)) is None


@pytest.mark.parametrize("data", [
    b"",
    b"@prefix x: <http://example.org/x#> .\nx:a x:b x:c .\n",  # Turtle, its format guessed
    b'<?xml version="1.0"?>\n<!DOCTYPE r [\n<!ENTITY e "cut off',  # the parser says so
    b'<r>\n<!DOCTYPE r [<!ENTITY e SYSTEM "x">]>\n</r>',  # after the root: never read
])
def test_what_is_no_dtd_gets_no_verdict(data: bytes) -> None:
    assert refusal(data) is None


def test_a_prolog_longer_than_the_first_read_is_read_to_its_end() -> None:
    data = _document("<!-- " + "x" * (FIRST_READ * 5) + ' -->\n<!ENTITY e SYSTEM "x">')
    found = refusal(data)
    assert found is not None and found.line == 4


@pytest.mark.parametrize("encode", [
    lambda text: text.encode("utf-16"),
    lambda text: b"\xef\xbb\xbf" + text.encode(),
    lambda text: (b'<?xml version="1.0" encoding="cp037"?>'
                  + text.partition("?>")[2].encode("cp037")),  # EBCDIC after the declaration
])
def test_the_prolog_is_read_in_the_encoding_the_parser_would_use(encode) -> None:
    text = '<?xml version="1.0"?>\n<!DOCTYPE r [\n<!ENTITY e SYSTEM "x">\n]><r/>'
    found = refusal(encode(text))
    assert found is not None and found.line == 3 and "external entity 'e'" in found.reason


def _files(folder: Path) -> list[Path]:
    return sorted(folder.rglob("*.owl"))


def test_skiros2s_own_files_pass_and_parse_exactly_as_rdflib_reads_them() -> None:
    files = _files(skiros2())
    assert len(files) == 6
    for path in files:
        data = path.read_bytes()
        assert refusal(data) is None, path
        ours = parse_ontology_file(OntologyFile(path, "xml", data))
        plain = rdflib.Graph().parse(data=data, format="xml", publicID=path.as_uri())
        named = {t for t in plain if not any(isinstance(x, BNode) for x in t)}
        assert len(ours) == len(plain)
        assert {t for t in ours if not any(isinstance(x, BNode) for x in t)} == named


def test_a_file_with_flat_entities_loads_with_them_expanded(tmp_path: Path) -> None:
    lab = tmp_path / "lab.owl"
    lab.write_text(FLAT, encoding="utf-8")
    assert load_index([lab], cache=False).is_class(LAB + "Workstation")


@pytest.mark.timeout(120)
def test_naming_the_hostile_file_is_an_error_with_its_file_and_line(tmp_path: Path) -> None:
    hostile = tmp_path / "hostile.owl"
    hostile.write_text(HOSTILE, encoding="utf-8")
    with pytest.raises(OntologyLoadError) as caught:
        load_index([hostile], cache=False)
    error = caught.value
    assert (error.path, error.line) == (str(hostile.resolve()), NESTED_LINE)
    assert str(error).startswith(f"{hostile.resolve()}:{NESTED_LINE}: refused before parsing")
    source = resolve_ontology_paths([hostile], environ={})
    with pytest.raises(OntologyLoadError, match="billion laughs"):
        load_source(source)  # named: the user's choice, so an error, never a skip


def _repository(root: Path) -> Path:
    """A git repository with a lab ontology and the hostile file in its ``owl/`` folder,
    and a skill module below it."""
    (root / "owl").mkdir(parents=True)
    (root / "owl" / "hostile.owl").write_text(HOSTILE, encoding="utf-8")
    (root / "owl" / "lab.owl").write_text(FLAT, encoding="utf-8")
    skill = root / "src" / "skills.py"
    skill.parent.mkdir()
    skill.write_text("# a skill module\n", encoding="utf-8")
    subprocess.run(["git", "init", "-q", str(root)], check=True)
    return skill


@pytest.mark.timeout(120)
def test_discovery_skips_the_hostile_file_with_one_warning_and_loads_the_rest(
        tmp_path: Path) -> None:
    skill = _repository(tmp_path / "repo")
    source = resolve_ontology_paths(None, environ={}, start=skill, roots=[skill])
    index, loaded = load_source(source)
    hostile = (tmp_path / "repo" / "owl" / "hostile.owl").resolve()
    assert [path for path, _reason in loaded.broken] == [hostile]
    assert hostile not in loaded.paths
    assert index.is_class(LAB + "Workstation")  # the flat file next to it still counts
    (warning,) = loaded.warnings()
    assert f"{hostile}:{NESTED_LINE}: refused before parsing" in warning and "skipped" in warning


@pytest.fixture
def unresolved(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[None]:
    """The process's active ontology unresolved, away from any configuration."""
    saved = active._active, active._source
    active._active = active._source = None
    monkeypatch.setenv("EZSKIROS_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.delenv("EZSKIROS_ONTOLOGY", raising=False)
    (tmp_path / "work").mkdir()
    monkeypatch.chdir(tmp_path / "work")
    monkeypatch.setattr(active, "_hint", [])
    yield
    active._active, active._source = saved


@pytest.mark.timeout(120)
def test_the_runtime_at_launch_logs_one_warning_and_runs(
        tmp_path: Path, unresolved: None, caplog: pytest.LogCaptureFixture) -> None:
    skill = _repository(tmp_path / "repo")
    active.note_source_file(skill)  # the first skill module that asks for vocabulary
    with caplog.at_level(logging.WARNING, logger="ezskiros_runtime"):
        index = active.active_index()
    assert index.is_class(LAB + "Workstation")
    warnings = [r.getMessage() for r in caplog.records if r.levelno >= logging.WARNING]
    assert len(warnings) == 1 and "owl/hostile.owl" in warnings[0], warnings
    assert "refused before parsing" in warnings[0]
