"""The persistent cache: hits without rdflib, invalidation, and tolerance of bad caches."""

from __future__ import annotations

import importlib
import json
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest
from shared_data import skiros2

from ezskiros_runtime.ontology.load import load_index

# The module itself, without asking the package: an ontology prefix named `cache` would win
# there, and asking loads the active ontology to find out.
index_cache = importlib.import_module("ezskiros_runtime.ontology.cache")

REPO = Path(__file__).resolve().parents[3]
FIXTURES = REPO / "fixtures" / "ontology"
WC = "http://example.org/ontologies/workcell.owl#"

CHILD = """
import json, sys
from ezskiros_runtime.ontology.cache import stats
from ezskiros_runtime.ontology.load import load_index
index = load_index(sys.argv[1:])
print(json.dumps({"rdflib": "rdflib" in sys.modules, "hits": stats.hits,
                  "writes": stats.writes, "classes": len(index.classes),
                  "fingerprint": index.fingerprint}))
"""


@pytest.fixture
def ontology(tmp_path: Path) -> Path:
    copy = tmp_path / "onto" / "inheritance.ttl"
    copy.parent.mkdir()
    shutil.copy(FIXTURES / "inheritance.ttl", copy)
    return copy


@pytest.fixture
def cache_dir(tmp_path: Path) -> Path:
    return tmp_path / "cache"


def _hits_and_writes() -> tuple[int, int]:
    return index_cache.stats.hits, index_cache.stats.writes


def test_second_load_hits_the_cache(ontology: Path, cache_dir: Path) -> None:
    hits, writes = _hits_and_writes()
    first = load_index([ontology], cache_dir=cache_dir)
    assert _hits_and_writes() == (hits, writes + 1)
    stored = index_cache.cache_path(cache_dir, first.fingerprint)
    assert stored.is_file()
    second = load_index([ontology], cache_dir=cache_dir)
    assert _hits_and_writes() == (hits + 1, writes + 1)
    assert second.properties == first.properties and second.classes == first.classes
    assert [p.name for p in cache_dir.iterdir()] == [stored.name]  # no temp files left


def test_warm_load_in_a_fresh_process_does_not_import_rdflib(
    ontology: Path, cache_dir: Path
) -> None:
    env = {**os.environ, "EZSKIROS_CACHE_DIR": str(cache_dir)}

    def child() -> dict[str, object]:
        result = subprocess.run(
            [sys.executable, "-c", CHILD, str(ontology)],
            capture_output=True,
            text=True,
            env=env,
            cwd=REPO,
            timeout=60,
            check=True,
        )
        return json.loads(result.stdout)

    cold = child()
    warm = child()
    assert cold["rdflib"] is True and cold["hits"] == 0 and cold["writes"] == 1
    assert warm["rdflib"] is False and warm["hits"] == 1 and warm["writes"] == 0
    assert warm["fingerprint"] == cold["fingerprint"] and warm["classes"] == 5


def test_content_change_invalidates(ontology: Path, cache_dir: Path) -> None:
    before = load_index([ontology], cache_dir=cache_dir)
    assert not before.is_class(WC + "Conveyor")
    with ontology.open("a") as stream:
        stream.write("\nwc:Conveyor a owl:Class .\n")
    hits = index_cache.stats.hits
    after = load_index([ontology], cache_dir=cache_dir)
    assert index_cache.stats.hits == hits
    assert after.fingerprint != before.fingerprint
    assert after.is_class(WC + "Conveyor")


def test_load_order_is_part_of_the_key(cache_dir: Path) -> None:
    a, b = FIXTURES / "paper.ttl", FIXTURES / "inheritance.ttl"
    assert (
        load_index([a, b], cache=False).fingerprint != load_index([b, a], cache=False).fingerprint
    )


def test_moved_files_still_hit_and_report_their_new_path(
    ontology: Path, cache_dir: Path, tmp_path: Path
) -> None:
    load_index([ontology], cache_dir=cache_dir)
    moved = tmp_path / "elsewhere" / "renamed.ttl"
    moved.parent.mkdir()
    shutil.copy(ontology, moved)
    hits = index_cache.stats.hits
    index = load_index([moved], cache_dir=cache_dir)
    assert index_cache.stats.hits == hits + 1
    assert index.sources == (str(moved.resolve()),)


