"""``check`` on the compound-skill fixture repository reports exactly the marked mistakes.

Every line of ``fixtures/compound_repo`` that carries ``# expect: EZ3xx`` must get that
finding, and no other compound finding may appear there; on every other fixture
repository of the project no compound finding at error severity may appear at all
(precision: an error is a real mistake). Real CLI, real child processes for the traced
trees, the bundled ontology.
"""

from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
REPO = ROOT / "fixtures" / "compound_repo"
MARKER = re.compile(r"# expect: (EZ\d{3}(?:, EZ\d{3})*)")


def _check(*args: str | Path) -> list[dict[str, object]]:
    run = subprocess.run([sys.executable, "-m", "ezmigrate", "check", "--output-format",
                          "json", "--exit-zero", "--trace", *map(str, args)],
                         capture_output=True,
                         text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    return json.loads(run.stdout)


def _markers() -> set[tuple[str, int, str]]:
    found = set()
    for path in REPO.rglob("*.py"):
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            match = MARKER.search(line)
            if match:
                found |= {(path.name, number, code) for code in match.group(1).split(", ")}
    return found


def test_every_marked_mistake_and_nothing_else_is_reported() -> None:
    expected = _markers()
    assert {code for _, _, code in expected} >= {f"EZ3{n:02d}" for n in range(1, 15)} - {
        "EZ300"}, "the fixture has a case for every compound check"
    found = _check(REPO, "--select", "EZ3")
    reported = {(Path(str(d["path"])).name, int(str(d["line"])), str(d["code"]))
                for d in found}
    assert reported == expected


def test_the_compound_findings_say_where_what_and_how_to_fix() -> None:
    found = {(Path(str(d["path"])).name, d["line"]): d for d in _check(REPO, "--select", "EZ3")}
    wait = found[("mistakes.py", 55)]
    assert wait["code"] == "EZ307" and wait["fix"] == "Did you mean 'Duration'?"
    assert "kit_wrong_specify" in str(wait["message"]) and "Wait" in str(wait["message"])
    deleted = found[("mistakes.py", 15)]
    assert deleted["fix"] == "Did you mean 'Pick'?" and "'PickPart'" in str(deleted["message"])
    traced = found[("computed.py", 26)]  # a loop: only tracing reads this tree
    assert traced["code"] == "EZ307" and traced["severity"] == "error"
    world = found[("computed.py", 34)]
    assert world["code"] == "EZ313" and "wmi" in str(world["message"])


def test_compound_errors_on_the_other_fixture_repositories_are_real() -> None:
    """Each folder is its own repository (their descriptions share names such as ``Wait``,
    as unrelated repositories do). No error; one warning, in both versions of one file:
    ``empty_bin`` remaps its vacuum cup (``rparts:VacuumEffectorSingleCup``) onto
    ``Place``'s ``Gripper`` (``rparts:GripperEffector``), classes no element can belong to
    at once."""
    others = [p for p in (ROOT / "fixtures").iterdir()  # lab_repo: test_lab_precision.py
              if p.is_dir() and p not in (REPO, ROOT / "fixtures" / "lab_repo")]
    found = [d for other in others for d in _check(other, "--select", "EZ3")]
    shown = {(Path(str(d["path"])).parent.name, Path(str(d["path"])).name, d["line"],
              d["code"], d["severity"]) for d in found}
    assert {s for s in shown if s[4] == "error"} == set()
    assert {s for s in shown if s[3] == "EZ311"} == {
        ("legacy", "mixed_impl.py", 103, "EZ311", "info"),
        ("migrated", "mixed_impl.py", 104, "EZ311", "info")}


def test_the_clean_tasks_use_the_standard_library_and_stay_silent() -> None:
    source = (REPO / "lab_tasks" / "src" / "lab_tasks" / "tasks.py").read_text()
    assert '"Wait"' in source and '"WmSetRelation"' in source
    found = _check(REPO / "lab_tasks" / "src" / "lab_tasks" / "tasks.py",
                   REPO / "lab_descriptions", "--select", "EZ3")
    assert [(d["line"], d["code"]) for d in found] == []


def test_findings_say_how_the_tree_was_obtained() -> None:
    found = {(Path(str(d["path"])).name, d["line"]): str(d["message"])
             for d in _check(REPO, "--select", "EZ3")}
    assert found[("mistakes.py", 55)].endswith("(tree read statically)")
    assert found[("computed.py", 26)].endswith("(tree traced by running expand)")


LIBRARY = '''\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element
from skiros2_skill.core.skill import SkillBase


class Scan(SkillDescription):
    def createDescription(self):
        self.addParam("Area", Element("skiros:Location"), ParamTypes.Required)


class Survey(SkillDescription):
    def createDescription(self):
        self.addParam("Zone", Element("skiros:Location"), ParamTypes.Required)


class survey(SkillBase):
    def createDescription(self):
        self.setDescription(Survey(), self.__class__.__name__)

    def expand(self, skill):
        skill(self.skill("Scan", "", remap={"Area": "Zone"}))
'''

PROJECT = '''\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element
from skiros2_skill.core.skill import SkillBase


class Patrol(SkillDescription):
    def createDescription(self):
        self.addParam("Route", Element("skiros:Location"), ParamTypes.Required)


class patrol(SkillBase):
    def createDescription(self):
        self.setDescription(Patrol(), self.__class__.__name__)

    def expand(self, skill):
        skill(self.skill("Scan", "", remap={"Area": "Route"}, specify={"Aera": None}),
              self.skill("Survey", "", remap={"Area": "Route"}))
'''


def test_skill_libraries_of_the_project_join_the_index(tmp_path: Path) -> None:
    """``Scan`` and ``Survey`` live in a library folder: without it both children are
    unknown; with ``[tool.ezmigrate] skill-libraries`` they resolve, the misspelt specify
    key is found, and a remap of a key the library's compound tree already remapped (Scan's
    ``Area``, to ``Zone``) is the error SkiROS2 logs as "already remapped"."""
    (tmp_path / "lib").mkdir()
    (tmp_path / "lib" / "library.py").write_text(LIBRARY)
    project = tmp_path / "project"
    project.mkdir()
    (project / "patrol.py").write_text(PROJECT)
    alone = {(d["line"], d["code"]) for d in _check(project, "--select", "EZ3")}
    assert alone == {(17, "EZ301"), (18, "EZ301")}
    (project / "pyproject.toml").write_text('[tool.ezmigrate]\nskill-libraries = ["../lib"]\n')
    found = {(d["line"], d["code"]) for d in _check(project, "--select", "EZ3")}
    assert found == {(17, "EZ307"), (18, "EZ314")}


def test_no_compound_error_on_generated_repositories(tmp_path: Path) -> None:
    from bench_generator import generator

    generator().generate(tmp_path / "repo", 150, skill_share=0.6, seed=7, messy_share=0.3)
    trees = sum(p.read_text(errors="replace").count("def expand(")
                for p in (tmp_path / "repo").rglob("*.py"))
    assert trees >= 20  # the generated repository has compound skills to check
    found = _check(tmp_path / "repo", "--select", "EZ3")
    assert [d for d in found if d["severity"] == "error"] == []


def test_the_review_report_judges_compound_skills_as_check_does(tmp_path: Path) -> None:
    """One compound pass (issue 29): with ``skill-libraries`` configured, the report of
    ``rewrite --report r.md`` lists what ``check`` finds (EZ307, EZ314), not the EZ301 a
    report without the library would claim."""
    (tmp_path / "lib").mkdir()
    (tmp_path / "lib" / "library.py").write_text(LIBRARY)
    project = tmp_path / "project"
    project.mkdir()
    (project / "patrol.py").write_text(PROJECT)
    (project / "pyproject.toml").write_text('[tool.ezmigrate]\nskill-libraries = ["../lib"]\n')
    run = subprocess.run([sys.executable, "-m", "ezmigrate", "rewrite", "--dry-run",
                          "--no-verify", "--report", str(tmp_path / "r.md"), "."], cwd=project,
                         capture_output=True, text=True, timeout=300, check=False)
    assert run.returncode in (0, 1), run.stderr
    report = (tmp_path / "r.md").read_text(encoding="utf-8")
    listed = set(re.findall(r"- \*\*(EZ3\d\d)\*\* line (\d+):", report))
    checked = {(d["code"], str(d["line"])) for d in _check(project, "--select", "EZ3")}
    assert listed == checked == {("EZ307", "17"), ("EZ314", "18")}
