"""The byte-exact cases of issue 20 (``fixtures/byte_exact/``): one test per input.

Each ``NAME.legacy`` migrates to ``NAME.migrated`` byte for byte, the result is a fixed
point, and the first reading (the stand-in one) already passes the line guard: the
causes are fixed, the guard is not what saves these files. Where libcst's own whole-file
reading loses a form feed (c11, c11b, c12), the guard refuses that reading.
"""

from __future__ import annotations

import ast
from pathlib import Path

import libcst as cst
import pytest
from codemod_case import settings

import ezmigrate.codemod.migrate as core
from ezmigrate.codemod.core.classes import description_classes, inert_classes
from ezmigrate.codemod.core.holes import Holes
from ezmigrate.codemod.core.syntax_facts import SyntaxFacts
from ezmigrate.codemod.migrate import Settings, exported_operations, guarded_readings, migrate

CASES = Path(__file__).resolve().parents[2] / "fixtures" / "byte_exact"
LEGACY = sorted(CASES.glob("*.legacy"))
WHOLE_READING_LOSES = {"c11-formfeed-in-function-kept-only-by-holes": 4,
                       "c11b-formfeed-before-decorated-def": 6,
                       "c12-eof-whole-lossy-holes-faithful": 8}


def test_every_case_of_the_shared_folder_is_here() -> None:
    assert len(LEGACY) == 18
    assert {p.stem for p in CASES.glob("*.migrated")} == {p.stem for p in LEGACY}


@pytest.mark.parametrize("legacy", LEGACY, ids=lambda p: p.stem)
def test_case_migrates_to_its_expected_bytes_on_the_first_reading(legacy: Path) -> None:
    source = legacy.read_bytes()
    expected = legacy.with_suffix(".migrated").read_bytes()
    result = migrate(source, settings(), legacy.name)
    assert result.error is None
    assert (result.new_source if result.new_source is not None else source) == expected
    first, lost = next(guarded_readings(source, settings(), legacy.name))
    assert lost is None, f"the stand-in reading would change line {lost}"
    assert first == result
    assert migrate(expected, settings(), legacy.name).new_source is None  # a fixed point


@pytest.mark.parametrize("name", sorted(WHOLE_READING_LOSES))
def test_the_guard_refuses_libcsts_lossy_whole_file_reading(name: str) -> None:
    source = (CASES / f"{name}.legacy").read_bytes()
    readings = [lost for _, lost in guarded_readings(source, settings())]
    assert readings == [None, WHOLE_READING_LOSES[name]]


def test_a_child_in_a_sibling_file_gets_the_operations_of_a_utf7_base() -> None:
    source = (CASES / "c05-codec-exported-operations-empty.legacy").read_bytes()
    operations = exported_operations(source, {"A"}, Settings())
    assert [op.key for op in operations["A"]] == ["A"]  # type: ignore[attr-defined]


def test_exported_operations_fall_back_to_the_whole_file_as_migrate_does(
        monkeypatch: pytest.MonkeyPatch) -> None:
    """A stand-in text libcst cannot read (here made so on purpose) costs a whole-file
    reading, not the base's operations."""
    source = (b"from skiros2_skill.core.skill import SkillDescription\n"
              b"from skiros2_common.core.params import ParamTypes\n"
              b"def f():\n    pass\n"
              b"class A(SkillDescription):\n    def createDescription(self):\n"
              b"        self.addParam('A', 1, ParamTypes.Required)\n")
    monkeypatch.setattr(core, "stand_in", lambda *_: Holes(b"def (:\n", ()))
    assert list(exported_operations(source, {"A"}, Settings())) == ["A"]
    assert migrate(source, settings()).count("converted") == 1


@pytest.mark.parametrize("bases", ["*SkillDescription", "*Pick", "SkillDescription, *more",
                                   "*more, SkillDescription", "Pick, **extra",
                                   "metaclass=M", "object"])
def test_ast_and_libcst_classify_starred_bases_alike(bases: str) -> None:
    source = ("from skiros2_common.core.abstract_skill import SkillDescription\n"
              "class Pick(SkillDescription):\n    def createDescription(self):\n"
              f"        pass\nclass X({bases}):\n    def createDescription(self):\n"
              "        pass\n")
    tree = ast.parse(source)
    facts = SyntaxFacts.of(tree)
    described = {c.name for c in description_classes(cst.parse_module(source), facts.legacy)}
    inert = {node.name for node in tree.body if isinstance(node, ast.ClassDef)
             and id(node) in inert_classes(tree, facts.legacy, ())}
    assert "X" in described or "X" in inert
    assert not described & inert


def test_two_classes_of_one_name_converge_in_one_run() -> None:
    source = ("from skiros2_common.core.abstract_skill import SkillDescription\n"
              "from skiros2_common.core.params import ParamTypes\n\n\n"
              "class A(SkillDescription):\n    def createDescription(self):\n"
              "        self.addParam('X', 1, ParamTypes.Required)\n\n\n"
              "class B(A):\n    pass\n\n\n"
              "class A(SkillDescription):\n    def createDescription(self):\n"
              "        self.addParam('Y', 2, ParamTypes.Required)\n")
    result = migrate(source, settings())
    assert [(s.name, s.status) for s in result.skills] == [
        ("A", "converted"), ("B", "unchanged"), ("A", "converted")]
    assert isinstance(result.new_source, str)
    assert "createDescription" not in result.new_source
    assert migrate(result.new_source, settings()).new_source is None
