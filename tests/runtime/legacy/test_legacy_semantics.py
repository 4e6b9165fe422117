"""SkiROS2 semantics as legacy-skiros2-api.md states them (§2, §3, §4, §8.1-§8.12).

Every test writes a real legacy skill file into ``tmp_path``, loads it through ``load_file``
(the stand-ins, the loader and the extractor together) and asserts concrete model contents.
"""

from __future__ import annotations

import importlib.util
import sys
import textwrap
from pathlib import Path

import pytest

from ezskiros_runtime.compare import compare
from ezskiros_runtime.legacy import legacy_imports, load_file
from ezskiros_runtime.legacy.loader import FileLoad
from ezskiros_runtime.model import Condition, Param, SkillModel, typed

HEADER = """\
from skiros2_common.core.abstract_skill import SkillDescription, ParamOptions
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element
"""

ROBOT = Param("Robot", "Inferred", "Element", "sumo:Agent")
T = typed(True)
F = typed(False)


def load(tmp_path: Path, body: str, name: str = "skills.py") -> FileLoad:
    path = tmp_path / name
    path.write_text(HEADER + textwrap.dedent(body))
    return load_file(path, permissive=False)


def models(tmp_path: Path, body: str) -> dict[str, SkillModel]:
    result = load(tmp_path, body)
    assert result.errors == []
    return {m.name: m for m in result.models}


def keys(model: SkillModel) -> list[str]:
    return [p.key for p in model.params]


def lock(key: str) -> tuple[Condition, Condition, Condition]:
    """The pre, hold and post conditions of ``ParamOptions.Lock`` on ``key`` (§3)."""
    def prop(label: str, desired: bool) -> Condition:
        return Condition("property", label, "skiros:StateProperty", key, operator="=",
                         value=typed("Idle"), desired_state=typed(desired))
    return prop(key + "Idle", True), prop(key + "Busy", False), prop(key + "Idle", True)


def rel(label: str, subject: str, obj: str, desired: object = True,
        relation: str = "skiros:contain") -> Condition:
    return Condition("relation", label, relation, subject, obj, desired_state=typed(desired))


# -- §2 --------------------------------------------------------------------------------------

def test_s2_descriptions_load_implementations_do_not(tmp_path: Path) -> None:
    result = load(tmp_path, """
        from skiros2_common.core.primitive import PrimitiveBase
        from skiros2_skill.core.skill import SkillBase, Sequential

        class Pick(SkillDescription):
            def createDescription(self):
                self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)

        class pick(PrimitiveBase):
            def createDescription(self):
                self.setDescription(Pick(), self.__class__.__name__)

        class pick_compound(SkillBase):
            def createDescription(self):
                self.setDescription(Pick(), self.__class__.__name__)

            def expand(self, skill):
                skill.setProcessor(Sequential())
                skill(self.skill("Pick", "", remap={"Object": "Thing"}))
        """)
    assert result.errors == []
    assert [m.name for m in result.models] == ["Pick"]
    (model,) = result.models
    assert model == SkillModel("Pick", "skiros:Pick",
                               params=(Param("Object", "Required", "Element", "skiros:Product"),
                                       ROBOT))
    assert model.source == str(tmp_path / "skills.py") and model.line == 8


def test_s2_empty_descriptions_get_only_robot(tmp_path: Path) -> None:
    got = models(tmp_path, """
        class NoMethod(SkillDescription):
            pass

        class Empty(SkillDescription):
            def createDescription(self):
                pass
        """)
    assert got["NoMethod"] == SkillModel("NoMethod", "skiros:NoMethod", params=(ROBOT,))
    assert got["Empty"].params == (ROBOT,) and got["Empty"].type == "skiros:Empty"


# -- §3 / §4 ---------------------------------------------------------------------------------

