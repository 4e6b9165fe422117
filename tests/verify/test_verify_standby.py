"""Workers started ahead of their jobs (``pool.Standby``) are used, and never leak.

Real zygote workers: the run's crew records every process it spawned, so the tests count
processes instead of timing anything.
"""

from __future__ import annotations

import os
from dataclasses import replace
from pathlib import Path

from ezmigrate.verify.pool import PoolConfig, Standby, job_for, run_jobs
from ezmigrate.verify.protocol import LoadOutcome
from ezskiros_runtime.ontology.index import bundled_ontology_path

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


PAINT = """\
from ezskiros_runtime import SkillDescription
from ezskiros_runtime.ontology import lab


class PaintIt(SkillDescription):
    def description(self, Paint: lab.Paint):
        pass
"""
LAB_OWL = Path(__file__).resolve().parents[2] / "fixtures" / "ros_repo" / "owl" / "lab.owl"


def _ahead(tmp_path: Path, ontology: tuple[str, ...]) -> tuple[LoadOutcome, int]:
    """``PaintIt`` loaded by a worker started ahead and told ``ontology`` later; the
    processes the run started."""
    (tmp_path / "paint.py").write_text(PAINT)
    config = PoolConfig(workers=1, ontology=ontology)
    standby = Standby(replace(config, ontology=()), 1, ahead=True)
    try:
        standby.use_ontology(ontology)
        [outcome] = run_jobs([job_for(tmp_path / "paint.py")], config, standby=standby)
    finally:
        standby.close()
    assert all(p.wait(timeout=30) is not None for p in standby.crew.processes)
    return outcome, len(standby.crew.processes)


def test_a_worker_started_ahead_loads_the_ontology_it_is_told(tmp_path: Path) -> None:
    """Started before the run knows its ontology (``ahead``), told it later: its jobs are
    judged against that ontology, as a worker started with it would judge them."""
    core = str(bundled_ontology_path())
    told, started = _ahead(tmp_path, (core, str(LAB_OWL)))
    assert started == 1  # the worker started ahead served: no other was started
    assert told.loaded and not told.errors and told.models[0]["name"] == "PaintIt"
    without, _ = _ahead(tmp_path, (core,))  # the lab's classes unknown: refused
    assert not without.loaded or without.errors or without.findings


def test_a_worker_started_ahead_and_never_used_is_ended_at_once() -> None:
    standby = Standby(PoolConfig(workers=1), 1, ahead=True)
    assert len(standby.crew.processes) == 1
    standby.close()  # never told its ontology: it waits for it, or still imports
    assert all(p.poll() is not None for p in standby.crew.processes)


def test_a_worker_quits_when_told_though_a_forked_process_holds_its_pipe() -> None:
    """A reading worker forked after the tracing worker started holds a copy of that
    worker's stdin, which then never ends: the pool says ``QUIT`` instead. The forked
    process here waits on a pipe of its own until the test releases it."""
    standby = Standby(PoolConfig(workers=1), 1, ahead=True)
    standby.use_ontology(())
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
