"""Every row of both tables in docs/dsl.md: the EzSkiROS form, its legacy counterpart, and a
changed variant. The form and the counterpart must load into EQUAL models, the variant into
an UNEQUAL one (so the equality is not vacuous).

Annotations are strings here (``from __future__ import annotations``): they are evaluated at
instantiation, while the ``paper`` fixture has paper.ttl active. Classes that stand for the
same skill are renamed ``Row`` so their SkiROS2 types (``skiros:Row``) agree.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from typing import Any

import pytest
from dsl_support import named, paper, quiet_model  # noqa: F401 - paper is a fixture

from ezskiros_runtime import (
    DESC,
    ELEMENT,
    INFERRED,
    KEY,
    LIST,
    OPTIONAL,
    REQUIRED,
    Lock,
    SkillDescription,
    abstract,
    any_of,
    check,
)
from ezskiros_runtime.compare import compare
from ezskiros_runtime.legacy.abstract_skill import ParamOptions
from ezskiros_runtime.legacy.abstract_skill import SkillDescription as LegacyDescription
from ezskiros_runtime.legacy.params import ParamTypes
from ezskiros_runtime.legacy.world_element import Element
from ezskiros_runtime.ontology import cora, rparts, skiros, sumo

pytestmark = pytest.mark.usefixtures("paper")

CONSTANT = 3
"""A module-level constant, as legacy code passes them (``addParam("S", CONSTANT, ...)``)."""

# --------------------------------------------------------------------------------------
# Parameters table
# --------------------------------------------------------------------------------------


@named("Row")
class EzElement(SkillDescription):
    def description(self, X: skiros.Product): ...


@named("Row")
class LegacyElement(LegacyDescription):
    def createDescription(self):
        self.addParam("X", Element("skiros:Product"), ParamTypes.Required)


@named("Row")
class VariantElement(SkillDescription):
    def description(self, X: skiros.Location): ...


@named("Row")
class EzInferred(SkillDescription):
    def description(self, X: INFERRED[skiros.Product]): ...


@named("Row")
class LegacyInferred(LegacyDescription):
    def createDescription(self):
        self.addParam("X", Element("skiros:Product"), ParamTypes.Inferred)


@named("Row")
class EzOptionalElement(SkillDescription):
    def description(self, X: OPTIONAL[skiros.Product]): ...


@named("Row")
class LegacyOptionalElement(LegacyDescription):
    def createDescription(self):
        self.addParam("X", Element("skiros:Product"), ParamTypes.Optional)


@named("Row")
class EzRequiredElement(SkillDescription):
    def description(self, X: REQUIRED[skiros.Product]): ...


@named("Row")
class EzVerbatimElement(SkillDescription):
    def description(self, X: ELEMENT(":Product")): ...


@named("Row")
class LegacyVerbatimElement(LegacyDescription):
    def createDescription(self):
        self.addParam("X", Element(":Product"), ParamTypes.Required)


@named("Row")
class EzUntypedElement(SkillDescription):
    def description(self, X: ELEMENT()): ...


@named("Row")
class LegacyUntypedElement(LegacyDescription):
    def createDescription(self):
        self.addParam("X", Element(), ParamTypes.Required)


@named("Row")
class VariantUntypedElement(SkillDescription):
    def description(self, X: ELEMENT("Product")): ...


@named("Row")
class EzTypeObjects(SkillDescription):
    def description(self, F: float, I: int, T: str, B: bool, D: dict, L: list): ...  # noqa: E741


@named("Row")
class LegacyTypeObjects(LegacyDescription):
    def createDescription(self):
        for key, python_type in (("F", float), ("I", int), ("T", str), ("B", bool),
                                 ("D", dict), ("L", list)):
            self.addParam(key, python_type, ParamTypes.Required)


@named("Row")
class VariantTypeObjects(SkillDescription):
    def description(self, F: float, I: float, T: str, B: bool, D: dict, L: list): ...  # noqa: E741


@named("Row")
class EzOptionalFloat(SkillDescription):
    def description(self, S: OPTIONAL[float] = 0.5): ...


@named("Row")
class LegacyOptionalFloat(LegacyDescription):
    def createDescription(self):
        self.addParam("S", 0.5, ParamTypes.Optional)


@named("Row")
class VariantOptionalFloat(SkillDescription):
    def description(self, S: REQUIRED[float] = 0.5): ...


@named("Row")
class EzIntDefault(SkillDescription):
    def description(self, S: int = 0): ...


@named("Row")
class LegacyIntDefault(LegacyDescription):
    def createDescription(self):
        self.addParam("S", 0, ParamTypes.Required)


@named("Row")
class VariantIntDefault(SkillDescription):
    def description(self, S: float = 0.0): ...


@named("Row")
class EzListDefault(SkillDescription):
    def description(self, S: LIST[float] = [2.0, 8.0]): ...  # noqa: B006


@named("Row")
class EzBuiltinListDefault(SkillDescription):
    def description(self, S: list[float] = [2.0, 8.0]): ...  # noqa: B006


@named("Row")
class LegacyListDefault(LegacyDescription):
    def createDescription(self):
        self.addParam("S", [2.0, 8.0], ParamTypes.Required)


@named("Row")
class VariantListDefault(SkillDescription):
    def description(self, S: LIST[float] = [2.0]): ...  # noqa: B006


@named("Row")
class EzBareMarker(SkillDescription):
    def description(self, S: OPTIONAL = CONSTANT): ...


@named("Row")
class LegacyBareMarker(LegacyDescription):
    def createDescription(self):
        self.addParam("S", CONSTANT, ParamTypes.Optional)


@named("Row")
class VariantBareMarker(SkillDescription):
    def description(self, S: OPTIONAL = float(CONSTANT)): ...


@named("Row")
class EzLock(SkillDescription):
    def description(self, C: REQUIRED[rparts.GripperEffector, Lock]): ...


@named("Row")
class LegacyLock(LegacyDescription):
    def createDescription(self):
        self.addParam("C", Element("rparts:GripperEffector"), ParamTypes.Required,
                      [ParamOptions.Lock])


@named("Row")
class VariantLock(SkillDescription):
    def description(self, C: REQUIRED[rparts.GripperEffector]): ...


@named("Row")
class EzDescribed(SkillDescription):
    def description(self, S: OPTIONAL[float, DESC("m/s")] = 0.5): ...


@named("Row")
class EzDescribedBare(SkillDescription):
    def description(self, S: OPTIONAL[float, "m/s"] = 0.5): ...  # noqa: F821, UP037


@named("Row")
class LegacyDescribed(LegacyDescription):
    def createDescription(self):
        self.addParam("S", 0.5, ParamTypes.Optional, [], "m/s")


@named("Row")
class VariantDescribed(SkillDescription):
    def description(self, S: OPTIONAL[float, "km/h"] = 0.5): ...  # noqa: F821, UP037


@named("Row")
class EzKey(SkillDescription):
    def description(self, On_Off: REQUIRED[bool, KEY("On/Off")] = True): ...


@named("Row")
class LegacyKey(LegacyDescription):
    def createDescription(self):
        self.addParam("On/Off", True, ParamTypes.Required)


@named("Row")
class VariantKey(SkillDescription):
    def description(self, On_Off: REQUIRED[bool] = True): ...


@named("Row")
class EzRobotLast(SkillDescription):
    def description(self, X: skiros.Product, Robot: INFERRED[sumo.Agent]): ...


@named("Row")
class LegacyRobotAutomatic(LegacyDescription):
    def createDescription(self):
        self.addParam("X", Element("skiros:Product"), ParamTypes.Required)


@named("Row")
class VariantRobotFirst(SkillDescription):
    def description(self, Robot: INFERRED[sumo.Agent], X: skiros.Product): ...


@named("Row")
class EzForeignElement(SkillDescription):
    def description(self, Arm: ELEMENT("scalable:Ur5")): ...  # vocabulary the ontology lacks


@named("Row")
class LegacyForeignElement(LegacyDescription):
    def createDescription(self):
        self.addParam("Arm", Element("scalable:Ur5"), ParamTypes.Required)


@named("Row")
class VariantForeignElement(SkillDescription):
    def description(self, Arm: ELEMENT("scalable:Ur10")): ...


PARAMETER_ROWS = [
    pytest.param(EzElement, LegacyElement, VariantElement, id="X: skiros.C"),
    pytest.param(EzInferred, LegacyInferred, EzOptionalElement, id="X: INFERRED[skiros.C]"),
    pytest.param(EzOptionalElement, LegacyOptionalElement, EzRequiredElement,
                 id="X: OPTIONAL[skiros.C]"),
    pytest.param(EzRequiredElement, LegacyElement, EzInferred, id="X: REQUIRED[skiros.C]"),
    pytest.param(EzVerbatimElement, LegacyVerbatimElement, EzElement, id='X: ELEMENT(":C")'),
    pytest.param(EzUntypedElement, LegacyUntypedElement, VariantUntypedElement,
                 id="X: ELEMENT()"),
    pytest.param(EzTypeObjects, LegacyTypeObjects, VariantTypeObjects,
                 id="S: float/int/str/bool/dict/list"),
    pytest.param(EzOptionalFloat, LegacyOptionalFloat, VariantOptionalFloat,
                 id="S: OPTIONAL[float] = 0.5"),
    pytest.param(EzIntDefault, LegacyIntDefault, VariantIntDefault, id="S: int = 0"),
    pytest.param(EzListDefault, LegacyListDefault, VariantListDefault,
                 id="S: LIST[float] = [2.0, 8.0]"),
    pytest.param(EzBuiltinListDefault, LegacyListDefault, VariantListDefault,
                 id="S: list[float] = [2.0, 8.0]", marks=pytest.mark.skipif(
                     sys.version_info < (3, 9), reason="list[float] runs from Python 3.9")),
    pytest.param(EzBareMarker, LegacyBareMarker, VariantBareMarker,
                 id="S: OPTIONAL = CONSTANT"),
    pytest.param(EzLock, LegacyLock, VariantLock, id="C: REQUIRED[C, Lock]"),
    pytest.param(EzDescribed, LegacyDescribed, VariantDescribed,
                 id='S: OPTIONAL[float, DESC("m/s")] = 0.5'),
    pytest.param(EzDescribedBare, LegacyDescribed, VariantDescribed,
                 id='S: OPTIONAL[float, "m/s"] = 0.5'),
    pytest.param(EzKey, LegacyKey, VariantKey, id='REQUIRED[bool, KEY("On/Off")] = True'),
    pytest.param(EzForeignElement, LegacyForeignElement, VariantForeignElement,
                 id='X: ELEMENT("scalable:Ur5") (not in the ontology)'),
    pytest.param(EzRobotLast, LegacyRobotAutomatic, VariantRobotFirst,
                 id="Robot: INFERRED[sumo.Agent] last"),
]

# --------------------------------------------------------------------------------------
# Conditions table: one pre-condition over A: Location, B: Product, G: Gripper, R: Robot
# --------------------------------------------------------------------------------------

PARAMS = (("A", "skiros:Location"), ("B", "skiros:Product"), ("G", "rparts:GripperEffector"),
          ("R", "cora:Robot"))


def ez(build: Callable[..., Any]) -> type:
    """An EzSkiROS class whose only condition is ``build(A, B, G, R)``."""

    @named("Row")
    class Row(SkillDescription):
        def description(self, A: skiros.Location, B: skiros.Product,
                        G: rparts.GripperEffector, R: cora.Robot):
            self.pre_conditions += build(A, B, G, R)

    return Row


def legacy(build: Callable[[Any], Any]) -> type:
    """The legacy class with the same parameters and the condition ``build(self)``."""

    @named("Row")
    class Row(LegacyDescription):
        def createDescription(self):
            for key, owl_class in PARAMS:
                self.addParam(key, Element(owl_class), ParamTypes.Required)
            self.addPreCondition(build(self))

    return Row


def legacy_or(d: Any, desired: bool, *children: Any) -> Any:
    either = d.getOrCond(desired)
    for child in children:
        either.addCondition(child)
    return either


def contain(d: Any, desired: bool = True, label: str | None = None) -> Any:
    default = "AContainB" if desired else "NotAContainB"
    return d.getRelationCond(label or default, "skiros:contain", "A", "B", desired)


def grip(d: Any) -> Any:
    return d.getRelationCond("GContainB", "skiros:contain", "G", "B", True)


def typed_b(d: Any) -> Any:
    return d.getOnTypeCond("BOfType", "B", "skiros:Product")


def other_statements(relation: str) -> type:
    """An EzSkiROS class whose body also runs statements that are no conditions (§5 of the
    legacy API: ``setAvailableForPlanning``, a plain attribute assignment); ``relation`` is
    read back from the attribute, so the variant shows the statements really run."""

    @named("Row")
    class Row(SkillDescription):
        def description(self, A: skiros.Location, B: skiros.Product,
                        G: rparts.GripperEffector, R: cora.Robot):
            self.setAvailableForPlanning(False)
            self.relation_name = relation
            self.pre_conditions += A.relation(self.relation_name, B)

    return Row


@named("Row")
class LegacyOtherStatements(LegacyDescription):
    def createDescription(self):
        self.setAvailableForPlanning(False)
        self.relation_name = "skiros:contain"
        for key, owl_class in PARAMS:
            self.addParam(key, Element(owl_class), ParamTypes.Required)
        self.addPreCondition(contain(self))


CONDITION_ROWS = [
    pytest.param(ez(lambda A, B, G, R: A.contain(B)), legacy(contain),
                 ez(lambda A, B, G, R: ~A.contain(B)), id="A.contain(B)"),
    pytest.param(other_statements("skiros:contain"), LegacyOtherStatements,
                 other_statements("skiros:hasA"), id="other statements kept"),
    pytest.param(ez(lambda A, B, G, R: ~A.contain(B)), legacy(lambda d: contain(d, False)),
                 ez(lambda A, B, G, R: A.contain(B)), id="~ A.contain(B)"),
    pytest.param(ez(lambda A, B, G, R: G.relation("cora:robotPart", R)),
                 legacy(lambda d: d.getRelationCond("GRobotPartR", "cora:robotPart", "G", "R",
                                                    True)),
                 ez(lambda A, B, G, R: G.relation("cora:robotpart", R)),
                 id='A.relation("cora:robotPart", B)'),
    pytest.param(ez(lambda A, B, G, R: abstract(A.contain(B))),
                 legacy(lambda d: d.getAbstractRelationCond("AContainB", "skiros:contain", "A",
                                                            "B", True)),
                 ez(lambda A, B, G, R: A.contain(B)), id="abstract(A.contain(B))"),
    pytest.param(ez(lambda A, B, G, R: A.PublishTf == False),
                 legacy(lambda d: d.getPropCond("APublishTf", "skiros:PublishTf", "A", "=",
                                                False, True)),
                 ez(lambda A, B, G, R: A.PublishTf == 0), id="F.Open == False"),
    *[pytest.param(ez(build),
                   legacy(lambda d, op=op: d.getPropCond("APositionX", "skiros:PositionX", "A",
                                                         op, 1.0, True)),
                   ez(other), id=f"F.PositionX {op} 1.0")
      for op, build, other in (
          (">", lambda A, B, G, R: A.PositionX > 1.0, lambda A, B, G, R: A.PositionX >= 1.0),
          ("<", lambda A, B, G, R: A.PositionX < 1.0, lambda A, B, G, R: A.PositionX <= 1.0),
          (">=", lambda A, B, G, R: A.PositionX >= 1.0, lambda A, B, G, R: A.PositionX > 1.0),
          ("<=", lambda A, B, G, R: A.PositionX <= 1.0, lambda A, B, G, R: A.PositionX < 1.0),
      )],
    pytest.param(ez(lambda A, B, G, R: A.PublishTf.eq(False)),
                 legacy(lambda d: d.getPropCond("APublishTf", "skiros:PublishTf", "A", "=",
                                                False, True)),
                 ez(lambda A, B, G, R: A.PublishTf.eq(0)), id="F.Open.eq(False)"),
    *[pytest.param(ez(build),
                   legacy(lambda d, op=op: d.getPropCond("APositionX", "skiros:PositionX", "A",
                                                         op, 1.0, True)),
                   ez(other), id=f"F.PositionX.{method}(1.0)")
      for op, method, build, other in (
          (">", "gt", lambda A, B, G, R: A.PositionX.gt(1.0),
           lambda A, B, G, R: A.PositionX.ge(1.0)),
          ("<", "lt", lambda A, B, G, R: A.PositionX.lt(1.0),
           lambda A, B, G, R: A.PositionX.le(1.0)),
          (">=", "ge", lambda A, B, G, R: A.PositionX.ge(1.0),
           lambda A, B, G, R: A.PositionX.gt(1.0)),
          ("<=", "le", lambda A, B, G, R: A.PositionX.le(1.0),
           lambda A, B, G, R: A.PositionX.lt(1.0)),
      )],
    pytest.param(ez(lambda A, B, G, R: A.property("skiros:Open", "=", False)),
                 legacy(lambda d: d.getPropCond("AOpen", "skiros:Open", "A", "=", False, True)),
                 ez(lambda A, B, G, R: A.property("skiros:Open", "==", False)),
                 id='F.property("skiros:Open", "=", False)'),
    pytest.param(ez(lambda A, B, G, R: A.has(skiros.PositionX)),
                 legacy(lambda d: d.getHasPropCond("AHasPositionX", "skiros:PositionX", "A",
                                                   True)),
                 ez(lambda A, B, G, R: ~A.has(skiros.PositionX)), id="O.has(skiros.Position)"),
    pytest.param(ez(lambda A, B, G, R: A.has("skiros:PositionX")),
                 legacy(lambda d: d.getHasPropCond("AHasPositionX", "skiros:PositionX", "A",
                                                   True)),
                 ez(lambda A, B, G, R: A.has(":PositionX")), id='O.has("skiros:Position")'),
    pytest.param(ez(lambda A, B, G, R: B.is_specified()),
                 legacy(lambda d: d.getIsSpecifiedCond("BSpecified", "B", True)),
                 ez(lambda A, B, G, R: B.generated()), id="O.is_specified()"),
    pytest.param(ez(lambda A, B, G, R: B.generated()),
                 legacy(lambda d: d.getGenerateCond("BGenerated", "B", True)),
                 ez(lambda A, B, G, R: ~B.generated()), id="O.generated()"),
    pytest.param(ez(lambda A, B, G, R: B.is_a(skiros.Product)), legacy(typed_b),
                 ez(lambda A, B, G, R: B.is_a(":Product")), id="O.is_a(skiros.Product)"),
    pytest.param(ez(lambda A, B, G, R: B.is_a(":Product")),
                 legacy(lambda d: d.getOnTypeCond("BOfType", "B", ":Product")),
                 ez(lambda A, B, G, R: B.is_a("Product")), id='O.is_a(":Product")'),
    pytest.param(ez(lambda A, B, G, R: A.contain(B) | G.contain(B) | B.is_a(skiros.Product)),
                 legacy(lambda d: legacy_or(d, True, contain(d), grip(d), typed_b(d))),
                 ez(lambda A, B, G, R: any_of(A.contain(B) | G.contain(B),
                                              B.is_a(skiros.Product))),
                 id="c1 | c2 | c3"),
    pytest.param(ez(lambda A, B, G, R: ~(A.contain(B) | G.contain(B))),
                 legacy(lambda d: legacy_or(d, False, contain(d), grip(d))),
                 ez(lambda A, B, G, R: ~A.contain(B) | G.contain(B)), id="~ (c1 | c2)"),
    pytest.param(ez(lambda A, B, G, R: any_of(A.contain(B), G.contain(B))),
                 legacy(lambda d: legacy_or(d, True, contain(d), grip(d))),
                 ez(lambda A, B, G, R: any_of(A.contain(B))), id="any_of(c1, c2)"),
    pytest.param(ez(lambda A, B, G, R: A.contain(B).named("Holding")),
                 legacy(lambda d: contain(d, True, "Holding")),
                 ez(lambda A, B, G, R: A.contain(B)), id='c.named("Holding")'),
    pytest.param(ez(lambda A, B, G, R: (~A.contain(B)).named("Empty")),
                 legacy(lambda d: contain(d, False, "Empty")),
                 ez(lambda A, B, G, R: ~A.contain(B)), id='(~c).named("Empty")'),
    pytest.param(ez(lambda A, B, G, R: ~A.contain(B).named("Empty")),
                 legacy(lambda d: contain(d, False, "Empty")),
                 ez(lambda A, B, G, R: A.contain(B).named("Empty")), id='~ c.named("Empty")'),
]


@pytest.mark.parametrize(("ez_class", "legacy_class", "variant_class"),
                         PARAMETER_ROWS + CONDITION_ROWS)
def test_form_loads_equal_to_its_legacy_counterpart_and_the_variant_does_not(
        ez_class, legacy_class, variant_class):
    expected = quiet_model(legacy_class)
    actual = quiet_model(ez_class)
    assert actual == expected
    assert compare(expected, actual) == []
    changed = quiet_model(variant_class)
    assert changed != expected
    assert compare(expected, changed) != []


@pytest.mark.parametrize("ez_class", [pytest.param(row.values[0], marks=row.marks)
                                      for row in PARAMETER_ROWS + CONDITION_ROWS])
def test_every_form_passes_the_type_checks(ez_class):
    assert [f for f in check(ez_class) if f.severity == "error"] == []


def test_other_statements_run_in_both_backends():
    """``setAvailableForPlanning`` is recorded but is no part of the model (§8.10: only some
    SkiROS2 branches have it); attribute assignments stay on the instance, in both forms."""
    for cls in (other_statements("skiros:contain"), LegacyOtherStatements):
        instance = cls()
        assert instance._available_for_planning is False
        assert instance.relation_name == "skiros:contain"
