"""Lowering: the order and exact arguments of the backend calls an EzSkiROS class makes.

``Recording`` wraps the legacy backend's public methods to log every call, in process, so
the tests can assert the sequence docs/dsl.md prescribes: all ``addParam`` in signature order
(options expanding at that moment), then the conditions in ``+=`` order, then SkiROS2's
automatic ``Robot``.
"""

from __future__ import annotations

from typing import Any

import pytest
from dsl_support import model, named, paper, quiet_model  # noqa: F401 - paper is a fixture

from ezskiros_runtime import (
    ELEMENT,
    INFERRED,
    KEY,
    LIST,
    OPTIONAL,
    REQUIRED,
    Consume,
    DescriptionError,
    EzSkirosWarning,
    Lock,
    Output,
    RespectType,
    SkillDescription,
    SkillTypeError,
    Unspecify,
    any_of,
)
from ezskiros_runtime.legacy.abstract_skill import ParamOptions
from ezskiros_runtime.legacy.abstract_skill import SkillDescription as LegacyDescription
from ezskiros_runtime.legacy.extract import model_of
from ezskiros_runtime.legacy.params import ParamTypes
from ezskiros_runtime.legacy.world_element import Element
from ezskiros_runtime.model import typed
from ezskiros_runtime.ontology import rparts, skiros

pytestmark = pytest.mark.usefixtures("paper")

SPEED_KEY = "Speed (m/s)"


class Recording(SkillDescription):
    """Logs the public backend calls (name and first argument) of its subclasses."""

    def __init__(self) -> None:
        self.log: list[tuple[str, Any]] = []
        super().__init__()

    def addParam(self, key, value, param_type, options=(), description=""):
        self.log.append(("addParam", key))
        super().addParam(key, value, param_type, options, description)

    def addPreCondition(self, condition):
        self.log.append(("pre", condition.label))
        super().addPreCondition(condition)

    def addHoldCondition(self, condition):
        self.log.append(("hold", condition.label))
        super().addHoldCondition(condition)

    def addPostCondition(self, condition):
        self.log.append(("post", condition.label))
        super().addPostCondition(condition)


class Ordered(Recording):
    def description(self, Gripper: REQUIRED[rparts.GripperEffector, Lock, RespectType],
                    Object: REQUIRED[skiros.Product, Consume, Unspecify, Output],
                    Place: skiros.Location):
        self.post_conditions += Gripper.contain(Object)
        self.pre_conditions += Place.contain(Object)
        self.hold_conditions += Place.contain(Object).named("Still")
        self.pre_conditions += ~ Gripper.contain(Object)


def test_params_first_with_options_expanding_then_conditions_in_plus_equals_order():
    built = Ordered()
    assert built.log == [
        ("addParam", "Gripper"),
        ("pre", "GripperIdle"), ("hold", "GripperBusy"), ("post", "GripperIdle"),
        ("pre", "GripperOfType"),
        ("addParam", "Object"),
        ("post", "ConsumeObject"), ("post", "UnsetObject"),
        ("addParam", "Place"),
        ("post", "GripperContainObject"),
        ("pre", "PlaceContainObject"),
        ("hold", "Still"),
        ("pre", "NotGripperContainObject"),
        ("addParam", "Robot"),  # generateDefParams, after createDescription
    ]
    built_model = model(Ordered)
    assert [p.options for p in built_model.params] == [("Lock", "RespectType"),
                                                       ("Consume", "Unspecify", "Output"),
                                                       (), ()]
    assert built_model.pre[1].vocabulary == "rparts:GripperEffector"  # RespectType's type


@named("Keys")
class EzKeys(SkillDescription):
    def description(self, Target: REQUIRED[skiros.Location, KEY("Target Location")],
                    First: REQUIRED[skiros.Product, KEY("X"), Lock],
                    Second: OPTIONAL[skiros.Product, KEY("X"), "the second"],  # noqa: F722
                    Speed: OPTIONAL[float, KEY(SPEED_KEY)] = 0.5):
        self.pre_conditions += Target.contain(First)
        self.pre_conditions += self.param("Speed (m/s)").is_specified()
        self.post_conditions += Target.contain(Second)


