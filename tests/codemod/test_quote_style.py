"""The emitted code follows the file's own quote style (issue 22, item 12).

A file written with single quotes gets single-quoted keys, types and vocabulary; a string
holding a single quote stays double-quoted (the fewer escapes, as black chooses); a file
with no preference keeps the double quotes of the DSL's documentation.
"""

from __future__ import annotations

from codemod_case import assert_migrates

HEADER = '''from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


'''


def test_single_quoted_file_gets_single_quotes():
    assert_migrates(HEADER + '''class Pick(SkillDescription):
    def createDescription(self):
        self.addParam('Object', Element('scalable:Thing'), ParamTypes.Required)
        self.addParam('On/Off', True, ParamTypes.Optional)
        self.addParam('Note', "it's", ParamTypes.Optional)
        self.addPreCondition(self.getRelationCond('Near', 'foo:near', 'On/Off', 'Object', True))
''', '''from ezskiros_runtime import SkillDescription, Annotated, OPTIONAL, REQUIRED, ELEMENT, KEY


class Pick(SkillDescription):
    def description(self,
                    Object: Annotated[REQUIRED, ELEMENT('scalable:Thing')],
                    On_Off: Annotated[OPTIONAL[bool], KEY('On/Off')] = True,
                    Note: OPTIONAL[str] = "it's"):
        self.pre_conditions += On_Off.relation('foo:near', Object).named('Near')
''')


def test_double_quoted_file_keeps_double_quotes():
    assert_migrates(HEADER + """class Pick(SkillDescription):
    def createDescription(self):
        self.addParam("Object", Element("scalable:Thing"), ParamTypes.Required)
        self.addParam('On/Off', True, ParamTypes.Optional)
""", """from ezskiros_runtime import SkillDescription, Annotated, OPTIONAL, REQUIRED, ELEMENT, KEY


class Pick(SkillDescription):
    def description(self,
                    Object: Annotated[REQUIRED, ELEMENT("scalable:Thing")],
                    On_Off: Annotated[OPTIONAL[bool], KEY("On/Off")] = True):
        pass
""")
