"""The legacy API objects on their own: params, Element, conditions, SkillDescription, extract."""

from __future__ import annotations

import pytest

from ezskiros_runtime.legacy import (
    AbstractConditionRelation,
    ConditionFunction,
    ConditionGenerate,
    ConditionIsSpecified,
    ConditionOnType,
    ConditionOr,
    ConditionProperty,
    ConditionRelation,
    Element,
    NotDeclarativeError,
    NotUpstreamAPIError,
    ParamHandler,
    ParamOptions,
    ParamTypes,
    ParamValueError,
    SkillDescription,
    UnsupportedConstructError,
    model_of,
)
from ezskiros_runtime.legacy.params import Param, classify_value, param_type_of
from ezskiros_runtime.model import Condition, typed


def test_param_types_members_ints_and_errors() -> None:
    assert [m.name for m in ParamTypes] == ["Required", "Optional", "Inferred"]
    assert [param_type_of(i) for i in (0, 1, 2)] == list(ParamTypes)
    assert param_type_of(ParamTypes.Inferred) is ParamTypes.Inferred
    for bad in (True, 3, -1, "Required", None, 1.0):
        with pytest.raises(NotUpstreamAPIError, match="not upstream SkiROS2 API"):
            param_type_of(bad)
    with pytest.raises(AttributeError, match="SharedInput is not upstream"):
        _ = ParamTypes.SharedInput
    assert not hasattr(ParamTypes, "LinkedOutput")
    with pytest.raises(AttributeError, match="LinkedOutput is not upstream"):
        _ = ParamOptions.LinkedOutput


def test_classify_value() -> None:
    robot = Element("sumo:Agent")
    assert classify_value(robot) == (Element, [robot])
    assert classify_value(Element) == (Element, [])
    assert classify_value(float) == (float, [])
    assert classify_value(True) == (bool, [True])  # bool before int
    assert classify_value(0) == (int, [0])
    assert classify_value([2.0, 8.0]) == (float, [2.0, 8.0])
    assert classify_value({}) == (dict, [{}])
    with pytest.raises(ParamValueError, match="empty list"):
        classify_value([])
    with pytest.raises(ParamValueError, match="mixes float and int"):
        classify_value([1.0, 2])
    with pytest.raises(ValueError):  # also a ValueError, as user code may expect
        classify_value(["a", 1])


def test_param_handler_keeps_first_position_on_redeclaration() -> None:
    handler = ParamHandler()
    handler.addParam("A", 1, ParamTypes.Required)
    handler.addParam("B", 2.0, ParamTypes.Optional, "b")
    handler.addParam("A", "x", 1, "again")
    assert list(handler) == ["A", "B"] and len(handler) == 2
    assert handler["A"].value == "x" and handler["A"].dataType is str
    assert handler["A"].paramType is ParamTypes.Optional
    assert handler["A"].description == "again"
    assert handler.hasParam("B") and not handler.hasParam("C")
    assert handler.getParam("B").values == [2.0]
    assert list(handler.getParamMap()) == ["A", "B"]
    with pytest.raises(NotUpstreamAPIError, match="tuple keys"):
        handler.addParam(("A", "B"), 1, 0)
    assert Param("K", "", float, 0).value is None
    assert repr(handler["A"]) == "Param('A', str, Optional, values=['x'])"


def test_element_stores_type_verbatim() -> None:
    assert Element().type == "Unknown"
    assert [Element(t).type for t in (":Location", "Location", "skiros:Location")] == [
        ":Location", "Location", "skiros:Location"]
    labelled = Element("skiros:Location", "kitchen", "skiros:Location-3")
    assert (labelled.label, labelled.id) == ("kitchen", "skiros:Location-3")
    assert repr(Element("skiros:X")) == "Element('skiros:X')"
    assert repr(labelled) == "Element('skiros:Location', 'kitchen', 'skiros:Location-3')"
    assert Element("a").is_plain() and not labelled.is_plain()


