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
    used = [f.get("python", "") for f in data["files"]]
    shown = scrub(SECOND)  # as a report names it: no absolute path (issue 22, item 3)
    assert any(shown in u for u in used), used


@needs_second
def test_without_one_the_oldest_newer_one_that_compiles_the_file_is_used(tmp_path):
    run, data = _run(tmp_path, env=_path_with(tmp_path, SECOND))
    assert run.returncode == 0, run.stderr
    assert data["skills"][0]["status"] == "converted"
    pythons = [f.get("python") for f in data["files"]]
    assert "bin/python3.12" in pythons, pythons  # the report's form of the path
    used = tmp_path / "bin" / "python3.12"  # the summary gives the absolute path
    assert ("1 file needs a newer Python than 3." in run.stderr
            and f"verified under {used}, the oldest found that reads it "
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
    pythons = [f.get("python") for f in data["files"]]
    assert "bin/python3.12" in pythons, pythons
    assert not any("python3.13" in (p or "") for p in pythons), pythons


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
    assert f"verified under {installed}, the oldest found that reads it" in run.stderr


def test_an_interpreter_that_does_not_exist_is_a_usage_error(tmp_path):
    run, _ = _run(tmp_path, "--python", str(tmp_path / "no-such-python"))
    assert run.returncode == 2
    assert "no such interpreter" in run.stderr and "Traceback" not in run.stderr


FAKE_PYTHON = """#!/bin/sh
# a repository's own interpreter: if anything runs it, the marker says so
echo "$0 $*" >> "{marker}"
echo 3.8.99
exit 0
"""

CATKIN_MANIFEST = """<?xml version="1.0"?>
<package format="2">
  <name>cell_skills</name>
  <version>0.1.0</version>
  <description>cell skills</description>
  <maintainer email="lab@example.org">Lab</maintainer>
  <license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend>
</package>
"""


def _planted(repo: Path, marker: Path) -> list[str]:
    """``python3.8`` and every newer ``python3.X`` a search could ask for, as executable
    scripts in the repository's root, its ``bin/`` and its ``tools/``; their names."""
    names = [f"python3.{minor}" for minor in range(8, 32)]
    for folder in (repo, repo / "bin", repo / "tools"):
        folder.mkdir(exist_ok=True)
        for name in names:
            script = folder / name
            script.write_text(FAKE_PYTHON.format(marker=marker), encoding="utf-8")
            script.chmod(0o755)
    return names


def test_a_repositorys_own_interpreters_are_never_run(tmp_path):
    """With ``.``, an empty entry, a relative ``bin`` and the repository's absolute
    ``tools/`` on PATH, run from inside the repository: a ROS 1 package (``python3.8`` is
    looked for) with a file only Python 3.12 reads (every newer ``python3.X`` is looked
    for). None of the repository's scripts runs, and no line names one of them."""
    repo = tmp_path / "cell_skills"
    (repo / "src").mkdir(parents=True)
    subprocess.run(["git", "init", "-q", str(repo)], check=True, timeout=60)
    (repo / "package.xml").write_text(CATKIN_MANIFEST, encoding="utf-8")
    (repo / "src" / "vision.py").write_text(NEWER_SKILL, encoding="utf-8")
    marker = tmp_path / "ran.txt"
    _planted(repo, marker)
    git = Path(shutil.which("git") or "/usr/bin/git").parent
    path = os.pathsep.join([".", "", "bin", str(repo / "tools"), str(git)])
    env = dict(os.environ, PATH=path, PYENV_ROOT=str(tmp_path / "no-pyenv"))
    for command in (["rewrite", "--dry-run", "src"], ["rewrite", "--check", "src"],
                    ["verify", "src", "src"], ["check", "--trace", "."]):
        run = _ezmigrate(command, repo, env)
        assert run.returncode in (0, 1), run.stderr
        assert not marker.exists(), (command, marker.read_text(), run.stderr)
        assert str(repo / "tools") not in run.stderr + run.stdout
        if command[0] != "check":  # both searches were made, and found nothing
            assert f"({sys.executable}), ontology read with" in run.stderr, run.stderr
            assert "no python3.8 was found on PATH's absolute entries" in run.stderr
            assert "no newer Python on PATH or in pyenv's versions folder" in run.stderr
    # the control: the same scripts in a folder outside the repository are found and run
    outside = tmp_path / "outside"
    outside.mkdir()
    _planted(outside, marker)
    env["PATH"] = os.pathsep.join([str(outside), path])
    run = _ezmigrate(["rewrite", "--dry-run", "src"], repo, env)
    assert marker.exists(), run.stderr
    assert f"({outside / 'python3.8'}), ontology read with" in run.stderr, run.stderr


def _ezmigrate(command: list[str], cwd: Path,
               env: dict[str, str]) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "ezmigrate", *command], cwd=cwd, env=env,
                          capture_output=True, text=True, check=False, timeout=600)