def test_s3_value_kinds(tmp_path: Path) -> None:
    (model,) = models(tmp_path, """
        class Values(SkillDescription):
            def createDescription(self):
                self.addParam("E", Element("skiros:Product"), ParamTypes.Required)
                self.addParam("C", Element, ParamTypes.Optional)
                self.addParam("F", float, ParamTypes.Required)
                self.addParam("D", {}, ParamTypes.Optional)
                self.addParam("S", "skiros:contain", ParamTypes.Optional)
                self.addParam("Blank", "", ParamTypes.Optional)
                self.addParam("Neg", -1.5, ParamTypes.Optional)
                self.addParam("On/Off", True, ParamTypes.Required, [], "switch")
                self.addParam("x", 1, ParamTypes.Required, description="lower")
        """).values()
    assert model.params == (
        Param("E", "Required", "Element", "skiros:Product"),
        Param("C", "Optional", "Element", None),
        Param("F", "Required", "float"),
        Param("D", "Optional", "dict", values=(typed({}),)),
        Param("S", "Optional", "str", values=(typed("skiros:contain"),)),
        Param("Blank", "Optional", "str", values=(typed(""),)),
        Param("Neg", "Optional", "float", values=(typed(-1.5),)),
        Param("On/Off", "Required", "bool", values=(T,), description="switch"),
        Param("x", "Required", "int", values=(typed(1),), description="lower"),
        ROBOT,
    )


def test_s3_every_option_expands_as_documented(tmp_path: Path) -> None:
    (model,) = models(tmp_path, """
        class Opts(SkillDescription):
            def createDescription(self):
                self.addParam("X", Element("skiros:Product"), ParamTypes.Required,
                              [ParamOptions.Consume, ParamOptions.Unspecify, ParamOptions.Lock,
                               ParamOptions.RespectType, ParamOptions.Output])
        """).values()
    pre_lock, hold_lock, post_lock = lock("X")
    assert model.params[0].options == ("Consume", "Unspecify", "Lock", "RespectType", "Output")
    assert model.pre == (pre_lock, Condition("on_type", "XOfType", "skiros:Product", "X"))
    assert model.hold == (hold_lock,)
    assert model.post == (
        Condition("generate", "ConsumeX", subject="X", desired_state=F),
        Condition("is_specified", "UnsetX", subject="X", desired_state=F),
        post_lock,
    )


def test_s3_quirk_description_passed_fourth_is_dropped(tmp_path: Path) -> None:
    (model,) = models(tmp_path, """
        class Quirk(SkillDescription):
            def createDescription(self):
                self.addParam("Speed", float, ParamTypes.Required, "speed in m/s")
                self.addParam("Arm", Element("scalable:Ur5"), ParamTypes.Required, "Lock")
                self.addParam("Kw", 0.5, ParamTypes.Optional, description="kept")
                self.addParam("Fifth", 0.5, ParamTypes.Optional, [], "kept too")
        """).values()
    assert model.params[:4] == (
        Param("Speed", "Required", "float", description=""),
        Param("Arm", "Required", "Element", "scalable:Ur5", options=()),
        Param("Kw", "Optional", "float", values=(typed(0.5),), description="kept"),
        Param("Fifth", "Optional", "float", values=(typed(0.5),), description="kept too"),
    )
    assert model.pre == model.hold == model.post == ()  # the string "Lock" matched nothing


def test_s4_factories(tmp_path: Path) -> None:
    (model,) = models(tmp_path, """
        class Factories(SkillDescription):
            def createDescription(self):
                self.addParam("A", Element("skiros:Location"), ParamTypes.Required)
                self.addParam("B", Element("skiros:Product"), ParamTypes.Required)
                self.addPreCondition(self.getRelationCond("AContainB", "skiros:contain",
                                                          "A", "B", True))
                self.addPreCondition(self.getAbstractRelationCond("Abs", "skiros:hasA",
                                                                  "A", "B", False))
                self.addPreCondition(self.getPropCond("Open", "skiros:Open", "A", ">=", 2,
                                                      True))
                self.addHoldCondition(self.getHasPropCond("BHasPosition", "skiros:Position",
                                                          "B", False))
                self.addHoldCondition(self.getIsSpecifiedCond("BSpecified", "B", True))
                self.addPostCondition(self.getGenerateCond("Gen", "B", True))
                self.addPostCondition(self.getOnTypeCond("BOfType", "B", ":Product"))
        """).values()
    assert model.pre == (
        rel("AContainB", "A", "B"),
        Condition("abstract_relation", "Abs", "skiros:hasA", "A", "B", desired_state=F),
        Condition("property", "Open", "skiros:Open", "A", operator=">=", value=typed(2),
                  desired_state=T),
    )
    assert model.hold == (
        Condition("has_property", "BHasPosition", "skiros:Position", "B", desired_state=F),
        Condition("is_specified", "BSpecified", subject="B", desired_state=T),
    )
    assert model.post == (
        Condition("generate", "Gen", subject="B", desired_state=T),
        Condition("on_type", "BOfType", ":Product", "B"),
    )


