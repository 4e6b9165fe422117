"""Workers started ahead of their jobs (``pool.Standby``) are used, and never leak.

Real zygote workers: the run's crew records every process it spawned, so the tests count
processes instead of timing anything.
"""

from __future__ import annotations

from pathlib import Path

from ezmigrate.verify.pool import PoolConfig, Standby, job_for, run_jobs

LEGACY = """\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes


class Wait(SkillDescription):
    def createDescription(self):
        self.addParam("Duration", 0.5, ParamTypes.Required)
"""


def test_a_run_uses_the_workers_already_started(tmp_path: Path) -> None:
    (tmp_path / "wait.py").write_text(LEGACY)
    config = PoolConfig(workers=1)
    standby = Standby(config, 1)
    try:
        [outcome] = run_jobs([job_for(tmp_path / "wait.py")], config, standby=standby)
        assert outcome.loaded and outcome.models[0]["name"] == "Wait"
        assert len(standby.crew.processes) == 1  # no second worker was started
        assert all(p.wait(timeout=30) is not None for p in standby.crew.processes)
    finally:
        standby.close()


def test_workers_nobody_took_are_stopped() -> None:
    standby = Standby(PoolConfig(workers=2), 2)
    standby.close()
    assert len(standby.crew.processes) == 2
    assert all(p.poll() is not None for p in standby.crew.processes)
