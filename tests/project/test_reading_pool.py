"""``check`` reads files and parses scenes in forked workers (``reading_pool``, issue 31):
the findings are those of one process, in the same order. That the work really left the
main process is observed, not timed: the main process's scene parser notes each call, and
a call made in a worker is not seen there."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest
from bench_generator import generator
from process_log import log_calls, logged

from ezmigrate.checking import reading_pool
from ezmigrate.checking.pipeline import run_check
from ezmigrate.project import runner
from ezmigrate.verify.pool import PoolConfig
from ezskiros_runtime.ontology.index import bundled_ontology_path
from ezskiros_runtime.ontology.load import load_index
from ezskiros_runtime.world import scene as scene_module

INDEX = load_index([bundled_ontology_path()])
SCENE = """\
@prefix owl: <http://www.w3.org/2002/07/owl#> .
@prefix skiros: <http://rvmi.aau.dk/ontologies/skiros.owl#> .
skiros:Scene-0 a skiros:Scene, owl:NamedIndividual ;
    skiros:contain skiros:Location-1 .
skiros:Location-1 a skiros:Location, owl:NamedIndividual ;
    skiros:contain skiros:Product-2 .
skiros:Product-2 a skiros:Product, owl:NamedIndividual .
"""


@pytest.fixture
def tree(tmp_path: Path) -> Path:
    root = tmp_path / "repo"
    generator().generate(root, 60, skill_share=1.0, seed=3, messy_share=0.3)
    (root / "scenes").mkdir()
    for number in range(3):
        (root / "scenes" / f"scene{number}.turtle").write_text(SCENE, encoding="utf-8")
    subprocess.run(["git", "init", "-q", str(root)], check=True)
    return root


def _findings(root: Path, workers: int) -> list[str]:
    scene_module._KNOWN.clear()  # as a new process: no scene parsed yet
    outcome = run_check([root], INDEX, PoolConfig(workers=workers))
    return [str(d) for d in outcome.diagnostics]


def test_the_workers_find_what_one_process_finds(tree: Path,
                                                 monkeypatch: pytest.MonkeyPatch) -> None:
    in_main: list[str] = []
    real = scene_module._parsed

    def parsed(where: str, text: str) -> scene_module.Scene:
        in_main.append(Path(where).name)
        return real(where, text)

    monkeypatch.setattr(scene_module, "_parsed", parsed)
    alone = _findings(tree, 1)
    assert sorted(in_main) == ["scene0.turtle", "scene1.turtle", "scene2.turtle"]
    in_main.clear()
    shared = _findings(tree, 2)
    assert shared == alone
    assert in_main == []  # every scene was parsed in a worker
    assert len(alone) > 10


def test_a_declined_file_is_migrated_once_in_the_turn_it_is_read(
        tree: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The codemod reads each file the plain reader declines where the file is read (in a
    worker, or the main process's share), and ``settle`` takes that reading instead of
    migrating the file again. Every process notes each migration in one log, appended to,
    so the workers' notes are seen too."""
    log = tmp_path / "migrated.log"
    log_calls(monkeypatch, runner, "migrate_file", log, lambda relative, *_: relative)
    shared = _findings(tree, 2)
    names = logged(log)
    assert len(names) >= 5 and len(names) == len(set(names))
    log.unlink()
    assert _findings(tree, 1) == shared
    assert sorted(logged(log)) == sorted(names)


def test_a_worker_that_meets_many_declined_files_takes_them_on(
        tree: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A worker leaves its first declined files to the main process (one libcst import for
    all), and from the ``TAKES_ON``-th on reads them itself, those it left included: both
    processes migrate, each file once, and the findings are one process's."""
    log = tmp_path / "migrated.log"
    log_calls(monkeypatch, runner, "migrate_file", log,
              lambda relative, *_: f"{os.getpid()} {relative}")
    shared = _findings(tree, 2)
    noted = [line.split(" ", 1) for line in logged(log)]
    names = [name for _, name in noted]
    assert len(names) == len(set(names)) >= 2 * reading_pool.TAKES_ON
    pids = {pid for pid, _ in noted}
    assert str(os.getpid()) in pids and len(pids) == 2  # the main process and the worker
    assert _findings(tree, 1) == shared


def test_each_file_is_read_once_by_whoever_takes_its_chunk(
        tree: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The main process takes chunks from the end of the list while no worker has started
    them (a cancelled future is never run): each file is read exactly once, by one process,
    and the readings come back in order (the findings are one process's)."""
    log = tmp_path / "read.log"
    log_calls(monkeypatch, reading_pool, "file_facts", log,
              lambda candidate, *_: candidate.relative)
    shared = _findings(tree, 2)
    read = logged(log)
    assert len(read) >= reading_pool.SHARED_FROM and len(read) == len(set(read))
    log.unlink()
    assert _findings(tree, 1) == shared
    assert sorted(logged(log)) == sorted(read)


def test_too_few_files_are_read_in_the_main_process(tmp_path: Path) -> None:
    pool = reading_pool.ReadingPool(2)
    try:
        assert pool.read_files([], compounds=True) == []
        assert pool._pool is None  # nothing to share: nothing forked
    finally:
        pool.close()
