"""Loops over constants in ``createDescription`` are unrolled; anything else keeps the skip."""

from codemod_case import HEADER, assert_migrates, assert_skipped

START = HEADER + "\n\nclass S(SkillDescription):\n    def createDescription(self):\n"
REQ = "ParamTypes.Required"


def test_a_loop_over_pairs_becomes_one_parameter_per_turn_in_loop_order():
    assert_migrates(START + (
        '        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)\n'
        '        for key, cls in (("Left", "skiros:Location"), ("Right", "skiros:Location")):\n'
        '            self.addParam(key, Element(cls), ParamTypes.Required)\n'
    ), '''\
from ezskiros_runtime import SkillDescription
from ezskiros_runtime.ontology import skiros


class S(SkillDescription):
    def description(self,
                    Object: skiros.Product,
                    Left: skiros.Location,
                    Right: skiros.Location):
        pass
''')


def test_literals_keep_their_spelling_and_a_one_line_loop_reads_the_same():
    assert_migrates(START + f'        for key in ("A", "B"): self.addParam(key, 1e-3, {REQ})\n', '''\
from ezskiros_runtime import SkillDescription


class S(SkillDescription):
    def description(self,
                    A: float = 1e-3,
                    B: float = 1e-3):
        pass
''')


def test_a_module_constant_and_a_string_are_iterated_as_python_does():
    before = HEADER + '\nSIDES = ["Left", "Right"]\n\n\nclass S(SkillDescription):\n' \
        '    def createDescription(self):\n' \
        '        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)\n' \
        '        for side in SIDES:\n' \
        '            self.addParam(side, Element("skiros:Location"), ParamTypes.Required)\n' \
        '            self.addPreCondition(self.getRelationCond("Has", "skiros:contain", ' \
        'side, "Object", False))\n' \
        '        for c in "XY":\n' \
        '            self.addParam(c, 0, ParamTypes.Optional)\n'
    assert_migrates(before, '''\
from ezskiros_runtime import SkillDescription, OPTIONAL
from ezskiros_runtime.ontology import skiros

SIDES = ["Left", "Right"]


class S(SkillDescription):
    def description(self,
                    Object: skiros.Product,
                    Left: skiros.Location,
                    Right: skiros.Location,
                    X: OPTIONAL[int] = 0,
                    Y: OPTIONAL[int] = 0):
        self.pre_conditions += ~ Left.contain(Object).named("Has")
        self.pre_conditions += ~ Right.contain(Object).named("Has")
''')


def test_comments_of_the_loop_are_kept_once_and_nested_loops_unroll():
    assert_migrates(START + (
        '        # the cells\n'
        '        for row in ("A", "B"):  # rows\n'
        '            self.addParam(row, Element("skiros:Location"), ParamTypes.Required)\n'
        '            # each row holds it\n'
        '            for thing in ("X",):\n'
        '                self.addPreCondition(self.getRelationCond("H", "skiros:contain", '
        'row, thing, True))\n'
        '        self.addParam(thing, Element("skiros:Product"), ParamTypes.Required)\n'
    ), '''\
from ezskiros_runtime import SkillDescription
from ezskiros_runtime.ontology import skiros


class S(SkillDescription):
    def description(self,
                    # the cells
                    # rows
                    A: skiros.Location,
                    B: skiros.Location,
                    X: skiros.Product):
        # each row holds it
        self.pre_conditions += A.contain(X).named("H")
        self.pre_conditions += B.contain(X).named("H")
''')


def test_the_loop_name_stays_bound_after_the_loop_when_a_kept_statement_reads_it():
    assert_migrates(START + (
        '        for key in ("A", "B"):\n'
        '            self.addParam(key, 0.5, ParamTypes.Optional)\n'
        '        self.last = key\n'
    ), '''\
from ezskiros_runtime import SkillDescription, OPTIONAL


class S(SkillDescription):
    def description(self,
                    A: OPTIONAL[float] = 0.5,
                    B: OPTIONAL[float] = 0.5):
        key = "B"
        self.last = key
''')


LOOP = '        for key in {iterable}:\n            self.addParam(key, 0.1, ParamTypes.Required)\n'


def test_a_loop_over_anything_computed_is_still_skipped():
    assert_skipped(START + LOOP.format(iterable="self.keys"), "a loop at line", "self.keys",
                   "unroll")
    assert_skipped(START + LOOP.format(iterable='sorted(("B", "A"))'), "a loop at line")
    assert_skipped(START + LOOP.format(iterable='{"A", "B"}'), "a loop at line")
    assert_skipped(START + LOOP.format(iterable="range(2)"), "a loop at line")
    assert_skipped(START + LOOP.format(iterable='("A", NAME)'), "a loop at line", "NAME")
    assert_skipped(START + LOOP.format(iterable='[*OTHER, "A"]'), "a loop at line", "starred")


def test_jumps_else_and_odd_targets_are_still_skipped():
    body = f'            self.addParam(key, 0.1, {REQ})\n'
    assert_skipped(START + '        for key in ("A", "B"):\n' + body + '            break\n',
                   "a loop at line", "break")
    assert_skipped(START + '        for key in ("A", "B"):\n            if key == "A":\n'
                   '                continue\n' + body, "a loop at line")
    assert_skipped(START + '        for key in ("A", "B"):\n' + body + '        else:\n'
                   '            pass\n', "a loop at line", "else")
    assert_skipped(START + '        for key, cls in (("A", "x", "y"),):\n' + body,
                   "a loop at line", "does not unpack")
    assert_skipped(START + '        for self.key in ("A", "B"):\n            pass\n',
                   "a loop at line", "not names")
    assert_skipped(START + '        while True:\n            break\n', "a loop at line")


def test_a_body_that_would_be_kept_as_written_is_still_skipped():
    assert_skipped(START + '        for key in ("A", "B"):\n            self.last = key\n',
                   "a loop at line", "self.last = key", "once per turn")
    assert_skipped(START + '        for key in ("A", "B"):\n            self._add(key)\n',
                   "self._add(...)", "not part of")
