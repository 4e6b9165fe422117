"""EZ320 (a child's Required parameter that nothing in the tree sets, SkiROS2 issue #91)
and EZ110 (an implementation whose createDescription never calls setDescription, issue
#109): real files in a temporary folder, the real check core.

What SkiROS2 does (``skill_utils.NodeExecutor._autoParametrizeBB``, develop and ros2):
a parameter that is not Optional, not an Element and has no value when the child is
grounded raises "Missing required parameter(s)". A value comes from the child's own
declaration (a default), a ``specify``, or the blackboard by key (after remapping): the
compound's parameters, what any node of the task wrote before.
"""

from __future__ import annotations

from pathlib import Path

from ezmigrate.checking.pipeline import run_check
from ezmigrate.lint.diagnostic import Diagnostic
from ezmigrate.verify.pool import PoolConfig

HEADER = '''\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.primitive import PrimitiveBase
from skiros2_common.core.world_element import Element
from skiros2_skill.core.skill import SkillBase


class Say(SkillDescription):
    def createDescription(self):
        self.addParam("Text", str, ParamTypes.Required)
        self.addParam("Loud", False, ParamTypes.Required)
        self.addParam("Voice", str, ParamTypes.Optional)
        self.addParam("Heard", float, ParamTypes.Inferred)
        self.addParam("Listener", Element("sumo:Agent"), ParamTypes.Required)


class Listen(SkillDescription):
    def createDescription(self):
        self.addParam("Text", "", ParamTypes.Optional)


class say(PrimitiveBase):
    def createDescription(self):
        self.setDescription(Say(), self.__class__.__name__)


class listen(PrimitiveBase):
    def createDescription(self):
        self.setDescription(Listen(), self.__class__.__name__)


class Greet(SkillDescription):
    def createDescription(self):
        {greet}


class greet(SkillBase):
    def createDescription(self):
        self.setDescription(Greet(), self.__class__.__name__)

    def expand(self, skill):
        skill(
            {children}
        )
'''


def check(folder: Path, children: str, greet: str = 'self.addParam("Who", str, '
          'ParamTypes.Optional)', extra: str = "") -> list[Diagnostic]:
    folder.mkdir(parents=True)
    (folder / "skills.py").write_text(HEADER.format(children=children, greet=greet) + extra,
                                      encoding="utf-8")
    return [d for d in run_check([folder], None, PoolConfig(workers=1)).diagnostics
            if d.severity != "info" or d.code in ("EZ320", "EZ110")]


def codes(found: list[Diagnostic]) -> list[tuple[str, str]]:
    return [(d.code, d.severity) for d in found if d.code != "EZ901"]


def test_a_required_parameter_nothing_sets_is_an_error_naming_autoparametrize(tmp_path):
    [hit] = [d for d in check(tmp_path / "t", 'self.skill("Say", ""),') if d.code == "EZ320"]
    assert hit.severity == "error" and "'Text'" in hit.message
    assert "_autoParametrizeBB" in hit.message and "Missing required parameter" in hit.message
    assert "Loud" not in hit.message  # declared with a value
    assert "Voice" not in hit.message and "Heard" not in hit.message  # Optional, Inferred
    assert "Listener" not in hit.message  # an Element: grounded from the world model


def test_what_sets_the_key_is_no_finding(tmp_path):
    near_misses = {
        "specified": 'self.skill("Say", "", specify={"Text": "hi"}),',
        "the compound declares it": ('self.skill("Say", ""),',
                                     'self.addParam("Text", str, ParamTypes.Required)'),
        "a remap onto a parameter of the compound": ('self.skill("Say", "", remap={"Text": '
                                                     '"Who"}),', None),
        "a sibling writes it": 'self.skill("Listen", ""), self.skill("Say", ""),',
        "a later sibling writes it (conservative)": 'self.skill("Say", ""), '
                                                    'self.skill("Listen", ""),',
    }
    for number, (why, case) in enumerate(near_misses.items()):
        children, greet = case if isinstance(case, tuple) else (case, None)
        args = {"greet": greet} if greet else {}
        found = check(tmp_path / str(number), children, **args)
        assert "EZ320" not in {d.code for d in found}, (why, [str(d) for d in found])


def test_a_remap_onto_a_key_nothing_sets_is_reported_once_under_its_new_name(tmp_path):
    found = check(tmp_path / "t", 'self.skill("Say", "", remap={"Text": "Line"}),')
    assert [d.code for d in found if d.code.startswith("EZ3")] == ["EZ320"]
    assert "'Line'" in found[-1].message or any("'Line'" in d.message for d in found)