def test_s4_condition_classes_built_directly_equal_factories(tmp_path: Path) -> None:
    got = models(tmp_path, """
        from skiros2_common.core.conditions import (ConditionRelation, ConditionProperty,
            ConditionHasProperty, ConditionOr)

        class Direct(SkillDescription):
            def createDescription(self):
                self.addPreCondition(ConditionRelation("R", "skiros:at", "Robot", "L", True))
                self.addPreCondition(ConditionProperty("P", "skiros:Open", "L", "=", False, True))
                self.addPreCondition(ConditionHasProperty("H", "skiros:Size", "L", True))
                either = ConditionOr()
                either.addCondition(ConditionRelation("R", "skiros:at", "Robot", "L", False))
                self.addPreCondition(either)

        class ViaFactories(SkillDescription):
            def createDescription(self):
                self.addPreCondition(self.getRelationCond("R", "skiros:at", "Robot", "L", True))
                self.addPreCondition(self.getPropCond("P", "skiros:Open", "L", "=", False, True))
                self.addPreCondition(self.getHasPropCond("H", "skiros:Size", "L", True))
                either = self.getOrCond()
                either.addCondition(self.getRelationCond("R", "skiros:at", "Robot", "L", False))
                self.addPreCondition(either)
        """)
    assert got["Direct"].pre == got["ViaFactories"].pre
    assert got["Direct"].pre[0] == rel("R", "Robot", "L", relation="skiros:at")
    assert got["Direct"].pre[3].kind == "or" and len(got["Direct"].pre) == 4


# -- §8 --------------------------------------------------------------------------------------

def test_s8_1_robot_is_appended_last_unless_declared(tmp_path: Path) -> None:
    got = models(tmp_path, """
        class Auto(SkillDescription):
            def createDescription(self):
                self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)
                self.addPreCondition(self.getRelationCond("RobotAtObject", "skiros:at",
                                                          "Robot", "Object", True))

        class Explicit(SkillDescription):
            def createDescription(self):
                self.addParam("Robot", Element("sumo:Agent"), ParamTypes.Inferred)
                self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)
                self.addPreCondition(self.getRelationCond("RobotAtObject", "skiros:at",
                                                          "Robot", "Object", True))

        class OtherRobot(SkillDescription):
            def createDescription(self):
                self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)
                self.addParam("Robot", Element("cora:Robot"), ParamTypes.Required, [], "mine")
        """)
    assert keys(got["Auto"]) == ["Object", "Robot"]
    assert got["Auto"].params[-1] == ROBOT  # Inferred, sumo:Agent, description ""
    assert keys(got["Explicit"]) == ["Robot", "Object"]
    assert got["Explicit"].params[0] == ROBOT
    assert got["Auto"].pre == got["Explicit"].pre
    assert got["Auto"].params != got["Explicit"].params  # the order differs
    assert got["OtherRobot"].params[1:] == (Param("Robot", "Required", "Element", "cora:Robot",
                                                  description="mine"),)


def test_s8_2_options_expand_only_for_element_instances(tmp_path: Path) -> None:
    (model,) = models(tmp_path, """
        class NoExpansion(SkillDescription):
            def createDescription(self):
                self.addParam("Lit", 0.5, ParamTypes.Required, [ParamOptions.Lock])
                self.addParam("Typ", str, ParamTypes.Required, [ParamOptions.Consume])
                self.addParam("Cls", Element, ParamTypes.Required, [ParamOptions.Lock,
                              ParamOptions.RespectType, ParamOptions.Unspecify])
                self.addParam("Lst", [Element("skiros:Product")], ParamTypes.Required,
                              [ParamOptions.Lock])
        """).values()
    assert model.pre == model.hold == model.post == ()
    assert all(p.options == () for p in model.params)
    assert model.params[2] == Param("Cls", "Required", "Element", None)


