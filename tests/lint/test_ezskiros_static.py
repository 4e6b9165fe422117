"""EzSkiROS descriptions read from their syntax (``lint/ezskiros_static``) give what loading
them gives, and nothing of the module runs: every EzSkiROS module of the project is both
read and loaded, and their models, class errors and findings compared; hostile modules
leave no trace of having run."""

from __future__ import annotations

import ast
import json
from pathlib import Path

import pytest

from ezmigrate.lint.ezskiros_static import read_ezskiros_statically
from ezskiros_runtime.dsl.policy import collecting
from ezskiros_runtime.legacy.errors import ModuleLoadError
from ezskiros_runtime.legacy.loader import load_bytes
from ezskiros_runtime.ontology import active_index, use_ontology
from ezskiros_runtime.ontology.index import bundled_ontology_path
from ezskiros_runtime.ontology.load import load_index

ROOT = Path(__file__).resolve().parents[2]
MODULES = sorted(p for p in (ROOT / "fixtures").rglob("*.py")
                 if b"ezskiros_runtime" in p.read_bytes() and b"SkillDescription" in p.read_bytes())


@pytest.fixture(autouse=True)
def core() -> None:
    use_ontology(load_index([bundled_ontology_path()]))


def _loaded(path: Path) -> tuple[list[str], list[tuple[str, str]], list[tuple[object, ...]]]:
    with collecting():
        found = load_bytes(path.read_bytes(), path)
    return ([json.dumps({**m.to_json(), "source": ""}, sort_keys=True) for m in found.models],
            [(e.skill, e.message) for e in found.errors],
            sorted((f.skill, f.kind, f.severity, f.line, f.message) for f in found.findings))


@pytest.mark.parametrize("path", MODULES, ids=lambda p: str(p.relative_to(ROOT)))
def test_reading_gives_what_loading_gives(path: Path) -> None:
    assert len(MODULES) >= 10
    read = read_ezskiros_statically(ast.parse(path.read_bytes()), str(path))
    try:
        models, errors, findings = _loaded(path)
    except ModuleLoadError:
        assert read.status == "import-error"
        return
    unread = {name for name, _, _ in read.unread} | {name for name, _ in read.maybe}
    assert read.status == "ok", read.message
    assert [json.dumps({**m, "source": ""}, sort_keys=True) for m in read.models] == \
        [m for m in models if json.loads(m)["name"] not in unread]
    assert [(e.skill, e.message) for e in read.errors] == \
        [e for e in errors if e[0] not in unread]
    assert sorted((f.skill, f.kind, f.severity, f.line, f.message) for f in read.findings) \
        == [f for f in findings if f[0] not in unread]


def test_nothing_of_the_module_runs(tmp_path: Path) -> None:
    """Statements that would write a file, or switch the run's ontology, are not run: the
    reading evaluates nothing but literals and the DSL's own forms."""
    marker = tmp_path / "ran"
    lab = tmp_path / "lab.ttl"
    lab.write_text("@prefix lab: <http://lab.example/lab#> .\n"
                   "@prefix owl: <http://www.w3.org/2002/07/owl#> .\n"
                   "lab:Planted a owl:Class .\n", encoding="utf-8")
    source = f'''
from pathlib import Path
from ezskiros_runtime import SkillDescription
from ezskiros_runtime.ontology import skiros, use_ontology

Path({str(marker)!r}).write_text("module")
SWITCHED = use_ontology([{str(lab)!r}])


class Fetch(SkillDescription):
    def description(self, Object: skiros.Product, Where: skiros.Location):
        Path({str(marker)!r}).write_text("description")
        self.pre_conditions += Where.contain(Object)
'''
    before = active_index()
    read = read_ezskiros_statically(ast.parse(source), str(tmp_path / "fetch.py"))
    assert not marker.exists()
    assert active_index() is before  # the run's ontology is as it was
    [(name, _, shape)] = read.unread
    assert name == "Fetch" and "expression statement" in shape


def test_what_is_not_read_is_named_with_its_shape(tmp_path: Path) -> None:
    source = '''
from ezskiros_runtime import SkillDescription
from ezskiros_runtime.ontology import skiros
from .helpers import gripper_conditions


class Looping(SkillDescription):
    def description(self, A: skiros.Location, B: skiros.Location):
        for other in (B,):
            self.pre_conditions += A.contain(other)


class Helped(SkillDescription):
    def description(self, A: skiros.Location):
        self.pre_conditions += gripper_conditions(A)


class Plain(SkillDescription):
    def description(self, A: skiros.Location, B: skiros.Product):
        self.pre_conditions += A.contain(B)
'''
    read = read_ezskiros_statically(ast.parse(source), str(tmp_path / "skills.py"))
    shapes = {name: shape for name, _, shape in read.unread}
    assert shapes["Looping"].endswith("is a loop")
    assert "gripper_conditions" in shapes["Helped"] and ".helpers" in shapes["Helped"]
    assert [m["name"] for m in read.models] == ["Plain"]


def test_a_description_read_in_part_is_still_a_type_compound_skills_may_name(
        tmp_path: Path) -> None:
    """A class whose ``description`` comes from a base of another module is not read, but
    it is a description all the same (loading it made one): a tree naming it is no
    "unknown child type" error."""
    import subprocess
    import sys

    pkg = tmp_path / "repo" / "pkg"
    pkg.mkdir(parents=True)
    (pkg / "__init__.py").write_text("")
    (pkg / "base.py").write_text(
        "from ezskiros_runtime import SkillDescription\n"
        "from ezskiros_runtime.ontology import skiros\n\n\n"
        "class Pick(SkillDescription):\n"
        "    def description(self, Object: skiros.Product):\n        pass\n")
    (pkg / "more.py").write_text(
        "from ezskiros_runtime.ontology import skiros\n"
        "from .base import Pick\n\n\nclass FastPick(Pick):\n    pass\n")
    (pkg / "tasks.py").write_text(
        "from skiros2_common.core.abstract_skill import SkillDescription\n"
        "from skiros2_skill.core.skill import SkillBase\n\n\n"
        "class Tidy(SkillDescription):\n    def createDescription(self):\n        pass\n\n\n"
        "class tidy(SkillBase):\n    def createDescription(self):\n"
        "        self.setDescription(Tidy(), self.__class__.__name__)\n\n"
        "    def expand(self, skill):\n"
        "        skill(self.skill(\"FastPick\", \"\"), self.skill(\"SlowPick\", \"\"))\n")
    subprocess.run(["git", "init", "-q", str(tmp_path / "repo")], check=True)
    run = subprocess.run([sys.executable, "-m", "ezmigrate", "check", "--no-cache",
                          "--exit-zero", "--output-format", "json", "--select", "EZ301",
                          "."], cwd=tmp_path / "repo", capture_output=True, text=True,
                         timeout=300, check=False)
    unknown = [d["message"] for d in json.loads(run.stdout)]
    assert len(unknown) == 1 and "'SlowPick'" in unknown[0], run.stdout + run.stderr
