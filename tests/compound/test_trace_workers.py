"""How many sandboxed workers trace a run's compound skills (``tracing.trace_workers``):
one until the trees to trace are many, since each worker's start costs a core about a
tenth of a second while the run is still busy on every core. Real files and real workers:
the test counts the workers the run spawned, and checks that every tree was traced."""

from __future__ import annotations

import os
import textwrap
import threading
import time
from pathlib import Path

import pytest

from ezmigrate.compound import tracing
from ezmigrate.compound.static import NeedsTrace
from ezmigrate.compound.tracing import TRACED_PER_WORKER, trace_workers
from ezmigrate.files.discover import Candidate
from ezmigrate.project.check import run_check, tracing_ahead
from ezmigrate.project.outcome_cache import OutcomeCache
from ezmigrate.verify import pool as pool_module
from ezmigrate.verify.pool import PoolConfig, Standby
from ezmigrate.verify.protocol import LoadJob

TASK = '''\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_skill.core.skill import SkillBase


class Task{n}(SkillDescription):
    def createDescription(self):
        pass


class task{n}(SkillBase):
    def createDescription(self):
        self.setDescription(Task{n}(), self.__class__.__name__)

    def expand(self, skill):
        for key in ("Duration",):  # a loop: only tracing reads this tree
            skill(self.skill("Wait", "", specfiy={{key: 1.0}}))
'''


@pytest.mark.parametrize(("count", "workers", "expected"), [
    (1, 2, 1), (TRACED_PER_WORKER, 2, 1), (TRACED_PER_WORKER + 1, 2, 2),
    (10 * TRACED_PER_WORKER, 2, 2), (10 * TRACED_PER_WORKER, 1, 1), (0, 2, 1)])
def test_one_worker_per_so_many_files_at_most_the_pools(count, workers, expected):
    assert trace_workers(count, PoolConfig(workers=workers)) == expected


def test_a_few_trees_are_traced_by_one_worker(tmp_path: Path, monkeypatch):
    _three_trees(tmp_path)
    spawned = _spawns_noted(monkeypatch)
    outcome = run_check([tmp_path], None, PoolConfig(workers=2), trace=True)
    traced = sorted(Path(d.path).name for d in outcome.diagnostics if d.code == "EZ309")
    assert traced == ["task0.py", "task1.py", "task2.py"]  # each tree traced, mistake found
    assert len(spawned) == 1


def _spawns_noted(monkeypatch: pytest.MonkeyPatch) -> list[list[str]]:
    """The command line of every worker the pool spawns from now on (real workers)."""
    spawned: list[list[str]] = []
    real = pool_module._Crew.spawn

    def noted(self: pool_module._Crew, args: list[str], *rest: object) -> object:
        spawned.append(args)
        return real(self, args, *rest)  # type: ignore[arg-type]

    monkeypatch.setattr(pool_module._Crew, "spawn", noted)
    return spawned


def _three_trees(root: Path) -> None:
    for n in range(3):
        (root / f"task{n}.py").write_text(textwrap.dedent(TASK.format(n=n)), encoding="utf-8")


def test_a_worker_started_ahead_traces_the_run(tmp_path: Path, monkeypatch):
    """``tracing_ahead`` starts the worker before the run knows its ontology; the run
    traces with it and starts no other."""
    _three_trees(tmp_path)
    spawned = _spawns_noted(monkeypatch)
    tracing = tracing_ahead([tmp_path], PoolConfig(workers=2), True, None)
    assert tracing is not None and len(spawned) == 1 and "--ontology-later" in spawned[0]
    try:
        tracing.use_ontology(())
        outcome = run_check([tmp_path], None, PoolConfig(workers=2), tracing=tracing,
                            trace=True)
    finally:
        tracing.close()
    traced = sorted(Path(d.path).name for d in outcome.diagnostics if d.code == "EZ309")
    assert traced == ["task0.py", "task1.py", "task2.py"]
    assert len(spawned) == 1


def test_a_worker_is_started_ahead_only_where_it_can_pay_off(tmp_path: Path):
    _three_trees(tmp_path)
    cache = tmp_path / ".cache"
    two = PoolConfig(workers=2)
    assert tracing_ahead([tmp_path / "task0.py"], two, True, None) is None  # named files
    assert tracing_ahead([tmp_path], PoolConfig(workers=1), True, None) is None
    assert tracing_ahead([tmp_path], two, False, None) is None  # nothing to trace
    OutcomeCache(cache).put("a-kept-run", 1, 1, [], [])
    assert tracing_ahead([tmp_path], two, True, cache) is None  # most likely kept
    for started in (tracing_ahead([tmp_path], two, True, None),
                    tracing_ahead([tmp_path], two, True, tmp_path / "empty-cache")):
        assert started is not None
        started.close()
        assert all(p.poll() is not None for p in started.crew.processes)


def test_the_trees_to_trace_are_traced_once_the_reading_ends(tmp_path: Path, monkeypatch):
    """``EarlyTraces``: every file to trace goes to the sandbox in one go when the reading
    ends, before the compound pass asks; the pass traces nothing more, and finds the
    mistakes in each tree as before."""
    _three_trees(tmp_path)
    asked: list[list[str]] = []
    real = tracing.trace_all

    def noted(jobs: list[LoadJob], *rest: object, **named: object) -> object:
        asked.append(sorted(Path(job.path).name for job in jobs))
        return real(jobs, *rest, **named)  # type: ignore[arg-type]

    monkeypatch.setattr(tracing, "trace_all", noted)
    outcome = run_check([tmp_path], None, PoolConfig(workers=2), trace=True)
    assert asked == [["task0.py", "task1.py", "task2.py"]]
    traced = sorted(Path(d.path).name for d in outcome.diagnostics if d.code == "EZ309")
    assert traced == ["task0.py", "task1.py", "task2.py"]


HANGS = '''\
from skiros2_skill.core.skill import SkillBase

open({fifo!r}).read()  # blocks until someone writes: no one will


class hangs(SkillBase):
    def expand(self, skill):
        for key in ("Duration",):
            skill(self.skill("Wait", "", specify={{key: 1.0}}))
'''


def test_traces_still_running_are_stopped_with_their_worker(tmp_path: Path):
    """A run that ends before its compound pass (an interrupt, an error) stops the traces
    it started: the worker and the child importing a module that blocks on a FIFO nobody
    opens for writing."""
    fifo = tmp_path / "never"
    os.mkfifo(fifo)
    (tmp_path / "hangs.py").write_text(HANGS.format(fifo=str(fifo)), encoding="utf-8")
    standby = Standby(PoolConfig(workers=1), 1)
    early = tracing.EarlyTraces(PoolConfig(workers=1))
    pending = [NeedsTrace("hangs", 6, "a loop")]
    early.start([(Candidate(tmp_path / "hangs.py", tmp_path), pending)], standby)
    writer = _open_when_read(fifo)  # the module is being imported: its child reads, blocked

    def stop() -> None:
        early.close()
        standby.close()

    stopping = threading.Thread(target=stop)
    stopping.start()
    stopping.join(timeout=120)
    os.close(writer)
    assert not stopping.is_alive()
    assert standby.crew.processes and all(p.poll() is not None
                                           for p in standby.crew.processes)


def _open_when_read(fifo: Path) -> int:
    """The FIFO's writing end, once a reader waits on it (until then opening it without
    blocking fails): nothing is ever written, so the reader stays blocked."""
    for _ in range(12000):
        try:
            return os.open(fifo, os.O_WRONLY | os.O_NONBLOCK)
        except OSError:
            time.sleep(0.01)
    raise AssertionError("the module was never imported")
