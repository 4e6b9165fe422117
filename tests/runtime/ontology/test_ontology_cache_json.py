"""The index cache holds no pickle (issue 40): JSON checked field by field, an entry that
does not check out is rebuilt from the files, and nothing in the folder can run code.

Real files, real rdflib, a real cache folder in a temporary directory; the pickle that
would write a marker is a real pickle, put where the old cache kept its entries and where
the new one keeps them.
"""

from __future__ import annotations

import importlib
import json
import os
import pickle
import shutil
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

import pytest
from shared_data import skiros2

from ezskiros_runtime.ontology.index import OntologyIndex
from ezskiros_runtime.ontology.index_codec import encode
from ezskiros_runtime.ontology.load import load_index

# The module itself, not the package's attribute: a prefix named `cache` would win there.
index_cache = importlib.import_module("ezskiros_runtime.ontology.cache")
REPO = Path(__file__).resolve().parents[3]
FIXTURES = REPO / "fixtures" / "ontology"


class _WritesMarker:
    """Unpickling this calls ``os.system`` to create the marker file."""

    def __init__(self, marker: Path) -> None:
        self.marker = marker

    def __reduce__(self) -> tuple[Any, ...]:
        return (os.system, (f"touch {self.marker}",))


@pytest.fixture
def files(tmp_path: Path) -> list[Path]:
    folder = tmp_path / "onto"
    folder.mkdir()
    for name in ("inheritance.ttl", "paper.ttl"):
        shutil.copy(FIXTURES / name, folder / name)
    return [folder / "inheritance.ttl", folder / "paper.ttl"]


def _same(one: OntologyIndex, other: OntologyIndex) -> None:
    assert encode(one, "v") == encode(other, "v")
    assert all(one.superclasses(c) == other.superclasses(c) for c in one.classes)


def _entry(cache_dir: Path, files: list[Path]) -> Path:
    fingerprint = load_index(files, cache=False).fingerprint
    cache_dir.mkdir(exist_ok=True)
    return index_cache.cache_path(cache_dir, fingerprint)


def test_an_entry_is_json_and_round_trips(files: list[Path], tmp_path: Path) -> None:
    cache_dir = tmp_path / "cache"
    built = load_index(files, cache_dir=cache_dir)
    entry = index_cache.cache_path(cache_dir, built.fingerprint)
    assert entry.suffix == ".json"
    assert json.loads(entry.read_bytes())["fingerprint"] == built.fingerprint
    hits = index_cache.stats.hits
    _same(load_index(files, cache_dir=cache_dir), built)
    assert index_cache.stats.hits == hits + 1


def _forgeries(good: bytes) -> list[bytes]:
    data = json.loads(good)
    wrong_kind = json.loads(good)
    wrong_kind["properties"][0][1] = "magic"
    other_content = dict(data, fingerprint="0" * 64)
    other_version = dict(data, version="0")
    extra_class = dict(data, classes=[*data["classes"], 7])
    bad_expression = json.loads(good)
    bad_expression["properties"][0][2] = [["exec", "rm -rf /"]]
    return [b"", good[: len(good) // 2], b"\x80\x05 not json", b"[]", b"null",
            json.dumps(wrong_kind).encode(), json.dumps(other_content).encode(),
            json.dumps(other_version).encode(), json.dumps(extra_class).encode(),
            json.dumps(bad_expression).encode(), b"{" * 100_000]


def test_a_forged_corrupt_or_truncated_entry_gives_the_index_of_no_cache(
    files: list[Path], tmp_path: Path
) -> None:
    reference = load_index(files, cache=False)
    good_dir = tmp_path / "good"
    load_index(files, cache_dir=good_dir)
    good = index_cache.cache_path(good_dir, reference.fingerprint).read_bytes()
    for number, forged in enumerate(_forgeries(good)):
        cache_dir = tmp_path / f"forged-{number}"
        entry = _entry(cache_dir, files)
        entry.write_bytes(forged)
        hits = index_cache.stats.hits
        loaded = load_index(files, cache_dir=cache_dir)
        assert index_cache.stats.hits == hits, forged[:60]  # not taken from the entry
        _same(loaded, reference)
        assert entry.read_bytes() == good  # rebuilt, and the entry written again


def test_a_pickle_in_the_cache_is_never_unpickled(files: list[Path], tmp_path: Path) -> None:
    cache_dir = tmp_path / "cache"
    marker = tmp_path / "marker"
    payload = pickle.dumps(_WritesMarker(marker))
    entry = _entry(cache_dir, files)
    entry.write_bytes(payload)  # under the name the index would be read from
    legacy = entry.with_suffix(".pickle")
    legacy.write_bytes(payload)  # and where earlier versions kept it
    reference = load_index(files, cache=False)
    env = {**os.environ, "EZSKIROS_CACHE_DIR": str(cache_dir)}
    child = ("import sys\nfrom ezskiros_runtime.ontology.load import load_index\n"
             "print(len(load_index(sys.argv[1:]).classes))")
    for _ in range(2):  # the first run rebuilds, the second hits the rewritten entry
        run = subprocess.run([sys.executable, "-c", child, *map(str, files)],
                             capture_output=True, text=True, env=env, cwd=str(REPO),
                             timeout=120, check=True)
        assert int(run.stdout) == len(reference.classes)
    _same(load_index(files, cache_dir=cache_dir), reference)
    assert not marker.exists()
    assert not legacy.exists()  # an old pickle is deleted, not read


def test_entries_unused_for_a_month_are_pruned(files: list[Path], tmp_path: Path) -> None:
    cache_dir = tmp_path / "cache"
    cache_dir.mkdir()
    old = cache_dir / f"ontology-index-{1:064x}.json"
    fresh = cache_dir / f"ontology-index-{2:064x}.json"
    for path in (old, fresh):
        path.write_text("{}")
    month = time.time() - (index_cache.MAX_AGE_DAYS + 1) * 24 * 3600
    os.utime(old, (month, month))
    load_index(files, cache_dir=cache_dir)
    assert fresh.exists() and not old.exists()


def test_the_key_covers_the_runtimes_own_code() -> None:
    for module in ("cache.py", "index_codec.py", "closure.py", "limits.py", "parsing.py"):
        assert module in index_cache._INDEX_CODE
    assert all((REPO / "ezskiros_runtime" / "ontology" / name).is_file()
               for name in index_cache._INDEX_CODE)


def test_the_real_core_round_trips_through_json(tmp_path: Path) -> None:
    cold = load_index([skiros2()], cache_dir=tmp_path / "cache")
    warm = load_index([skiros2()], cache_dir=tmp_path / "cache")
    _same(warm, cold)
    assert warm.properties == cold.properties
    assert {i: p.super_properties for i, p in warm.properties.items()} == \
        {i: p.super_properties for i, p in cold.properties.items()}