def test_corrupt_cache_file_is_ignored_and_replaced(ontology: Path, cache_dir: Path) -> None:
    fingerprint = load_index([ontology], cache=False).fingerprint
    stored = index_cache.cache_path(cache_dir, fingerprint)
    cache_dir.mkdir()
    stored.write_bytes(b"\x80\x05 definitely not a pickle")
    index = load_index([ontology], cache_dir=cache_dir)
    assert index.is_class(WC + "Hand")
    hits = index_cache.stats.hits
    load_index([ontology], cache_dir=cache_dir)  # the rebuild rewrote a good file
    assert index_cache.stats.hits == hits + 1


def test_foreign_pickle_under_the_right_name_is_ignored(ontology: Path, cache_dir: Path) -> None:
    fingerprint = load_index([ontology], cache=False).fingerprint
    cache_dir.mkdir()
    import pickle

    index_cache.cache_path(cache_dir, fingerprint).write_bytes(pickle.dumps({"not": "an index"}))
    assert load_index([ontology], cache_dir=cache_dir).is_class(WC + "Hand")


def test_unwritable_cache_location_is_tolerated(ontology: Path, tmp_path: Path) -> None:
    blocker = tmp_path / "a-file"
    blocker.write_text("a file where the cache folder should be")
    ignored = index_cache.stats.ignored_errors
    index = load_index([ontology], cache_dir=blocker / "cache")
    assert index.is_class(WC + "Hand")
    assert index_cache.stats.ignored_errors > ignored
    assert blocker.read_text().startswith("a file")


def test_cache_false_neither_reads_nor_writes(ontology: Path, cache_dir: Path) -> None:
    load_index([ontology], cache=False, cache_dir=cache_dir)
    assert not cache_dir.exists()


def test_cache_location_from_environment(tmp_path: Path) -> None:
    home = Path.home()
    assert index_cache.default_cache_dir({"EZSKIROS_CACHE_DIR": str(tmp_path)}) == tmp_path
    assert index_cache.default_cache_dir({"XDG_CACHE_HOME": str(tmp_path)}) == tmp_path / "ezskiros"
    assert index_cache.default_cache_dir({}) == home / ".cache" / "ezskiros"
    env = {"EZSKIROS_CACHE_DIR": "", "XDG_CACHE_HOME": str(tmp_path)}
    assert index_cache.default_cache_dir(env) == tmp_path / "ezskiros"


