"""getOrCond + addCondition, negated disjunctions, nesting, and wrapping of long ones."""

from codemod_case import HEADER, assert_migrates, assert_skipped

PRELUDE = HEADER + (
    "\n\nclass S(SkillDescription):\n    def createDescription(self):\n"
    '        self.addParam("A", Element("skiros:Location"), ParamTypes.Required)\n'
    '        self.addParam("B", Element("skiros:Product"), ParamTypes.Required)\n')
SIGNATURE = '''


class S(SkillDescription):
    def description(self,
                    A: skiros.Location,
                    B: skiros.Product):
'''


def test_or_of_two_with_children_added_after_use():
    assert_migrates(PRELUDE + (
        '        o = self.getOrCond(True)\n'
        '        o.addCondition(self.getRelationCond("AContainB", "skiros:contain", "A", "B", True))\n'
        '        self.addPreCondition(o)\n'
        '        o.addCondition(self.getPropCond("X", "skiros:PositionX", "B", ">", 0.5, True))\n'
    ), 'from ezskiros_runtime import SkillDescription\nfrom ezskiros_runtime.ontology import skiros'
       + SIGNATURE + '        self.pre_conditions += A.contain(B) | B.PositionX.gt(0.5).named("X")\n')


def test_negated_or_and_nested_or_use_any_of():
    assert_migrates(PRELUDE + (
        '        inner = self.getOrCond()\n'
        '        inner.addCondition(self.getRelationCond("AContainB", "skiros:contain", "A", "B", True))\n'
        '        inner.addCondition(self.getRelationCond("AAtB", "skiros:at", "A", "B", True))\n'
        '        outer = self.getOrCond(False)\n'
        '        outer.addCondition(inner)\n'
        '        outer.addCondition(self.getIsSpecifiedCond("ASpecified", "A", True))\n'
        '        self.addHoldCondition(outer)\n'
    ), 'from ezskiros_runtime import SkillDescription, any_of\n'
       'from ezskiros_runtime.ontology import skiros' + SIGNATURE
       + '        self.hold_conditions += ~any_of(A.contain(B) | A.at(B), A.is_specified())\n')


def test_long_disjunction_wraps_aligned():
    children = "".join(
        f'        o.addCondition(self.getRelationCond("L{i}", "skiros:contain", "A", "B", True))\n'
        for i in range(3))
    assert_migrates(PRELUDE + '        o = self.getOrCond(True)\n' + children
                    + '        self.addPreCondition(o)\n',
                    'from ezskiros_runtime import SkillDescription\n'
                    'from ezskiros_runtime.ontology import skiros' + SIGNATURE
                    + '        self.pre_conditions += (A.contain(B).named("L0")\n'
                      '                                | A.contain(B).named("L1")\n'
                      '                                | A.contain(B).named("L2"))\n')


def test_empty_or_and_addcondition_on_unknown_object_are_skipped():
    assert_skipped(PRELUDE + '        o = self.getOrCond(True)\n        self.addPreCondition(o)\n',
                   "empty disjunction")
    assert_skipped(PRELUDE + '        self.helper.addCondition(self.getIsSpecifiedCond("x", "A", True))\n',
                   "local or-condition")
