"""Stand-in for ``skiros2_common.core.abstract_skill``: ``SkillDescription`` and ``ParamOptions``.

This ``SkillDescription`` is *the* base class of both worlds: legacy classes loaded through the
stand-ins derive from it, and EzSkiROS classes derive from it too, so one extractor
(``extract.model_of``) reads both and the comparison cannot be fooled by two implementations.

What the extractor (and anyone else) may read after construction:

- ``self._type`` -- ``"skiros:" + ClassName`` (legacy-skiros2-api.md §2);
- ``self.params`` -- a ``ParamHandler``, an ordered ``Mapping[str, Param]``;
- ``self._pre_conditions``, ``self._hold_conditions``, ``self._post_conditions`` -- lists of
  condition objects in call order;
- ``self._available_for_planning`` -- what ``setAvailableForPlanning`` recorded (default True).

Construction follows §2 to the letter: set the type, create the empty containers, call
``createDescription()``, then ``generateDefParams()`` (the automatic ``Robot``, last, §8.1).
``generateDefConditions`` is deliberately *not* called (§8.8).
"""

from __future__ import annotations

from collections.abc import Iterable
from enum import Enum
from typing import Any

from ._strict_enum import StrictEnumType
from .conditions import (
    AbstractConditionRelation,
    ConditionGenerate,
    ConditionHasProperty,
    ConditionIsSpecified,
    ConditionOnType,
    ConditionOr,
    ConditionProperty,
    ConditionRelation,
)
from .errors import NotUpstreamAPIError, UnsupportedConstructError
from .params import ParamHandler, ParamTypes
from .world_element import Element

__all__ = ["ParamOptions", "SkillCore", "SkillDescription", "State"]

ROBOT_KEY = "Robot"
ROBOT_TYPE = "sumo:Agent"
LOCK_PROPERTY = "skiros:StateProperty"


class ParamOptions(Enum, metaclass=StrictEnumType):
    """Options of ``addParam``; each expands into conditions (§3). ``Output`` expands to
    nothing but is still recorded on the parameter."""

    Consume = 0
    Unspecify = 1
    Lock = 2
    RespectType = 3
    Output = 4


class State(Enum):
    """Skill execution states; implementations return them (we never run implementations)."""

    Uninitialized = -1
    Failure = 0
    Success = 1
    Running = 2
    Idle = 3