def test_s8_2_expansions_interleave_with_explicit_conditions(tmp_path: Path) -> None:
    (model,) = models(tmp_path, """
        class Interleave(SkillDescription):
            def createDescription(self):
                self.addPreCondition(self.getRelationCond("First", "skiros:at", "Robot", "L",
                                                          True))
                self.addPostCondition(self.getRelationCond("PostFirst", "skiros:at", "Robot",
                                                           "L", False))
                self.addParam("Arm", Element("rparts:ArmDevice"), ParamTypes.Required,
                              [ParamOptions.Lock])
                self.addPreCondition(self.getRelationCond("Second", "skiros:at", "Robot", "L",
                                                          False))
                self.addParam("L", Element("skiros:Location"), ParamTypes.Inferred)
        """).values()
    pre_lock, hold_lock, post_lock = lock("Arm")
    assert model.pre == (rel("First", "Robot", "L", relation="skiros:at"), pre_lock,
                         rel("Second", "Robot", "L", False, relation="skiros:at"))
    assert model.hold == (hold_lock,)
    assert model.post == (rel("PostFirst", "Robot", "L", False, relation="skiros:at"),
                          post_lock)
    assert keys(model) == ["Arm", "L", "Robot"]


def test_s8_3_redeclared_key_keeps_first_position_and_first_conditions(tmp_path: Path) -> None:
    (model,) = models(tmp_path, """
        class Twice(SkillDescription):
            def createDescription(self):
                self.addParam("A", Element("skiros:Product"), ParamTypes.Required,
                              [ParamOptions.Lock])
                self.addParam("B", float, ParamTypes.Required)
                self.addParam("A", 1.0, ParamTypes.Optional, [ParamOptions.Consume])
                self.addParam("B", Element("skiros:Location"), ParamTypes.Required,
                              [ParamOptions.Consume])
        """).values()
    pre_lock, hold_lock, post_lock = lock("A")
    assert model.params == (
        Param("A", "Optional", "float", values=(typed(1.0),)),
        Param("B", "Required", "Element", "skiros:Location", options=("Consume",)),
        ROBOT,
    )
    assert model.pre == (pre_lock,) and model.hold == (hold_lock,)
    assert model.post == (post_lock,
                          Condition("generate", "ConsumeB", subject="B", desired_state=F))


def test_s8_4_list_defaults_are_multi_valued_of_first_type(tmp_path: Path) -> None:
    (model,) = models(tmp_path, """
        class Lists(SkillDescription):
            def createDescription(self):
                self.addParam("Range", [2.0, 8.0], ParamTypes.Required)
                self.addParam("Names", ["a", "b", "c"], ParamTypes.Optional)
                self.addParam("One", [True], ParamTypes.Optional)
                self.addParam("Zero", 0, ParamTypes.Optional)
                self.addParam("ZeroF", 0.0, ParamTypes.Optional)
        """).values()
    assert model.params[:5] == (
        Param("Range", "Required", "float", values=(typed(2.0), typed(8.0))),
        Param("Names", "Optional", "str", values=(typed("a"), typed("b"), typed("c"))),
        Param("One", "Optional", "bool", values=(T,)),
        Param("Zero", "Optional", "int", values=(typed(0),)),
        Param("ZeroF", "Optional", "float", values=(typed(0.0),)),
    )


def test_s8_4_empty_and_mixed_lists_raise(tmp_path: Path) -> None:
    result = load(tmp_path, """
        class EmptyList(SkillDescription):
            def createDescription(self):
                self.addParam("L", [], ParamTypes.Required)

        class Mixed(SkillDescription):
            def createDescription(self):
                self.addParam("L", [1, 2.0], ParamTypes.Required)

        class BoolInt(SkillDescription):
            def createDescription(self):
                self.addParam("L", [True, 1], ParamTypes.Required)

        class Fine(SkillDescription):
            def createDescription(self):
                self.addParam("L", [1, 2], ParamTypes.Required)

        class IntBool(SkillDescription):  # type-exact: bool is not int here (§8.12)
            def createDescription(self):
                self.addParam("L", [1, True], ParamTypes.Required)
        """)
    assert [m.name for m in result.models] == ["Fine"]
    errors = {e.skill: e for e in result.errors}
    assert errors.keys() == {"EmptyList", "Mixed", "BoolInt", "IntBool"}
    assert "empty list" in errors["EmptyList"].message
    assert "ParamValueError" in errors["Mixed"].message
    assert "mixes int and float" in errors["Mixed"].message
    assert "mixes bool and int" in errors["BoolInt"].message
    assert "mixes int and bool" in errors["IntBool"].message
    assert errors["Mixed"].kind == "description" and errors["Mixed"].line == 9
    assert errors["Mixed"].message.endswith("(line 11)")  # the addParam call


