"""The readings ``facts_cache`` keeps, as JSON that cannot run code when it is read.

A file's facts are objects of this project's own classes (``FileFacts``, ``TreeFacts``,
``ModuleFacts``, the runtime's ``CompoundModel`` and ``Scene``, ...) holding literals,
tuples, sets and dicts. ``encode`` writes each object as its class's name and its fields;
``decode`` rebuilds only classes of ``ezmigrate`` and ``ezskiros_runtime`` (the modules
already imported, or importable from those two packages), setting their fields directly:
no constructor, no ``__setstate__``, no callable named by the data is ever called, so a
forged entry can at worst be a wrong reading, which its signature (``cache_folder``)
already refuses. Anything else in the data is a ``CodecError``, a miss.
"""

from __future__ import annotations

import base64
import dataclasses
import importlib
import json
import sys
from typing import Any

OWN = ("ezmigrate.", "ezskiros_runtime.")
"""The packages whose classes an entry may name."""


class CodecError(ValueError):
    """Data that is not an encoding of our own readings."""


def encode(value: Any) -> Any:
    """``value`` as JSON-ready data (lists, dicts of strings, literals). Every dict of the
    encoding is a tagged node (``t``, ``b``, ``fs``, ``s``, ``d``, or ``c`` with ``f``), so
    that the JSON parser can rebuild each node as it reads it (``loads``)."""
    if value is None or isinstance(value, (bool, int, float, str)):
        return value
    if isinstance(value, list):
        return [encode(v) for v in value]
    if isinstance(value, bytes):
        return {"b": base64.b64encode(value).decode("ascii")}
    if isinstance(value, tuple):
        return {"t": [encode(v) for v in value]}
    if isinstance(value, (set, frozenset)):  # in one order, whatever the hash seed:
        items = sorted((encode(v) for v in value), key=_order)  # one reading, one text
        return {"fs" if isinstance(value, frozenset) else "s": items}
    if isinstance(value, dict):
        return {"d": [[encode(k), encode(v)] for k, v in value.items()]}
    kind = type(value)
    name = f"{kind.__module__}:{kind.__qualname__}"
    if not name.startswith(OWN):
        raise CodecError(f"not a reading of ours: {name}")
    return {"c": name, "f": [[key, encode(v)] for key, v in _fields(value).items()]}


def _order(item: Any) -> str:
    return json.dumps(item, sort_keys=True)


def _fields(value: Any) -> dict[str, Any]:
    if dataclasses.is_dataclass(value):
        return {f.name: getattr(value, f.name) for f in dataclasses.fields(value)}
    found: dict[str, Any] = dict(getattr(value, "__dict__", {}))
    for slot in getattr(type(value), "__slots__", ()):
        if hasattr(value, slot):
            found[slot] = getattr(value, slot)
    return found


def loads(payload: bytes | str) -> Any:
    """The value ``encode`` gave the JSON text ``payload`` for, each node rebuilt by the
    JSON parser as it reads it (``_node``: a Python call per tagged node, not per value);
    ``CodecError`` for anything else (``ValueError`` for text that is no JSON)."""
    return json.loads(payload, object_hook=_node)


def decode(data: Any) -> Any:
    """``loads`` of data already parsed from JSON."""
    if data is None or isinstance(data, (bool, int, float, str)):
        return data
    if isinstance(data, list):
        return [decode(v) for v in data]
    if isinstance(data, dict):
        return _node({key: decode(v) for key, v in data.items()})
    raise CodecError("unexpected data")


def _node(node: dict[str, Any]) -> Any:
    """One tagged node of an encoding, its contents rebuilt already."""
    if len(node) == 1:
        [(tag, value)] = node.items()
        if tag == "t":
            return tuple(_list(value))
        if tag == "b" and isinstance(value, str):
            try:
                return base64.b64decode(value, validate=True)
            except ValueError as error:
                raise CodecError("bytes that are not base64") from error
        if tag == "fs":
            return frozenset(_list(value))
        if tag == "s":
            return set(_list(value))
        if tag == "d":
            return dict(_pairs(value))
    elif len(node) == 2 and isinstance(node.get("c"), str) and "f" in node:
        return _instance(node["c"], _pairs(node["f"]))
    raise CodecError("unexpected data")


def _list(data: Any) -> list[Any]:
    if not isinstance(data, list):
        raise CodecError("a list was expected")
    return data


def _pairs(data: Any) -> list[tuple[Any, Any]]:
    """The ``[key, value]`` pairs of a dict's or an object's encoding."""
    pairs = _list(data)
    if not all(isinstance(p, list) and len(p) == 2 for p in pairs):
        raise CodecError("an entry is no pair")
    return [(key, value) for key, value in pairs]


def _instance(name: str, fields: list[tuple[Any, Any]]) -> Any:
    """An object of our own class ``name`` with ``fields`` set, its constructor not run."""
    kind, allowed = _class(name)
    value: Any = object.__new__(kind)
    for key, item in fields:
        if not isinstance(key, str) or (allowed is not None and key not in allowed):
            raise CodecError(f"{name} has no field {key!r}")
        object.__setattr__(value, key, item)
    return value


_CLASSES: dict[str, tuple[type, frozenset[str] | None]] = {}
"""Each class an entry named, found once per process (a pack names a few dozen classes in
ten thousand objects)."""


def _class(name: str) -> tuple[type, frozenset[str] | None]:
    """Our own class ``name`` (``module:qualname``) and its fields (None: not a dataclass)."""
    found = _CLASSES.get(name)
    if found is not None:
        return found
    module_name, _, qualname = name.partition(":")
    if not name.startswith(OWN) or not qualname:
        raise CodecError(f"not a class of ours: {name}")
    module = sys.modules.get(module_name)
    if module is None:
        try:
            module = importlib.import_module(module_name)
        except ImportError as error:
            raise CodecError(f"no module {module_name}") from error
    kind: Any = module
    for part in qualname.split("."):
        kind = getattr(kind, part, None)
    if not isinstance(kind, type) or kind.__module__ != module_name:
        raise CodecError(f"not a class of ours: {name}")
    allowed = frozenset(f.name for f in dataclasses.fields(kind)) \
        if dataclasses.is_dataclass(kind) else None
    _CLASSES[name] = (kind, allowed)
    return kind, allowed
