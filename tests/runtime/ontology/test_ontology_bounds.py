"""Bounded ontology reading (issue 41): linear closures, and limits on bytes, triples, time
and entity expansion that refuse a file by name, with the limit and how to raise it.

Real files in temporary folders, parsed by the real rdflib (4.2.2 on the robot's 3.8 too).
The hostile files are scaled down and the limits lowered through their environment
variables, so every test runs in about a second; how time and memory grow with the chain
is measured in ``bench/bench_ontology_bounds.py`` (numbers in ``bench/RESULTS.md``).
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from hostile_ontology import CHAIN, chain_turtle, entity_owl

from ezskiros_runtime.ontology.config import OntologySource, load_source
from ezskiros_runtime.ontology.errors import OntologyLimitError, OntologyLoadError
from ezskiros_runtime.ontology.expressions import Named
from ezskiros_runtime.ontology.index import bundled_ontology_path
from ezskiros_runtime.ontology.load import load_index

REPO = Path(__file__).resolve().parents[3]
LAB = """\
@prefix lab: <http://lab.example.org/lab#> .
@prefix owl: <http://www.w3.org/2002/07/owl#> .
lab:Workstation a owl:Class .
"""


def _write(folder: Path, name: str, text: str) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / name
    path.write_text(text, encoding="utf-8")
    return path


def _cache_bytes(folder: Path) -> int:
    return sum(entry.stat().st_size for entry in folder.glob("ontology-index-*"))


def test_a_long_chain_loads_and_answers_through_the_whole_chain(tmp_path: Path) -> None:
    length = 3000
    chain = _write(tmp_path, "chain.ttl", chain_turtle(length, properties=True))
    index = load_index([chain], cache_dir=tmp_path / "cache")
    bottom, top = CHAIN + "C1", CHAIN + f"C{length}"
    assert index.is_subclass(bottom, top) and not index.is_subclass(top, bottom)
    assert len(index.superclasses(bottom)) == length
    assert index.witness(top, Named(bottom)) == bottom
    lowest = index.property(CHAIN + "p1")
    assert lowest is not None and len(lowest.super_properties) == length - 1
    assert lowest.domains == (Named(top),) and lowest.domain_sources == (CHAIN + f"p{length}",)
    warm = load_index([chain], cache_dir=tmp_path / "cache")
    assert warm.is_subclass(bottom, top) and warm.properties == index.properties


def test_the_cached_chain_grows_linearly_not_with_its_closure(tmp_path: Path) -> None:
    """Every class kept its ancestors before: doubling the chain quadrupled the entry
    (251 MB at 10,000). Direct edges only: doubling it doubles the entry."""
    sizes = []
    for length in (1000, 2000, 4000):
        chain = _write(tmp_path / str(length), "chain.ttl", chain_turtle(length))
        load_index([chain], cache_dir=tmp_path / str(length) / "cache")
        sizes.append(_cache_bytes(tmp_path / str(length) / "cache"))
    assert sizes[1] < 2.3 * sizes[0] and sizes[2] < 2.3 * sizes[1], sizes
    assert sizes[2] < 600_000, sizes  # the closure alone would be 8 million entries


def test_a_file_over_the_triple_limit_is_refused_with_its_name_and_the_limit(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    chain = _write(tmp_path, "chain.ttl", chain_turtle(500))
    monkeypatch.setenv("EZSKIROS_ONTOLOGY_MAX_TRIPLES", "200")
    with pytest.raises(OntologyLimitError) as refused:
        load_index([chain], cache_dir=tmp_path / "cache")
    message = str(refused.value)
    assert str(chain) in message and "200 triples" in message
    assert "EZSKIROS_ONTOLOGY_MAX_TRIPLES" in message
    assert refused.value.path == str(chain)
    monkeypatch.setenv("EZSKIROS_ONTOLOGY_MAX_TRIPLES", "1000")  # raised: loads now,
    index = load_index([chain], cache_dir=tmp_path / "cache")  # not the kept refusal
    assert index.is_subclass(CHAIN + "C1", CHAIN + "C500")


@pytest.mark.parametrize("suffix", [".owl", ".nt"])
def test_the_triple_limit_holds_for_every_format(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, suffix: str
) -> None:
    triples = "".join(f"<{CHAIN}C{n}> <http://www.w3.org/2000/01/rdf-schema#subClassOf> "
                      f"<{CHAIN}C{n + 1}> .\n" for n in range(300))
    if suffix == ".owl":
        import rdflib

        graph = rdflib.Graph()
        graph.parse(data=triples, format="nt")
        serialized = graph.serialize(format="xml")
        triples = serialized if isinstance(serialized, str) else serialized.decode("utf-8")
    path = _write(tmp_path, "big" + suffix, triples)
    monkeypatch.setenv("EZSKIROS_ONTOLOGY_MAX_TRIPLES", "100")
    with pytest.raises(OntologyLimitError, match="EZSKIROS_ONTOLOGY_MAX_TRIPLES"):
        load_index([path], cache=False)


def test_a_file_over_the_size_limit_is_refused_before_it_is_parsed(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    chain = _write(tmp_path, "chain.ttl", chain_turtle(100))
    monkeypatch.setenv("EZSKIROS_ONTOLOGY_MAX_BYTES", "1000")
    with pytest.raises(OntologyLimitError) as refused:
        load_index([chain], cache=False)
    assert str(chain) in str(refused.value) and "1,000 bytes" in str(refused.value)
    assert "EZSKIROS_ONTOLOGY_MAX_BYTES" in str(refused.value)


def test_a_parse_over_the_time_limit_is_refused(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A microsecond cannot hold 2,000 triples on any machine: the refusal is certain."""
    chain = _write(tmp_path, "chain.ttl", chain_turtle(2000))
    monkeypatch.setenv("EZSKIROS_ONTOLOGY_MAX_SECONDS", "0.000001")
    with pytest.raises(OntologyLimitError, match="EZSKIROS_ONTOLOGY_MAX_SECONDS") as refused:
        load_index([chain], cache=False)
    assert str(chain) in str(refused.value)