def test_s8_5_param_type_as_int(tmp_path: Path) -> None:
    got = models(tmp_path, """
        class Ints(SkillDescription):
            def createDescription(self):
                self.addParam("A", Element("skiros:Product"), 0)
                self.addParam("B", 0.5, 1)
                self.addParam("C", Element("skiros:Location"), 2)

        class Members(SkillDescription):
            def createDescription(self):
                self.addParam("A", Element("skiros:Product"), ParamTypes.Required)
                self.addParam("B", 0.5, ParamTypes.Optional)
                self.addParam("C", Element("skiros:Location"), ParamTypes.Inferred)
        """)
    assert [p.kind for p in got["Ints"].params] == ["Required", "Optional", "Inferred",
                                                    "Inferred"]
    assert got["Ints"].params == got["Members"].params


def test_s8_5_other_param_types_are_not_upstream(tmp_path: Path) -> None:
    result = load(tmp_path, """
        class Fork(SkillDescription):
            def createDescription(self):
                self.addParam("A", Element("skiros:Product"), ParamTypes.SharedInput)

        class Word(SkillDescription):
            def createDescription(self):
                self.addParam("A", 0.5, "Optional")

        class Three(SkillDescription):
            def createDescription(self):
                self.addParam("A", 0.5, 3)

        class Remap(SkillDescription):
            def createDescription(self):
                self.addParam("A", 0.5, ParamTypes.Optional, remap={"A": "B"})

        class TupleKey(SkillDescription):
            def createDescription(self):
                self.addParam(("A", "B"), 0.5, ParamTypes.Optional)
        """)
    assert result.models == []
    errors = {e.skill: e for e in result.errors}
    assert {e.kind for e in result.errors} == {"not-upstream-api"}
    assert "ParamTypes.SharedInput is not upstream SkiROS2 API" in errors["Fork"].message
    assert "Required, Optional, Inferred" in errors["Fork"].message
    assert "'Optional'" in errors["Word"].message and "3 (int)" in errors["Three"].message
    assert "remap" in errors["Remap"].message
    assert "tuple" in errors["TupleKey"].message


def test_s8_6_element_type_strings_are_verbatim(tmp_path: Path) -> None:
    got = models(tmp_path, """
        class Colon(SkillDescription):
            def createDescription(self):
                self.addParam("L", Element(":Location"), ParamTypes.Required)

        class Bare(SkillDescription):
            def createDescription(self):
                self.addParam("L", Element("Location"), ParamTypes.Required)

        class Prefixed(SkillDescription):
            def createDescription(self):
                self.addParam("L", Element("skiros:Location"), ParamTypes.Required)

        class Typo(SkillDescription):
            def createDescription(self):
                self.addParam("L", Element("skiros;:Location"), ParamTypes.Required)

        class NoType(SkillDescription):
            def createDescription(self):
                self.addParam("L", Element(), ParamTypes.Required, [ParamOptions.RespectType])
        """)
    types = {name: m.params[0].element_type for name, m in got.items()}
    assert types == {"Colon": ":Location", "Bare": "Location", "Prefixed": "skiros:Location",
                     "Typo": "skiros;:Location", "NoType": "Unknown"}
    assert got["NoType"].pre == (Condition("on_type", "LOfType", "Unknown", "L"),)
    params = [m.params for m in got.values()]
    assert all(a != b for i, a in enumerate(params) for b in params[i + 1:])


def test_s8_7_factories_only_construct_or_is_labelled_or_operator_free(tmp_path: Path) -> None:
    (model,) = models(tmp_path, """
        class Seven(SkillDescription):
            def createDescription(self):
                c = self.getRelationCond("Twice", "skiros:contain", "A", "B", True)
                self.addPreCondition(c)
                self.addPreCondition(c)
                unused = self.getRelationCond("Unused", "skiros:contain", "A", "B", True)
                either = self.getOrCond(False)
                either.addCondition(self.getRelationCond("X", "skiros:contain", "A", "B", True))
                inner = self.getOrCond()
                inner.addCondition(self.getPropCond("P", "skiros:Open", "A", "~=", "1", True))
                either.addCondition(inner)
                self.addHoldCondition(either)
                self.addPostCondition(self.getPropCond("Q", "skiros:Size", "A", "!!", 2.5, 0))
        """).values()
    twice = rel("Twice", "A", "B")
    assert model.pre == (twice, twice)
    assert model.hold == (Condition("or", "or", desired_state=F, children=(
        rel("X", "A", "B"),
        Condition("or", "or", desired_state=T, children=(
            Condition("property", "P", "skiros:Open", "A", operator="~=", value=typed("1"),
                      desired_state=T),)),
    )),)
    assert model.post == (Condition("property", "Q", "skiros:Size", "A", operator="!!",
                                    value=typed(2.5), desired_state=typed(0)),)


