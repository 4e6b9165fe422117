"""Paths as every other tool prints them (issue 22, item 3).

Relative to the working directory when inside it (stderr, report and ``check`` alike, even
for a PATH given absolute), dry-run diff headers relative to the repository root so that
``git apply`` from there takes them, no absolute path in a report, and report lines those
of the written file with the legacy line beside them.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures"
LEGACY = '''"""Drive skills."""
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


class Drive(SkillDescription):
    def createDescription(self):
        self.addParam("Base", Element("skiros:Location"), ParamTypes.Required)
        self.addParam("Linear", float, ParamTypes.Required, "Linear velocity")
        self.addPreCondition(self.getRelationCond("At", "skiros:at", "Base", "Base", True))


class Loop(SkillDescription):
    def createDescription(self):
        for key in sorted(("A", "B")):  # computed: kept as legacy
            self.addParam(key, 0.5, ParamTypes.Optional)
'''


def ezmigrate(cwd: Path, *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "ezmigrate", *args], cwd=cwd,
                          capture_output=True, text=True, stdin=subprocess.DEVNULL,
                          timeout=300, check=False)


def repository(tmp_path: Path) -> Path:
    subprocess.run(["git", "init", "-q", str(tmp_path)], check=True)
    folder = tmp_path / "src" / "pkg"
    folder.mkdir(parents=True)
    (folder / "__init__.py").write_text("", encoding="utf-8")
    (folder / "drive.py").write_text(LEGACY, encoding="utf-8")
    return folder / "drive.py"


PACKAGE = """<?xml version="1.0"?>
<package format="2">
  <name>pkg</name>
  <version>0.1.0</version>
  <description>skills</description>
  <maintainer email="lab@example.org">lab</maintainer>
  <license>MIT</license>
  <buildtool_depend>catkin</buildtool_depend>
</package>
"""


def test_dry_run_diffs_apply_from_the_repository_root(tmp_path: Path):
    path = repository(tmp_path)
    (path.parent / "package.xml").write_text(PACKAGE, encoding="utf-8")  # a ROS package
    run = ezmigrate(path.parent, "rewrite", "--dry-run", "--no-verify", ".")  # from deep inside
    assert run.stdout.startswith("--- a/src/pkg/drive.py\n+++ b/src/pkg/drive.py\n"), run.stdout
    assert "\n--- a/src/pkg/package.xml\n+++ b/src/pkg/package.xml\n" in run.stdout
    (tmp_path / "m.diff").write_text(run.stdout, encoding="utf-8")
    subprocess.run(["git", "apply", "m.diff"], cwd=tmp_path, check=True)
    assert "def description(self," in path.read_text(encoding="utf-8")
    assert "<exec_depend>" in (path.parent / "package.xml").read_text(encoding="utf-8")


def test_stderr_report_and_check_use_one_base_and_no_absolute_path(tmp_path: Path):
    path = repository(tmp_path)
    absolute = str(path.parent)  # given absolute, printed relative to the working directory
    ontology = str(FIXTURES.parent / "ezskiros_runtime" / "ontology" / "data")
    run = ezmigrate(tmp_path, "rewrite", "--no-verify", "--ontology", ontology,
                    "--report", "r.json", absolute)
    assert run.returncode == 0, run.stderr
    assert "\nsrc/pkg/drive.py:15: Loop: skipped" in "\n" + run.stderr  # the written line
    report = (tmp_path / "r.json").read_text(encoding="utf-8")
    assert str(tmp_path) not in report and str(FIXTURES.parent) not in report
    assert {s["file"] for s in json.loads(report)["skills"]} == {"src/pkg/drive.py"}
    markdown = ezmigrate(tmp_path, "rewrite", "--dry-run", "--ontology", ontology,
                         "--report", "r.md", absolute)
    assert markdown.returncode == 0, markdown.stderr
    text = (tmp_path / "r.md").read_text(encoding="utf-8")
    assert "## `src/pkg/drive.py`" in text and str(FIXTURES.parent) not in text
    checked = ezmigrate(tmp_path, "check", "--select", "EZ902", absolute)
    assert checked.stdout.startswith("src/pkg/drive.py:"), checked.stdout


def test_report_lines_are_the_written_files_with_the_legacy_line_beside(tmp_path: Path):
    path = repository(tmp_path)
    run = ezmigrate(tmp_path, "rewrite", "--no-verify", "--report", "r.json", "src")
    assert run.returncode == 0, run.stderr
    written = path.read_text(encoding="utf-8").splitlines()
    skills = {s["class"]: s for s in json.loads(
        (tmp_path / "r.json").read_text(encoding="utf-8"))["skills"]}
    drive, loop = skills["Drive"], skills["Loop"]
    assert written[drive["line"] - 1] == "class Drive(EzSkillDescription):"
    assert drive["legacy_line"] == 7
    assert written[loop["line"] - 1] == "class Loop(SkillDescription):"
    assert loop["legacy_line"] == 14
    [finding] = [f for f in drive["findings"] if f["code"] == "EZ101"]
    assert finding["legacy_line"] == 10
    assert written[finding["line"] - 1].lstrip().startswith("Linear: float):  # Linear velocity")
