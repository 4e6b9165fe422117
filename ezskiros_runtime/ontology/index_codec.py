"""An `OntologyIndex` as JSON-ready data and back, checking every field on the way in.

Why not pickle: unpickling runs whatever code the file names, and the cache folder is
writable by anything that ever ran as the user, so one bad process could own every later
one (issue 40). JSON can only describe data; ``decode`` then accepts exactly the shape
``encode`` writes (strings where strings belong, known property kinds, expressions of the
five known forms) and raises `MalformedIndex` on anything else, so a truncated, forged or
foreign entry is rebuilt from the ontology files instead of trusted.

Compact on purpose: an expression is an IRI string when named (nearly always) and a
two-element list otherwise; a property is one list. The warm start reads this on every
launch. Runs on the robot's Python 3.8.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from .expressions import ClassExpr, ComplementOf, IntersectionOf, Named, UnionOf, Unsupported
from .index import PROPERTY_KINDS, ClassGraph, OntologyIndex, PropertyInfo

FORMAT = "ezskiros-ontology-index"
MAX_DEPTH = 64
"""Deepest class expression accepted (real files nest two or three levels)."""


class MalformedIndex(ValueError):
    """The data is not an index this code wrote."""


def encode(index: OntologyIndex, version: str) -> dict[str, Any]:
    """The index as plain JSON data (dicts, lists, strings, None)."""
    return {
        "format": FORMAT,
        "version": version,
        "fingerprint": index.fingerprint,
        "default_prefix": index.default_prefix,
        "prefixes": dict(index.prefixes),
        "classes": sorted(index.classes),
        "superclasses": {c: sorted(index.direct_superclasses(c)) for c in
                         sorted(index.direct_superclass_map())},
        "equivalent": {c: sorted(index.equivalent_classes(c)) for c in
                       sorted(index.equivalent_class_map())},
        "properties": [_property(info) for _iri, info in sorted(index.properties.items())],
        "sources": list(index.sources),
        "individuals": None if index.individuals is None else dict(index.individuals),
    }


def _property(info: PropertyInfo) -> list[Any]:
    return [info.iri, info.kind, [_expression(e) for e in info.domains],
            [_expression(e) for e in info.ranges], sorted(info.parents),
            list(info.domain_sources), list(info.range_sources)]


def _expression(expr: ClassExpr) -> Any:
    if isinstance(expr, Named):
        return expr.iri
    if isinstance(expr, UnionOf):
        return ["or", [_expression(m) for m in expr.members]]
    if isinstance(expr, IntersectionOf):
        return ["and", [_expression(m) for m in expr.members]]
    if isinstance(expr, ComplementOf):
        return ["not", _expression(expr.expr)]
    if isinstance(expr, Unsupported):
        return ["?", expr.text]
    raise TypeError(f"not a class expression: {expr!r}")


def decode(data: object, fingerprint: str, version: str) -> OntologyIndex:
    """The index ``data`` describes; `MalformedIndex` unless it is exactly what ``encode``
    wrote for this fingerprint and format version."""
    top = _mapping(data)
    if top.get("format") != FORMAT or top.get("version") != version:
        raise MalformedIndex("not an index of this format")
    if top.get("fingerprint") != fingerprint:
        raise MalformedIndex("an index of other content")
    individuals = top.get("individuals")
    return OntologyIndex(
        prefixes=_strings_to(top.get("prefixes"), _string),
        classes=ClassGraph(_strings(top.get("classes")),
                           _strings_to(top.get("superclasses"), _strings),
                           _strings_to(top.get("equivalent"), _strings)),
        properties=_properties(top.get("properties")),
        sources=_strings(top.get("sources")),
        fingerprint=fingerprint,
        default_prefix=_string(top.get("default_prefix")),
        individuals=None if individuals is None else _strings_to(individuals, _strings),
    )


def _properties(value: object) -> dict[str, PropertyInfo]:
    found: dict[str, PropertyInfo] = {}
    for entry in _list(value):
        fields = _list(entry)
        if len(fields) != 7:
            raise MalformedIndex("a property of another shape")
        iri, kind = _string(fields[0]), _string(fields[1])
        if kind not in PROPERTY_KINDS:
            raise MalformedIndex(f"unknown property kind {kind!r}")
        found[iri] = PropertyInfo(
            iri=iri, kind=kind,
            domains=tuple(_read_expression(e, 0) for e in _list(fields[2])),
            ranges=tuple(_read_expression(e, 0) for e in _list(fields[3])),
            parents=frozenset(_strings(fields[4])),
            domain_sources=tuple(_strings(fields[5])),
            range_sources=tuple(_strings(fields[6])))
    return found


def _read_expression(value: object, depth: int) -> ClassExpr:
    if isinstance(value, str):
        return Named(value)
    if depth > MAX_DEPTH:
        raise MalformedIndex("a class expression nested too deep")
    pair = _list(value)
    if len(pair) != 2:
        raise MalformedIndex("a class expression of another shape")
    tag, body = pair
    if tag == "or":
        return UnionOf(tuple(_read_expression(m, depth + 1) for m in _list(body)))
    if tag == "and":
        return IntersectionOf(tuple(_read_expression(m, depth + 1) for m in _list(body)))
    if tag == "not":
        return ComplementOf(_read_expression(body, depth + 1))
    if tag == "?":
        return Unsupported(_string(body))
    raise MalformedIndex(f"unknown class expression {tag!r}")


def _mapping(value: object) -> Mapping[str, Any]:
    if not isinstance(value, dict):
        raise MalformedIndex("an object was expected")
    return value


def _list(value: object) -> list[Any]:
    if not isinstance(value, list):
        raise MalformedIndex("a list was expected")
    return value


def _string(value: object) -> str:
    if not isinstance(value, str):
        raise MalformedIndex("a string was expected")
    return value


def _strings(value: object) -> list[str]:
    items = _list(value)
    if not all(isinstance(item, str) for item in items):
        raise MalformedIndex("a list of strings was expected")
    return items


def _strings_to(value: object, read: Any) -> dict[str, Any]:
    return {_string(key): read(item) for key, item in _mapping(value).items()}
