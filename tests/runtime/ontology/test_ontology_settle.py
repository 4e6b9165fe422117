"""Settling a source before loading it (``config.settle_source``, ``load.probe_index``): which
files load and the fingerprint of their index, known without decoding an index the cache
holds. A ``check`` the outcome cache answers needs no more; one that reads loads the index
after, and finds the same fingerprint."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from ezskiros_runtime.ontology.config import (
    OntologySource,
    load_source,
    resolve_ontology_paths,
    settle_source,
)
from ezskiros_runtime.ontology.errors import OntologyLoadError
from ezskiros_runtime.ontology.load import load_index, probe_index

REPO = Path(__file__).resolve().parents[3]
FIXTURES = REPO / "fixtures" / "ontology"

PROBE = """
import json, sys
from ezskiros_runtime.ontology.cache import stats
from ezskiros_runtime.ontology.load import probe_index
fingerprint, built = probe_index(sys.argv[1:])
print(json.dumps({"fingerprint": fingerprint, "built": built is not None,
                  "index": "ezskiros_runtime.ontology.index" in sys.modules,
                  "rdflib": "rdflib" in sys.modules, "hits": stats.hits}))
"""


@pytest.fixture
def cache_dir(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    folder = tmp_path / "cache"
    monkeypatch.setenv("EZSKIROS_CACHE_DIR", str(folder))
    return folder


@pytest.fixture
def lab(tmp_path: Path) -> Path:
    """A repository whose ``owl/`` folder holds a good file and an empty ``lth.owl``."""
    root = tmp_path / "lab"
    (root / "owl").mkdir(parents=True)
    shutil.copy(FIXTURES / "inheritance.ttl", root / "owl" / "inheritance.ttl")
    (root / "owl" / "lth.owl").write_text("", encoding="utf-8")
    (root / "pyproject.toml").write_text("[project]\nname = 'lab'\n", encoding="utf-8")
    return root


def test_a_probe_builds_once_then_answers_without_decoding(cache_dir: Path) -> None:
    ontology = FIXTURES / "inheritance.ttl"

    def child() -> dict[str, object]:
        done = subprocess.run([sys.executable, "-c", PROBE, str(ontology)],
                              capture_output=True, text=True, cwd=REPO, timeout=120,
                              env={**os.environ, "EZSKIROS_CACHE_DIR": str(cache_dir)},
                              check=True)
        return json.loads(done.stdout)

    cold, warm = child(), child()
    assert cold["built"] is True and cold["rdflib"] is True
    assert warm == {"fingerprint": cold["fingerprint"], "built": False, "index": False,
                    "rdflib": False, "hits": 0}
    assert load_index([ontology]).fingerprint == warm["fingerprint"]


def test_settling_leaves_out_a_broken_discovered_file_as_loading_does(
        lab: Path, cache_dir: Path) -> None:
    source = resolve_ontology_paths(None, start=lab, roots=[lab])
    assert source.origin.startswith("discovered:")
    settled = settle_source(source)
    index, loaded = load_source(source)
    assert settled.source == loaded
    assert [p.name for p, _ in settled.source.broken] == ["lth.owl"]
    assert "lth.owl" not in [p.name for p in settled.source.paths]
    assert settled.fingerprint == index.fingerprint == settled.index().fingerprint
    assert settled.index() is settled.index()  # loaded once


def test_a_named_broken_file_is_an_error_when_settling(lab: Path, cache_dir: Path) -> None:
    named = OntologySource((lab / "owl" / "lth.owl",), "argument")
    with pytest.raises(OntologyLoadError) as raised:
        settle_source(named)
    assert raised.value.path is not None and "lth.owl" in str(raised.value.path)
    with pytest.raises(OntologyLoadError):
        probe_index([lab / "owl" / "lth.owl"])  # refused again, from the cache


def test_a_probe_without_the_cache_builds_the_index(cache_dir: Path) -> None:
    fingerprint, built = probe_index([FIXTURES / "inheritance.ttl"], cache=False)
    assert built is not None and built.fingerprint == fingerprint
    assert not cache_dir.exists()  # nothing kept
