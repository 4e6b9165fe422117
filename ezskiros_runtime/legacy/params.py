"""Stand-in for ``skiros2_common.core.params``: ``ParamTypes``, ``Param``, ``ParamHandler``.

The value rules are the part that decides equivalence, so they follow
legacy-skiros2-api.md §3 and §8.4 exactly:

- an ``Element`` instance: data type ``Element``, one value (the element);
- the ``Element`` class, or any Python type object: that type, no value;
- a list literal: multi-valued, of the *first* element's type (``[2.0, 8.0]`` is float with two
  values); ``[]`` and mixed-type lists raise, as in SkiROS2;
- anything else: its own type, one value. ``type()`` is used, never ``isinstance``, so
  ``True`` is bool and ``0`` int and ``0.0`` float (§8.12).

``param_type`` may be a ``ParamTypes`` member or the int 0/1/2 (§8.5).
"""

from __future__ import annotations

import typing
from collections.abc import Iterator
from enum import Enum
from typing import Any

from ._strict_enum import StrictEnumType
from .errors import NotUpstreamAPIError, ParamValueError
from .world_element import Element

__all__ = ["Param", "ParamHandler", "ParamTypes", "classify_value", "param_type_of"]


class ParamTypes(Enum, metaclass=StrictEnumType):
    """The kind of a parameter. ``Inferred`` is an Element the skill manager fills in by
    reasoning over the pre-conditions (§3)."""

    Required = 0
    Optional = 1
    Inferred = 2


def param_type_of(value: object) -> ParamTypes:
    """Normalize ``param_type``: a member, or the int 0/1/2 that SkiROS2 also accepts (§8.5).

    ``bool`` is refused although it is an ``int``: ``True`` as a parameter kind is a bug, not
    an idiom. Anything else (a fork's ``SharedInput`` member, a string) is not upstream API.
    """
    if isinstance(value, ParamTypes):
        return value
    if type(value) is int and value in (0, 1, 2):
        return ParamTypes(value)
    raise NotUpstreamAPIError(
        f"param_type must be ParamTypes.Required/Optional/Inferred or the int 0/1/2, got "
        f"{value!r} ({type(value).__name__}): not upstream SkiROS2 API"
    )


def classify_value(value: Any) -> tuple[type, list[Any]]:
    """The ``(data type, values)`` SkiROS2 stores for an ``addParam`` value (§3, §8.4)."""
    if isinstance(value, Element):
        return Element, [value]
    if isinstance(value, type):  # float, str, ..., and the Element class itself
        return value, []
    if isinstance(value, list):
        if not value:
            raise ParamValueError(
                "an empty list has no element type: SkiROS2 rejects [] as a parameter value "
                "(give the type, e.g. list, or a non-empty default)"
            )
        first = type(value[0])
        for item in value[1:]:
            if type(item) is not first:
                raise ParamValueError(
                    f"list default {value!r} mixes {first.__name__} and "
                    f"{type(item).__name__}: SkiROS2 rejects mixed-type lists"
                )
        return first, list(value)
    return type(value), [value]


class Param:
    """One parameter as SkiROS2 stores it (key, description, data type, kind, values).

    ``options`` is ours: the ``ParamOptions`` member names that took effect in ``addParam``
    (only for Element instances, §8.2), recorded for the normalized model.
    """

    def __init__(self, key: str, description: str, value: Any, param_type: Any) -> None:
        self._key = key
        self._description = description
        self._param_type = param_type_of(param_type)
        self._data_type, self._values = classify_value(value)
        self.options: tuple[str, ...] = ()

    @property
    def key(self) -> str:
        return self._key

    @property
    def description(self) -> str:
        return self._description

    @property
    def dataType(self) -> type:
        return self._data_type

    @property
    def paramType(self) -> ParamTypes:
        return self._param_type

    @property
    def values(self) -> list[Any]:
        return self._values

    @property
    def value(self) -> Any:
        """The first value or ``None`` (implementation code reads ``params[k].value``)."""
        return self._values[0] if self._values else None

    def __repr__(self) -> str:
        return (
            f"Param({self._key!r}, {self._data_type.__name__}, {self._param_type.name}, "
            f"values={self._values!r})"
        )


class ParamHandler(typing.Mapping[str, Param]):
    """The ordered parameters of a description, key -> ``Param``.

    Declaring a key twice replaces the parameter but keeps the first position (§8.3): exactly
    what assigning an existing key of a ``dict`` does.
    """

    def __init__(self) -> None:
        self._params: dict[str, Param] = {}

    def addParam(self, key: str, value: Any, param_type: Any, description: str = "") -> Param:
        """Declare (or redeclare) ``key``; returns the stored ``Param``."""
        if not isinstance(key, str):
            raise NotUpstreamAPIError(
                f"parameter key {key!r} is a {type(key).__name__}, not a str: "
                "not upstream SkiROS2 API (tuple keys exist only in forks)"
            )
        param = Param(key, description, value, param_type)
        self._params[key] = param
        return param

    def hasParam(self, key: str) -> bool:
        return key in self._params

    def getParam(self, key: str) -> Param:
        return self._params[key]

    def getParamMap(self) -> dict[str, Param]:
        return dict(self._params)

    def __getitem__(self, key: str) -> Param:
        return self._params[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self._params)

    def __len__(self) -> int:
        return len(self._params)

    def __repr__(self) -> str:
        return f"ParamHandler({list(self._params.values())!r})"
