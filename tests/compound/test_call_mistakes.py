"""Mistakes in ``self.skill(...)`` calls that SkiROS2 fails on when ``expand`` runs, found
whether the tree is read statically, traced, or neither (issue 21, patterns 3 and 4), and
the tracer's stand-ins for what real ``expand`` bodies use. Real files, the real check core
(static reader, child process for tracing), no mocks.
"""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from ezmigrate.checking.pipeline import run_check
from ezmigrate.checking.run import CheckSettings
from ezmigrate.lint.diagnostic import Diagnostic
from ezmigrate.verify.pool import PoolConfig

MODULE = '''\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element
from skiros2_skill.core.skill import SkillBase


class Task(SkillDescription):
    def createDescription(self):
        self.addParam("Pause", 1.0, ParamTypes.Optional)
        self.addParam("Spot", Element("skiros:Location"), ParamTypes.Required)


class task(SkillBase):
    def createDescription(self):
        self.setDescription(Task(), self.__class__.__name__)

    def expand(self, skill):
{body}
'''


def ez3(tmp_path: Path, body: str) -> list[Diagnostic]:
    tmp_path.mkdir(parents=True, exist_ok=True)
    path = tmp_path / "task.py"
    path.write_text(MODULE.format(body=textwrap.indent(textwrap.dedent(body).strip(),
                                                       " " * 8)), encoding="utf-8")
    outcome = run_check([path], None, PoolConfig(workers=1), CheckSettings(trace=True))
    return [d for d in outcome.diagnostics if d.code.startswith("EZ3")]


def codes(found: list[Diagnostic]) -> list[tuple[str, str]]:
    return sorted((d.code, d.severity) for d in found)


LOOP = 'for key in ("Duration",):\n    '
WORLD = 'here = self.wmi.get_element(self.params["Spot"].value)\n'

CASES = [  # (code, trigger, near miss): literal, traced and untraceable trees
    ("EZ309", 'skill(self.skill("Wait", "", specfiy={"Duration": 1.0}))',
     'skill(self.skill("Wait", "", specify={"Duration": 1.0}))'),
    ("EZ309", LOOP + 'skill(self.skill("Wait", "", specfiy={key: 1.0}))',
     LOOP + 'skill(self.skill("Wait", "", specify={key: 1.0}))'),
    ("EZ309", 'skill(self.skill("Wait", "", remap="Duration"))',
     'skill(self.skill("Wait", "", remap=""))'),
    ("EZ315", 'skill(self.skill("Wait", "", specify={"Duration": self.params["Pause"]}))',
     'skill(self.skill("Wait", "", specify={"Duration": self.params["Pause"].value}))'),
    ("EZ315", LOOP + 'skill(self.skill("Wait", "", specify={key: self.params["Pause"]}))',
     LOOP + 'skill(self.skill("Wait", "", specify={key: self.params["Pause"].value}))'),
]


@pytest.mark.parametrize(("code", "trigger", "near_miss"), CASES,
                         ids=[f"{c}-{i}" for i, (c, _, _) in enumerate(CASES)])
def test_a_call_mistake_is_an_error_and_its_near_miss_is_clean(tmp_path: Path, code: str,
                                                               trigger: str, near_miss: str):
    assert (code, "error") in codes(ez3(tmp_path / "hit", trigger))
    assert ez3(tmp_path / "miss", near_miss) == []


def test_call_mistakes_are_found_in_a_tree_that_cannot_be_traced(tmp_path: Path):
    found = ez3(tmp_path / "hit", WORLD + 'skill(self.skill("Wait", "", specfiy={"Duration": '
                                  'self.params["Pause"]}))')
    assert codes(found) == [("EZ309", "error"), ("EZ313", "info")]
    typo = next(d for d in found if d.code == "EZ309")
    assert "specfiy" in typo.message and "specify=" in typo.message
    near = ez3(tmp_path / "miss", WORLD + 'skill(self.skill("Wait", "", specify={"Duration": '
                                  'self.params["Pause"]}))')
    assert codes(near) == [("EZ313", "info"), ("EZ315", "error")]
    assert "self.wmi.get_element" in next(d.message for d in near if d.code == "EZ313")