def test_a_typo_of_the_specify_key_is_one_finding_not_two(tmp_path):
    found = check(tmp_path / "t", 'self.skill("Say", "", specify={"Txt": "hi"}),')
    assert [d.code for d in found if d.code.startswith("EZ3")] == ["EZ307"]


def test_a_tree_around_the_compound_that_sets_the_key_is_no_finding(tmp_path):
    outer = '''

class Visit(SkillDescription):
    def createDescription(self):
        self.addParam("Text", "hello", ParamTypes.Optional)


class visit(SkillBase):
    def createDescription(self):
        self.setDescription(Visit(), self.__class__.__name__)

    def expand(self, skill):
        skill(self.skill("Greet", ""))
'''
    found = check(tmp_path / "t", 'self.skill("Say", ""),', extra=outer)
    assert "EZ320" not in {d.code for d in found}, [str(d) for d in found]
    silent = outer.replace('"Text", "hello"', '"Other", "hello"')
    [hit] = [d for d in check(tmp_path / "u", 'self.skill("Say", ""),', extra=silent)
             if d.code == "EZ320"]
    assert hit.severity == "error"


def test_a_tree_that_cannot_be_read_makes_it_info(tmp_path):
    unread = '''

class Roam(SkillDescription):
    def createDescription(self):
        pass


class roam(SkillBase):
    def createDescription(self):
        self.setDescription(Roam(), self.__class__.__name__)

    def expand(self, skill):
        for name in self.names():
            skill(self.skill(name, ""))
'''
    [hit] = [d for d in check(tmp_path / "t", 'self.skill("Say", ""),', extra=unread)
             if d.code == "EZ320"]
    assert hit.severity == "info" and "compound tree of the run" in hit.message


def test_the_standard_library_wm_set_relation_needs_its_relation(tmp_path):
    found = check(tmp_path / "t", 'self.skill("WmSetRelation", "", remap={"Src": "Who"}),')
    assert [(d.code, "'Relation'" in d.message) for d in found
            if d.code == "EZ320"] == [("EZ320", True)]
    fine = check(tmp_path / "u", 'self.skill("WmSetRelation", "", specify={"Relation": '
                 '"skiros:contain"}),')
    assert "EZ320" not in {d.code for d in fine}


IMPLEMENTATIONS = '''\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.primitive import PrimitiveBase


class Say(SkillDescription):
    def createDescription(self):
        self.addParam("Text", "", ParamTypes.Optional)


class LabBase(PrimitiveBase):
    def helper(self):
        return 1


class say(LabBase):
    def createDescription(self):
        {body}

    def execute(self):
        return self.success("done")
'''


def undescribed(folder: Path, body: str, launch: str | None = None) -> list[Diagnostic]:
    folder.mkdir(parents=True)
    (folder / "skills.py").write_text(IMPLEMENTATIONS.format(body=body), encoding="utf-8")
    return [d for d in run_check([folder], None, PoolConfig(workers=1)).diagnostics
            if d.code == "EZ110"]


def test_an_implementation_that_never_sets_its_description_is_an_error(tmp_path):
    [hit] = undescribed(tmp_path / "t", 'self.addParam("Extra", 1.0, ParamTypes.Optional)')
    assert hit.severity == "error" and hit.line == 16 and "add_skill" in hit.message
    assert "#109" in hit.message


def test_a_create_description_that_may_set_it_is_no_finding(tmp_path):
    for number, body in enumerate((
            "self.setDescription(Say(), self.__class__.__name__)",
            "super(say, self).createDescription()",
            "self.describe()",  # a helper of the class
            "describe(self)",  # a function given self
            "raise NotImplementedError()",  # an abstract base
            "if True:\n            self.setDescription(Say(), 'say')")):
        assert undescribed(tmp_path / str(number), body) == [], body


def test_a_base_other_implementations_derive_from_is_no_finding(tmp_path):
    folder = tmp_path / "t"
    folder.mkdir()
    (folder / "skills.py").write_text(IMPLEMENTATIONS.format(body="pass") + '''

class say_loud(say):
    def createDescription(self):
        self.setDescription(Say(), "say_loud")
''', encoding="utf-8")
    found = run_check([folder], None, PoolConfig(workers=1)).diagnostics
    assert "EZ110" not in {d.code for d in found}
