"""``check --trace``'s cache of loads: a second run on an unchanged repository loads nothing
again, gives the same findings, and any change of a Python file the load read, the
ontology or ``--no-cache`` misses."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

from cache_support import check_json
from cache_support import entries as cache_entries

from ezmigrate.cache.load_cache import LoadCache, cached_loads
from ezmigrate.verify.protocol import LoadJob, LoadOutcome

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures"
LOADS = "loads/[0-9a-f][0-9a-f]/*.json"
"""The loads' entries (whole runs are kept apart, in ``outcomes/``: test_outcome_cache)."""


def _repo(tmp_path: Path) -> Path:
    repo = tmp_path / "repo"
    repo.mkdir()
    subprocess.run(["git", "init", "-q", str(repo)], check=True)
    for name in ("pick_and_place.py", "conditions.py", "descriptions.py"):
        shutil.copy(FIXTURES / "migrated" / name, repo / name)
    return repo


def test_the_second_run_reads_the_cache_and_finds_the_same(tmp_path: Path) -> None:
    repo = _repo(tmp_path)
    first = check_json(repo, "--trace")
    assert first.returncode == 0, first.stderr
    entries = sorted(cache_entries(repo).glob(LOADS))
    assert len(entries) == 3  # one loaded outcome per EzSkiROS file
    assert not (repo / ".ezmigrate_cache").exists()  # nothing in the checkout
    stamps = [entry.stat().st_mtime_ns for entry in entries]
    second = check_json(repo, "--trace")
    assert second.stdout == first.stdout
    assert [entry.stat().st_mtime_ns for entry in entries] == stamps  # nothing rewritten
    uncached = check_json(repo, "--trace", "--no-cache")
    assert uncached.stdout == first.stdout


def test_a_changed_file_misses_and_a_damaged_entry_is_a_miss(tmp_path: Path) -> None:
    repo = _repo(tmp_path)
    first = check_json(repo, "--trace")
    for entry in cache_entries(repo).glob(LOADS):
        entry.write_text("{not json")
    assert check_json(repo, "--trace").stdout == first.stdout
    before = len(list(cache_entries(repo).glob(LOADS)))
    (repo / "unrelated.py").write_text("X = 1\n")  # nothing imports it: nothing misses
    assert check_json(repo, "--trace").stdout == first.stdout
    assert len(list(cache_entries(repo).glob(LOADS))) == before


def test_a_changed_module_misses_for_the_files_importing_it_alone(tmp_path: Path) -> None:
    """A load runs the file's imports: a file of the run it imports (here through a
    package's ``__init__``) is part of its key, and no other file is (issue 31)."""
    repo = _repo(tmp_path)
    (repo / "lab").mkdir()
    (repo / "lab" / "__init__.py").write_text("from .units import SCALE\n")
    (repo / "lab" / "units.py").write_text("SCALE = 1.0\n")
    descriptions = repo / "descriptions.py"
    descriptions.write_text("import lab\n" + descriptions.read_text())
    first = check_json(repo, "--trace")
    assert first.returncode == 0, first.stderr
    before = len(list(cache_entries(repo).glob(LOADS)))
    (repo / "lab" / "units.py").write_text("SCALE = 2.0\n")
    assert check_json(repo, "--trace").stdout == first.stdout
    assert len(list(cache_entries(repo).glob(LOADS))) == before + 1  # descriptions.py alone


def test_cached_loads_loads_only_the_misses_in_one_batch(tmp_path: Path) -> None:
    folder = tmp_path / "user-cache" / "projects" / "p"
    cache = LoadCache.for_run(folder, [("a.py", b"A"), ("b.py", b"B")], "onto",
                              None)
    jobs = [LoadJob("/x/a.py", None, None), LoadJob("/x/b.py", None, None)]
    batches: list[list[str]] = []

    def load(batch: list[LoadJob]) -> list[LoadOutcome]:
        batches.append([job.path for job in batch])
        return [LoadOutcome("ok" if job.path.endswith("a.py") else "timeout", job.path)
                for job in batch]

    first = cached_loads(jobs, [b"A", b"B"], load, cache)
    second = cached_loads(jobs, [b"A", b"B"], load, cache)
    assert [o.message for o in first] == [o.message for o in second] == ["/x/a.py", "/x/b.py"]
    assert batches == [["/x/a.py", "/x/b.py"], ["/x/b.py"]]  # a timeout is never kept
    other = LoadCache.for_run(folder, [("a.py", b"A"), ("b.py", b"B")], "other",
                              None)
    cached_loads(jobs[:1], [b"A"], load, other)  # another ontology: another key
    assert batches[-1] == ["/x/a.py"]


def test_a_data_file_the_module_reads_is_part_of_the_key(tmp_path: Path) -> None:
    """What a load reads besides the file (here a data file read at import, and a module
    loaded with ``importlib``) is noted by the child, and a kept load whose reads changed
    is a miss: the next run says what ``--no-cache`` says."""
    repo = _repo(tmp_path)
    (repo / "limits.txt").write_text("ok\n")
    (repo / "helper_mod.py").write_text("VALUE = 1\n")
    descriptions = repo / "descriptions.py"
    descriptions.write_text(
        "import importlib, pathlib\n"
        "importlib.import_module('helper_mod')\n"
        "assert pathlib.Path(__file__).with_name('limits.txt').read_text() == 'ok\\n'\n"
        + descriptions.read_text())
    first = check_json(repo, "--trace")
    assert '"EZ904"' not in first.stdout, first.stdout
    (repo / "limits.txt").write_text("broken\n")
    broken = check_json(repo, "--trace")
    assert broken.stdout == check_json(repo, "--trace", "--no-cache").stdout
    assert '"EZ904"' in broken.stdout
    (repo / "limits.txt").write_text("ok\n")
    (repo / "helper_mod.py").write_text("raise ImportError('helper broke')\n")
    helper = check_json(repo, "--trace")
    assert "helper broke" in helper.stdout