def test_empty_remaps_are_none_and_the_rest_of_the_tree_is_still_checked(tmp_path: Path):
    found = ez3(tmp_path, 'skill(self.skill("Wait", "", remap="", specify={"Time": 1.0}),\n'
                          '      self.skill("Wait", "", remap=[], specify={}))')
    assert codes(found) == [("EZ307", "error")]


def test_the_stand_ins_have_the_api_expand_bodies_use(tmp_path: Path):
    body = (LOOP + 'skill(self.skill("Wait", "", specify={key: self.params["Spot"].value.label}'
            '),\n          self.skill("Wait", "", specify={key: self.params["Pause"].values}))')
    assert ez3(tmp_path, body) == []


def test_no_message_names_the_tracers_own_classes(tmp_path: Path):
    bodies = ['skill(self.skill(self.params["Pause"].value))',
              'skill(self.skill(self.params["Pause"]))',
              LOOP + 'skill(self.params["Pause"])',
              LOOP + 'skill(self.skill("Wait", "", remap={key: self.params["Spot"].value}))']
    for number, body in enumerate(bodies):
        for found in ez3(tmp_path / str(number), body):
            assert not any(name in found.message + found.fix for name in
                           ("_Param", "ParamRef", "Recorded", "object at 0x")), found


MODIFIED = '''\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_skill.core.skill import PrimitiveBase, SkillBase


class Spray(SkillDescription):
    def createDescription(self):
        self.addParam("Colour", str, ParamTypes.Required)


class spray(PrimitiveBase):
    def createDescription(self):
        self.setDescription(Spray(), self.__class__.__name__)

    def modifyDescription(self, skill):
        {owner}.addParam("Pressure", 2.0, ParamTypes.Optional)


class Paint(SkillDescription):
    def createDescription(self):
        pass


class paint(SkillBase):
    def createDescription(self):
        self.setDescription(Paint(), self.__class__.__name__)

    def expand(self, skill):
        skill(self.skill("Spray", "", specify={{"Colour": "red", "Pressure": 3.0}}))
'''


def test_a_specify_of_what_modify_description_adds_is_dropped(tmp_path: Path):
    """SkiROS2 calls ``instance.modifyDescription(wrapper)`` when the tree is grounded
    (``SkillWrapper.setInstance``), after ``self.skill(...)`` applied its ``specify``:
    ``skill.addParam`` declares the key on the wrapper too late for it (EZ319, a warning);
    ``self.addParam`` never declares it there (EZ307)."""
    (tmp_path / "wrapper").mkdir()
    (tmp_path / "wrapper" / "paint.py").write_text(MODIFIED.format(owner="skill"))
    found = run_check([tmp_path / "wrapper"], None, PoolConfig(workers=1),
                      CheckSettings(trace=True)).diagnostics
    [late] = [d for d in found if d.code.startswith("EZ3")]
    assert (late.code, late.severity) == ("EZ319", "warning") and "'Pressure'" in late.message
    (tmp_path / "itself").mkdir()
    (tmp_path / "itself" / "paint.py").write_text(MODIFIED.format(owner="self"))
    found = run_check([tmp_path / "itself"], None, PoolConfig(workers=1),
                      CheckSettings(trace=True)).diagnostics
    [dropped] = [d for d in found if d.code.startswith("EZ3")]
    assert dropped.code == "EZ307" and "'Pressure'" in dropped.message
    assert "modifyDescription to itself" in dropped.message


