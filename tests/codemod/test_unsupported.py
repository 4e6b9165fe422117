"""The catch-all rule: a statement no other rule claims blocks its skill, kept as written.

Legacy statement in ``createDescription``        Outcome (skill skipped, EZ902 kept-legacy)
``self._helper(...)``                             "self._helper(...) at line N is not part of
                                                  the SkiROS2 description API ... inline it"
any other statement (``print(...)``, ``x += 1``,  "`<its first line>` at line N is not a
``del``, ``import``, ``return value`` ...)        declarative description statement"
"""

import pytest
from codemod_case import HEADER, assert_migrates, assert_skipped, assert_unchanged, settings

from ezmigrate.codemod.migrate import migrate
from ezskiros_runtime.codes import BY_CODE

START = HEADER + "\n\nclass S(SkillDescription):\n    def createDescription(self):\n"
"""Lines 1-3 the header, 6 the class, 7 the def: the first body statement is line 8."""
PARAM = '        self.addParam("A", Element("skiros:Location"), ParamTypes.Required)\n'
"""Line 8; a statement after it is on line 9."""
CATCH_ALL = "is not a declarative description statement"


def assert_kept_legacy(result, line: int) -> None:
    """The only skill is skipped, its verdict filed under EZ902, reported at the class."""
    [skill] = result.skills
    assert (skill.status, skill.code, skill.line) == ("skipped", "EZ902", line)
    assert BY_CODE[skill.code].name == "kept-legacy"


def test_unclaimed_self_method_names_the_method_and_its_line():
    result = assert_skipped(START + PARAM + '        self._common()\n',
                            "self._common(...) at line 9", "not part of the SkiROS2 "
                            "description API", "inline it by hand, then migrate")
    assert_kept_legacy(result, 6)
    # a call over several lines is reported where it starts
    result = assert_skipped(START + PARAM + '        self._add_gripper(\n'
                            '            "Gripper",\n        )\n',
                            "self._add_gripper(...) at line 9")
    assert_kept_legacy(result, 6)


@pytest.mark.parametrize("statement", [
    'print("x")',
    "helper(self)",
    'rospy.loginfo("declaring")',
    "self.helper.build(self)",  # a method of an attribute, not of self
    "self._factory()()",  # the result of a self method is called
    'other.addPreCondition(self.getIsSpecifiedCond("ASpecified", "A", True))',
])
def test_other_calls_are_quoted_with_their_line(statement):
    result = assert_skipped(START + PARAM + f"        {statement}\n",
                            f"`{statement}` at line 9 {CATCH_ALL}",
                            "parameters or conditions could depend on it at run time")
    assert_kept_legacy(result, 6)


@pytest.mark.parametrize("statement", [
    "x += 1",
    "self.x += 1",
    "a, b = 1, 2",
    'a = b = "A"',
    'x: str = "A"',
    'self.d["k"] = 1',
    "self.a.b = 1",
    "del self.x",
    "global G",
    "import math",
    "assert True",
    'raise ValueError("no")',
    "return self.x",
    "self.x",
    "(x := 1)",
    "yield",
])
def test_statements_that_are_not_calls_are_quoted_with_their_line(statement):
    result = assert_skipped(START + PARAM + f"        {statement}\n",
                            f"`{statement}` at line 9 {CATCH_ALL}")
    assert_kept_legacy(result, 6)


def test_a_statement_over_several_lines_is_quoted_by_its_first_line():
    result = assert_skipped(START + PARAM + '        print(\n            "x",\n        )\n',
                            f"`print(` at line 9 {CATCH_ALL}")
    assert '"x"' not in (result.skills[0].reason or "")


def test_the_first_blocking_statement_is_the_one_reported():
    result = assert_skipped(START + '        print("first")\n' + PARAM + '        self._second()\n',
                            '`print("first")` at line 8')
    assert "_second" not in (result.skills[0].reason or "")
    assert "line 10" not in (result.skills[0].reason or "")


def test_a_skipped_file_is_left_byte_identical():
    """Odd spacing, comments, a coding cookie and no final newline: nothing is touched."""
    source = ("# -*- coding: utf-8 -*-\n" + HEADER
              + "\n\nclass S( SkillDescription ):\n"
              + "    def createDescription(self):  # declares S\n"
              + "        #=======Params=========\n"
              + '        self.addParam("A",  Element("skiros:Location"), ParamTypes.Required)\n'
              + "        self._common()   # adds the rest")
    result = assert_unchanged(source)
    assert "self._common(...) at line 11" in (result.skills[0].reason or "")
    assert_kept_legacy(result, 7)
    as_bytes = migrate(source.encode(), settings(), "case.py")
    assert as_bytes.new_source is None
    assert [(s.status, s.reason) for s in as_bytes.skills] == \
        [(s.status, s.reason) for s in result.skills]


