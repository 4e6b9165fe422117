"""Descriptions deriving from descriptions: parents inlined, unconverted parents block children."""

from codemod_case import HEADER, assert_migrates, run

PARENT = HEADER + '''

class Arm(SkillDescription):
    def createDescription(self):
        self.addParam("Arm", Element("skiros:Location"), ParamTypes.Required)
'''


def test_parent_call_spellings_are_inlined_and_bare_children_inherit():
    assert_migrates(PARENT + '''

class A(Arm):
    def createDescription(self):
        Arm.createDescription(self)
        self.addParam("Speed", 0.1, ParamTypes.Optional)


class B(Arm):
    def createDescription(self):
        super().createDescription()


class C(Arm):
    def createDescription(self):
        self.addParam("Via", float, ParamTypes.Required)
        super(C, self).createDescription()


class D(A):
    pass
''', '''\
from ezskiros_runtime import SkillDescription, OPTIONAL
from ezskiros_runtime.ontology import skiros


class Arm(SkillDescription):
    def description(self,
                    Arm: skiros.Location):
        pass


class A(Arm):
    def description(self,
                    Arm: skiros.Location,
                    Speed: OPTIONAL[float] = 0.1):
        pass


class B(Arm):
    def description(self,
                    Arm: skiros.Location):
        pass


class C(Arm):
    def description(self,
                    Via: float,
                    Arm: skiros.Location):
        pass


class D(A):
    pass
''')


def test_children_of_a_skipped_parent_are_skipped_too():
    result = run(HEADER + '''

class Arm(SkillDescription):
    def createDescription(self):
        self._helper()


class A(Arm):
    def createDescription(self):
        Arm.createDescription(self)


class Other(SkillDescription):
    def createDescription(self):
        self.addParam("X", float, ParamTypes.Required)
''')
    statuses = {s.name: (s.status, s.reason or "") for s in result.skills}
    assert statuses["Arm"][0] == "skipped"
    assert statuses["A"] == ("skipped", "its base class Arm was not converted")
    assert statuses["Other"][0] == "converted"
    assert isinstance(result.new_source, str)
    assert "class Arm(SkillDescription)" in result.new_source
    assert "class Other(EzSkillDescription)" in result.new_source
    assert "SkillDescription as EzSkillDescription" in result.new_source
