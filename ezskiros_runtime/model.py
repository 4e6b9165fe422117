"""The normalized skill description: the one data type every part of the project meets at.

A legacy class loaded through the legacy backend, an EzSkiROS class loaded through the
runtime, and a legacy class extracted statically from source all become a ``SkillModel``.
Equivalence of a migration is equality of two models, so the model stores exactly what
SkiROS2 stores and nothing it does not: verbatim type strings (``":Location"`` and
``"skiros:Location"`` differ, see legacy-skiros2-api.md §8.6) and type-exact values
(``True``, ``1``, ``1.0`` and ``"True"`` differ, §8.12).

Values are kept *typed*: a ``Typed`` is a hashable ``(type_name, payload)`` pair, nested for
lists and dicts, so plain ``==`` on models is type-exact (Python alone says ``True == 1``).
"""

from __future__ import annotations

import json
import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field, replace
from typing import Any, Literal, Tuple, get_args

Typed = Tuple[str, Any]
"""A type-exact value: ``("float", 0.5)``, ``("list", (("float", 2.0), ...))``."""

ParamKind = Literal["Required", "Optional", "Inferred"]
PARAM_KINDS: tuple[str, ...] = get_args(ParamKind)

ConditionKind = Literal[
    "relation",
    "abstract_relation",
    "property",
    "has_property",
    "is_specified",
    "generate",
    "on_type",
    "or",
]
CONDITION_KINDS: tuple[str, ...] = get_args(ConditionKind)
CONDITION_LISTS: tuple[str, ...] = ("pre", "hold", "post")


def typed(value: Any) -> Typed:
    """Turn a Python value into its type-exact, hashable form.

    ``bool`` is tested before ``int`` because ``bool`` subclasses ``int``. Floats that JSON
    cannot carry (nan, inf) are kept as their ``repr`` so that the model stays serializable.
    Anything else (a module constant of an exotic type) is kept by type name and ``repr``.
    """
    if value is None:
        return ("none", None)
    if isinstance(value, bool):
        return ("bool", value)
    if isinstance(value, int):
        return ("int", value)
    if isinstance(value, float):  # + 0.0: -0.0 equals 0.0, so it must serialize alike
        return ("float", value + 0.0 if math.isfinite(value) else repr(value))
    if isinstance(value, str):
        return ("str", value)
    if isinstance(value, (list, tuple)):
        return ("list" if isinstance(value, list) else "tuple", tuple(typed(v) for v in value))
    if isinstance(value, dict):
        items = tuple(sorted(((typed(k), typed(v)) for k, v in value.items()), key=repr))
        return ("dict", items)
    return (f"opaque:{type(value).__name__}", repr(value))


def untyped(value: Typed) -> Any:
    """Back from ``Typed`` to a plain Python value (used for rendering and emission)."""
    name, payload = value
    if name == "none":
        return None
    if name == "float" and isinstance(payload, str):
        return float(payload)
    if name in ("list", "tuple"):
        items = [untyped(v) for v in payload]
        return items if name == "list" else tuple(items)
    if name == "dict":
        return {untyped(k): untyped(v) for k, v in payload}
    if name.startswith("opaque:"):
        return _Opaque(name[len("opaque:") :], payload)
    return payload


@dataclass(frozen=True)
class _Opaque:
    """Stand-in for a value we only know by type name and ``repr``."""

    type_name: str
    text: str

    def __repr__(self) -> str:
        return self.text


@dataclass(frozen=True)
class Param:
    """One ``addParam`` as SkiROS2 stores it.

    ``data_type`` is ``"Element"`` for world-model elements (``element_type`` then holds the
    verbatim type string, or ``None`` when the ``Element`` class itself was passed) and the
    Python type name otherwise. ``values`` holds the defaults (several for a list default,
    none for a type object or an element). ``options`` are the ``ParamOptions`` member names
    that took effect (they only do for ``Element`` instances, §8.2).
    """

    key: str
    kind: str
    data_type: str
    element_type: str | None = None
    values: tuple[Typed, ...] = ()
    description: str = ""
    options: tuple[str, ...] = ()


@dataclass(frozen=True)
class Condition:
    """One condition object as SkiROS2 stores it.

    ``vocabulary`` is the verbatim relation, property or type string. ``value`` and
    ``desired_state`` are typed so that ``True`` and ``1`` differ. ``children`` is only used
    by ``kind == "or"``.
    """

    kind: str
    label: str
    vocabulary: str | None = None
    subject: str | None = None
    object: str | None = None
    operator: str | None = None
    value: Typed | None = None
    desired_state: Typed | None = None
    children: tuple[Condition, ...] = ()