class SkillDescription:
    """A SkiROS2 skill description: a type, ordered parameters, ordered conditions."""

    def __init__(self) -> None:
        self._type = "skiros:" + type(self).__name__
        self._params = ParamHandler()
        self._pre_conditions: list[Any] = []
        self._hold_conditions: list[Any] = []
        self._post_conditions: list[Any] = []
        self._available_for_planning = True
        self.createDescription()
        self.generateDefParams()

    # -- what subclasses override -------------------------------------------------------
    def createDescription(self) -> None:
        """Declare parameters and conditions; the default declares nothing (an empty
        description still gets the automatic ``Robot``, §7)."""

    # -- read accessors -------------------------------------------------------------------
    @property
    def type(self) -> str:
        return self._type

    @property
    def params(self) -> ParamHandler:
        """Ordered ``key -> Param`` (implementation code reads ``self.params[k].value``)."""
        return self._params

    # -- parameters -----------------------------------------------------------------------
    def addParam(self, key: str, value: Any, param_type: Any, options: Iterable[Any] = (),
                 description: str = "", **fork_only: Any) -> None:
        """Declare a parameter and expand its options at once (§3, §8.2, §8.3).

        Options expand only when ``value`` is an ``Element`` *instance*; their conditions are
        appended now, so they interleave with explicit conditions in call order. Items that
        are no ``ParamOptions`` member match nothing: a description passed 4th is a string
        whose characters are iterated and ignored, and the description stays ``""`` -- the
        real-world quirk of §3, reproduced on purpose. A redeclared key keeps its first
        position (the handler's job) and the first declaration's conditions stay.
        """
        if fork_only:
            raise NotUpstreamAPIError(
                f"addParam({key!r}, ..., {', '.join(f'{k}=...' for k in fork_only)}): "
                "keyword not upstream SkiROS2 API (a fork's extension)"
            )
        param = self._params.addParam(key, value, param_type, description)
        if not isinstance(value, Element):
            return
        taken: list[str] = []
        for option in options:
            if isinstance(option, ParamOptions):
                taken.append(option.name)
                self._expand_option(key, value, option)
        param.options = tuple(taken)

    def _expand_option(self, key: str, element: Element, option: ParamOptions) -> None:
        """The conditions one option stands for, with SkiROS2's labels (§3)."""
        if option is ParamOptions.Consume:
            self.addPostCondition(self.getGenerateCond("Consume" + key, key, False))
        elif option is ParamOptions.Unspecify:
            self.addPostCondition(self.getIsSpecifiedCond("Unset" + key, key, False))
        elif option is ParamOptions.Lock:
            self.addPreCondition(
                self.getPropCond(key + "Idle", LOCK_PROPERTY, key, "=", "Idle", True))
            self.addHoldCondition(
                self.getPropCond(key + "Busy", LOCK_PROPERTY, key, "=", "Idle", False))
            self.addPostCondition(
                self.getPropCond(key + "Idle", LOCK_PROPERTY, key, "=", "Idle", True))
        elif option is ParamOptions.RespectType:
            self.addPreCondition(self.getOnTypeCond(key + "OfType", key, element.type))
        # ParamOptions.Output expands to nothing.

    def generateDefParams(self) -> None:
        """Append the automatic ``Robot`` (Element ``sumo:Agent``, Inferred, description "")
        unless a ``Robot`` was declared (§2, §8.1)."""
        if not self._params.hasParam(ROBOT_KEY):
            self.addParam(ROBOT_KEY, Element(ROBOT_TYPE), ParamTypes.Inferred)

    def generateDefConditions(self) -> None:
        """Exists in SkiROS2 but ``__init__`` never calls it (§8.8), so normally no code runs it.

        We do not reproduce its body: a description that calls it explicitly fails loudly
        rather than yielding a model that might silently differ from SkiROS2's.
        """
        raise UnsupportedConstructError(
            "generateDefConditions() called explicitly: its effect is not reproduced by the "
            "legacy backend (SkiROS2 itself never calls it, §8.8)"
        )

    def setAvailableForPlanning(self, value: Any) -> None:
        """Record the flag (only some SkiROS2 branches have it, §8.10); not part of the model."""
        self._available_for_planning = value

    # -- conditions -----------------------------------------------------------------------
    def addPreCondition(self, condition: Any) -> None:
        self._pre_conditions.append(condition)

    def addHoldCondition(self, condition: Any) -> None:
        self._hold_conditions.append(condition)

    def addPostCondition(self, condition: Any) -> None:
        self._post_conditions.append(condition)

    # -- condition factories (§4): they only construct (§8.7) ----------------------------
    def getRelationCond(self, label: str, relation: str, subject_key: str, object_key: str,
                        desired_state: Any) -> ConditionRelation:
        return ConditionRelation(label, relation, subject_key, object_key, desired_state)

    def getAbstractRelationCond(self, label: str, relation: str, subject_key: str,
                                object_key: str, desired_state: Any) -> AbstractConditionRelation:
        return AbstractConditionRelation(label, relation, subject_key, object_key, desired_state)

    def getPropCond(self, label: str, property: str, subject_key: str, operator: Any,
                    value: Any, desired_state: Any) -> ConditionProperty:
        return ConditionProperty(label, property, subject_key, operator, value, desired_state)

    def getHasPropCond(self, label: str, property: str, subject_key: str,
                       desired_state: Any) -> ConditionHasProperty:
        return ConditionHasProperty(label, property, subject_key, desired_state)

    def getIsSpecifiedCond(self, label: str, subject_key: str,
                           desired_state: Any) -> ConditionIsSpecified:
        return ConditionIsSpecified(label, subject_key, desired_state)

    def getGenerateCond(self, label: str, subject_key: str,
                        desired_state: Any) -> ConditionGenerate:
        return ConditionGenerate(label, subject_key, desired_state)

    def getOnTypeCond(self, label: str, subject_key: str, type: str) -> ConditionOnType:
        return ConditionOnType(label, subject_key, type)

    def getOrCond(self, desired_state: Any = True) -> ConditionOr:
        return ConditionOr(desired_state)


class SkillCore(SkillDescription):
    """Common base of the *implementation* classes (``PrimitiveBase``, ``SkillBase``).

    Their ``createDescription`` only calls ``setDescription(SomeDescription(), name)`` (§2).
    They derive from ``SkillDescription`` as in SkiROS2 (``modifyDescription`` code calls
    ``addParam`` on them), which is why the loader excludes them explicitly.
    """

    def setDescription(self, description: SkillDescription, label: str = "") -> None:
        """Adopt a description's type, parameters and conditions (never run by ezmigrate)."""
        self._description = description
        self._label = label
        self._type = description._type
        self._params = description._params
        self._pre_conditions = list(description._pre_conditions)
        self._hold_conditions = list(description._hold_conditions)
        self._post_conditions = list(description._post_conditions)
