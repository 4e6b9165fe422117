"""``check``'s fast path (``lint/plain_reader.py``) reports exactly what the codemod's
reader makes ``check`` report, on every file it accepts, and declines what it cannot read.

The oracle is the real codemod (``ezmigrate.codemod.migrate.migrate``, libcst) on the same bytes;
the corpora are every Python file under ``fixtures/`` and repositories written by
``bench/generate_repo.py`` (plain ones, and ones with messy and Python 2 files).
"""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest
from bench_generator import generator

from ezmigrate.checking import file_facts
from ezmigrate.checking import per_file as check
from ezmigrate.checking.per_file import legacy_diagnostics as _legacy
from ezmigrate.checking.pipeline import run_check
from ezmigrate.codemod.migrate import Settings, migrate
from ezmigrate.files.prefilter import may_hold_descriptions
from ezmigrate.lint.diagnostic import Positions
from ezmigrate.lint.plain_reader import Declined, read_plain
from ezmigrate.report.results import FileResult
from ezmigrate.verify.pool import PoolConfig
from ezskiros_runtime.ontology.index import bundled_ontology_path
from ezskiros_runtime.ontology.load import load_index

REPO = Path(__file__).resolve().parents[2]
INDEX = load_index([bundled_ontology_path()])


def _reported(path: str, data: bytes, result: FileResult) -> list[tuple[object, ...]]:
    """What ``check`` makes of one file's static result, and the skills behind it."""
    found = _legacy(path, result, Positions(data.decode("utf-8", "replace")), INDEX)
    skills = [(s.name, s.line, s.status, s.static, s.model,
               [(f.kind, f.line, f.message) for f in s.findings if f.kind in
                check.KEPT_FROM_CODEMOD]) for s in result.skills]
    return [*((str(d),) for d in found), *skills]


def _compare_tree(root: Path) -> tuple[int, int]:
    """(files accepted, files that may hold descriptions); asserts equality on each."""
    accepted = considered = 0
    for path in sorted(root.rglob("*.py")):
        data = path.read_bytes()
        if not may_hold_descriptions(data) or b"ezskiros_runtime" in data:
            continue
        considered += 1
        fast = read_plain(data, path.name)
        if isinstance(fast, Declined):
            continue
        accepted += 1
        slow = migrate(data, Settings(index=INDEX), path.name)
        assert _reported(str(path), data, fast) == _reported(str(path), data, slow), path
        assert (fast.foreign_bases, fast.exports) == (slow.foreign_bases, slow.exports), path
    return accepted, considered


def test_fixtures_read_the_same_both_ways() -> None:
    accepted, considered = _compare_tree(REPO / "fixtures")
    assert considered >= 30 and accepted >= 10  # the fast path is exercised, not bypassed


@pytest.mark.parametrize(("seed", "messy", "py2"), [(0, 0.0, 0.0), (1, 0.5, 0.1),
                                                    (2, 0.3, 0.0)])
def test_generated_repositories_read_the_same_both_ways(tmp_path: Path, seed: int,
                                                        messy: float, py2: float) -> None:
    generator().generate(tmp_path / "repo", 120, skill_share=1.0, seed=seed,
                          messy_share=messy, py2_share=py2)
    accepted, considered = _compare_tree(tmp_path / "repo")
    assert considered >= 100
    if messy == 0.0:  # plain generated code is what the fast path is for
        assert accepted >= 0.9 * considered


def _diagnostics(paths: list[Path]) -> tuple[list[str], int]:
    outcome = run_check(paths, INDEX, PoolConfig(workers=1))
    return [str(d) for d in outcome.diagnostics], outcome.skills


@pytest.mark.parametrize("tree", ["fixtures/ros_repo", "fixtures"])
def test_whole_runs_agree_with_the_codemod_path(tree: str,
                                                monkeypatch: pytest.MonkeyPatch) -> None:
    """Cross-file bases included: a declined file brings along the plain files of its
    package that may define its bases."""
    fast = _diagnostics([REPO / tree])
    monkeypatch.setattr(file_facts, "read_plain", lambda data, path, tree=None: Declined())
    assert fast == _diagnostics([REPO / tree])
    assert fast[1] > 0


HEADER = """\
from skiros2_common.core.abstract_skill import SkillDescription, ParamOptions
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element
"""

PLAIN = HEADER + """
class Pick(SkillDescription):
    \"\"\"Pick an object.\"\"\"

    def createDescription(self):
        \"\"\"Its parameters.\"\"\"
        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)
        self.addParam("Speed", 0.5, ParamTypes.Optional, "m/s")
        self.addParam("Arm", Element("skiros:Arm"), 2, [ParamOptions.Lock])
        self.addPreCondition(self.getRelationCond("ArmHolds", "skiros:contain", "Arm",
                                                  "Object", False))
"""


