"""How many sandboxed workers trace a run's compound skills (``tracing.trace_workers``):
one until the trees to trace are many, since each worker's start costs a core about a
tenth of a second while the run is still busy on every core. Real files and real workers:
the test counts the workers the run spawned, and checks that every tree was traced."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from ezmigrate.checking.pipeline import run_check
from ezmigrate.checking.run import CheckSettings
from ezmigrate.compound import tracing
from ezmigrate.compound.tracing import TRACED_PER_WORKER, trace_workers
from ezmigrate.verify import pool as pool_module
from ezmigrate.verify.pool import PoolConfig
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
    outcome = run_check([tmp_path], None, PoolConfig(workers=2), CheckSettings(trace=True))
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


def test_the_trees_to_trace_are_traced_in_one_go(tmp_path: Path, monkeypatch):
    """``check --trace``: every file to trace goes to the sandbox in one go, and the
    mistakes in each tree are found."""
    _three_trees(tmp_path)
    asked: list[list[str]] = []
    real = tracing.trace_all

    def noted(jobs: list[LoadJob], *rest: object, **named: object) -> object:
        asked.append(sorted(Path(job.path).name for job in jobs))
        return real(jobs, *rest, **named)  # type: ignore[arg-type]

    monkeypatch.setattr(tracing, "trace_all", noted)
    outcome = run_check([tmp_path], None, PoolConfig(workers=2), CheckSettings(trace=True))
    assert asked == [["task0.py", "task1.py", "task2.py"]]
    traced = sorted(Path(d.path).name for d in outcome.diagnostics if d.code == "EZ309")
    assert traced == ["task0.py", "task1.py", "task2.py"]
