"""Top-level functions stood in for while libcst reads a module (``core/holes.py``).

The speed-up must be invisible: every file migrates to the same bytes, with the same
verdicts, line numbers and reasons, as when libcst reads the whole file. Checked on every
fixture file (as bytes and as text) and on the shapes that could tell the two apart.
"""

from __future__ import annotations

import ast
from pathlib import Path

import libcst as cst
import pytest

import ezmigrate.codemod.migrate as core
from ezmigrate.codemod.core.classes import ezskiros_classes
from ezmigrate.codemod.core.holes import MARK, stand_in
from ezmigrate.codemod.migrate import Settings, migrate
from ezmigrate.report.results import FileResult
from ezskiros_runtime.ontology.load import load_index

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures"
SETTINGS = Settings(index=load_index())

LEGACY = ("from skiros2_common.core.abstract_skill import SkillDescription\n"
          "from skiros2_common.core.params import ParamTypes\n"
          "from skiros2_common.core.world_element import Element\n")
SKILL = ('class Pick(SkillDescription):\n'
         '    def createDescription(self):\n'
         '        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)\n')


def _whole(source: bytes | str, monkeypatch: pytest.MonkeyPatch) -> FileResult:
    """What ``migrate`` gives when libcst reads the whole file."""
    with monkeypatch.context() as patch:
        patch.setattr(core, "stand_in", lambda *_: None)
        return migrate(source, SETTINGS, "m.py")


def _same_both_ways(source: bytes | str, monkeypatch: pytest.MonkeyPatch) -> FileResult:
    stood_in = migrate(source, SETTINGS, "m.py")
    assert stood_in == _whole(source, monkeypatch)
    return stood_in


def _fixture_files() -> list[Path]:
    return sorted(FIXTURES.rglob("*.py"))


