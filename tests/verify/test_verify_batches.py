"""Batched loads (``pool.run_batched``): one child loads several files one after the other,
and every outcome that stands is what a child of its own would have said.

Real zygote workers and real children; a file that never finishes loading holds its batch
by construction (it loops), so the tests wait for a timeout instead of racing one.
"""

from __future__ import annotations

import shutil
from pathlib import Path

from ezmigrate.verify.pool import PoolConfig, job_for, run_batched, run_jobs

ISOLATION = Path(__file__).resolve().parents[2] / "fixtures" / "isolation"
SKILL = """\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes


class {name}(SkillDescription):
    def createDescription(self):
        self.addParam("Duration", {value}, ParamTypes.Required)
"""


def _skills(folder: Path, count: int) -> list[Path]:
    paths = []
    for number in range(count):
        path = folder / f"skill_{number}.py"
        path.write_text(SKILL.format(name=f"Skill{number}", value=number / 2))
        paths.append(path)
    return paths


def test_a_batch_gives_what_one_child_per_file_gives(tmp_path: Path) -> None:
    jobs = [job_for(p) for p in _skills(tmp_path, 5)]
    config = PoolConfig(workers=2)
    batched = run_batched(jobs, config, 4)
    alone = run_jobs(jobs, config)
    assert [(o.status, o.models) for o in batched] == [(o.status, o.models) for o in alone]
    assert [o.models[0]["name"] for o in batched] == [f"Skill{n}" for n in range(5)]


def test_a_file_that_hangs_costs_its_batch_a_timeout_not_the_verdicts(tmp_path: Path) -> None:
    paths = _skills(tmp_path, 3)
    shutil.copy(ISOLATION / "loops_forever.py", tmp_path / "loops_forever.py")
    paths.insert(1, tmp_path / "loops_forever.py")
    outcomes = run_batched([job_for(p) for p in paths], PoolConfig(workers=2, timeout=5), 4)
    assert [o.status for o in outcomes] == ["ok", "timeout", "ok", "ok"]
    assert [o.models[0]["name"] for o in outcomes if o.loaded] == ["Skill0", "Skill1",
                                                                   "Skill2"]


def test_a_failed_load_keeps_its_own_captured_output(tmp_path: Path) -> None:
    paths = _skills(tmp_path, 2)
    for name in ("prints_stdout.py", "raises_on_import.py"):
        shutil.copy(ISOLATION / name, tmp_path / name)
    paths += [tmp_path / "prints_stdout.py", tmp_path / "raises_on_import.py"]
    jobs = [job_for(p) for p in paths]
    config = PoolConfig(workers=1)
    batched = run_batched(jobs, config, 4, alone=lambda outcome: not outcome.loaded)
    alone = run_jobs(jobs, config)
    assert not batched[3].loaded
    assert (batched[3].status, batched[3].stdout, batched[3].stderr) == (
        alone[3].status, alone[3].stdout, alone[3].stderr)
    assert batched[2].stdout == alone[2].stdout  # its batch was loaded again, file by file
