"""``check --no-trace`` imports no user code: neither EzSkiROS files (loaded to run their
checks) nor compound skills (traced when the syntax cannot give their tree). Without it,
both are imported, in the sandbox; each module here leaves a marker when it is imported."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures"

MARK = '''import os
if os.environ.get("EZMIGRATE_TEST_MARKER"):
    open(os.path.join(os.environ["EZMIGRATE_TEST_MARKER"], __name__), "w").close()
'''

COMPOUND = MARK + '''from skiros2_skill.core.skill import SerialStar, SkillBase
from skiros2_common.core.abstract_skill import SkillDescription

STEPS = ("Wait", "Wait")


class Tidy(SkillDescription):
    def createDescription(self):
        pass


class tidy(SkillBase):
    def createDescription(self):
        self.setDescription(Tidy(), self.__class__.__name__)

    def expand(self, skill):
        skill.setProcessor(SerialStar())
        for name in STEPS:
            skill(self.skill(name, ""))
'''


@pytest.fixture
def repo(tmp_path: Path) -> Path:
    root = tmp_path / "repo"
    root.mkdir()
    migrated = (FIXTURES / "migrated" / "pick_and_place.py").read_text(encoding="utf-8")
    (root / "ez_skills.py").write_text(MARK + migrated, encoding="utf-8")
    (root / "tasks.py").write_text(COMPOUND, encoding="utf-8")
    return root


def _check(repo: Path, markers: Path, *extra: str) -> subprocess.CompletedProcess[str]:
    markers.mkdir(exist_ok=True)
    env = dict(os.environ, EZMIGRATE_TEST_MARKER=str(markers))
    return subprocess.run([sys.executable, "-m", "ezmigrate", "check", "--exit-zero",
                           "--no-cache", *extra, "."], cwd=repo, env=env, capture_output=True,
                          text=True, timeout=600, check=False)


def test_no_trace_imports_nothing_and_says_what_it_left(repo: Path, tmp_path: Path) -> None:
    run = _check(repo, tmp_path / "none", "--no-trace")
    assert run.returncode == 0, run.stderr
    assert sorted(p.name for p in (tmp_path / "none").iterdir()) == []
    assert "1 EzSkiROS file(s) not loaded (--no-trace)" in run.stderr
    assert "--no-trace keeps its module from being imported" in run.stdout


def test_without_it_both_are_imported_in_the_sandbox(repo: Path, tmp_path: Path) -> None:
    run = _check(repo, tmp_path / "all")
    assert run.returncode == 0, run.stderr
    imported = sorted(p.name.rpartition(".")[2] for p in (tmp_path / "all").iterdir())
    assert imported == ["ez_skills", "tasks"]  # (module names as the sandbox gives them)