@pytest.mark.parametrize("path", _fixture_files(), ids=lambda p: str(p.relative_to(FIXTURES)))
def test_every_fixture_file_migrates_the_same_with_and_without_holes(
        path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    data = path.read_bytes()
    _same_both_ways(data, monkeypatch)
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError:
        return  # only bytes can hold it
    _same_both_ways(text, monkeypatch)


SHAPES = {
    "helpers around the skill": "import os\n\n\ndef helper(a):\n    return a\n\n\n" + LEGACY
    + "\n\n" + SKILL + "\n\ndef main():\n    print(helper(1))\n",
    "decorated and async": LEGACY + "import functools\n\n\n@functools.lru_cache()\n"
    "@functools.wraps(print)\ndef cached(x):\n    return x\n\n\nasync def run():\n"
    "    await cached(1)\n\n\n" + SKILL,
    "one-line def and trailing comment": LEGACY + "def f(): return 1  # keep me\n\n\n" + SKILL,
    "crlf": (LEGACY + "\n\ndef helper():\n    return 2\n\n\n" + SKILL).replace("\n", "\r\n"),
    "comment indented after a function, then a legacy import dropped":
        "def helper():\n    return 1\n    # the end of helper\n" + LEGACY + "\n\n" + SKILL,
    "function first, no docstring": "def first():\n    pass\n\n\n" + LEGACY + "\n\n" + SKILL,
    "two-space functions before four-space classes":
        "def helper():\n  if True:\n    return 1\n\n\n" + LEGACY + "\n\n" + SKILL,
    "a function named like an ontology prefix": LEGACY + "\n\ndef skiros():\n    pass\n\n\n"
    + SKILL,
    "a function that uses a legacy name": LEGACY + "\n\ndef make():\n    return Element('x')\n"
    "\n\n" + SKILL,
    "no trailing newline": LEGACY + "\n\n" + SKILL + "\n\ndef last():\n    return 0",
    "a lone carriage return": LEGACY + "x = 1\ry = 2\n\ndef f():\n    pass\n\n\n" + SKILL,
    "non-ASCII function name": "# -*- coding: utf-8 -*-\n" + LEGACY + "\n\ndef größe():\n"
    "    return 1\n\n\n" + SKILL,
    "nested function and class inside": LEGACY + "\n\ndef outer():\n    def inner():\n"
    "        class Local(SkillDescription):\n            pass\n    return inner\n\n\n"
    + SKILL,
}


def test_a_latin_1_file_keeps_its_bytes_outside_the_skill(
        monkeypatch: pytest.MonkeyPatch) -> None:
    source = ("# -*- coding: latin-1 -*-\n" + LEGACY + "\n\ndef label():\n"
              "    return 'Großteil'\n\n\n" + SKILL).encode("latin-1")
    result = _same_both_ways(source, monkeypatch)
    assert isinstance(result.new_source, bytes)
    assert b"    return 'Gro\xdfteil'\n" in result.new_source


def test_holes_keep_every_line_and_fill_back_to_the_original() -> None:
    source = SHAPES["decorated and async"].encode()
    holes = stand_in(source, ast.parse(source))
    assert holes is not None
    assert [original.split(b"\n")[0] for _, original in holes.filled] == [
        b"@functools.lru_cache()", b"async def run():"]
    assert holes.text.count(b"\n") == source.count(b"\n")
    kept = [line for line in holes.text.split(b"\n") if MARK not in line and line != b"'''"]
    assert all(line in source.split(b"\n") for line in kept)
    assert b"await" not in holes.text and b"return x" not in holes.text
    assert holes.fill(cst.parse_module(holes.text).bytes) == source


def test_nothing_is_stood_in_for_where_lines_could_be_counted_differently() -> None:
    for source in (SHAPES["a lone carriage return"].encode(),
                   SHAPES["helpers around the skill"].encode() + b"# " + MARK + b"\n",
                   (LEGACY + SKILL).encode()):  # no function at all
        assert stand_in(source, ast.parse(source)) is None


def test_a_placeholder_that_does_not_come_back_makes_fill_refuse() -> None:
    source = SHAPES["helpers around the skill"].encode()
    holes = stand_in(source, ast.parse(source))
    assert holes is not None
    first, _ = holes.filled[0]
    assert holes.fill(holes.text.replace(first, b"pass")) is None
    assert holes.fill(holes.text + first) is None  # printed twice


def test_when_holes_do_not_fill_the_whole_file_is_read(
        monkeypatch: pytest.MonkeyPatch) -> None:
    source = SHAPES["helpers around the skill"].encode()
    expected = _whole(source, monkeypatch)
    monkeypatch.setattr(core.Holes, "fill", lambda self, code: None)
    assert migrate(source, SETTINGS, "m.py") == expected


# -- class bodies: only of classes that cannot be descriptions ----------------------------

IMPLEMENTATION = ("from skiros2_common.core.primitive import PrimitiveBase\n"
                  "from skiros2_skill.core.skill import SkillBase, Sequential\n")
PRIMITIVE = ("class pick(PrimitiveBase):\n"
             "    # the robot side\n"
             "    def createDescription(self):\n"
             "        self.setDescription(Pick(), self.__class__.__name__)\n\n"
             "    @staticmethod\n"
             "    def helper():\n"
             "        return Element('x')\n\n"
             "    def execute(self):\n"
             "        return self.success('done')\n"
             "        # the end of execute\n")

CLASS_SHAPES = {
    "primitive and compound": LEGACY + IMPLEMENTATION + "\n\n" + SKILL + "\n\n" + PRIMITIVE
    + "\n\nclass pick_all(SkillBase):\n    def expand(self, skill):\n"
    "        skill.setProcessor(Sequential())\n",
    "plain classes": LEGACY + "\n\nclass Config:\n    speed = 1\n\n\n"
    "class Error(Exception, metaclass=type):\n    '''doc'''\n\n\n" + SKILL,
    "decorated first method, comment before it": LEGACY + IMPLEMENTATION + "\n\n"
    "class tool(PrimitiveBase):\n\n    # helpers\n    @property\n    def name(self):\n"
    "        return 1\n\n\n" + SKILL,
    "body on the header line": LEGACY + "\n\nclass Empty(Exception): pass\n\n\n" + SKILL,
    "a child of a description of the module": LEGACY + "\n\n" + SKILL
    + "\n\nclass PickFast(Pick):\n    def createDescription(self):\n"
    "        Pick.createDescription(self)\n"
    "        self.addParam('Speed', 1.0, ParamTypes.Optional)\n",
    "a child without createDescription": LEGACY + "\n\n" + SKILL
    + "\n\nclass PickAgain(Pick):\n    pass\n",
    "multi-line header": LEGACY + IMPLEMENTATION + "\n\nclass tool(\n    PrimitiveBase,\n):\n"
    "    def execute(self):\n        return 1\n\n\n" + SKILL,
    "a legacy base imported as a module": LEGACY + "import skiros2_common.core.primitive as prim"
    "\n\n\nclass tool(prim.PrimitiveBase):\n    def execute(self):\n        return 1\n\n\n"
    + SKILL,
    "the ezskiros_runtime base under a legacy-looking name": LEGACY
    + "from ezskiros_runtime import SkillDescription as PrimitiveBase\n\n\n"
    "class Other(PrimitiveBase):\n    def createDescription(self):\n        pass\n\n\n"
    + SKILL,
}


def _stood_in_classes(source: bytes, settings: Settings = SETTINGS) -> list[str]:
    tree = ast.parse(source)
    facts = core.SyntaxFacts.of(tree)
    inert = core.inert_classes(tree, facts.legacy, {
        *settings.external, *settings.migrated_bases, *settings.unresolved_bases})
    holes = stand_in(source, tree, inert)
    text = holes.text if holes is not None else source
    return [node.name for node in ast.parse(text).body if isinstance(node, ast.ClassDef)
            and any(MARK in ast.get_source_segment(text.decode(), stmt).encode()
                    for stmt in node.body)]


@pytest.mark.parametrize("text", [*SHAPES.values(), *CLASS_SHAPES.values()],
                         ids=[*SHAPES.keys(), *CLASS_SHAPES.keys()])
def test_shapes_migrate_the_same_with_and_without_holes(
        text: str, monkeypatch: pytest.MonkeyPatch) -> None:
    for source in (text, text.encode("utf-8")):
        result = _same_both_ways(source, monkeypatch)
        assert result.new_source is not None, result
        assert [s.status for s in result.skills][:1] == ["converted"]
        migrated = result.new_source
        ast.parse(migrated)
        assert (MARK.decode() if isinstance(migrated, str) else MARK) not in migrated


@pytest.mark.parametrize(("shape", "stood_in"), [
    ("primitive and compound", ["pick", "pick_all"]),
    ("plain classes", ["Config", "Error"]),
    ("decorated first method, comment before it", ["tool"]),
    ("body on the header line", []),
    ("a child of a description of the module", []),
    ("a child without createDescription", []),
    ("multi-line header", ["tool"]),
    ("a legacy base imported as a module", ["tool"]),
    ("the ezskiros_runtime base under a legacy-looking name", []),
])
def test_only_classes_that_cannot_be_descriptions_lose_their_body(
        shape: str, stood_in: list[str]) -> None:
    assert _stood_in_classes(CLASS_SHAPES[shape].encode()) == stood_in


def test_bases_the_settings_name_keep_their_class_whole() -> None:
    source = (LEGACY + "from .base import Navigate, Helper\n\n\nclass Go(Navigate):\n"
              "    def createDescription(self):\n        pass\n\n\nclass Tool(Helper):\n"
              "    x = 1\n\n\n" + SKILL).encode()
    assert _stood_in_classes(source) == ["Go", "Tool"]
    for settings in (Settings(external={"Navigate": []}),
                     Settings(migrated_bases=frozenset({"Navigate"})),
                     Settings(unresolved_bases={"Navigate": "not given"})):
        assert _stood_in_classes(source, settings) == ["Tool"]


@pytest.mark.parametrize("path", _fixture_files(), ids=lambda p: str(p.relative_to(FIXTURES)))
def test_classes_stood_in_for_are_never_descriptions(path: Path) -> None:
    data = path.read_bytes()
    try:
        tree = ast.parse(data)
        module = cst.parse_module(data)
    except (SyntaxError, ValueError, cst.ParserSyntaxError):
        return
    facts = core.SyntaxFacts.of(tree)
    inert = core.inert_classes(tree, facts.legacy, ())
    names = {node.name for node in tree.body if id(node) in inert}
    described = {c.name for c in core.description_classes(module, facts.legacy)}
    assert not names & (described | ezskiros_classes(module))


def test_libcst_never_sees_the_code_stood_in_for(monkeypatch: pytest.MonkeyPatch) -> None:
    parsed: list[bytes | str] = []
    real = core.cst.parse_module

    def spy(text: bytes | str) -> cst.Module:
        parsed.append(text)
        return real(text)

    monkeypatch.setattr(core.cst, "parse_module", spy)
    source = CLASS_SHAPES["primitive and compound"].encode()
    result = migrate(source, SETTINGS, "m.py")
    assert result.new_source is not None and b"self.success('done')" in result.new_source
    assert len(parsed) == 1
    assert b"self.success" not in parsed[0] and b"setProcessor" not in parsed[0]
    assert b"addParam" in parsed[0]  # the description is read
