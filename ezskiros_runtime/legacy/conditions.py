"""Stand-in for ``skiros2_common.core.conditions``: the condition classes.

Each class takes the same positional arguments as the factory that builds it, label first
(legacy-skiros2-api.md §4), because some legacy code calls the classes directly (§7). They only
*store* their arguments: SkiROS2 validates nothing at construction (the property operator is
not checked, §8.7), so neither do we. ``to_model()`` turns a condition into the normalized
``model.Condition`` with type-exact values (``True`` and ``1`` differ, §8.12).
"""

from __future__ import annotations

from typing import Any

from .. import model
from ..labels import OR_LABEL
from .errors import NotDeclarativeError

__all__ = [
    "AbstractConditionRelation",
    "ConditionBase",
    "ConditionFunction",
    "ConditionGenerate",
    "ConditionHasProperty",
    "ConditionIsSpecified",
    "ConditionOnType",
    "ConditionOr",
    "ConditionProperty",
    "ConditionRelation",
    "condition_model",
]


def _typed(value: Any) -> model.Typed:
    return model.typed(value)


class ConditionBase:
    """Common part: a free-text ``label`` (shown in logs and the GUI, §4)."""

    def __init__(self, label: str) -> None:
        self.label = label

    def to_model(self) -> model.Condition:
        """The normalized form; every declarative subclass overrides this."""
        raise NotDeclarativeError(f"{type(self).__name__} {self.label!r} has no model form")

    def __repr__(self) -> str:
        fields = ", ".join(f"{k}={v!r}" for k, v in vars(self).items())
        return f"{type(self).__name__}({fields})"


class ConditionRelation(ConditionBase):
    """subject --relation--> object holds (desired_state True) or not (False)."""

    kind = "relation"

    def __init__(self, label: str, relation: str, subject_key: str, object_key: str,
                 desired_state: Any) -> None:
        super().__init__(label)
        self.relation = relation
        self.subject_key = subject_key
        self.object_key = object_key
        self.desired_state = desired_state

    def to_model(self) -> model.Condition:
        return model.Condition(
            kind=self.kind, label=self.label, vocabulary=self.relation,
            subject=self.subject_key, object=self.object_key,
            desired_state=_typed(self.desired_state),
        )


class AbstractConditionRelation(ConditionRelation):
    """The same relation over abstract (class-level) elements (``getAbstractRelationCond``)."""

    kind = "abstract_relation"


class ConditionProperty(ConditionBase):
    """subject's data property compared with ``value``; the operator is kept as given (§8.7)."""

    def __init__(self, label: str, property: str, subject_key: str, operator: Any, value: Any,
                 desired_state: Any) -> None:
        super().__init__(label)
        self.property = property
        self.subject_key = subject_key
        self.operator = operator
        self.value = value
        self.desired_state = desired_state

    def to_model(self) -> model.Condition:
        return model.Condition(
            kind="property", label=self.label, vocabulary=self.property,
            subject=self.subject_key, operator=self.operator, value=_typed(self.value),
            desired_state=_typed(self.desired_state),
        )


class ConditionHasProperty(ConditionBase):
    """subject has (or lacks) the data property at all."""

    def __init__(self, label: str, property: str, subject_key: str, desired_state: Any) -> None:
        super().__init__(label)
        self.property = property
        self.subject_key = subject_key
        self.desired_state = desired_state

    def to_model(self) -> model.Condition:
        return model.Condition(
            kind="has_property", label=self.label, vocabulary=self.property,
            subject=self.subject_key, desired_state=_typed(self.desired_state),
        )


class _SubjectStateCondition(ConditionBase):
    """Shared shape of the two conditions that take only a subject and a desired state."""

    kind = ""

    def __init__(self, label: str, subject_key: str, desired_state: Any) -> None:
        super().__init__(label)
        self.subject_key = subject_key
        self.desired_state = desired_state

    def to_model(self) -> model.Condition:
        return model.Condition(
            kind=self.kind, label=self.label, subject=self.subject_key,
            desired_state=_typed(self.desired_state),
        )


class ConditionIsSpecified(_SubjectStateCondition):
    """The parameter has (or has not) a value (``Unspecify`` expands to it, §3)."""

    kind = "is_specified"


class ConditionGenerate(_SubjectStateCondition):
    """The element is created (True) or destroyed (False) by the skill (``Consume``, §3)."""

    kind = "generate"


class ConditionOnType(ConditionBase):
    """The element is of that OWL type (``RespectType``, §3). It has no desired state."""

    def __init__(self, label: str, subject_key: str, type: str) -> None:
        super().__init__(label)
        self.subject_key = subject_key
        self.type = type

    def to_model(self) -> model.Condition:
        return model.Condition(
            kind="on_type", label=self.label, vocabulary=self.type, subject=self.subject_key,
        )


class ConditionOr(ConditionBase):
    """A disjunction; always labelled ``"or"`` (§8.7). Children keep ``addCondition`` order."""

    def __init__(self, desired_state: Any = True) -> None:
        super().__init__(OR_LABEL)
        self.desired_state = desired_state
        self.children: list[Any] = []

    def addCondition(self, condition: Any) -> None:
        self.children.append(condition)

    def to_model(self) -> model.Condition:
        return model.Condition(
            kind="or", label=self.label, desired_state=_typed(self.desired_state),
            children=tuple(condition_model(c, f"child #{i} of or-condition")
                           for i, c in enumerate(self.children, 1)),
        )


class ConditionFunction(ConditionBase):
    """A condition evaluated by an arbitrary Python callable.

    It constructs (real files use it, §7) but has no declarative form: ``to_model`` raises
    ``NotDeclarativeError`` so the skill is skipped with that reason, never "proven" equal.
    """

    def __init__(self, label: str, function: Any, *args: Any, **kwargs: Any) -> None:
        super().__init__(label)
        self.function = function
        self.args = args
        self.kwargs = kwargs

    def to_model(self) -> model.Condition:
        name = getattr(self.function, "__name__", type(self.function).__name__)
        raise NotDeclarativeError(
            f"condition {self.label!r} is a ConditionFunction (calls {name}): arbitrary Python "
            "has no declarative form, so this skill cannot be migrated or compared"
        )


def condition_model(condition: Any, where: str) -> model.Condition:
    """``condition.to_model()``, with a clear error for objects that are no condition at all
    (SkiROS2's ``addPreCondition`` appends whatever it is given)."""
    to_model = getattr(condition, "to_model", None)
    if not isinstance(condition, ConditionBase) or to_model is None:
        raise NotDeclarativeError(
            f"{where} is not a SkiROS2 condition object but {type(condition).__name__} "
            f"({condition!r})"
        )
    result: model.Condition = to_model()
    return result
