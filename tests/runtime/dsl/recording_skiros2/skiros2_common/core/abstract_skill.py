"""Recording stand-in for ``skiros2_common.core.abstract_skill``.

``SkillDescription`` follows SkiROS2's construction (``createDescription`` then
``generateDefParams``) and appends one line per public call to ``self.calls``, in the
notation of the legacy API. ``addParam`` records its arguments with SkiROS2's defaults filled
in (``options=[]``, ``description=""``), so a 3-argument legacy call and the runtime's
5-argument call record the same line exactly when they mean the same thing.
"""

from enum import Enum

from .params import ParamTypes
from .world_element import Element


class ParamOptions(Enum):
    """Same members as SkiROS2's."""

    Consume = 0
    Unspecify = 1
    Lock = 2
    RespectType = 3
    Output = 4


def show(value):
    """A value as it would be written in legacy code."""
    if isinstance(value, RecordedCondition):
        return value.name
    if isinstance(value, Enum):
        return f"{type(value).__name__}.{value.name}"
    if isinstance(value, type):
        return value.__name__
    if isinstance(value, list):
        return "[" + ", ".join(show(v) for v in value) + "]"
    return repr(value)


class RecordedCondition:
    """What a factory returns: its own call text as a name (or-conditions get a number)."""

    def __init__(self, owner, name):
        self.owner = owner
        self.name = name

    def addCondition(self, condition):
        self.owner.calls.append(f"{self.name}.addCondition({show(condition)})")


class SkillDescription:
    """Records every public call a description makes."""

    def __init__(self):
        self.calls = []
        self._type = "skiros:" + type(self).__name__
        self._or_count = 0
        self.createDescription()
        self.generateDefParams()

    def createDescription(self):
        pass

    def generateDefParams(self):
        self.calls.append("generateDefParams()")

    def _record(self, name, *args):
        text = f"{name}({', '.join(show(a) for a in args)})"
        self.calls.append(text)
        return text

    def addParam(self, key, value, param_type, options=[], description=""):  # noqa: B006
        self._record("addParam", key, value, param_type, list(options), description)

    def addPreCondition(self, condition):
        self._record("addPreCondition", condition)

    def addHoldCondition(self, condition):
        self._record("addHoldCondition", condition)

    def addPostCondition(self, condition):
        self._record("addPostCondition", condition)

    def _factory(self, name, *args):
        return RecordedCondition(self, self._record(name, *args))

    def getRelationCond(self, label, relation, subj, obj, desired_state):
        return self._factory("getRelationCond", label, relation, subj, obj, desired_state)

    def getAbstractRelationCond(self, label, relation, subj, obj, desired_state):
        return self._factory("getAbstractRelationCond", label, relation, subj, obj,
                             desired_state)

    def getPropCond(self, label, prop, subj, operator, value, desired_state):
        return self._factory("getPropCond", label, prop, subj, operator, value, desired_state)

    def getHasPropCond(self, label, prop, subj, desired_state):
        return self._factory("getHasPropCond", label, prop, subj, desired_state)

    def getIsSpecifiedCond(self, label, subj, desired_state):
        return self._factory("getIsSpecifiedCond", label, subj, desired_state)

    def getGenerateCond(self, label, subj, desired_state):
        return self._factory("getGenerateCond", label, subj, desired_state)

    def getOnTypeCond(self, label, subj, type):
        return self._factory("getOnTypeCond", label, subj, type)

    def getOrCond(self, desired_state=True):
        self._or_count += 1
        self._record("getOrCond", desired_state)
        return RecordedCondition(self, f"or#{self._or_count}")


__all__ = ["Element", "ParamOptions", "ParamTypes", "SkillDescription"]