def test_a_skipped_skill_stays_verbatim_next_to_a_converted_one():
    blocked = '''

class Blocked(SkillDescription):
    def createDescription( self ):
        # set up
        self.addParam("A", float, ParamTypes.Required)   # trailing
        self._common ()
'''
    result = assert_migrates(HEADER + '''

class Good(SkillDescription):
    def createDescription(self):
        self.addParam("A", float, ParamTypes.Required)
''' + blocked, '''\
from skiros2_common.core.abstract_skill import SkillDescription
from ezskiros_runtime import SkillDescription as EzSkillDescription
from skiros2_common.core.params import ParamTypes


class Good(EzSkillDescription):
    def description(self,
                    A: float):
        pass
''' + blocked)
    assert [(s.name, s.status) for s in result.skills] == [("Good", "converted"),
                                                          ("Blocked", "skipped")]
    assert result.skills[1].code == "EZ902" and result.skills[0].code is None
    assert "self._common(...) at line 14" in (result.skills[1].reason or "")
    assert isinstance(result.new_source, str) and result.new_source.endswith(blocked)


def test_a_description_deriving_from_a_blocked_one_is_kept_too():
    result = assert_unchanged(START + PARAM + '        print("x")\n' + '''

class T(S):
    def createDescription(self):
        S.createDescription(self)
        self.addParam("B", float, ParamTypes.Required)
''')
    assert [(s.name, s.status, s.code) for s in result.skills] == [
        ("S", "skipped", "EZ902"), ("T", "skipped", "EZ902")]
    assert '`print("x")` at line 9' in (result.skills[0].reason or "")
    assert "its base class S was not converted" in (result.skills[1].reason or "")


def test_statements_other_rules_claim_never_reach_the_catch_all():
    assert_migrates(START + (
        '        """Declares S."""\n'
        '        key = "A"\n'
        '        self.setAvailableForPlanning(False)\n'
        '        self.note = "kept"\n'
        '        self.addParam(key, Element("skiros:Location"), ParamTypes.Required)\n'
        '        c = self.getIsSpecifiedCond("ASpecified", "A", True)\n'
        '        self.addPreCondition(c)\n'
        '        pass\n'
        '        return\n'
    ), '''\
from ezskiros_runtime import SkillDescription
from ezskiros_runtime.ontology import skiros


class S(SkillDescription):
    def description(self,
                    A: skiros.Location):
        """Declares S."""
        self.setAvailableForPlanning(False)
        self.note = "kept"
        self.pre_conditions += A.is_specified()
''')


def test_code_outside_create_description_is_not_inspected():
    """Other methods of a description, and implementations, may do anything."""
    assert_migrates(START + PARAM + '''
    def _common(self):
        print("x")
        self.extra = compute()


class Pick(PrimitiveBase):
    def createDescription(self):
        self.setDescription(S(), self.__class__.__name__)

    def execute(self):
        print("running")
        return self.success("done")
''', '''\
from ezskiros_runtime import SkillDescription
from ezskiros_runtime.ontology import skiros


class S(SkillDescription):
    def description(self,
                    A: skiros.Location):
        pass

    def _common(self):
        print("x")
        self.extra = compute()


class Pick(PrimitiveBase):
    def createDescription(self):
        self.setDescription(S(), self.__class__.__name__)

    def execute(self):
        print("running")
        return self.success("done")
''')


def test_already_migrated_descriptions_with_any_statements_are_left_alone():
    result = assert_unchanged('''\
from ezskiros_runtime import SkillDescription
from ezskiros_runtime.ontology import skiros


class S(SkillDescription):
    def description(self,
                    A: skiros.Location):
        print("traced")
        self._common()
        x = 1
        self.pre_conditions += A.is_specified()
''')
    assert result.skills == []


def test_the_reason_spells_the_receiver_as_the_source_does():
    assert_skipped(HEADER + "\n\nclass S(SkillDescription):\n    def createDescription(me):\n"
                   "        me._common()\n", "me._common(...) at line 8")


def test_a_discarded_factory_call_is_not_called_foreign_api():
    result = assert_skipped(START + PARAM + '        self.getIsSpecifiedCond("ASpecified", "A", '
                            'True)\n', "self.getIsSpecifiedCond(...) at line 9")
    assert "not part of the SkiROS2 description API" not in (result.skills[0].reason or "")


def test_a_statement_before_a_semicolon_is_quoted_without_it():
    assert_skipped(START + '        print("x"); self.addParam("B", float, 0)\n',
                   f'`print("x")` at line 8 {CATCH_ALL}')
