"""``check`` imports no repository code unless told (``--trace``): an EzSkiROS file is read
from its syntax, a compound skill whose tree the syntax cannot give is reported as unread.
With ``--trace`` both are imported, in the sandbox. Each module here writes a marker file
when it is imported, and the compound skill's ``expand`` writes one when it runs; the
marker paths are literal in the modules, so no environment variable is needed to reach
them."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures"


def _mark(markers: Path, name: str) -> str:
    return f"open({str(markers / name)!r}, 'w').close()\n"


def _compound(markers: Path) -> str:
    return _mark(markers, "tasks-imported") + f'''\
from skiros2_skill.core.skill import SerialStar, SkillBase
from skiros2_common.core.abstract_skill import SkillDescription

STEPS = ("Wait", "Wait")


class Tidy(SkillDescription):
    def createDescription(self):
        pass


class tidy(SkillBase):
    def createDescription(self):
        self.setDescription(Tidy(), self.__class__.__name__)

    def expand(self, skill):
        open({str(markers / "expand-ran")!r}, "w").close()
        skill.setProcessor(SerialStar())
        for name in STEPS:
            skill(self.skill(name, ""))
'''


@pytest.fixture
def repo(tmp_path: Path) -> Path:
    root = tmp_path / "repo"
    root.mkdir()
    markers = tmp_path / "markers"
    markers.mkdir()
    migrated = (FIXTURES / "migrated" / "pick_and_place.py").read_text(encoding="utf-8")
    (root / "ez_skills.py").write_text(_mark(markers, "ez_skills-imported") + migrated,
                                       encoding="utf-8")
    (root / "tasks.py").write_text(_compound(markers), encoding="utf-8")
    return root


def _check(repo: Path, *extra: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "ezmigrate", "check", "--exit-zero",
                           "--no-cache", "--output-format", "json", *extra, "."], cwd=repo,
                          capture_output=True, text=True, timeout=600, check=False)


def _markers(repo: Path) -> list[str]:
    return sorted(p.name for p in (repo.parent / "markers").iterdir())


def test_check_runs_no_repository_code_and_says_what_it_left(repo: Path) -> None:
    run = _check(repo)
    assert run.returncode == 0, run.stderr
    assert _markers(repo) == []
    found = json.loads(run.stdout)
    unread = [d for d in found if d["code"] == "EZ313"]
    assert len(unread) == 1 and "check --trace runs it" in unread[0]["message"]
    assert unread[0]["path"].endswith("tasks.py")


def test_with_trace_both_are_imported_and_expand_runs(repo: Path) -> None:
    run = _check(repo, "--trace")
    assert run.returncode == 0, run.stderr
    assert _markers(repo) == ["expand-ran", "ez_skills-imported", "tasks-imported"]


def test_the_ezskiros_findings_are_those_loading_gives(repo: Path) -> None:
    """The descriptions read from the syntax give what loading them gives: same findings
    of the EzSkiROS file, line for line, with and without ``--trace``."""
    (repo / "ez_skills.py").write_text(
        (repo / "ez_skills.py").read_text(encoding="utf-8")
        .replace("skiros.Location", "skiros.Locaton", 1), encoding="utf-8")
    static, loaded = _check(repo), _check(repo, "--trace")

    def of_file(run: subprocess.CompletedProcess[str]) -> list[tuple[int, str, str]]:
        # the sandbox names the file by its absolute path, the static reading as given
        return sorted((d["line"], d["code"], d["message"].replace(f"{repo}/", ""))
                      for d in json.loads(run.stdout) if d["path"].endswith("ez_skills.py"))

    assert of_file(static) == of_file(loaded)
    assert of_file(static), "the mistyped class must be found"
