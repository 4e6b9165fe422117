"""How many sandboxed workers trace a run's compound skills (``analysis.trace_workers``):
one until the trees to trace are many, since each worker's start costs a core about a
tenth of a second while the run is still busy on every core. Real files and real workers:
the test counts the workers the run spawned, and checks that every tree was traced."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from ezmigrate.compound.analysis import TRACED_PER_WORKER, trace_workers
from ezmigrate.project.check import run_check, tracing_ahead
from ezmigrate.project.outcome_cache import OutcomeCache
from ezmigrate.verify import pool as pool_module
from ezmigrate.verify.pool import PoolConfig

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
    spawned: list[list[str]] = []
    real = pool_module._Crew.spawn

    def noted(self: pool_module._Crew, args: list[str], *rest: object) -> object:
        spawned.append(args)
        return real(self, args, *rest)  # type: ignore[arg-type]

    monkeypatch.setattr(pool_module._Crew, "spawn", noted)
    outcome = run_check([tmp_path], None, PoolConfig(workers=2))
    traced = sorted(Path(d.path).name for d in outcome.diagnostics if d.code == "EZ309")
    assert traced == ["task0.py", "task1.py", "task2.py"]  # each tree traced, mistake found
    assert len(spawned) == 1


def _three_trees(root: Path) -> None:
    for n in range(3):
        (root / f"task{n}.py").write_text(textwrap.dedent(TASK.format(n=n)), encoding="utf-8")


def test_a_worker_started_ahead_traces_the_run(tmp_path: Path, monkeypatch):
    """``tracing_ahead`` starts the worker before the run knows its ontology; the run
    traces with it and starts no other."""
    _three_trees(tmp_path)
    spawned: list[list[str]] = []
    real = pool_module._Crew.spawn

    def noted(self: pool_module._Crew, args: list[str], *rest: object) -> object:
        spawned.append(args)
        return real(self, args, *rest)  # type: ignore[arg-type]

    monkeypatch.setattr(pool_module._Crew, "spawn", noted)
    tracing = tracing_ahead([tmp_path], PoolConfig(workers=2), True, None)
    assert tracing is not None and len(spawned) == 1 and "--ontology-later" in spawned[0]
    try:
        tracing.use_ontology(())
        outcome = run_check([tmp_path], None, PoolConfig(workers=2), tracing=tracing)
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
