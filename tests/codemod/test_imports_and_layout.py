"""Imports added once and pruned when unused; file layout (newlines, tabs, encodings) kept."""

from codemod_case import assert_migrates, assert_unchanged, run, settings

from ezmigrate.codemod.migrate import migrate

LEGACY = '''\
"""Module docstring."""
# SkiROS2 imports
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes as PT
from skiros2_common.core.world_element import Element
from skiros2_common.core.primitive import PrimitiveBase


class S(SkillDescription):
    def createDescription(self):
        self.addParam("A", Element("skiros:Location"), PT.Required)


class s(PrimitiveBase):
    def createDescription(self):
        self.setDescription(S(), self.__class__.__name__)
'''


def test_legacy_imports_pruned_comment_kept_implementation_untouched():
    assert_migrates(LEGACY, '''\
"""Module docstring."""
# SkiROS2 imports
from ezskiros_runtime import SkillDescription
from ezskiros_runtime.ontology import skiros
from skiros2_common.core.primitive import PrimitiveBase


class S(SkillDescription):
    def description(self,
                    A: skiros.Location):
        pass


class s(PrimitiveBase):
    def createDescription(self):
        self.setDescription(S(), self.__class__.__name__)
''')


def test_name_clashes_get_aliases():
    result = run("from threading import Lock\nskiros = 1\n" + LEGACY.replace(
        'PT.Required)', 'PT.Required, [ParamOptions.Lock])').replace(
        "import SkillDescription\n", "import SkillDescription, ParamOptions\n"))
    assert isinstance(result.new_source, str)
    assert "Lock as EzLock" in result.new_source
    assert "skiros as skiros_ns" in result.new_source
    assert "A: REQUIRED[skiros_ns.Location, EzLock]" in result.new_source


def test_files_without_descriptions_and_migrated_files_are_untouched():
    assert_unchanged("import os\n\n\ndef f():\n    return 1\n")
    assert_unchanged(run(LEGACY).new_source or "")
    assert_unchanged("from skiros2_common.core.primitive import PrimitiveBase\n\n\n"
                     "class P(PrimitiveBase):\n    def createDescription(self):\n        pass\n")


def test_crlf_tabs_bom_cookie_and_missing_final_newline_are_kept():
    source = LEGACY.replace("    ", "\t").replace("\n", "\r\n").rstrip("\r\n")
    data = b"\xef\xbb\xbf" + source.encode("utf-8")
    out = migrate(data, settings(), "x.py").new_source
    assert isinstance(out, bytes)
    assert out.startswith(b"\xef\xbb\xbf")
    assert b"\r\n" in out and b"\n" not in out.replace(b"\r\n", b"")
    assert b"\tdef description(\r\n\t\t\tself,\r\n\t\t\tA: skiros.Location):\r\n" in out
    assert not out.endswith(b"\n")
    latin = ("# -*- coding: latin-1 -*-\n# Größe\n" + LEGACY).encode("latin-1")
    out = migrate(latin, settings(), "y.py").new_source
    assert isinstance(out, bytes) and "# Größe".encode("latin-1") in out


def test_unparseable_source_is_reported_with_line_and_column():
    result = run("class S(SkillDescription):\n    def createDescription(self):\n        print 'x'\n")
    assert result.error is not None and "line 3" in result.error and result.new_source is None


def test_a_file_too_deeply_nested_for_libcst_is_reported_with_its_line():
    deep = LEGACY + "\n\nLIMIT = " + "-" * 1000 + "1\n"
    result = run(deep)
    line = deep.splitlines().index("LIMIT = " + "-" * 1000 + "1") + 1
    assert result.error is not None and result.new_source is None and not result.skills
    assert result.error.startswith(f"nested too deeply to migrate (the statement at line {line})")
    assert result.error_line == line