def test_default_cache_dir_is_used(
    ontology: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("EZSKIROS_CACHE_DIR", str(tmp_path / "env-cache"))
    index = load_index([ontology])
    assert index_cache.cache_path(tmp_path / "env-cache", index.fingerprint).is_file()


def test_real_ontology_round_trips_through_the_cache(cache_dir: Path) -> None:
    cold = load_index([skiros2()], cache_dir=cache_dir)
    hits = index_cache.stats.hits
    warm = load_index([skiros2()], cache_dir=cache_dir)
    assert index_cache.stats.hits == hits + 1
    assert warm.properties == cold.properties
    assert warm.prefixes == cold.prefixes
    assert all(warm.superclasses(c) == cold.superclasses(c) for c in cold.classes)


def test_package_version_is_part_of_the_key(monkeypatch: pytest.MonkeyPatch) -> None:
    import ezskiros_runtime

    files = [FIXTURES / "paper.ttl"]
    before = load_index(files, cache=False).fingerprint
    monkeypatch.setattr(ezskiros_runtime, "__version__", "99.0", raising=False)
    assert load_index(files, cache=False).fingerprint != before


def test_fast_sha256_matches_hashlib() -> None:
    import hashlib

    data = (FIXTURES / "paper.ttl").read_bytes()
    fast = index_cache._sha256_factory()()
    fast.update(data)
    assert fast.hexdigest() == hashlib.sha256(data).hexdigest()


def test_old_indexes_are_pruned(ontology: Path, cache_dir: Path) -> None:
    cache_dir.mkdir()
    stale = [cache_dir / f"ontology-index-{n:064x}.json" for n in range(index_cache.KEEP_INDEXES)]
    recent = time.time() - 3600  # within MAX_AGE_DAYS: only the count prunes them
    for number, path in enumerate(stale):
        path.write_bytes(b"old")
        os.utime(path, (recent + number, recent + number))
    unrelated = cache_dir / "notes.txt"
    unrelated.write_text("not ours")
    index = load_index([ontology], cache_dir=cache_dir)
    remaining = sorted(p.name for p in cache_dir.glob("ontology-index-*.json"))
    assert len(remaining) == index_cache.KEEP_INDEXES
    assert index_cache.cache_path(cache_dir, index.fingerprint).name in remaining
    assert stale[0].name not in remaining  # the least recently used one went
    assert unrelated.exists()


REFUSED = """
import json, sys
from ezskiros_runtime.ontology.cache import stats
from ezskiros_runtime.ontology.errors import OntologyLoadError
from ezskiros_runtime.ontology.load import load_index
try:
    load_index(sys.argv[1:])
except OntologyLoadError as error:
    print(json.dumps({"rdflib": "rdflib" in sys.modules, "hits": stats.hits,
                      "message": str(error), "path": error.path, "line": error.line}))
"""


def test_a_refused_file_is_refused_again_without_rdflib_until_it_changes(
    ontology: Path, cache_dir: Path
) -> None:
    """A repository with an empty ``lth.owl`` among its ontologies (discovery leaves it
    out, after the load refuses it) must not import rdflib and parse on every run."""
    broken = ontology.parent / "lth.owl"
    broken.write_text("", encoding="utf-8")
    env = {**os.environ, "EZSKIROS_CACHE_DIR": str(cache_dir)}

    def child(*paths: Path) -> dict[str, object]:
        result = subprocess.run([sys.executable, "-c", REFUSED, *map(str, paths)],
                                capture_output=True, text=True, env=env, cwd=REPO,
                                timeout=60, check=True)
        return json.loads(result.stdout) if result.stdout.strip() else {}

    cold = child(ontology.parent)
    warm = child(ontology.parent)
    assert cold["rdflib"] is True and cold["hits"] == 0
    assert warm["rdflib"] is False and warm["hits"] == 1
    assert {k: warm[k] for k in ("message", "path", "line")} == \
        {k: cold[k] for k in ("message", "path", "line")}
    assert str(broken) in str(cold["path"])

    moved = ontology.parent.parent / "moved"
    ontology.parent.rename(moved)  # the same bytes elsewhere: the error names the new place
    there = child(moved)
    assert there["rdflib"] is True and str(moved / "lth.owl") in str(there["path"])

    (moved / "lth.owl").unlink()  # fixed: it loads
    fixed = subprocess.run([sys.executable, "-c", CHILD, str(moved)], capture_output=True,
                           text=True, env=env, cwd=REPO, timeout=60, check=True)
    assert json.loads(fixed.stdout)["classes"] == 5


INDIVIDUALS = """
import json, sys
from ezskiros_runtime.ontology.load import load_index
from ezskiros_runtime.world.scene import individuals_of
index = load_index(sys.argv[1:])
print(json.dumps({"rdflib": "rdflib" in sys.modules, "kept": index.individuals,
                  "given": individuals_of(index)}))
"""


def test_the_index_keeps_the_individuals_the_files_declare(tmp_path: Path) -> None:
    """A robot description's individuals (``owl/robot.owl``) are kept with the index from
    its build: the same as parsing its files again (``ontology_individuals``), and a
    cached index in a fresh process hands them over without importing rdflib."""
    from ezskiros_runtime.world.scene import ontology_individuals

    owl = REPO / "fixtures" / "world_repo" / "owl"
    index = load_index([skiros2(), owl], cache=False)
    assert index.individuals is not None and len(index.individuals) >= 3
    assert index.individuals == ontology_individuals(list(index.sources))
    env = {**os.environ, "EZSKIROS_CACHE_DIR": str(tmp_path / "cache")}
    runs = [json.loads(subprocess.run(
        [sys.executable, "-c", INDIVIDUALS, str(skiros2()), str(owl)], capture_output=True,
        text=True, env=env, cwd=REPO, timeout=120, check=True).stdout) for _ in range(2)]
    assert runs[1]["rdflib"] is False
    assert runs[0]["kept"] == runs[1]["kept"] == runs[1]["given"] == index.individuals
