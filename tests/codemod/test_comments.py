"""Comments inside ``createDescription`` survive, next to what they described.

Before/after pairs for the places a comment can hide in a declaration: inside a multi-line
``addParam`` call, on a declaration that a second one with the same key replaces, and on the
``def`` line when the last parameter has an end-of-line comment of its own.
"""

from __future__ import annotations

from codemod_case import HEADER, assert_migrates

IMPORTS = '''from ezskiros_runtime import SkillDescription, OPTIONAL, REQUIRED, Lock
from ezskiros_runtime.ontology import skiros
'''


def test_comments_inside_a_multi_line_add_param_go_above_its_parameter():
    assert_migrates(HEADER + '''

class Look(SkillDescription):
    def createDescription(self):
        self.addParam(
            "Camera",  # which camera
            Element("skiros:DepthCamera"),
            # kind below
            ParamTypes.Required, [ParamOptions.Lock])
''', IMPORTS.replace(" OPTIONAL,", "") + '''

class Look(SkillDescription):
    def description(self,
                    # which camera
                    # kind below
                    Camera: REQUIRED[skiros.DepthCamera, Lock]):
        pass
''')


def test_a_replaced_declaration_hands_its_comments_to_the_one_that_replaces_it():
    assert_migrates(HEADER + '''

class Move(SkillDescription):
    def createDescription(self):
        # the first speed
        self.addParam("Speed", 0.5, ParamTypes.Optional)  # m/s, first
        self.addParam("Speed", 1.0, ParamTypes.Optional)  # second
''', IMPORTS.replace(", REQUIRED, Lock", "").replace(
        "from ezskiros_runtime.ontology import skiros\n", "") + '''

class Move(SkillDescription):
    def description(self,
                    # the first speed
                    # m/s, first
                    Speed: OPTIONAL[float] = 1.0):  # second
        pass
''')


def test_the_def_line_comment_and_the_last_parameter_comment_both_stay():
    assert_migrates(HEADER + '''

class Hold(SkillDescription):
    def createDescription(self):  # header comment
        self.addParam("B", Element("skiros:Product"), ParamTypes.Required)  # B comment
''', IMPORTS.replace(", OPTIONAL, REQUIRED, Lock", "") + '''

class Hold(SkillDescription):
    def description(self,  # header comment
                    B: skiros.Product):  # B comment
        pass
''')


def test_the_def_line_comment_stays_on_the_def_line_without_parameters():
    assert_migrates(HEADER + '''

class Idle(SkillDescription):
    def createDescription(self):  # nothing to declare
        self.setAvailableForPlanning(False)
''', IMPORTS.replace(", OPTIONAL, REQUIRED, Lock", "").replace(
        "from ezskiros_runtime.ontology import skiros\n", "") + '''

class Idle(SkillDescription):
    def description(self):  # nothing to declare
        self.setAvailableForPlanning(False)
''')