@named("Keys")
class LegacyKeys(LegacyDescription):
    def createDescription(self):
        self.addParam("Target Location", Element("skiros:Location"), ParamTypes.Required)
        self.addParam("X", Element("skiros:Product"), ParamTypes.Required, [ParamOptions.Lock])
        self.addParam("X", Element("skiros:Product"), ParamTypes.Optional, [], "the second")
        self.addParam("Speed (m/s)", 0.5, ParamTypes.Optional)
        self.addPreCondition(self.getRelationCond("Target LocationContainX", "skiros:contain",
                                                  "Target Location", "X", True))
        self.addPreCondition(self.getIsSpecifiedCond("Speed (m/s)Specified", "Speed (m/s)",
                                                     True))
        self.addPostCondition(self.getRelationCond("Target LocationContainX", "skiros:contain",
                                                   "Target Location", "X", True))


def test_key_escapes_and_a_duplicate_key_replace_in_place_like_skiros2():
    ez = model(EzKeys)
    assert ez == model(LegacyKeys)
    assert [p.key for p in ez.params] == ["Target Location", "X", "Speed (m/s)", "Robot"]
    duplicate = ez.param("X")
    assert (duplicate.kind, duplicate.description, duplicate.options) == ("Optional",
                                                                          "the second", ())
    assert [c.label for c in ez.pre] == ["XIdle", "Target LocationContainX",
                                         "Speed (m/s)Specified"]  # first X's Lock stays


@named("Robots")
class NoRobot(SkillDescription):
    def description(self, X: skiros.Product):
        self.pre_conditions += self.param("Robot").relation("skiros:spatiallyRelated", X)


@named("Robots")
class RobotFirst(SkillDescription):
    def description(self, Robot: INFERRED[rparts.GripperEffector], X: skiros.Product):
        self.pre_conditions += Robot.contain(X)


def test_the_automatic_robot_is_appended_last_unless_declared():
    automatic = model(NoRobot)
    assert [(p.key, p.kind, p.element_type) for p in automatic.params] == [
        ("X", "Required", "skiros:Product"), ("Robot", "Inferred", "sumo:Agent")]
    assert automatic.pre[0].subject == "Robot"
    declared = model(RobotFirst)
    assert [(p.key, p.element_type) for p in declared.params] == [
        ("Robot", "rparts:GripperEffector"), ("X", "skiros:Product")]


LABEL = "skiros:contain"


class Constants(SkillDescription):
    def description(self, Relation: REQUIRED = LABEL, Extra: OPTIONAL = {},  # noqa: B006
                    Thing: INFERRED = Element(":Product")):  # noqa: B008
        self.pre_conditions += self.param("Location").contain(Thing)


def test_bare_kind_markers_pass_constants_as_is():
    params = quiet_model(Constants).params
    assert [(p.key, p.kind, p.data_type, p.values) for p in params[:2]] == [
        ("Relation", "Required", "str", (typed("skiros:contain"),)),
        ("Extra", "Optional", "dict", (typed({}),)),
    ]
    assert (params[2].kind, params[2].data_type, params[2].element_type) == (
        "Inferred", "Element", ":Product")


class Lists(SkillDescription):
    def description(self, Sizes: LIST[float] = [2.0, 8.0], Names: list = ["a"]):  # noqa: B006
        pass


def test_list_defaults_are_multi_valued_and_never_shared_between_instances():
    first, second = Lists(), Lists()
    assert first.params["Sizes"].values == [2.0, 8.0]
    assert first.params["Sizes"].dataType is float
    assert first.params["Names"].values == ["a"]
    first.params["Sizes"].values.append(99.0)
    assert second.params["Sizes"].values == [2.0, 8.0]


class KeywordOnly(SkillDescription):
    def description(self, Speed: OPTIONAL[float] = 0.5, *, Object: skiros.Product,
                    Place: ELEMENT(":Location")):
        self.pre_conditions += Place.contain(Object)


class PositionalOnly(SkillDescription):
    def description(self, Place: skiros.Location, /, Object: skiros.Product):
        self.pre_conditions += Place.contain(Object)


