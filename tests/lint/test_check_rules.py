"""One minimal file per finding code that triggers it, and a near-miss that does not.

Legacy files go through the real static pass (the codemod's reader and the runtime's
checks on the extracted trace); EzSkiROS files are read from their syntax and checked by
the runtime's checks, as ``check`` does without ``--trace``.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from check_support import ezskiros, legacy, lint

from ezskiros_runtime.codes import RULES, code_for

REQ, OPT, INF = "ParamTypes.Required", "ParamTypes.Optional", "ParamTypes.Inferred"
LOC = f'self.addParam("Box", Element("skiros:Location"), {REQ})'
PROD = f'self.addParam("Item", Element("skiros:Product"), {REQ})'


def rel(subject: str, obj: str, prop: str = "skiros:contain", which: str = "Pre",
        desired: str = "True") -> str:
    return (f'self.add{which}Condition(self.getRelationCond("L{which}{desired}", "{prop}", '
            f'"{subject}", "{obj}", {desired}))')


def prop(subject: str, name: str, op: str, value: str) -> str:
    return (f'self.addPreCondition(self.getPropCond("P", "{name}", "{subject}", "{op}", '
            f'{value}, True))')


IMPLEMENTATION = """

from skiros2_skill.core.primitive import PrimitiveBase


class skill_impl(PrimitiveBase):
    def createDescription(self):
        self.setDescription(Skill(), self.__class__.__name__)

    def execute(self):
        found = self._wmi.resolve_element(Element("{cls}"))
        return self.success(str((self.params["{key}"].value, found)))
"""

UNDESCRIBED = """

from skiros2_skill.core.primitive import PrimitiveBase


class skill_impl(PrimitiveBase):
    def createDescription(self):
        {describe}

    def execute(self):
        return self.success("done")
"""

PROPERTY = """

class measure_impl(PrimitiveBase):
    def createDescription(self):
        self.setDescription(Skill(), self.__class__.__name__)

    def execute(self):
        box = self.params["Box"].value
        box.setProperty("lab:Depth", 0.3)
        return self.success(str(box.getProperty("{read}").value))
"""

COMPOUND = legacy(f"{LOC}\n{PROD}") + """

from skiros2_skill.core.skill import RetryOnFail, Sequential, SkillBase


class Child(SkillDescription):
    def createDescription(self):
        self.addParam("Target", Element("skiros:Location"), ParamTypes.Required)
        self.addParam("Speed", 0.5, ParamTypes.Optional)


class Bin(SkillDescription):
    def createDescription(self):
        self.addParam("Target", Element("skiros:LargeBox"), ParamTypes.Required)


class Middle(SkillDescription):
    def createDescription(self):
        self.addParam("Spot", Element("skiros:Location"), ParamTypes.Required)


class middle_impl(SkillBase):
    def createDescription(self):
        self.setDescription(Middle(), self.__class__.__name__)

    def modifyDescription(self, skill):
        skill.addParam("Pace", 1.0, ParamTypes.Optional)

    def expand(self, skill):
        skill(self.skill("Child", "", remap={{"Target": "Spot"}}))


class skill_tree(SkillBase):
    def createDescription(self):
        self.setDescription(Skill(), self.__class__.__name__)

    def expand(self, skill):
        {expand}