def test_s8_8_no_automatic_has_post_conditions(tmp_path: Path) -> None:
    (model,) = models(tmp_path, """
        class Plain(SkillDescription):
            def createDescription(self):
                self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)
                self.addParam("Location", Element("skiros:Location"), ParamTypes.Inferred)
        """).values()
    assert model.pre == model.hold == model.post == ()
    result = load(tmp_path, """
        class CallsIt(SkillDescription):
            def createDescription(self):
                self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)
                self.generateDefConditions()
        """, name="explicit.py")
    assert result.models == [] and "generateDefConditions" in result.errors[0].message


def test_s8_9_inherited_descriptions_and_bases_from_elsewhere(tmp_path: Path) -> None:
    (tmp_path / "shared_base.py").write_text(HEADER + textwrap.dedent("""
        class SharedBase(SkillDescription):
            def createDescription(self):
                self.addParam("Shared", Element("skiros:Product"), ParamTypes.Required)
        """))
    got = models(tmp_path, """
        from shared_base import SharedBase

        class Parent(SkillDescription):
            def createDescription(self):
                self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)

        class Child(Parent):
            def createDescription(self):
                super().createDescription()
                self.addParam("Extra", 1.0, ParamTypes.Optional)

        class FromShared(SharedBase):
            pass
        """)
    assert set(got) == {"Parent", "Child", "FromShared"}  # SharedBase is not defined here
    assert got["Child"].type == "skiros:Child"
    assert keys(got["Child"]) == ["Object", "Extra", "Robot"]
    assert keys(got["FromShared"]) == ["Shared", "Robot"]
    assert got["FromShared"].type == "skiros:FromShared"
    assert "shared_base" not in sys.modules


def test_s8_10_set_available_for_planning_keeps_file_loadable(tmp_path: Path) -> None:
    got = models(tmp_path, """
        class Hidden(SkillDescription):
            def createDescription(self):
                self.setAvailableForPlanning(False)
                self.addParam("X", 0.5, ParamTypes.Optional)

        class Shown(SkillDescription):
            def createDescription(self):
                self.addParam("X", 0.5, ParamTypes.Optional)
        """)
    assert got["Hidden"].params == got["Shown"].params
    assert got["Hidden"].pre == got["Shown"].pre == ()


def test_s8_11_stand_in_skiros2_common_works_without_rospy_and_is_removed_afterwards() -> None:
    """Our stand-in ``skiros2_common`` (SkiROS2's own needs rospy, §8.11) exists only inside
    ``legacy_imports``. Detecting the backend by importing skiros2_common is tested in
    tests/runtime/dsl/test_dsl_backend.py."""
    assert importlib.util.find_spec("skiros2_common") is None
    with pytest.raises(ImportError):
        import skiros2_common  # noqa: F401
    with legacy_imports(permissive=False):
        from skiros2_common.core.world_element import Element

        assert Element("skiros:X").type == "skiros:X"
        assert "rospy" not in sys.modules  # SkiROS2's world_element needs rospy; ours not
        with pytest.raises(ImportError):
            import rospy  # noqa: F401
    assert "skiros2_common" not in sys.modules


def test_s8_12_values_are_compared_type_exactly(tmp_path: Path) -> None:
    got = models(tmp_path, """
        def make(name, value):
            class D(SkillDescription):
                def createDescription(self):
                    self.addParam("V", value, ParamTypes.Optional)
                    self.addPreCondition(self.getPropCond("P", "skiros:Open", "X", "=", value,
                                                          True))
            D.__name__ = D.__qualname__ = name
            D.__module__ = __name__
            return D

        IsTrue = make("IsTrue", True)
        IsOne = make("IsOne", 1)
        IsOneF = make("IsOneF", 1.0)
        IsText = make("IsText", "True")
        """)
    assert [m.params[0].values for m in got.values()] == [
        (T,), (typed(1),), (typed(1.0),), (typed("True"),)]
    normalized = [m.with_location(None, None) for m in got.values()]
    for i, a in enumerate(normalized):
        for b in normalized[i + 1:]:
            assert a.params != b.params and a.pre != b.pre
            assert compare(a, b) != []