def test_a_keyword_typo_in_a_branch_the_trace_did_not_take_is_found(tmp_path: Path) -> None:
    """``expand`` branches on a run-time value: tracing takes one branch, the syntax shows
    every ``self.skill`` call (issue 30, a fork's operate_handle)."""
    branch = '''\
        kind = self.params["Pause"].value
        if kind == 1.0:
            skill(self.skill("Wait", "", specify={"Duration": 1.0}))
        else:
            skill(self.skill("Wait", "", TYPO={"Duration": 2.0}))
        '''
    found = ez3(tmp_path / "typo", branch.replace("TYPO", "specfiy"))
    assert [(d.code, d.line, d.severity) for d in found] == [("EZ309", 22, "error")]
    assert "specfiy=" in found[0].message and "specify=" in found[0].message
    assert ez3(tmp_path / "fine", branch.replace("TYPO", "specify")) == []


@pytest.mark.parametrize(("label", "severity"), [("", "error"), ("wait", "info")])
def test_a_type_matched_only_as_a_regular_expression_fails_without_a_label(
        tmp_path: Path, label: str, severity: str) -> None:
    """SkillInstanciator finds the description by regex but its instances by the literal
    type: without a label nothing loads one (issue 30, a lab's "cubes_and_update()")."""
    found = ez3(tmp_path, f'skill(self.skill("Wai.", "{label}", specify={{"Duration": 1.0}}))')
    assert [(d.code, d.severity) for d in found] == [("EZ302", severity)]


TWO_IMPLEMENTATIONS = '''\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element
from skiros2_skill.core.skill import SkillBase
from skiros2_skill.core.primitive import PrimitiveBase


class Go(SkillDescription):
    def createDescription(self):
        self.addParam("Target", Element("skiros:Location"), ParamTypes.Required)


class go_plain(PrimitiveBase):
    def createDescription(self):
        self.setDescription(Go(), "go_plain")


class go_via(PrimitiveBase):
    def createDescription(self):
        self.setDescription(Go(), "go_via")

    def modifyDescription(self, skill):
        skill.addParam("Via", Element("skiros:Location"), ParamTypes.Optional)


class Tour(SkillDescription):
    def createDescription(self):
        self.addParam("Via", Element("skiros:Location"), ParamTypes.Required)


class tour(SkillBase):
    def createDescription(self):
        self.setDescription(Tour(), self.__class__.__name__)

    def expand(self, skill):
        skill(self.skill("Go", "LABEL", remap={"Target": "Via"}))
'''


@pytest.mark.parametrize(("label", "expected"), [
    ("go_plain", []),  # adds nothing: the remap renames Target
    ("go_via", [("EZ306", "error")]),  # its modifyDescription declares Via on the node
    ("", [("EZ306", "info")]),  # the skill manager picks one at run time
])
def test_a_remap_onto_a_key_modify_description_adds_depends_on_the_label(
        tmp_path: Path, label: str, expected: list[tuple[str, str]]) -> None:
    """What an implementation adds in modifyDescription is on the nodes it runs, not on
    every node of its description (issue 30, a lab's navigate_and_open_doors)."""
    path = tmp_path / "tour.py"
    path.write_text(TWO_IMPLEMENTATIONS.replace("LABEL", label), encoding="utf-8")
    outcome = run_check([path], None, PoolConfig(workers=1), CheckSettings(trace=True))
    assert codes([d for d in outcome.diagnostics if d.code.startswith("EZ3")]) == expected


def test_a_remap_onto_nothing_is_said_even_where_part_of_the_tree_is_unknown(
        tmp_path: Path) -> None:
    """A remap value no parameter and no known node declares (the value never reaches the
    child) is EZ308 also when another node's parameters are unknown, saying so (issue 30,
    a lab's Problem1 remapped onto 'Object1' while its parent declares 'Waste1')."""
    body = ('skill(self.skill("Mystery", ""),\n'
            '      self.skill("Wait", "", remap={"Duration": "Nowhere"}))')
    found = [d for d in ez3(tmp_path / "a", body) if d.code == "EZ308"]
    assert [(d.code, d.severity) for d in found] == [("EZ308", "info")]
    assert "unless a node whose parameters this run could not read writes it" in \
        found[0].message
    fine = body.replace('"Nowhere"', '"Pause"')
    assert [d for d in ez3(tmp_path / "b", fine) if d.code == "EZ308"] == []