def test_a_plain_description_is_read(tmp_path: Path) -> None:
    result = read_plain(PLAIN.encode(), "pick.py")
    assert isinstance(result, FileResult)
    [skill] = result.skills
    assert (skill.name, skill.line, skill.status) == ("Pick", 5, "converted")
    assert skill.static is not None
    assert [p.key for p in skill.static.params] == ["Object", "Speed", "Arm"]
    assert [f.kind for f in skill.findings] == ["description-in-options"]


def test_module_constants_are_read_as_the_codemod_reads_them() -> None:
    source = HEADER + textwrap.dedent("""
        KEY = "Object"
        SPEED = 0.5
        class A(SkillDescription):
            def createDescription(self):
                self.addParam(KEY, Element("skiros:Product"), ParamTypes.Required)
                self.addParam("Speed", SPEED, ParamTypes.Optional)
        """)
    fast = read_plain(source.encode(), "a.py")
    assert isinstance(fast, FileResult)
    slow = migrate(source, Settings(index=INDEX), "a.py")
    assert _reported("a.py", source.encode(), fast) == _reported("a.py", source.encode(), slow)
    [skill] = fast.skills
    assert skill.static is not None
    assert [(p.key, p.value) for p in skill.static.params] == [("Object", None),
                                                                ("Speed", 0.5)]


@pytest.mark.parametrize("body", [
    "class A(SkillDescription):\n    def createDescription(self):\n        pass\n",
    'class A(SkillDescription):\n    """Doc."""\n    def createDescription(self):\n'
    '        """Doc."""\n        pass\n',
    "class A(SkillDescription):\n    def createDescription(self):\n        pass\n"
    '        self.addParam("x", float, ParamTypes.Required)\n        pass\n',
    "class A(SkillDescription):\n    pass\n",
    'class A(SkillDescription):\n    """Doc."""\n',
    'class A(SkillDescription):\n    """Doc."""\n    pass\n    pass\n'
    'class B(SkillDescription):\n    def createDescription(self):\n'
    '        self.addParam("x", float, ParamTypes.Required)\n',
])
def test_pass_is_read_as_the_codemod_drops_it(body: str) -> None:
    """An empty description (``pass``, met in 11 files of the public repositories) is
    plain: the codemod drops ``pass`` (``kept_statements``), and so does this reader; so
    is a description class with no ``createDescription`` at all."""
    source = HEADER + body
    fast = read_plain(source.encode(), "a.py")
    assert isinstance(fast, FileResult)
    slow = migrate(source, Settings(index=INDEX), "a.py")
    assert _reported("a.py", source.encode(), fast) == _reported("a.py", source.encode(), slow)


@pytest.mark.parametrize("body", [
    'KEY = "Object"\nKEY = "Other"\nclass A(SkillDescription):\n'
    '    def createDescription(self):\n        self.addParam(KEY, float, ParamTypes.Required)\n',
    'KEY = "Object"; SPEED = 1\nclass A(SkillDescription):\n    def createDescription(self):\n'
    '        self.addParam(KEY, float, ParamTypes.Required)\n',
    'import math\nclass A(SkillDescription):\n    def createDescription(self):\n'
    '        self.addParam("x", math.pi, ParamTypes.Required)\n',
    'class A(SkillDescription):\n    def createDescription(self):\n'
    '        key = "Object"\n        self.addParam(key, float, ParamTypes.Required)\n',
    'class A(SkillDescription):\n    def createDescription(self):\n'
    '        for k in "ab":\n            self.addParam(k, float, ParamTypes.Required)\n',
    'class A(SkillDescription):\n    def createDescription(self):\n'
    '        self.addParam("x", float, ParamTypes.Required)\n'
    'class B(A):\n    def createDescription(self):\n        A.createDescription(self)\n',
    '@decorate\nclass A(SkillDescription):\n    def createDescription(self):\n'
    '        self.addParam("x", float, ParamTypes.Required)\n',
    'class A(SkillDescription):\n    description = "x"\n    def createDescription(self):\n'
    '        self.addParam("x", float, ParamTypes.Required)\n',
    'class A(SkillDescription):\n    def createDescription(self):\n'
    '        self.addParam("x", [], ParamTypes.Required)\n',
    'class A(SkillDescription):\n    def createDescription(self):\n'
    '        self.addPreCondition(self.getRelationCond(1, "skiros:contain", "x", "y", True))\n',
    'class A(SkillDescription):\n    def createDescription(self):\n'
    '        self.addPreCondition(self.getRelationCond("L", "skiros:contain", "x", "y", 1))\n',
    'class A(SkillDescription):\n    def createDescription(self):\n'
    '        self.addPreCondition(self.getOrCond("L", [], True))\n',
    "class A(SkillDescription):\n    ...\n",
    "class A(SkillDescription):\n    pass\n    def helper(self):\n        pass\n",
    'class A(SkillDescription):\n    def createDescription(self):\n'
    '        self.addParam((("a", "b")), float, ParamTypes.Required)\n',
    'class A(SkillDescription):\n    def createDescription(self):\n'
    '        self.addParam(key=("a", "b"), value=float, param_type=ParamTypes.Required)\n',
    'class A(SkillDescription):\n    def createDescription(self):\n'
    '        self.addParam(("a",\n                       "b"), float, ParamTypes.Required)\n',
    'class A(SkillDescription):\n    def createDescription(self):\n'
    '        self.addParam("x", float, ParamTypes.Required, key="y")\n',
    'class A(SkillDescription):\n    def createDescription(self):\n'
    '        self.addParam(*("x", float, ParamTypes.Required), remap="y")\n',
    'from skiros2_common.core.conditions import ConditionFunction\n'
    'class A(SkillDescription):\n    def createDescription(self):\n'
    '        self.addPreCondition(ConditionFunction("L", lambda: True))\n',
    'class A(SkillDescription):\n    def createDescription(self):\n'
    '        self.addParam("x", float, ParamTypes.Required\n',
])
def test_anything_else_is_left_to_the_codemod(body: str) -> None:
    assert isinstance(read_plain((HEADER + body).encode(), "a.py"), Declined)


