"""End to end on a repository laid out like a real SkiROS2 lab's (``fixtures/ros_repo``).

A copy is made a git repository and ``ezmigrate rewrite`` runs at its root, as a lab would
run it: the lab's ``owl/`` files are found (the vendored core is not loaded twice), every
description class converts and verifies, and the diff holds nothing but the migrated
descriptions and the import lines the migration needed.
"""

from __future__ import annotations

import difflib
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import libcst as cst
import pytest
from verify_support import second_python

from ezmigrate.files.package_xml import RUNTIME_PACKAGE
from ezmigrate.verify.interpreters import find_python

REPO = Path(__file__).resolve().parents[2] / "fixtures" / "ros_repo"
SKILLS = Path("lab_skills/src/lab_skills/skills")
DESCRIPTIONS = {"PaintPart", "GoToStation", "PaintAtStation", "DetectPaint"}
NEWER = "vision.py"
"""Uses Python 3.12 f-strings: verifiable only under a Python that can import it."""


ROBOT = find_python("3.8")
"""lab_skills is a ROS 1 (catkin) package: with Python 3.8 on this machine, rewrite verifies
under it (the robot's), and vision.py, which 3.8 cannot read, fails as it would on the robot."""

SECOND = second_python()
"""A newer interpreter for vision.py, put on PATH as ``python3.12`` for the run (pyenv's
shims do not run it), so that ``rewrite`` finds it the way it would on a lab's machine."""


def _newer_python() -> str | None:
    """The interpreter that can verify vision.py (3.12 syntax), or None when the run cannot:
    the run verifies under the robot's 3.8 when it finds one, and the file again under the
    oldest newer Python that reads it."""
    return SECOND


@pytest.fixture(scope="module")
def migrated(tmp_path_factory):
    root = tmp_path_factory.mktemp("lab") / "ros_repo"
    shutil.copytree(REPO, root)
    subprocess.run(["git", "init", "-q", str(root)], check=True)
    report = root.parent / "report.json"
    env = dict(os.environ)
    if SECOND is not None:
        bin_dir = root.parent / "bin"
        bin_dir.mkdir()
        (bin_dir / "python3.12").symlink_to(SECOND)
        env["PATH"] = os.pathsep.join([str(bin_dir), env.get("PATH", "")])
    run = subprocess.run([sys.executable, "-m", "ezmigrate", "rewrite", ".", "--report",
                          str(report)], cwd=root, capture_output=True, text=True,
                         check=False, timeout=900, env=env)
    return root, run, json.loads(report.read_text(encoding="utf-8"))


def test_the_lab_ontology_is_found_and_the_vendored_core_skipped(migrated):
    _, run, data = migrated
    lines = [line for line in run.stderr.splitlines() if line.startswith("ezmigrate: ontology")]
    # the repository is the working directory: named as ruff and black would, "."
    assert lines == ["ezmigrate: ontology: the bundled SkiROS2 core plus the owl/ folders of "
                     ".: owl/lab.owl, owl/robot.owl (vendored SkiROS2 "
                     "copies skipped: vendor/skiros2/owl/skiros.owl)"]
    assert data["ontology"] == lines[0].removeprefix("ezmigrate: ")
    assert "unknown" not in run.stderr  # lab:PaintStation, lab:paintedAt, ... are known


def test_every_description_converts_and_verifies(migrated):
    _, run, data = migrated
    skills = {s["class"]: s for s in data["skills"]}
    assert set(skills) == DESCRIPTIONS
    for name in DESCRIPTIONS - {"DetectPaint"}:
        assert (skills[name]["status"], skills[name]["equivalent"]) == ("converted", True), \
            skills[name]
    detect = skills["DetectPaint"]
    if ROBOT is not None:  # verified under the robot's Python 3.8, which cannot read it
        assert "verified under Python 3.8" in run.stderr
    if _newer_python() is None:  # the one file no Python here can import: said, not written
        assert detect["status"] == "failed"
        assert "SyntaxError" in detect["reason"] or "cannot import under" in detect["reason"]
    else:  # loaded again under the oldest Python that reads it, and the summary says so
        assert (detect["status"], detect["equivalent"]) == ("converted", True), detect
        assert "1 file needs a newer Python than 3." in run.stderr
        assert "the oldest found that reads it (" in run.stderr
    assert "Traceback" not in run.stderr