def test_condition_classes_to_model() -> None:
    assert ConditionRelation("L", "skiros:contain", "A", "B", False).to_model() == Condition(
        "relation", "L", "skiros:contain", "A", "B", desired_state=typed(False))
    assert AbstractConditionRelation("L", "skiros:hasA", "A", "B", 1).to_model() == Condition(
        "abstract_relation", "L", "skiros:hasA", "A", "B", desired_state=typed(1))
    assert ConditionProperty("P", "skiros:Open", "F", "<>", 1.0, True).to_model() == Condition(
        "property", "P", "skiros:Open", "F", operator="<>", value=typed(1.0),
        desired_state=typed(True))
    assert ConditionIsSpecified("S", "X", True).to_model().kind == "is_specified"
    assert ConditionGenerate("G", "X", False).to_model() == Condition(
        "generate", "G", subject="X", desired_state=typed(False))
    assert not isinstance(ConditionGenerate("G", "X", False), ConditionIsSpecified)
    assert ConditionOnType("T", "X", "skiros:Product").to_model() == Condition(
        "on_type", "T", "skiros:Product", "X")


def test_condition_or_and_function() -> None:
    either = ConditionOr()
    assert either.label == "or" and either.desired_state is True
    first = ConditionRelation("a", "skiros:at", "R", "L", True)
    either.addCondition(first)
    either.addCondition(first)
    assert [c.label for c in either.to_model().children] == ["a", "a"]

    def gripper_free(_: object) -> bool:
        return True

    function = ConditionFunction("Free", gripper_free, "Gripper", True)
    assert function.label == "Free" and function.args == ("Gripper", True)
    with pytest.raises(NotDeclarativeError, match=r"ConditionFunction.*gripper_free"):
        function.to_model()
    either.addCondition(ConditionFunction("Lambda", lambda s: True))
    with pytest.raises(NotDeclarativeError, match="Lambda"):
        either.to_model()


class Described(SkillDescription):
    def createDescription(self) -> None:
        self.setAvailableForPlanning(False)
        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required,
                      [ParamOptions.Consume])
        self.addParam("Where", Element("skiros:Location", "kitchen"), ParamTypes.Optional)
        self.addParam("Many", [Element("a:B"), Element("a:C")], ParamTypes.Optional)
        self.addPreCondition(self.getRelationCond("WhereContainObject", "skiros:contain",
                                                  "Where", "Object", True))


def test_skill_description_accessors_and_model() -> None:
    skill = Described()
    assert skill._type == skill.type == "skiros:Described"
    assert list(skill.params) == ["Object", "Where", "Many", "Robot"]
    assert skill.params["Object"].options == ("Consume",)
    assert skill._available_for_planning is False
    assert [c.label for c in skill._pre_conditions] == ["WhereContainObject"]
    assert [c.label for c in skill._post_conditions] == ["ConsumeObject"]
    assert skill._hold_conditions == []
    model = model_of(skill)
    assert model.name == "Described" and model.type == "skiros:Described"
    assert model.params[0].values == ()  # a plain element needs no value
    # a labelled element, or several, keep their values so that a difference is not lost
    assert model.params[1].element_type == "skiros:Location"
    assert model.params[1].values == (("opaque:Element", "Element('skiros:Location', "
                                                         "'kitchen', '')"),)
    assert [v[1] for v in model.params[2].values] == ["Element('a:B')", "Element('a:C')"]


def test_base_description_and_unsupported_calls() -> None:
    base = SkillDescription()
    assert base._type == "skiros:SkillDescription" and list(base.params) == ["Robot"]
    with pytest.raises(UnsupportedConstructError, match="generateDefConditions"):
        base.generateDefConditions()
    base.addPreCondition("not a condition")
    with pytest.raises(NotDeclarativeError, match="pre-condition #1 is not a SkiROS2"):
        model_of(base)
