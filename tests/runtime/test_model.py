"""The normalized model (model.py) and what consumes it: labels, notation, compare."""

from __future__ import annotations

import json
import math

import pytest

from ezskiros_runtime.compare import compare, equivalent
from ezskiros_runtime.labels import OR_LABEL, capitalised, conventional_label, local_name
from ezskiros_runtime.model import (
    Condition,
    Param,
    SkillModel,
    models_by_name,
    typed,
    untyped,
)
from ezskiros_runtime.notation import literal, render_condition, render_param


def rel(label: str, subject: str = "A", obj: str = "B", desired: object = True,
        relation: str = "skiros:contain") -> Condition:
    return Condition("relation", label, relation, subject, obj, desired_state=typed(desired))


def element(key: str, cls: str = "skiros:Location", kind: str = "Required",
            options: tuple[str, ...] = ()) -> Param:
    return Param(key, kind, "Element", cls, options=options)


ROBOT = element("Robot", "sumo:Agent", "Inferred")


def pick(**changes: object) -> SkillModel:
    base: dict[str, object] = {
        "name": "Pick",
        "type": "skiros:Pick",
        "params": (element("Object", "skiros:Product"), element("Gripper", "rparts:Gripper"),
                   Param("Speed", "Optional", "float", values=(typed(0.5),)), ROBOT),
        "pre": (rel("GripperContainObject", "Gripper", "Object", False),
                Condition("property", "GripperOpen", "skiros:Open", "Gripper", operator="=",
                          value=typed(True), desired_state=typed(True))),
        "post": (rel("GripperContainObject", "Gripper", "Object"),),
    }
    base.update(changes)
    return SkillModel(**base)  # type: ignore[arg-type]


# -- typed() -------------------------------------------------------------------------------

def test_typed_is_type_exact_where_python_equality_is_not() -> None:
    values = [True, 1, 1.0, "True", "1"]
    assert True == 1 == 1.0  # the trap typed() exists for
    typed_values = [typed(v) for v in values]
    assert len(set(typed_values)) == len(values)
    assert typed(True) == ("bool", True)
    assert typed(0) == ("int", 0)
    assert typed(0.0) == ("float", 0.0)
    assert typed(None) == ("none", None)


def test_typed_nests_and_distinguishes_list_from_tuple() -> None:
    assert typed([2.0, 8]) == ("list", (("float", 2.0), ("int", 8)))
    assert typed((1,)) == ("tuple", (("int", 1),))
    assert typed([1]) != typed((1,))
    assert typed({"b": 1, "a": [True]}) == typed({"a": [True], "b": 1})  # order-free dicts
    assert typed({"a": 1}) != typed({"a": 1.0})


def test_typed_keeps_non_finite_floats_and_opaque_values_serializable() -> None:
    assert typed(float("nan")) == typed(float("nan"))  # nan != nan in Python
    assert typed(float("inf")) == ("float", "inf")
    assert math.isinf(untyped(typed(float("-inf"))))

    class Thing:
        def __repr__(self) -> str:
            return "Thing()"

    assert typed(Thing()) == ("opaque:Thing", "Thing()")
    assert repr(untyped(typed(Thing()))) == "Thing()"


def test_untyped_inverts_typed() -> None:
    for value in [0, 0.5, "x", True, None, [1.0, 2.0], (1, "a"), {"k": [1, 2]}, {1: (2,)}]:
        back = untyped(typed(value))
        assert back == value and type(back) is type(value)


# -- JSON ----------------------------------------------------------------------------------

def test_json_round_trip_keeps_every_detail() -> None:
    model = pick(
        params=(element("X", ":Location", options=("Lock", "Consume")),
                Param("L", "Required", "float", values=(typed(2.0), typed(8.0)),
                      description="two"),
                Param("D", "Optional", "dict", values=(typed({"a": [1, (2, 3)], 1: None}),)),
                Param("N", "Optional", "float", values=(typed(float("nan")),)),
                Param("T", "Required", "float"), Param("E", "Required", "Element"), ROBOT),
        hold=(Condition("or", OR_LABEL, desired_state=typed(False),
                        children=(rel("x"), Condition("on_type", "XOfType", "skiros:Product",
                                                      "X"))),),
    ).with_location("/src/skills.py", 12)
    text = json.dumps(model.to_json())
    back = SkillModel.from_json(json.loads(text))
    assert back == model
    assert (back.source, back.line) == ("/src/skills.py", 12)
    assert back.canonical_json() == model.canonical_json()


