"""addPreCondition / addHoldCondition / addPostCondition <-> ``+=`` on the three lists."""

from codemod_case import HEADER, assert_migrates, assert_skipped, assert_unchanged

PRELUDE = HEADER + (
    "\n\nclass S(SkillDescription):\n    def createDescription(self):\n"
    '        self.addParam("A", Element("skiros:Location"), ParamTypes.Required)\n'
    '        self.addParam("B", Element("skiros:Product"), ParamTypes.Required)\n')
"""The first statement after it is on line 10."""
OUT = '''\
from ezskiros_runtime import SkillDescription
from ezskiros_runtime.ontology import skiros


class S(SkillDescription):
    def description(self,
                    A: skiros.Location,
                    B: skiros.Product):
'''
CONTAIN = 'self.getRelationCond("AContainB", "skiros:contain", "A", "B", True)'
NOT_CONTAIN = 'self.getRelationCond("NotAContainB", "skiros:contain", "A", "B", False)'


def test_each_add_method_fills_its_own_list_in_call_order():
    assert_migrates(PRELUDE + (
        f'        self.addPostCondition({CONTAIN})\n'
        f'        self.addPreCondition({NOT_CONTAIN})\n'
        '        self.addHoldCondition(self.getIsSpecifiedCond("ASpecified", "A", True))\n'
        '        self.addPreCondition(self.getIsSpecifiedCond("BSpecified", "B", True))\n'
    ), OUT + '        self.post_conditions += A.contain(B)\n'
             '        self.pre_conditions += ~ A.contain(B)\n'
             '        self.hold_conditions += A.is_specified()\n'
             '        self.pre_conditions += B.is_specified()\n')


def test_a_condition_held_in_a_local_is_inlined_where_it_is_added():
    """Both uses get the condition; the assignment itself disappears."""
    assert_migrates(PRELUDE + (
        f'        held = {CONTAIN}\n'
        '        self.addPreCondition(held)\n'
        '        self.addPostCondition(held)\n'
    ), OUT + '        self.pre_conditions += A.contain(B)\n'
             '        self.post_conditions += A.contain(B)\n')


def test_a_reassigned_local_adds_the_condition_it_holds_at_that_point():
    assert_migrates(PRELUDE + (
        f'        c = {CONTAIN}\n'
        '        self.addPreCondition(c)\n'
        '        c = self.getRelationCond("AAtB", "skiros:at", "A", "B", False)\n'
        '        self.addPostCondition(c)\n'
    ), OUT + '        self.pre_conditions += A.contain(B)\n'
             '        self.post_conditions += ~ A.at(B).named("AAtB")\n')


def test_the_same_condition_added_twice_stays_twice():
    """Factories only construct; SkiROS2 keeps both entries (legacy API §8.7)."""
    assert_migrates(PRELUDE + (
        f'        self.addHoldCondition({CONTAIN})\n'
        f'        self.addHoldCondition({CONTAIN})\n'
    ), OUT + '        self.hold_conditions += A.contain(B)\n'
             '        self.hold_conditions += A.contain(B)\n')


def test_keyword_argument_condition_classes_and_semicolons():
    assert_migrates("from skiros2_common.core.conditions import ConditionRelation\n" + PRELUDE + (
        f'        self.addPreCondition(condition={CONTAIN})\n'
        '        self.addHoldCondition(ConditionRelation("AAtB", "skiros:at", "A", "B", True))\n'
        f'        self.addPostCondition({CONTAIN}); self.addPostCondition({NOT_CONTAIN})\n'
    ), OUT + '        self.pre_conditions += A.contain(B)\n'
             '        self.hold_conditions += A.at(B)\n'
             '        self.post_conditions += A.contain(B)\n'
             '        self.post_conditions += ~ A.contain(B)\n')


def test_property_conditions_are_method_calls_that_need_no_brackets():
    """``A.PositionX.gt(0.5)``, not ``A.PositionX > 0.5``: a comparison needs brackets once
    named or negated, and ``== True`` is what linters flag (E712) and their fixes break."""
    assert_migrates(PRELUDE + (
        '        self.addPreCondition(self.getPropCond("APositionX", "skiros:PositionX", "A", ">", 0.5, True))\n'
        '        self.addHoldCondition(self.getPropCond("X", "skiros:PositionX", "A", ">", 0.5, True))\n'
        '        self.addPostCondition(self.getPropCond("NotAPositionX", "skiros:PositionX", "A", "<", 1.0, False))\n'
    ), OUT + '        self.pre_conditions += A.PositionX.gt(0.5)\n'
             '        self.hold_conditions += A.PositionX.gt(0.5).named("X")\n'
             '        self.post_conditions += ~ A.PositionX.lt(1.0)\n')