def test_keyword_only_and_positional_only_parameters_keep_signature_order():
    assert [p.key for p in model(KeywordOnly).params] == ["Speed", "Object", "Place", "Robot"]
    assert model(KeywordOnly).pre[0].label == "PlaceContainObject"
    assert [p.key for p in model(PositionalOnly).params] == ["Place", "Object", "Robot"]


def test_string_annotations_are_evaluated_in_the_module_globals():
    assert isinstance(Ordered.description.__annotations__["Place"], str)
    assert model(Ordered).param("Place").element_type == "skiros:Location"


class Nothing(SkillDescription):
    pass


class LegacyStyle(SkillDescription):
    def createDescription(self):
        self.addParam("Speed", float, ParamTypes.Required)


class Child(Ordered):
    pass


def test_no_description_declares_nothing_and_legacy_overrides_and_inheritance_work():
    assert [(p.key, p.kind) for p in model(Nothing).params] == [("Robot", "Inferred")]
    assert Nothing().findings == []
    assert [p.key for p in model(LegacyStyle).params] == ["Speed", "Robot"]
    assert [p.key for p in model(Child).params] == ["Gripper", "Object", "Place", "Robot"]


class Statements(SkillDescription):
    def description(self, A: skiros.Location, B: skiros.Product, C: skiros.Product):
        self.setAvailableForPlanning(False)
        held = [A.contain(x) for x in (B, C)]
        for condition in held:
            self.pre_conditions += condition
        self.post_conditions += [~ held[0], ~ held[1]]


def test_other_statements_run_while_tracing_and_lists_of_conditions_are_accepted():
    built = Statements()
    assert built._available_for_planning is False
    assert [c.label for c in model(Statements).pre] == ["AContainB", "AContainC"]
    assert [c.label for c in model(Statements).post] == ["NotAContainB", "NotAContainC"]
    assert [c.final_label for c in built.post_conditions] == ["NotAContainB", "NotAContainC"]


def test_plus_equals_after_construction_lowers_at_once():
    built = Statements()
    built.hold_conditions += built.param("A").contain(built.param("B")).named("Late")
    assert [c.label for c in built._hold_conditions] == ["Late"]


def test_conditions_on_undeclared_keys_are_kept_and_reported():
    with pytest.warns(EzSkirosWarning, match="'Location', which the description does not "
                                             "declare"):
        built = Constants()
    (condition,) = model_of(built).pre
    assert (condition.label, condition.subject, condition.object) == (
        "LocationContainThing", "Location", "Thing")
    assert "Location" not in built.params


@pytest.mark.parametrize(("default", "reason"), [
    ([2.0, 8], "item 8 of type int"),
    ([], "needs a non-empty list default"),
])
def test_bad_list_defaults_are_type_errors(default, reason):
    class Bad(SkillDescription):
        def description(self, Sizes: LIST[float] = default):
            pass

    with pytest.raises(SkillTypeError, match=reason):
        Bad()


def test_star_args_are_rejected():
    class Bad(SkillDescription):
        def description(self, *args: float):
            pass

    with pytest.raises(DescriptionError, match=r"\*args"):
        Bad()


class Disjunctions(SkillDescription):
    def description(self, A: skiros.Location, B: skiros.Product, C: skiros.Product):
        self.pre_conditions += (A.contain(B) | A.contain(C)) | B.generated()
        self.pre_conditions += ~(A.contain(B) | A.contain(C)) | B.generated()
        self.pre_conditions += any_of(A.contain(B), A.contain(C)) | B.generated()
        self.pre_conditions += B.generated() | (A.contain(B) | A.contain(C))


def shape(condition: Any) -> Any:
    """An or-condition as nested lists of child labels, with its desired state."""
    if condition.kind != "or":
        return condition.label
    return [condition.desired_state[1], *[shape(c) for c in condition.children]]


def test_the_flatten_rule_only_flattens_a_plain_left_operand():
    assert [shape(c) for c in model(Disjunctions).pre] == [
        [True, "AContainB", "AContainC", "BGenerated"],
        [True, [False, "AContainB", "AContainC"], "BGenerated"],
        [True, [True, "AContainB", "AContainC"], "BGenerated"],
        [True, "BGenerated", [True, "AContainB", "AContainC"]],
    ]
    assert {c.label for c in model(Disjunctions).pre} == {"or"}