"""


def tree(*children: str, expand: str = "") -> str:
    """A legacy module whose compound skill ``skill_tree`` (implementing ``Skill``: Box, a
    location, and Item, a product) has these children, or this ``expand`` body."""
    return COMPOUND.format(expand=expand or f"skill({', '.join(children)})")


TARGET = 'remap={"Target": "Box"}'
CASES: dict[str, tuple[str, str]] = {
    "EZ301": (tree('self.skill("Chld", "")'), tree('self.skill("Child", "")')),
    "EZ302": (tree('self.skill("Chil.", "")'), tree('self.skill("Child", "")')),
    "EZ303": (tree('self.skill("Child", "middle_impl")'), tree('self.skill("Middle", '
                                                               '"middle_impl")')),
    "EZ304": (tree('self.skill("Child", "", remap={"Goal": "Box"})'),
              tree(f'self.skill("Child", "", {TARGET})')),
    "EZ305": (tree('self.skill("Middle", "", remap={"Speed": "Box"})'),
              tree('self.skill("Middle", "", remap={"Spot": "Box"})')),
    "EZ314": (tree('self.skill("Middle", "", remap={"Target": "Box"})'),  # middle_impl's own
              tree('self.skill("Middle", "", remap={"Spot": "Box"})')),
    "EZ315": (tree('self.skill("Child", "", specify={"Speed": self.params["Box"]})'),
              tree('self.skill("Child", "", specify={"Speed": self.params["Box"].value})')),
    "EZ306": (tree('self.skill("Child", "", remap={"Target": "Speed"})'),
              tree(f'self.skill("Child", "", {TARGET})')),
    "EZ307": (tree('self.skill("Child", "", specify={"Sped": 1.0})'),
              tree('self.skill("Child", "", specify={"Speed": 1.0})')),
    "EZ308": (tree('self.skill("Child", "", remap={"Target": "Station"})'),
              tree(f'self.skill("Child", "", {TARGET})')),
    "EZ309": (tree('self.skill(self.skill("Child", ""))'),
              tree(f'self.skill(Sequential())(self.skill("Child", "", {TARGET}))')),
    "EZ310": (tree(f'self.skill(RetryOnFail(Sequential()))(self.skill("Child", "", {TARGET}))'),
              tree(f'self.skill(Sequential())(self.skill("Child", "", {TARGET}))')),
    "EZ311": (tree('self.skill("Child", "", remap={"Target": "Item"})'),
              tree(f'self.skill("Child", "", {TARGET})')),
    "EZ312": (tree(f'self.skill("Bin", "", {TARGET})'), tree(f'self.skill("Child", "", {TARGET})')),
    "EZ313": (tree(expand='skill(self.skill("Child", "", remap={"Target": self.wmi.box}))'),
              tree(expand='skill(self.skill("Child", "", remap={"Target": "Box"}))')),
    "EZ317": (tree(f'self.skill(Sequentail())(self.skill("Child", "", {TARGET}))'),
              tree(f'self.skill(Sequential())(self.skill("Child", "", {TARGET}))')),
    "EZ318": (tree('self.skill("Middle", "midle_impl", remap={"Spot": "Box"})'),
              tree('self.skill("Middle", "middle_impl", remap={"Spot": "Box"})')),
    "EZ319": (tree('self.skill("Middle", "", remap={"Spot": "Box"}, specify={"Pace": 2.0})'),
              tree('self.skill("Middle", "", remap={"Spot": "Box"})')),
    "EZ320": (tree('self.skill("WmSetRelation", "", remap={"Src": "Box", "Dst": "Item"})'),
              tree('self.skill("WmSetRelation", "", remap={"Src": "Box", "Dst": "Item"}, '
                   'specify={"Relation": "skiros:contain"})')),
    "EZ110": (legacy(LOC) + UNDESCRIBED.format(describe="pass"),
              legacy(LOC) + UNDESCRIBED.format(
                  describe="self.setDescription(Skill(), self.__class__.__name__)")),
    "EZ101": (legacy(f'self.addParam("Speed", 0.1, {REQ}, "metres per second")'),
              legacy(f'self.addParam("Speed", 0.1, {REQ}, description="metres per second")')),
    "EZ102": (legacy(f'self.addParam("Speed", 0.1, {REQ}, [ParamOptions.Lock])'),
              legacy(f'self.addParam("Box", Element("skiros:Location"), {REQ}, '
                     '[ParamOptions.Lock])')),
    "EZ103": (legacy(f'self.addParam("Speed", 0.1, {OPT})\nself.addParam("Speed", 0.2, {OPT})'),
              legacy(f'self.addParam("Speed", 0.1, {OPT})\nself.addParam("Slow", 0.2, {OPT})')),
    "EZ104": (legacy(f'{LOC}\n{rel("Box", "Tool")}'), legacy(f'{LOC}\n{PROD}\n'
                                                               f'{rel("Box", "Item")}')),
    "EZ105": (legacy(f'{LOC}\nself.addParam("Item", Element("skiros:Product"), {INF})'),
              legacy(f'{LOC}\nself.addParam("Item", Element("skiros:Product"), {INF})\n'
                     f'{rel("Box", "Item")}')),
    "EZ107": (legacy(f'{LOC}\n{PROD}\n{rel("Box", "Item")}\n'
                     f'{rel("Box", "Item", desired="False")}'),
              legacy(f'{LOC}\n{PROD}\n{rel("Box", "Item")}\n'
                     f'{rel("Box", "Item", which="Post", desired="False")}')),
    "EZ201": (legacy(f'{PROD}\nself.addParam("Other", Element("skiros:Product"), {REQ})\n'
                     f'{rel("Item", "Other")}'),
              legacy(f'{LOC}\n{PROD}\n{rel("Box", "Item")}')),
    "EZ202": (legacy(f'{LOC}\nself.addParam("Spot", Element("skiros:Location"), {REQ})\n'
                     f'{rel("Box", "Spot")}'),
              legacy(f'{LOC}\n{PROD}\n{rel("Box", "Item")}')),
    "EZ203": (legacy(f'self.addParam("Any", Element("skiros:Thing"), {REQ})\n{PROD}\n'
                     f'{rel("Any", "Item")}'),
              legacy(f'{LOC}\n{PROD}\n{rel("Box", "Item")}')),
    "EZ204": (legacy(f'{LOC}\nself.addParam("Any", Element("skiros:Thing"), {REQ})\n'
                     f'{rel("Box", "Any")}'),
              legacy(f'{LOC}\n{PROD}\n{rel("Box", "Item")}')),
    "EZ205": (legacy(f'{LOC}\n{PROD}\n{rel("Box", "Item", prop="skiros:Label")}'),
              legacy(f'{LOC}\n{prop("Box", "skiros:Label", "=", repr("a"))}')),
    "EZ206": (legacy(f'{LOC}\n{prop("Box", "skiros:Open", "=", "3")}'),
              legacy(f'{LOC}\n{prop("Box", "skiros:Open", "=", "True")}')),
    "EZ207": (legacy(f'{LOC}\n{prop("Box", "skiros:Label", ">", repr("a"))}'),
              legacy(f'{LOC}\n{prop("Box", "skiros:Label", "=", repr("a"))}')),
    "EZ208": (legacy(f'{LOC}\n{prop("Box", "skiros:Label", "~=", repr("a"))}'),
              legacy(f'{LOC}\n{prop("Box", "skiros:Label", "=", repr("a"))}')),
    "EZ209": (legacy(f'self.addParam("Fruit", Element("skiros:Banana"), {REQ})'),
              legacy(f'self.addParam("Fruit", Element("skiros:Product"), {REQ})')),
    "EZ211": (legacy(f'self.addParam("Hand", Element("Gripper"), {REQ})'),
              legacy(f'self.addParam("Hand", Element("skiros:Gripper"), {REQ})')),
    "EZ212": (legacy(f'self.addParam("Param", Element("skiros;:Product"), {REQ})'),
              legacy(f'self.addParam("Param", Element("skiros:Product"), {REQ})')),
    "EZ213": (legacy(f'self.addParam("Crate", Element("skiros:Large_box"), {REQ})'),
              legacy(f'self.addParam("Crate", Element("skiros:LargeBox"), {REQ})')),
    "EZ401": (legacy(f'{LOC}\n{PROD}\nself.addParam("Bin", Element("skiros:Location"), {REQ})\n'
                     f'{rel("Box", "Item")}\n{rel("Bin", "Item", which="Post")}'),
              legacy(f'{LOC}\n{PROD}\nself.addParam("Bin", Element("skiros:Location"), {REQ})\n'
                     f'{rel("Box", "Item")}\n{rel("Box", "Item", which="Post", desired="False")}'
                     f'\n{rel("Bin", "Item", which="Post")}')),
    "EZ109": (legacy(LOC) + IMPLEMENTATION.format(key="Boks", cls="skiros:Location"),
              legacy(LOC) + IMPLEMENTATION.format(key="Box", cls="skiros:Location")),
    "EZ214": (legacy(LOC) + IMPLEMENTATION.format(key="Box", cls="skiros:Locaton"),
              legacy(LOC) + IMPLEMENTATION.format(key="Box", cls="skiros:Location")),
    "EZ215": (legacy(LOC) + IMPLEMENTATION.format(key="Box", cls="skiros:Location")
              + PROPERTY.format(read="lab:Reach"),
              legacy(LOC) + IMPLEMENTATION.format(key="Box", cls="skiros:Location")
              + PROPERTY.format(read="skiros:Label")),
    "EZ901": (legacy(f'self.addParam("Speed", 0.1, {REQ})'),
              ezskiros("def description(self, Speed: float = 0.1):\n    pass")),
    "EZ902": (legacy(f'for key in sorted(("B", "A")):\n    self.addParam(key, 0.1, {REQ})'),
              legacy(f'self.addParam("A", 0.1, {REQ})\nself.addParam("B", 0.1, {REQ})')),
    "EZ905": (legacy(f'self.addParam("Speed", 0.1, {REQ}') + "class Broken(:\n",
              legacy(f'self.addParam("Speed", 0.1, {REQ})')),
    # EzSkiROS files: read from their syntax, checked as the runtime checks them
    "EZ106": (ezskiros("def description(self, Speed: float = 1):\n    pass"),
              ezskiros("def description(self, Speed: float = 1.0):\n    pass")),
    "EZ108": (ezskiros("def description(self, *args):\n    pass"),
              ezskiros("def description(self, Speed: float = 1.0):\n    pass")),
    "EZ210": (ezskiros("def description(self, A: skiros.Location, B: skiros.Location):\n"
                       "    self.pre_conditions += A.near(B)"),
              ezskiros("def description(self, A: skiros.Location, B: skiros.Location):\n"
                       "    self.pre_conditions += A.relation('skiros:near', B)")),
    "EZ904": (ezskiros("def description(self, Box: skiros.Locaton):\n    pass"),
              ezskiros("def description(self, Box: skiros.Location):\n    pass")),
    "EZ907": (ezskiros("def description(self, A: skiros.Location, B: skiros.Location):\n"
                       "    for other in (B,):\n"
                       "        self.pre_conditions += A.contain(other)"),
              ezskiros("def description(self, A: skiros.Location, B: skiros.Location):\n"
                       "    self.pre_conditions += A.contain(B)")),
}
NOT_FROM_CHECK = {
    "EZ100": "tested with the suppression comments (test_check_formats.py)",
    "EZ316": "needs a launch file's skill_list: its trigger and near miss are in "
             "tests/lint/test_launch.py",
    "EZ903": "a verification verdict: `rewrite` and `verify` report it, `check` never verifies",
    "EZ906": "the line guard's verdict on a bug of ezmigrate, which no input triggers: "
             "tests/codemod/test_guard.py installs a lossy transform and checks it through "
             "rewrite, --dry-run, --check, stdin and check",
    **dict.fromkeys(("EZ402", "EZ403", "EZ404", "EZ405", "EZ406", "EZ407", "EZ408", "EZ409"),
                    "findings of scenes, not of Python files: each has its trigger and near "
                    "miss in tests/lint/test_world_check.py"),
    **dict.fromkeys(("EZ410", "EZ411", "EZ412"),
                    "findings of the lab's ontology files and scenes: their triggers and near "
                    "misses are in tests/lint/test_world_check.py"),
}


def test_every_code_has_a_case():
    assert {r.code for r in RULES} == set(CASES) | set(NOT_FROM_CHECK)


@pytest.mark.parametrize("code", sorted(CASES))
def test_code_fires_on_its_file_and_not_on_the_near_miss(tmp_path: Path, code: str):
    trigger, near_miss = CASES[code]
    found = lint(tmp_path / "hit", trigger)
    assert code in {d.code for d in found}, "\n".join(map(str, found))
    hit = next(d for d in found if d.code == code)
    assert hit.line >= 1 and hit.column >= 1 and hit.path.endswith("skill.py")
    missed = lint(tmp_path / "miss", near_miss)
    assert code not in {d.code for d in missed}, "\n".join(map(str, missed))


def test_prefix_typo_replaces_the_vaguer_findings_of_the_same_term(tmp_path: Path):
    found = lint(tmp_path / "t", CASES["EZ212"][0])
    codes = [d.code for d in found if d.code != "EZ901"]
    assert codes == ["EZ212"], codes
    assert "did you mean skiros:Product?" in found[-1].message


def test_verification_failure_has_its_code():
    assert code_for("failed") == "EZ903" and code_for("not-equivalent") == "EZ903"


BASED = tree(f'self.skill("NAME", "", {TARGET})') + """

class BigBin(Bin):
    def createDescription(self):
        Bin.createDescription(self)
"""


def test_a_child_type_naming_a_base_description_is_unknown(tmp_path: Path):
    """The skill manager loads leaf descriptions only: once ``BigBin`` derives from
    ``Bin``, ``"Bin"`` names nothing it could load, and the message says why."""
    found = lint(tmp_path / "base", BASED.replace("NAME", "Bin"))
    [hit] = [d for d in found if d.code == "EZ301"]
    assert "base other descriptions derive from" in hit.message
    leaf = lint(tmp_path / "leaf", BASED.replace("NAME", "BigBin"))
    assert "EZ301" not in {d.code for d in leaf}, "\n".join(map(str, leaf))
