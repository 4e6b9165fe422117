"""Files this Python cannot import are verified under another one.

``--python PATH`` (or ``[tool.ezmigrate] python``) names it; without it, a file with
syntax newer than ours is loaded again under the oldest newer ``python3.X`` (on PATH, else
in pyenv's versions folder) that compiles it, and the summary and the report say which.
Needs a second interpreter of 3.12 or later: found on PATH or in pyenv's versions folder,
else these tests are skipped with the reason.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from verify_support import second_python

from ezmigrate.files.paths import scrub

NEWER_SKILL = '''\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


def describe(detection):
    return f"{detection["label"]} at {detection["pose"]}"


class DetectPaint(SkillDescription):
    def createDescription(self):
        self.addParam("Camera", Element("skiros:DepthCamera"), ParamTypes.Inferred)
        self.addParam("Speed", 0.5, ParamTypes.Optional)
        self.addPreCondition(self.getRelationCond("RobotHasCamera", "skiros:hasA", "Robot",
                                                  "Camera", True))
'''


SECOND = second_python()
needs_second = pytest.mark.skipif(
    SECOND is None or sys.version_info >= (3, 12),
    reason="no second interpreter of Python 3.12 or later on PATH or in ~/.pyenv/versions "
           "(or this Python already imports the file)")


def _run(tmp_path: Path, *extra: str, env: dict[str, str] | None = None,
         cwd: Path | None = None) -> tuple[subprocess.CompletedProcess[str], dict]:
    folder = tmp_path / "skills"
    folder.mkdir(exist_ok=True)
    (folder / "vision.py").write_text(NEWER_SKILL, encoding="utf-8")
    report = tmp_path / "report.json"
    run = subprocess.run([sys.executable, "-m", "ezmigrate", "rewrite", str(folder),
                          "--report", str(report), *extra], capture_output=True, text=True,
                         check=False, timeout=600, env=env, cwd=cwd or tmp_path)
    data = json.loads(report.read_text(encoding="utf-8")) if report.exists() else {}
    return run, data


def _path_with(tmp_path: Path, python: str | None) -> dict[str, str]:
    """PATH holding only our own bin folder and, if given, ``python`` as ``python3.12``."""
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    if python is not None:
        (bin_dir / "python3.12").symlink_to(python)
    (bin_dir / "git").symlink_to(shutil.which("git") or "/usr/bin/git")
    return dict(os.environ, PATH=str(bin_dir))


@needs_second
def test_the_given_interpreter_loads_both_versions(tmp_path):
    assert SECOND is not None
    run, data = _run(tmp_path, "--python", SECOND)
    assert run.returncode == 0, run.stderr
    assert [(s["class"], s["status"], s["equivalent"]) for s in data["skills"]] == [
        ("DetectPaint", "converted", True)]
    notes = [n for f in data["files"] for n in f["notes"]]
    shown = scrub(SECOND)  # as a report names it: no absolute path (issue 22, item 3)
    assert any(n.startswith("verified under ") and shown in n for n in notes), notes


@needs_second
def test_without_one_the_oldest_newer_one_that_compiles_the_file_is_used(tmp_path):
    run, data = _run(tmp_path, env=_path_with(tmp_path, SECOND))
    assert run.returncode == 0, run.stderr
    assert data["skills"][0]["status"] == "converted"
    notes = [n for f in data["files"] for n in f["notes"]]
    assert any(n.startswith("verified under python3.12 (") for n in notes), notes
    assert ("1 file needs a newer Python than 3." in run.stderr
            and "verified under python3.12, the oldest found that reads it "
                "(skills/vision.py)" in run.stderr), run.stderr


@needs_second
def test_the_oldest_of_several_newer_interpreters_is_chosen(tmp_path):
    """3.12 and 3.13 both read the file: a ROS 2 package that needs 3.12 runs on Jazzy
    (3.12), so 3.12 verifies it, whichever is newest."""
    assert SECOND is not None
    env = _path_with(tmp_path, SECOND)
    (tmp_path / "bin" / "python3.13").symlink_to(SECOND)  # a newer name, same interpreter
    (tmp_path / "bin" / "python3.12").unlink()
    (tmp_path / "bin" / "python3.12").symlink_to(SECOND)
    _, data = _run(tmp_path, env=env)
    notes = [n for f in data["files"] for n in f["notes"]]
    assert any(n.startswith("verified under python3.12 (") for n in notes), notes
    assert not any("python3.13" in n for n in notes), notes


@needs_second
def test_the_project_can_name_its_interpreter(tmp_path):
    (tmp_path / "pyproject.toml").write_text(f'[tool.ezmigrate]\npython = "{SECOND}"\n',
                                             encoding="utf-8")
    run, data = _run(tmp_path, env=_path_with(tmp_path, None))
    assert run.returncode == 0, run.stderr
    assert data["skills"][0]["equivalent"] is True


def test_with_no_newer_interpreter_the_file_is_said_to_need_one(tmp_path):
    env = dict(_path_with(tmp_path, None), PYENV_ROOT=str(tmp_path / "no-pyenv"))
    run, data = _run(tmp_path, env=env)
    assert run.returncode == 1
    skill = data["skills"][0]
    assert skill["status"] == "failed" and "cannot import under Python 3." in skill["reason"]
    assert "no newer Python on PATH or in pyenv's versions folder" in skill["reason"]
    assert "def createDescription" in (tmp_path / "skills" / "vision.py").read_text()


@needs_second
def test_a_newer_interpreter_installed_by_pyenv_verifies_the_file(tmp_path):
    """Not on PATH, but in pyenv's versions folder (as robots' Pythons are on a developer's
    machine): used, and the summary names it."""
    assert SECOND is not None
    installed = tmp_path / "pyenv" / "versions" / "3.12.9" / "bin" / "python3.12"
    installed.parent.mkdir(parents=True)
    installed.symlink_to(SECOND)
    env = dict(_path_with(tmp_path, None), PYENV_ROOT=str(tmp_path / "pyenv"))
    run, data = _run(tmp_path, env=env)
    assert run.returncode == 0, run.stderr
    assert data["skills"][0]["status"] == "converted"
    assert "verified under python3.12, the oldest found that reads it" in run.stderr


def test_an_interpreter_that_does_not_exist_is_a_usage_error(tmp_path):
    run, _ = _run(tmp_path, "--python", str(tmp_path / "no-such-python"))
    assert run.returncode == 2
    assert "no such interpreter" in run.stderr and "Traceback" not in run.stderr
