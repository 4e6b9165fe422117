"""A legacy class ``rewrite`` keeps gets the same findings before and after the rest of its
file is migrated (issue 30): once the file is EzSkiROS, ``check`` loads it, and the
runtime's refusal of a fork's API must not turn the static pass's info into an error."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

from check_support import cli

MIXED = """\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


class Shared(SkillDescription):
    def createDescription(self):
        self.addParam("Out", Element("skiros:Parameter"), ParamTypes.SharedOutput)


class Plain(SkillDescription):
    def createDescription(self):
        self.addParam("Name", True, ParamTypes.Required)
"""


def _about_shared(folder: Path) -> list[tuple[str, str]]:
    run = cli(".", "--output-format", "json", "--no-cache", cwd=folder)
    assert run.returncode in (0, 1), run.stderr
    return sorted((str(d["code"]), str(d["severity"])) for d in json.loads(run.stdout)
                  if str(d["message"]).startswith("Shared:"))


def test_a_kept_legacy_class_has_the_same_findings_once_its_neighbours_are_migrated(
        tmp_path: Path) -> None:
    (tmp_path / "pkg").mkdir()
    (tmp_path / "pkg" / "skills.py").write_text(MIXED, encoding="utf-8")
    subprocess.run(["git", "init", "-q", str(tmp_path)], check=True)
    before = _about_shared(tmp_path)
    assert before == [("EZ902", "info")]
    rewrite = subprocess.run([sys.executable, "-m", "ezmigrate", "rewrite", "--no-verify", "."],
                             cwd=tmp_path, capture_output=True, text=True, check=False,
                             stdin=subprocess.DEVNULL, timeout=300)
    assert rewrite.returncode == 0, rewrite.stderr
    migrated = (tmp_path / "pkg" / "skills.py").read_text(encoding="utf-8")
    assert "def description(self" in migrated and "ParamTypes.SharedOutput" in migrated
    assert _about_shared(tmp_path) == before