KEPT = [
    # a fork's shared parameters: the key names the skill that writes it
    '        self.addParam(("timer", "timed_out"), Element("skiros:Parameter"), '
    'ParamTypes.Required)\n',
    '        self.addParam("timed_out", Element("skiros:Parameter"), ParamTypes.SharedOutput)\n',
    '        self.addParam("x", float, ParamTypes.Required, remap="y")\n',
    '        self.addParam("x", float, ParamTypes.Required, key="z", remap="y")\n',
    '        self.addParam(1, float, ParamTypes.Required)\n',
    '        self.addParam(-1, float, ParamTypes.Required)\n',
    '        self.addParam( None , float, ParamTypes.Required)\n',
    '        self.addParam({"a": [1, 2]}, float, ParamTypes.Required)\n',
    '        self.addParam(("a", "b"), float, ParamTypes.Required, remap="y")\n',
    '        self.addParam(("a", "b"), float, ParamTypes.SharedInput)\n',
    '        self.addParam("x", float, ParamTypes.SharedInput, remap="y")\n',
    '        self.addParam("x", 1, ParamTypes.SharedInput, [ParamOptions.Lock], "d")\n',
    '        self.addParam("x", float, ParamTypes.Required)\n'
    '        self.addParam(("a", "b"), float, ParamTypes.Required)\n'
    '        for k in "ab":\n            pass\n',
]


@pytest.mark.parametrize("line", KEPT)
def test_what_the_codemod_keeps_is_kept_here_too(line: str) -> None:
    """Forks' extensions (a ``(skill, key)`` pair as the key, ``ParamTypes.SharedOutput``,
    ``remap=``: 11 files of the public repositories) keep the skill where the codemod
    meets them, with its words, and the file stays plain; the skill beside it converts."""
    source = HEADER + textwrap.dedent("""
        class Kept(SkillDescription):
            def createDescription(self):
        """) + line + textwrap.dedent("""
        class Plain(SkillDescription):
            def createDescription(self):
                self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)
        """)
    fast = read_plain(source.encode(), "a.py")
    assert isinstance(fast, FileResult)
    slow = migrate(source, Settings(index=INDEX), "a.py")
    assert _reported("a.py", source.encode(), fast) == _reported("a.py", source.encode(), slow)
    assert [(s.name, s.status) for s in fast.skills] == [("Kept", "skipped"),
                                                          ("Plain", "converted")]
    assert fast.skills[0].reason == slow.skills[0].reason
    assert fast.exports == slow.exports == ["Plain"]


def test_a_base_from_a_sibling_brings_the_package_along(tmp_path: Path) -> None:
    """``child.py`` derives from a plain description of ``base.py``: only the codemod's
    package pass knows (the plain reader names the base it imports, as the codemod's first
    reading does); ``check`` must report the child's skill (not keep it)."""
    pkg = tmp_path / "pkg"
    pkg.mkdir()
    (pkg / "__init__.py").write_text("")
    (pkg / "base.py").write_text(HEADER + textwrap.dedent("""
        class Move(SkillDescription):
            def createDescription(self):
                self.addParam("Target", Element("skiros:Location"), ParamTypes.Required)
        """))
    (pkg / "child.py").write_text(HEADER + "from .base import Move\n" + textwrap.dedent("""
        class MoveFast(Move):
            def createDescription(self):
                Move.createDescription(self)
                self.addParam("Speed", 1.0, ParamTypes.Optional, "fast")
        """))
    child = read_plain((pkg / "child.py").read_bytes(), "child.py")
    assert isinstance(child, FileResult)  # read, with nothing described yet: its base
    assert (child.skills, child.foreign_bases) == ([], [("Move", ".base")])  # is a sibling's
    diagnostics, skills = _diagnostics([tmp_path])
    assert skills == 2
    assert any("child.py" in d and "EZ101" in d and "MoveFast" in d for d in diagnostics)
