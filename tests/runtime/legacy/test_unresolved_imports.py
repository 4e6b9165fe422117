"""Imports that cannot be resolved are not the skill's problem: both versions get the same
permissive stand-in, the report names it, and a genuine error of the file still fails.
"""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from ezskiros_runtime.legacy.errors import ModuleLoadError
from ezskiros_runtime.legacy.loader import load_file

SKILL = '''\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element
import rospy
from geometry_msgs.msg import Pose
from .helpers import make_pose{extra}


class Place(SkillDescription):
    def createDescription(self):
        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)
        self.addParam("Speed", 0.5, ParamTypes.Optional)
'''


def _write(folder: Path, extra: str = "", helpers: bool = False) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "place.py"
    path.write_text(SKILL.format(extra=extra), encoding="utf-8")
    if helpers:
        (folder / "helpers.py").write_text("def make_pose():\n    return 'pose'\n",
                                           encoding="utf-8")
    return path


def test_a_relative_import_of_a_file_passed_alone_gets_a_stand_in_and_is_listed(tmp_path):
    loaded = load_file(_write(tmp_path / "alone"))
    assert [m.name for m in loaded.models] == ["Place"]
    assert loaded.stood_in == [".helpers"]  # rospy and geometry_msgs are expected


def test_a_sibling_that_exists_is_imported_for_real(tmp_path):
    folder = tmp_path / "with_helpers"
    loaded = load_file(_write(folder, helpers=True))
    assert [m.name for m in loaded.models] == ["Place"] and loaded.stood_in == []


def test_a_genuine_error_of_the_file_stays_a_failure(tmp_path):
    path = _write(tmp_path / "broken", extra="\nVALUE = undefined_name + 1")
    with pytest.raises(ModuleLoadError, match="undefined_name"):
        load_file(path)


def test_a_name_only_a_stood_in_star_import_could_give_fails_naming_the_module(tmp_path):
    path = _write(tmp_path / "star", extra="\nfrom .common import *\nSPEED = DEFAULT_SPEED")
    with pytest.raises(ModuleLoadError) as caught:
        load_file(path)
    assert "DEFAULT_SPEED" in str(caught.value)
    assert "perhaps from .common, imported with * but not found" in str(caught.value)


def test_verification_compares_both_versions_and_the_report_names_the_stand_in(tmp_path):
    folder = tmp_path / "tree"
    _write(folder)
    original = tmp_path / "original"
    shutil.copytree(folder, original)
    report = tmp_path / "report.json"
    run = subprocess.run([sys.executable, "-m", "ezmigrate", "rewrite", str(folder / "place.py"),
                          "--report", str(report)],
                         capture_output=True, text=True, check=False, timeout=600)
    assert run.returncode == 0, run.stderr
    data = json.loads(report.read_text(encoding="utf-8"))
    assert [(s["class"], s["status"], s["equivalent"]) for s in data["skills"]] == [
        ("Place", "converted", True)]
    notes = [n for f in data["files"] for n in f["notes"]]
    assert any("stood in" in n and ".helpers" in n for n in notes), data["files"]
    assert "def description(self," in (folder / "place.py").read_text(encoding="utf-8")