def test_only_disjunctions_wrap_a_long_line():
    label = "AContainBAsLongAsTheGripperIsClosedAndTheArmStaysAboveTheTable"
    children = "".join(
        f'        o.addCondition(self.getRelationCond("L{i}", "skiros:contain", "A", "B", True))\n'
        for i in range(3))
    assert_migrates(PRELUDE + (
        f'        self.addPreCondition(self.getRelationCond("{label}", "skiros:contain", "A", "B", True))\n'
        '        o = self.getOrCond(False)\n' + children
        + '        self.addPostCondition(o)\n'
        '        short = self.getOrCond(True)\n'
        f'        short.addCondition({CONTAIN})\n'
        '        short.addCondition(self.getIsSpecifiedCond("ASpecified", "A", True))\n'
        '        self.addHoldCondition(short)\n'
    ), OUT + f'        self.pre_conditions += A.contain(B).named("{label}")\n'
             '        self.post_conditions += ~(A.contain(B).named("L0")\n'
             '                                  | A.contain(B).named("L1")\n'
             '                                  | A.contain(B).named("L2"))\n'
             '        self.hold_conditions += A.contain(B) | A.is_specified()\n')


def test_comments_inside_and_after_the_call_survive():
    assert_migrates(PRELUDE + (
        '        #=======PreConditions=========\n'
        '        self.addPreCondition(  # the gripper must hold it\n'
        '            self.getRelationCond("AContainB", "skiros:contain",  # relation\n'
        '                                 "A", "B", True))\n'
        f'        self.addPostCondition({CONTAIN})  # still held\n'
    ), OUT + '        #=======PreConditions=========\n'
             '        # the gripper must hold it\n'
             '        # relation\n'
             '        self.pre_conditions += A.contain(B)\n'
             '        self.post_conditions += A.contain(B)  # still held\n')


def test_the_self_parameter_keeps_its_own_name():
    assert_migrates(HEADER + (
        "\n\nclass S(SkillDescription):\n    def createDescription(me):\n"
        '        me.addParam("A", Element("skiros:Location"), ParamTypes.Required)\n'
        '        me.addHoldCondition(me.getIsSpecifiedCond("ASpecified", "A", True))\n'
    ), '''\
from ezskiros_runtime import SkillDescription
from ezskiros_runtime.ontology import skiros


class S(SkillDescription):
    def description(me,
                    A: skiros.Location):
        me.hold_conditions += A.is_specified()
''')


def test_arguments_outside_the_upstream_signature_are_skipped():
    assert_skipped(PRELUDE + f'        self.addPreCondition({CONTAIN}, True)\n',
                   "addPreCondition called with 2 arguments at line 10",
                   "upstream SkiROS2 takes 1")
    assert_skipped(PRELUDE + f'        self.addHoldCondition(cond={CONTAIN})\n',
                   "addHoldCondition(cond=...) at line 10", "not upstream SkiROS2 API")
    assert_skipped(PRELUDE + '        self.addPostCondition(*conditions)\n',
                   "addPostCondition called with `*` arguments at line 10")
    assert_skipped(PRELUDE + '        self.addPreCondition()\n',
                   "addPreCondition at line 10 lacks condition")


def test_an_argument_that_builds_no_known_condition_is_skipped():
    reason = "does not build a condition with a SkiROS2 factory or condition class"
    assert_skipped(PRELUDE + '        self.addPreCondition(make_condition())\n',
                   f"`make_condition()` at line 10 {reason}")
    assert_skipped(PRELUDE + '        self.addPreCondition(c)\n', f"`c` at line 10 {reason}")
    assert_skipped(PRELUDE + '        c = "AContainB"\n        self.addPreCondition(c)\n',
                   f"`c` at line 11 {reason}")
    # a local that held a condition but was then rebound holds it no longer
    assert_skipped(PRELUDE + f'        c = {CONTAIN}\n        c = make()\n'
                   '        self.addPreCondition(c)\n', f"`c` at line 12 {reason}")
    assert_skipped("from skiros2_common.core.conditions import ConditionFunction\n" + PRELUDE
                   + '        self.addPreCondition(ConditionFunction("f", lambda: True))\n',
                   "ConditionFunction at line 11", "no EzSkiROS form")


def test_only_the_three_add_methods_on_self_are_claimed():
    """Another receiver, or another method, is not this rule's: the skill is kept."""
    assert_skipped(PRELUDE + f'        other.addPreCondition({CONTAIN})\n',
                   f"`other.addPreCondition({CONTAIN})` at line 10",
                   "not a declarative description statement")
    assert_skipped(PRELUDE + f'        self.addPrecondition({CONTAIN})\n',
                   "self.addPrecondition(...) at line 10", "not part of the SkiROS2")


def test_migrated_condition_lists_and_implementations_are_left_alone():
    result = assert_unchanged('''\
from ezskiros_runtime import SkillDescription
from ezskiros_runtime.ontology import skiros


class S(SkillDescription):
    def description(self,
                    A: skiros.Location,
                    B: skiros.Product):
        self.pre_conditions += ~ A.contain(B)
        self.hold_conditions += A.is_specified()
        self.post_conditions += A.contain(B)
''')
    assert result.skills == []
    result = assert_unchanged(f'''\
from skiros2_common.core.primitive import PrimitiveBase


class Pick(PrimitiveBase):
    def createDescription(self):
        self.setDescription(PickDescription(), self.__class__.__name__)

    def modifyDescription(self, skill):
        skill.addPreCondition(skill.getRelationCond("AContainB", "skiros:contain", "A", "B", True))


class NotADescription(object):
    def createDescription(self):
        self.addPreCondition({CONTAIN})
''')
    assert result.skills == []