@dataclass(frozen=True)
class SkillModel:
    """A loaded skill description: type name, ordered parameters, ordered conditions."""

    name: str
    type: str
    params: tuple[Param, ...] = ()
    pre: tuple[Condition, ...] = ()
    hold: tuple[Condition, ...] = ()
    post: tuple[Condition, ...] = ()
    source: str | None = field(default=None, compare=False)
    line: int | None = field(default=None, compare=False)

    def conditions(self, which: str) -> tuple[Condition, ...]:
        """The ``pre``, ``hold`` or ``post`` list by name."""
        if which not in CONDITION_LISTS:
            raise ValueError(f"unknown condition list {which!r}")
        result: tuple[Condition, ...] = getattr(self, which)
        return result

    def param(self, key: str) -> Param | None:
        """The parameter with this key, if declared."""
        return next((p for p in self.params if p.key == key), None)

    def with_location(self, source: str | None, line: int | None) -> SkillModel:
        """The same model, remembered as coming from ``source:line`` (not part of equality)."""
        return replace(self, source=source, line=line)

    def to_json(self) -> dict[str, Any]:
        """A JSON-ready dict; ``from_json`` reads it back to an equal model."""
        return {
            "name": self.name,
            "type": self.type,
            "params": [_param_json(p) for p in self.params],
            **{which: [_condition_json(c) for c in self.conditions(which)]
               for which in CONDITION_LISTS},
            **({"source": self.source} if self.source is not None else {}),
            **({"line": self.line} if self.line is not None else {}),
        }

    def canonical_json(self) -> str:
        """The canonical text form: sorted keys, no whitespace, no source location.

        Two models are equal exactly when their canonical JSON is equal.
        """
        data = self.to_json()
        data.pop("source", None)
        data.pop("line", None)
        return json.dumps(data, sort_keys=True, separators=(",", ":"), ensure_ascii=False)

    @classmethod
    def from_json(cls, data: Mapping[str, Any]) -> SkillModel:
        """Read the dict that ``to_json`` wrote."""
        return cls(
            name=data["name"],
            type=data["type"],
            params=tuple(_param_from_json(p) for p in data.get("params", ())),
            pre=tuple(_condition_from_json(c) for c in data.get("pre", ())),
            hold=tuple(_condition_from_json(c) for c in data.get("hold", ())),
            post=tuple(_condition_from_json(c) for c in data.get("post", ())),
            source=data.get("source"),
            line=data.get("line"),
        )


def _typed_json(value: Typed | None) -> Any:
    if value is None:
        return None
    name, payload = value
    if name in ("list", "tuple"):
        return {"type": name, "value": [_typed_json(v) for v in payload]}
    if name == "dict":
        return {"type": name, "value": [[_typed_json(k), _typed_json(v)] for k, v in payload]}
    return {"type": name, "value": payload}


def _typed_from_json(data: Any) -> Typed | None:
    if data is None:
        return None
    name, payload = data["type"], data["value"]
    if name in ("list", "tuple"):
        return (name, tuple(_typed_from_json(v) for v in payload))
    if name == "dict":
        return (name, tuple((_typed_from_json(k), _typed_from_json(v)) for k, v in payload))
    return (name, payload)


def _param_json(p: Param) -> dict[str, Any]:
    return {
        "key": p.key,
        "kind": p.kind,
        "data_type": p.data_type,
        "element_type": p.element_type,
        "values": [_typed_json(v) for v in p.values],
        "description": p.description,
        "options": list(p.options),
    }


def _param_from_json(d: Mapping[str, Any]) -> Param:
    return Param(
        key=d["key"],
        kind=d["kind"],
        data_type=d["data_type"],
        element_type=d.get("element_type"),
        values=tuple(v for v in (_typed_from_json(x) for x in d.get("values", ()))
                     if v is not None),
        description=d.get("description", ""),
        options=tuple(d.get("options", ())),
    )


def _condition_json(c: Condition) -> dict[str, Any]:
    return {
        "kind": c.kind,
        "label": c.label,
        "vocabulary": c.vocabulary,
        "subject": c.subject,
        "object": c.object,
        "operator": c.operator,
        "value": _typed_json(c.value),
        "desired_state": _typed_json(c.desired_state),
        "children": [_condition_json(x) for x in c.children],
    }


def _condition_from_json(d: Mapping[str, Any]) -> Condition:
    return Condition(
        kind=d["kind"],
        label=d["label"],
        vocabulary=d.get("vocabulary"),
        subject=d.get("subject"),
        object=d.get("object"),
        operator=d.get("operator"),
        value=_typed_from_json(d.get("value")),
        desired_state=_typed_from_json(d.get("desired_state")),
        children=tuple(_condition_from_json(x) for x in d.get("children", ())),
    )


def models_by_name(models: Iterable[SkillModel]) -> dict[str, SkillModel]:
    """Index models by class name (the key under which two versions of a file are matched)."""
    return {m.name: m for m in models}
