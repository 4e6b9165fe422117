"""Workers started before their jobs (``pool.Standby``) are used, and never leak.

Real zygote workers: the run's crew records every process it spawned, so the tests count
processes instead of timing anything.
"""

from __future__ import annotations

import os
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


def test_a_worker_quits_when_told_though_a_forked_process_holds_its_pipe() -> None:
    """A process forked after a worker started (a reading worker) holds a copy of that
    worker's stdin, which then never ends: the pool says ``QUIT`` instead. The forked
    process here waits on a pipe of its own until the test releases it."""
    standby = Standby(PoolConfig(workers=1), 1)
    worker = standby.take()
    assert worker is not None
    release_read, release_write = os.pipe()
    holder = os.fork()
    if holder == 0:  # holds every descriptor of the pool's, the worker's pipes among them
        os.read(release_read, 1)
        os._exit(0)
    try:
        worker.close()
        assert worker.process.returncode == 0  # it quit on its own, not killed
    finally:
        os.write(release_write, b"x")
        os.waitpid(holder, 0)
        os.close(release_read)
        os.close(release_write)
