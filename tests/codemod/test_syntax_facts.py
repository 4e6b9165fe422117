"""The module facts the migration reads: from ``ast`` (the fast path) and from libcst (the
fallback for syntax newer than this Python) they must be the same facts.

Every Python file of the fixture repositories is read both ways; then a file only
Python 3.12 can parse migrates exactly as its 3.11 spelling does.
"""

from __future__ import annotations

import ast
from pathlib import Path

import libcst as cst
import pytest

from ezmigrate.codemod.core.cst_facts import facts_of
from ezmigrate.codemod.core.syntax_facts import SyntaxFacts, legacy_names
from ezmigrate.codemod.migrate import migrate

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures"
CONSTANTS = {"True", "False", "None"}  # libcst names, ast constants: no import binds them


def _python_files() -> list[Path]:
    found = []
    for path in sorted(FIXTURES.rglob("*.py")):
        try:
            ast.parse(path.read_bytes())
            cst.parse_module(path.read_bytes())
        except (SyntaxError, ValueError, cst.ParserSyntaxError):
            continue
        found.append(path)
    return found


FILES = _python_files()


def test_the_fixtures_hold_enough_files_to_compare() -> None:
    assert len(FILES) >= 40
    assert sum(b"createDescription" in p.read_bytes() for p in FILES) >= 20


@pytest.mark.parametrize("path", FILES, ids=[str(p.relative_to(FIXTURES)) for p in FILES])
def test_ast_and_libcst_give_the_same_facts(path: Path) -> None:
    data = path.read_bytes()
    fast = SyntaxFacts.of(ast.parse(data))
    slow = facts_of(cst.parse_module(data))
    assert {n: c for n, c in fast.names.items()} == {
        n: c for n, c in slow.names.items() if n not in CONSTANTS}
    assert fast.bindings == slow.bindings
    assert (fast.legacy.symbols, fast.legacy.modules) == (slow.legacy.symbols,
                                                          slow.legacy.modules)
    assert [(c.line, c.spans) for c in fast.classes] == [(c.line, c.spans)
                                                         for c in slow.classes]
    for mine, theirs in zip(fast.classes, slow.classes, strict=True):
        if mine.create is None or theirs.create is None:
            assert mine.create is theirs.create is None
            continue
        assert (mine.create.column, mine.create.spans, mine.create.bound) == (
            theirs.create.column, theirs.create.spans, theirs.create.bound)
        assert dict(mine.create.names) == {n: c for n, c in theirs.create.names.items()
                                           if n not in CONSTANTS}


LEGACY = '''\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element

LABELS = {"k": "Pick"}


def describe(detection):
    return LINE


class Pick(SkillDescription):
    def createDescription(self):
        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)
        self.addParam(
            "Speed",  # metres per second
            0.5,
            ParamTypes.Optional)
        self.addPreCondition(self.getRelationCond("Held", "skiros:contain", "Object",
                                                  "Object", False))
'''


def test_a_file_only_a_newer_python_parses_migrates_as_its_older_spelling() -> None:
    newer_line = 'f"{detection["label"]} at {LABELS["k"]}"'
    older_line = "f\"{detection['label']} at {LABELS['k']}\""
    newer, older = LEGACY.replace("LINE", newer_line), LEGACY.replace("LINE", older_line)
    with pytest.raises(SyntaxError):
        ast.parse(newer)  # this interpreter cannot: libcst must carry the facts
    new_result, old_result = migrate(newer), migrate(older)
    assert new_result.error is None and new_result.new_source is not None
    assert [(s.name, s.line, s.status) for s in new_result.skills] == [
        (s.name, s.line, s.status) for s in old_result.skills] == [("Pick", 12, "converted")]
    assert old_result.new_source is not None
    assert new_result.new_source.replace(newer_line, older_line) == old_result.new_source
    assert "# metres per second" in new_result.new_source


REFERENCES = '''\
import wmi
from skiros2_common.core.world_element import Element


def build(ParamTypes, *, label="x"):
    global COUNT
    try:
        return wmi.Element(":Location", Element=label, kind=ParamTypes)
    except KeyError as SkillDescription:
        return dict(SkillDescription=1)


class Pick:
    match COUNT:
        case {"k": 1, **rest}:
            pass
        case Point(x=other) | [*others] | found:
            pass
'''


def test_only_references_to_a_name_count_as_its_uses() -> None:
    """An attribute (``wmi.Element``), a keyword (``Element=``), a parameter, a definition,
    an ``except ... as`` or a pattern's capture spells a name without using an import of
    it (issue 43: counting them kept unused legacy imports). Both readers agree."""
    fast = SyntaxFacts.of(ast.parse(REFERENCES))
    slow = facts_of(cst.parse_module(REFERENCES))
    expected = {"COUNT": 2, "wmi": 1, "label": 1, "ParamTypes": 1, "dict": 1, "KeyError": 1,
                "Point": 1}
    assert dict(fast.names) == expected
    assert {n: c for n, c in slow.names.items() if n not in CONSTANTS} == expected


NESTED_IMPORTS = """\
import os

try:
    from skiros2_common.core.abstract_skill import SkillDescription as Old
except ImportError:
    from skiros2_common.core.abstract_skill import SkillDescription
else:
    import skiros2_common.core.params as params


def later():
    from skiros2_common.core.world_element import Element as Old
    if True:
        import skiros2_common.core.params


class Holder:
    def method(self):
        with open("x") as handle:
            from skiros2_common.core.abstract_skill import SkillDescription as Late
"""


def test_legacy_names_walks_the_statements_to_the_same_names_in_the_same_order() -> None:
    """``legacy_names`` (the EzSkiROS reader's) against ``SyntaxFacts.of``'s, which walks
    every node: every fixture, and imports in every kind of block, one alias bound twice."""
    for tree in [*(ast.parse(path.read_bytes()) for path in FILES), ast.parse(NESTED_IMPORTS)]:
        ours, theirs = legacy_names(tree), SyntaxFacts.of(tree).legacy
        assert list(ours.symbols.items()) == list(theirs.symbols.items())
        assert list(ours.modules.items()) == list(theirs.modules.items())
    nested = legacy_names(ast.parse(NESTED_IMPORTS))
    assert {"Old", "SkillDescription", "Late"} <= set(nested.symbols)
    assert "params" in nested.modules
