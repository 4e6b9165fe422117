"""``check`` reads files and parses scenes in forked workers (``reading_pool``, issue 31):
the findings are those of one process, in the same order. That the work really left the
main process is observed, not timed: the main process's scene parser notes each call, and
a call made in a worker is not seen there."""

from __future__ import annotations

import os
import subprocess
from collections.abc import Callable
from pathlib import Path
from typing import Any

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
    """The main process takes chunks from the end of the list and the worker from the start
    (``worker_channel.Claims``): each file is read exactly once, by one process, and the
    readings come back in order (the findings are one process's)."""
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
        assert pool._worker is None  # nothing to share: nothing forked
    finally:
        pool.close()


def _held_until_the_worker_reads(monkeypatch: pytest.MonkeyPatch,
                                 in_worker: Callable[[int], None]) -> None:
    """The worker's chunk reader replaced by ``in_worker(pipe)`` (which writes a byte to the
    pipe), and the main process's first chunk held until that byte comes: the worker is
    sure to take a chunk, however fast either process is."""
    ready, said = os.pipe()
    real = reading_pool._read_files
    held = [True]

    def main_reads(*args: Any) -> Any:
        if held[0]:
            held[0] = False
            os.read(ready, 1)
        return real(*args)

    monkeypatch.setattr(reading_pool, "_read_in_worker", lambda *_: in_worker(said))
    monkeypatch.setattr(reading_pool, "_read_files", main_reads)


def test_a_worker_that_dies_leaves_its_share_to_the_main_process(
        tree: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The worker ends at its first chunk of files (``os._exit``, as a kill would end it):
    the main process reads every chunk the worker took, and the run finds what one
    process finds."""
    alone = _findings(tree, 1)

    def dies(said: int) -> None:
        os.write(said, b"x")
        os._exit(3)

    _held_until_the_worker_reads(monkeypatch, dies)
    assert _findings(tree, 2) == alone


def test_a_task_that_fails_in_the_worker_is_done_again_here(
        tree: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A chunk whose reading raises in the worker is read again by the main process (and
    would raise here, as in one process); the worker goes on with the next."""
    alone = _findings(tree, 1)

    def fails(said: int) -> None:
        os.write(said, b"x")
        raise RuntimeError("a bug of ours, in the worker only")

    _held_until_the_worker_reads(monkeypatch, fails)
    assert _findings(tree, 2) == alone


def test_without_a_temporary_folder_the_run_reads_alone(
        tree: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The worker's files cannot be made (a read-only temporary folder, no descriptors
    left): the run reads in the main process and finds what one process finds."""
    import tempfile

    alone = _findings(tree, 1)

    def refused(*_: object, **__: object) -> None:
        raise PermissionError(13, "Permission denied", "/tmp")

    monkeypatch.setattr(tempfile, "mkstemp", refused)
    started: list[bool] = []
    real = reading_pool.ReadingPool._start

    def start(pool: reading_pool.ReadingPool, scenes: Any) -> bool:
        started.append(real(pool, scenes))
        return started[-1]

    monkeypatch.setattr(reading_pool.ReadingPool, "_start", start)
    assert _findings(tree, 2) == alone
    assert started and not any(started)  # asked to fork, and read alone instead


def test_the_claims_give_each_task_once_from_either_end() -> None:
    import multiprocessing

    from ezmigrate.checking.worker_channel import Claims

    claims = Claims(2, multiprocessing.get_context("fork").Lock())
    claims.open(1, 5)
    assert claims.front(0) is None  # a list never opened has nothing to take
    taken = [claims.front(1), claims.back(1), claims.front(1), claims.back(1),
             claims.front(1), claims.back(1), claims.front(1)]
    assert taken == [0, 4, 1, 3, 2, None, None]
    claims.open(1, 2)  # the next batch starts afresh
    assert [claims.back(1), claims.back(1), claims.front(1)] == [1, 0, None]
