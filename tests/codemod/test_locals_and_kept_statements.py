"""Locals that are inlined, statements kept as written, and statements that block migration."""

from codemod_case import HEADER, assert_migrates, assert_skipped

START = HEADER + "\n\nclass S(SkillDescription):\n    def createDescription(self):\n"


def test_condition_locals_and_string_constants_are_inlined():
    assert_migrates(START + (
        '        obj = "B"\n'
        '        self.addParam("A", Element("skiros:Location"), ParamTypes.Required)\n'
        '        self.addParam(obj, Element("skiros:Product"), ParamTypes.Required)\n'
        '        held = self.getRelationCond("AContainB", "skiros:contain", "A", obj, True)\n'
        '        self.addPreCondition(held)\n'
        '        self.addPostCondition(held)\n'
    ), '''\
from ezskiros_runtime import SkillDescription
from ezskiros_runtime.ontology import skiros


class S(SkillDescription):
    def description(self,
                    A: skiros.Location,
                    B: skiros.Product):
        self.pre_conditions += A.contain(B)
        self.post_conditions += A.contain(B)
''')


def test_inlined_literal_locals_go_but_their_comments_stay():
    """Every read of ``obj`` and ``rel`` was inlined, so their assignments would be dead code
    (ruff F841); ``b = a`` is dead too once nothing reads ``b``, and then so is ``a``."""
    assert_migrates(START + (
        '        # the thing to hold\n'
        '        obj = "B"  # a product\n'
        '        rel = "skiros:contain"\n'
        '        a = "m/s"\n'
        '        b = a\n'
        '        self.addParam("A", Element("skiros:Location"), ParamTypes.Required, [], b)\n'
        '        self.addParam(obj, Element("skiros:Product"), ParamTypes.Required)\n'
        '        self.addPreCondition(self.getRelationCond("AContainB", rel, "A", obj, True))\n'
    ), '''\
from ezskiros_runtime import SkillDescription, Annotated, DESC
from ezskiros_runtime.ontology import skiros


class S(SkillDescription):
    def description(self,
                    A: Annotated[skiros.Location, DESC("m/s")],
                    B: skiros.Product):
        # the thing to hold
        # a product
        self.pre_conditions += A.contain(B)
''')


def test_a_literal_local_something_kept_still_reads_stays():
    assert_migrates(START + (
        '        obj = "B"\n'
        '        self.addParam(obj, Element("skiros:Product"), ParamTypes.Required)\n'
        '        self.note = obj\n'
    ), '''\
from ezskiros_runtime import SkillDescription
from ezskiros_runtime.ontology import skiros


class S(SkillDescription):
    def description(self,
                    B: skiros.Product):
        obj = "B"
        self.note = obj
''')


def test_kept_statements_docstring_and_attribute_assignments():
    assert_migrates(START + (
        '        """Declare the skill."""\n'
        '        self.setAvailableForPlanning(False)\n'
        '        self.note = "kept"  # read by the primitive\n'
        '        self.addParam("A", float, ParamTypes.Required)\n'
        '        pass\n'
    ), '''\
from ezskiros_runtime import SkillDescription


class S(SkillDescription):
    def description(self,
                    A: float):
        """Declare the skill."""
        self.setAvailableForPlanning(False)
        self.note = "kept"  # read by the primitive
''')


def test_docstring_only_and_empty_descriptions():
    assert_migrates(HEADER + (
        '\n\nclass D(SkillDescription):\n    def createDescription(self):\n        """Only a docstring."""\n'
        '\n\nclass E(SkillDescription):\n    def createDescription(self):\n        pass\n'
        '\n\nclass F(SkillDescription):\n    pass\n'
    ), '''\
from ezskiros_runtime import SkillDescription


class D(SkillDescription):
    def description(self):
        """Only a docstring."""


class E(SkillDescription):
    def description(self):
        pass


class F(SkillDescription):
    pass
''')


def test_statements_that_could_declare_at_run_time_block_the_skill():
    assert_skipped(START + '        for k in self.keys:\n            self.addParam(k, float, 0)\n',
                   "a loop at line", "unroll")
    assert_skipped(START + '        if True:\n            self.addParam("A", float, 0)\n',
                   "a conditional")
    assert_skipped(START + '        self._common()\n', "self._common(...)", "not part of")
    assert_skipped(START + '        print("x")\n', "not a declarative description statement")
    assert_skipped(HEADER + '\n\nclass S(SkillDescription):\n    def createDescription(self, x):\n'
                   '        pass\n', "takes parameters besides self")


def test_a_condition_local_used_for_more_than_adding_it_blocks_the_skill():
    """``c`` disappears when it is inlined: a kept ``self.cond = c`` would be a NameError."""
    assert_skipped(HEADER + '''

class Watch(SkillDescription):
    def createDescription(self):
        self.addParam("A", Element("skiros:Location"), ParamTypes.Required)
        self.addParam("B", Element("skiros:Product"), ParamTypes.Required)
        c = self.getRelationCond("AContainB", "skiros:contain", "A", "B", True)
        self.addPreCondition(c)
        self.watched = c
''', "`self.watched = c` at line 12", "condition stored in `c`")


def test_names_the_migrated_method_would_collide_with_block_the_skill():
    for body, reason in [
        ("    description = 'picks things up'\n", "already defines `description` (line 7)"),
        ("    def description(self):\n        return 'x'\n", "already defines `description`"),
        ("    def createDescription(self):\n        pass\n", "bound 2 times in S (lines 7, 9)"),
        ("    createDescription = None\n", "bound 2 times"),
    ]:
        assert_skipped(HEADER + "\n\nclass S(SkillDescription):\n" + body
                       + "    def createDescription(self):\n"
                       + '        self.addParam("A", float, 0)\n', reason)