def test_canonical_json_is_equality_and_ignores_location() -> None:
    a = pick().with_location("a.py", 1)
    b = pick().with_location("b.py", 99)
    assert a == b and a.canonical_json() == b.canonical_json()
    assert "a.py" not in a.canonical_json()
    c = pick(post=(rel("GripperContainObject", "Gripper", "Object", 1),))  # 1, not True
    assert c != a and c.canonical_json() != a.canonical_json()


def test_model_accessors() -> None:
    model = pick()
    assert model.param("Speed") == Param("Speed", "Optional", "float", values=(typed(0.5),))
    assert model.param("Nope") is None
    assert model.conditions("post") == model.post
    with pytest.raises(ValueError, match="unknown condition list"):
        model.conditions("during")
    assert models_by_name([model, pick(name="Place")]).keys() == {"Pick", "Place"}


# -- labels --------------------------------------------------------------------------------

def test_conventional_labels() -> None:
    assert local_name("skiros:contain") == "contain" and local_name("contain") == "contain"
    assert capitalised("robotPart") == "RobotPart"
    assert conventional_label("relation", subject="Gripper", vocabulary="skiros:contain",
                              object="Object", desired_state=False) == "NotGripperContainObject"
    assert conventional_label("property", subject="F", vocabulary="skiros:Open") == "FOpen"
    assert conventional_label("has_property", subject="O",
                              vocabulary="skiros:Position") == "OHasPosition"
    assert conventional_label("is_specified", subject="O", desired_state=False) == "NotOSpecified"
    assert conventional_label("generate", subject="O") == "OGenerated"
    assert conventional_label("on_type", subject="O", desired_state=False) == "OOfType"
    assert conventional_label("or") == "or"
    # only False itself negates: a non-bool desired state keeps the plain label
    assert conventional_label("generate", subject="O", desired_state=0) == "OGenerated"
    with pytest.raises(ValueError):
        conventional_label("magic")


# -- notation ------------------------------------------------------------------------------

def test_notation_renders_legacy_calls() -> None:
    assert render_param(element("Gripper", "rparts:Gripper", options=("Lock",))) == (
        "addParam('Gripper', Element('rparts:Gripper'), ParamTypes.Required, "
        "[ParamOptions.Lock])")
    assert render_param(Param("S", "Optional", "float", values=(typed(0.5),),
                              description="m/s")) == (
        "addParam('S', 0.5, ParamTypes.Optional, [], 'm/s')")
    assert render_param(Param("S", "Required", "float")) == (
        "addParam('S', float, ParamTypes.Required)")
    assert render_param(Param("L", "Required", "float", values=(typed(2.0), typed(8.0)))) == (
        "addParam('L', [2.0, 8.0], ParamTypes.Required)")
    assert render_param(Param("E", "Required", "Element")) == (
        "addParam('E', Element, ParamTypes.Required)")
    assert render_condition(rel("GripperContainObject", "Gripper", "Object", False)) == (
        "getRelationCond('GripperContainObject', 'skiros:contain', 'Gripper', 'Object', False)")
    prop = Condition("property", "FOpen", "skiros:Open", "F", operator="=", value=typed(1),
                     desired_state=typed(True))
    assert render_condition(prop) == "getPropCond('FOpen', 'skiros:Open', 'F', '=', 1, True)"
    assert render_condition(Condition("on_type", "OOfType", ":Product", "O")) == (
        "getOnTypeCond('OOfType', 'O', ':Product')")
    disjunction = Condition("or", "or", desired_state=typed(False),
                            children=(rel("a"), rel("b")))
    assert render_condition(disjunction) == (
        "getOrCond(False) <- [getRelationCond('a', 'skiros:contain', 'A', 'B', True), "
        "getRelationCond('b', 'skiros:contain', 'A', 'B', True)]")
    assert literal(typed("x")) == "'x'" and literal(None) == "None"