def test_only_absolute_entries_outside_the_checked_repository_are_searched(tmp_path, monkeypatch):
    """The rule itself, in this process: relative entries never count, an absolute one
    inside a path given to ``never_search`` (or inside its git top level) stops counting,
    and what is found is an absolute path."""
    from ezmigrate.verify import interpreters

    monkeypatch.setattr(interpreters, "_UNSEARCHED", set())
    repo = tmp_path / "repo"
    (repo / "pkg").mkdir(parents=True)
    (repo / ".git").mkdir()
    marker = tmp_path / "ran.txt"
    _planted(repo, marker)
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    _planted(elsewhere, marker)
    monkeypatch.chdir(repo)
    monkeypatch.setenv("PYENV_ROOT", str(tmp_path / "no-pyenv"))
    monkeypatch.setenv("PATH", os.pathsep.join([".", "", "bin"]))
    assert interpreters.find_python("3.8") is None
    assert interpreters.resolve("python3.8") is None
    monkeypatch.setenv("PATH", os.pathsep.join([".", str(repo / "tools"), str(elsewhere)]))
    assert interpreters.find_python("3.8") == str(repo / "tools" / "python3.8")
    interpreters.never_search([repo / "pkg"])  # a path given: its git top level is repo
    assert interpreters.find_python("3.8") == str(elsewhere / "python3.8")
    assert interpreters.resolve("./bin/python3.8") == str(repo / "bin" / "python3.8")
    assert not marker.exists()


def test_a_python_without_rdflib_verifies_from_the_ontology_cache_this_run_filled(
        tmp_path: Path) -> None:
    """A robot's Python found on the machine (``python3.8`` from pyenv, ``--python``) often
    lacks rdflib. Its worker runs under a private ``HOME``, so it must be told where the
    ontology cache this run filled lives (``worker_environment``): else it looks in an
    empty folder, parses the ontology with an rdflib it does not have, and every skill
    fails with "crashed: no result". Here the cache is the default one (no
    ``EZSKIROS_CACHE_DIR``), as on a developer's machine."""
    base = Path(sys.base_prefix) / "bin" / f"python{sys.version_info[0]}.{sys.version_info[1]}"
    if not base.is_file():
        pytest.skip(f"no base interpreter at {base}")
    if subprocess.run([str(base), "-c", "import rdflib"], capture_output=True,
                      check=False).returncode == 0:
        pytest.skip("the base interpreter has rdflib: it cannot stand for a robot's without")
    robot = tmp_path / "bin" / "robot-python"
    robot.parent.mkdir()
    robot.write_text(f'#!/bin/sh\nexec "{base}" "$@"\n', encoding="utf-8")
    robot.chmod(0o755)
    repo = tmp_path / "repo"
    repo.mkdir()
    shutil.copy(Path(__file__).resolve().parents[2] / "fixtures" / "legacy" / "conditions.py",
                repo / "conditions.py")
    env = {name: value for name, value in os.environ.items() if name != "EZSKIROS_CACHE_DIR"}
    env["XDG_CACHE_HOME"] = str(tmp_path / "user-cache")
    run = subprocess.run([sys.executable, "-m", "ezmigrate", "rewrite", "--dry-run",
                          "--python", str(robot), "."], cwd=repo, env=env,
                         capture_output=True, text=True, check=False, timeout=600)
    assert "crashed" not in run.stdout + run.stderr, run.stderr
    summary = run.stderr.strip().splitlines()[-1]
    assert " 0 failed" in summary and " 0 converted" not in summary, summary
    # with no cache it can read, it cannot start: each skill says why, not "no result"
    blocked = tmp_path / "not-a-folder"
    blocked.write_text("", encoding="utf-8")
    env["EZSKIROS_CACHE_DIR"] = str(blocked)
    run = subprocess.run([sys.executable, "-m", "ezmigrate", "rewrite", "--dry-run",
                          "--python", str(robot), "."], cwd=repo, env=env,
                         capture_output=True, text=True, check=False, timeout=600)
    failed = [line for line in run.stderr.splitlines() if ": failed: " in line]
    assert failed and all(f"the verification worker did not start under {robot}: "
                          "ModuleNotFoundError: No module named 'rdflib'" in line
                          for line in failed), run.stderr
    assert "internal error" not in run.stderr