def _allowed_lines(source: str, classes: set[str]) -> set[int]:
    """Lines a migration may touch: the description classes' and the module's imports.
    (libcst, not ``ast``: vision.py has syntax newer than this Python.)"""
    wrapper = cst.metadata.MetadataWrapper(cst.parse_module(source))
    positions = wrapper.resolve(cst.metadata.PositionProvider)
    allowed: set[int] = set()
    for node in wrapper.module.body:
        is_import = isinstance(node, cst.SimpleStatementLine) and all(
            isinstance(small, (cst.Import, cst.ImportFrom)) for small in node.body)
        if (isinstance(node, cst.ClassDef) and node.name.value in classes) or is_import:
            span = positions[node]
            allowed.update(range(span.start.line, span.end.line + 1))
    return allowed


def test_the_diff_holds_only_descriptions_and_the_imports_they_needed(migrated):
    root, _, _ = migrated
    changed = []
    for original in sorted(REPO.rglob("*")):
        if not original.is_file():
            continue
        relative = original.relative_to(REPO)
        before, after = original.read_bytes(), (root / relative).read_bytes()
        if before == after:
            continue
        changed.append(relative.as_posix())
        old, new = before.decode().splitlines(), after.decode().splitlines()
        if relative.name == "package.xml":  # the runtime declared: one line added, no other
            assert [line for line in new if line not in old] == [
                f"  <exec_depend>{RUNTIME_PACKAGE}</exec_depend>"]
            assert len(new) == len(old) + 1
            continue
        old_ok = _allowed_lines(before.decode(), DESCRIPTIONS)
        new_ok = _allowed_lines(after.decode(), DESCRIPTIONS)
        matcher = difflib.SequenceMatcher(a=old, b=new, autojunk=False)
        for tag, i1, i2, j1, j2 in matcher.get_opcodes():
            if tag == "equal":
                continue
            outside = [old[i] for i in range(i1, i2) if i + 1 not in old_ok] + \
                      [new[j] for j in range(j1, j2) if j + 1 not in new_ok]
            assert outside == [], f"{relative}: lines outside descriptions and imports"
    expected = {(SKILLS / n).as_posix() for n in ("paint.py", "navigation.py", "tasks.py")}
    expected.add("lab_skills/package.xml")
    if _newer_python() is not None:
        expected.add((SKILLS / NEWER).as_posix())
    assert set(changed) == expected


def test_unused_imports_stay_and_new_imports_follow_the_star_import(migrated):
    root, _, _ = migrated
    navigation = (root / SKILLS / "navigation.py").read_text(encoding="utf-8")
    for kept in ("import skiros2_common.tools.logger as log\n",
                 "from skiros2_skill.core.skill import SkillBase, State, SkillWrapper, "
                 "ParallelFf\n",
                 "from skiros2_common.core.primitive import PrimitiveBase\n",
                 "from skiros2_skill.ros.skill_manager import SkillManager\n"):
        assert kept in navigation
    paint = (root / SKILLS / "paint.py").read_text(encoding="utf-8")
    assert paint.index("from ..helpers import *") < paint.index("from ezskiros_runtime import")


def test_the_migrated_repository_verifies_against_the_original(migrated, tmp_path):
    root, _, _ = migrated
    original = tmp_path / "ros_repo"  # a repository of its own, as the lab's checkout is
    shutil.copytree(REPO, original)
    subprocess.run(["git", "init", "-q", str(original)], check=True)
    src = Path("lab_skills/src")  # the package root: relative imports resolve
    run = subprocess.run([sys.executable, "-m", "ezmigrate", "verify", str(original / src),
                          str(root / src), "--exclude", NEWER],
                         capture_output=True, text=True, check=False, timeout=900)
    assert run.returncode == 0, run.stderr
    assert "3 classes, 3 equivalent, 0 not equivalent" in run.stderr