# -- compare -------------------------------------------------------------------------------

def test_compare_equal_models_and_names_do_not_matter() -> None:
    assert compare(pick(), pick()) == []
    assert equivalent(pick(), pick(name="Renamed"))


def test_compare_finds_param_difference() -> None:
    after = pick(params=(element("Object", "skiros:Product"), element("Gripper", ":Gripper"),
                         Param("Speed", "Optional", "float", values=(typed(0.5),)), ROBOT))
    diffs = compare(pick(), after)
    assert len(diffs) == 1
    assert diffs[0].where == "params" and diffs[0].message == "parameter #2 differs"
    assert diffs[0].before is not None and "'rparts:Gripper'" in diffs[0].before
    assert diffs[0].after is not None and "':Gripper'" in diffs[0].after


def test_compare_finds_missing_and_added_conditions() -> None:
    after = pick(post=(), hold=(rel("Extra"),))
    diffs = compare(pick(), after)
    assert [(d.where, d.message) for d in diffs] == [
        ("hold", "hold-condition #1 added by migration"),
        ("post", "post-condition #1 missing after migration"),
    ]


def test_compare_order_and_ignore_order() -> None:
    before = pick()
    after = pick(params=(before.params[1], before.params[0], *before.params[2:]),
                 pre=tuple(reversed(before.pre)))
    diffs = compare(before, after)
    assert {(d.where, d.message) for d in diffs} == {
        ("params", "same parameters in a different order"),
        ("pre", "same pre-conditions in a different order"),
    }
    assert compare(before, after, ignore_order=True) == []
    # ignore_order still sees a real difference
    changed = pick(pre=(before.pre[0],))
    assert [d.message for d in compare(before, changed, ignore_order=True)] == [
        "pre-condition missing after migration"]


def test_compare_labels_and_ignore_labels() -> None:
    before = pick()
    after = pick(post=(rel("Holding", "Gripper", "Object"),))
    diffs = compare(before, after)
    assert [(d.where, d.message) for d in diffs] == [("post", "post-condition #1 differs")]
    assert compare(before, after, ignore_labels=True) == []


def test_compare_reports_details_the_notation_does_not_show() -> None:
    before = pick(params=(Param("S", "Required", "float", values=(typed(1.0),)),))
    after = pick(params=(Param("S", "Required", "int", values=(typed(1.0),)),))
    diffs = compare(before, after)
    assert [(d.where, d.message) for d in diffs] == [("model", "models differ")]


def test_compare_flags_relax_only_order_and_labels() -> None:
    # Fixed bug: with ignore_order/ignore_labels the final exact check was skipped, so a
    # difference invisible in the notation (here the data type) passed as equivalent.
    before = pick(params=(Param("S", "Required", "float", values=(typed(1.0),)),))
    after = pick(params=(Param("S", "Required", "int", values=(typed(1.0),)),))
    assert not equivalent(before, after, ignore_order=True)
    assert not equivalent(before, after, ignore_labels=True)
    relabelled = pick(post=(rel("Holding", "Gripper", "Object"),),
                      pre=tuple(reversed(pick().pre)))
    assert equivalent(pick(), relabelled, ignore_order=True, ignore_labels=True)


def test_compare_type_difference_and_difference_text() -> None:
    diffs = compare(pick(), pick(type="skiros:Other"))
    assert diffs[0].where == "type" and diffs[0].to_json()["after"] == "skiros:Other"
    assert str(diffs[0]) == "type: skill type differs\n  - skiros:Pick\n  + skiros:Other"


def test_equal_models_have_equal_canonical_json_even_for_negative_zero() -> None:
    """``-0.0 == 0.0``: a model equal to another must also serialize to the same text."""
    negative = pick(params=(Param("Speed", "Optional", "float", values=(typed(-0.0),)),))
    positive = pick(params=(Param("Speed", "Optional", "float", values=(typed(0.0),)),))
    assert negative == positive
    assert negative.canonical_json() == positive.canonical_json()
    assert SkillModel.from_json(json.loads(json.dumps(negative.to_json()))) == positive