def test_many_expansions_of_a_flat_entity_are_refused(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """80,000 uses of a 256-character entity took minutes; scaled: 400 uses of 200."""
    owl = _write(tmp_path, "lab.owl", entity_owl(400, 200))
    monkeypatch.setenv("EZSKIROS_ONTOLOGY_MAX_ENTITY_EXPANSION", "50000")
    with pytest.raises(OntologyLimitError) as refused:
        load_index([owl], cache=False)
    assert f"{owl}:10: refused" in str(refused.value)
    assert "EZSKIROS_ONTOLOGY_MAX_ENTITY_EXPANSION" in str(refused.value)
    monkeypatch.setenv("EZSKIROS_ONTOLOGY_MAX_ENTITY_EXPANSION", "100000")
    assert load_index([owl], cache=False).is_class("http://example.org/x")


def test_the_number_of_entity_references_is_bounded(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    owl = _write(tmp_path, "lab.owl", entity_owl(300, 1))
    monkeypatch.setenv("EZSKIROS_ONTOLOGY_MAX_ENTITY_REFERENCES", "250")
    with pytest.raises(OntologyLimitError, match="more than 250 entity references"):
        load_index([owl], cache=False)


def test_a_discovered_file_over_a_limit_is_skipped_and_the_others_load(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    owl = tmp_path / "repo" / "owl"
    big = _write(owl, "chain.ttl", chain_turtle(1500))
    lab = _write(owl, "lab.ttl", LAB)
    monkeypatch.setenv("EZSKIROS_ONTOLOGY_MAX_TRIPLES", "1000")  # the core has about 500
    monkeypatch.setenv("EZSKIROS_CACHE_DIR", str(tmp_path / "cache"))
    source = OntologySource((bundled_ontology_path(), big, lab), f"discovered:{owl.parent}")
    index, loaded = load_source(source)
    assert index.is_class("http://lab.example.org/lab#Workstation")
    assert not index.is_class(CHAIN + "C1")
    [warning] = loaded.warnings()
    assert str(big) in warning and "EZSKIROS_ONTOLOGY_MAX_TRIPLES" in warning


def test_a_named_file_over_a_limit_stops_the_load(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    big = _write(tmp_path, "chain.ttl", chain_turtle(500))
    monkeypatch.setenv("EZSKIROS_ONTOLOGY_MAX_TRIPLES", "200")
    with pytest.raises(OntologyLoadError, match=r"chain\.ttl"):
        load_source(OntologySource((big,), "argument"))


ROBOT = """
import json
from ezskiros_runtime.ontology.errors import OntologyLoadError
from ezskiros_runtime.ontology.active import active_index
try:
    active_index()
except OntologyLoadError as error:
    print(json.dumps({"refused": str(error)}))
else:
    print(json.dumps({"refused": None}))
"""


def test_the_robot_importing_the_runtime_gets_the_same_refusal(tmp_path: Path) -> None:
    """The runtime in a fresh process, configured as on a robot by the environment: the
    refusal, not a hang (the timeout is only the safety net)."""
    big = _write(tmp_path, "chain.ttl", chain_turtle(500))
    env = {**os.environ, "EZSKIROS_ONTOLOGY": str(big),
           "EZSKIROS_ONTOLOGY_MAX_TRIPLES": "200",
           "EZSKIROS_CACHE_DIR": str(tmp_path / "cache")}
    run = subprocess.run([sys.executable, "-c", ROBOT], capture_output=True, text=True,
                         env=env, cwd=str(tmp_path), timeout=120, check=True)
    refused = json.loads(run.stdout)["refused"]
    assert refused is not None and str(big) in refused
    assert "200 triples" in refused and "EZSKIROS_ONTOLOGY_MAX_TRIPLES" in refused


def test_a_limit_set_to_nonsense_keeps_the_default(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    from ezskiros_runtime.ontology.limits import MAX_TRIPLES

    for raw in ("", "lots", "-5", "0", "inf"):
        assert MAX_TRIPLES.value({"EZSKIROS_ONTOLOGY_MAX_TRIPLES": raw}) == MAX_TRIPLES.default
    assert MAX_TRIPLES.value({"EZSKIROS_ONTOLOGY_MAX_TRIPLES": "1_000"}) == 1000
