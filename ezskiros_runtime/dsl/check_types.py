"""Check: do conditions fit the ontology's types (domain, range, datatype, operator)?

These are the paper's early checks. The subject of a relation must satisfy every
``rdfs:domain`` and its object every ``rdfs:range`` (the index already folds in
``subPropertyOf`` inheritance, and ``satisfies`` handles the subclass closure and
``owl:unionOf``). A data property's value must have the Python type its XSD range means and
ordering operators need a numeric range. Whatever the index cannot decide (an unknown class,
an unsupported class expression) is skipped: a checker must not guess.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from ..ontology.expressions import every
from ..ontology.naming import XSD
from .check_context import CheckContext
from .check_vocabulary import walk
from .collectors import Recorded
from .conditions import Cond
from .vocabulary import to_iri

_INTS = ("int", "integer", "long", "short", "byte", "nonNegativeInteger", "positiveInteger",
         "nonPositiveInteger", "negativeInteger", "unsignedInt", "unsignedLong",
         "unsignedShort", "unsignedByte")
XSD_PYTHON: dict[str, tuple[type, ...]] = {
    "boolean": (bool,),
    "string": (str,),
    "normalizedString": (str,),
    "token": (str,),
    "float": (float, int),
    "double": (float, int),
    "decimal": (float, int),
    **{name: (int,) for name in _INTS},
}
"""Python value types a property condition may compare an XSD datatype with (type-exact:
``bool`` is not an ``int``)."""

ORDERING = (">", "<", ">=", "<=")
OPERATORS = ("=", *ORDERING)


_PLAIN = (bool, int, float, str, list, dict)


def _plain_value_type(ctx: CheckContext, key: str) -> str | None:
    """The Python type name of a parameter that is certainly no world element, else None.

    A bare kind marker may carry any run-time value (``Thing: INFERRED = Element(...)``),
    so only plain data types and literals of them count as certain.
    """
    spec = ctx.params.get(key)
    if spec is None or spec.is_element:
        return None
    value = spec.value
    if isinstance(value, type):
        return value.__name__ if value in _PLAIN else None
    return type(value).__name__ if type(value) in _PLAIN else None


def _check_side(ctx: CheckContext, record: Recorded, cond: Cond, key: str | None,
                exprs: Sequence[Any], side: str) -> None:
    """One side (subject or object) of a condition against the property's domains/ranges.

    An error only when the condition can never hold: the parameter is no world element, or
    no class at or below its declared one satisfies every expectation. A parameter whose
    class is merely wider (``Robot: INFERRED[sumo.Agent]`` where ``sumo:Device`` is
    expected: ``cora:Robot`` is both) may be bound to a fitting element at run time, which
    SkiROS2's legacy skills rely on, so that is the ``*-unproven`` kind (a warning).
    File, line and skill are the finding's own fields (``str(finding)`` shows them).
    """
    if key is None:
        return
    kind = "domain" if side == "subject" else "range"
    what = _plain_value_type(ctx, key)
    if what is not None:  # a float can be in no relation and has no properties at all
        ctx.add(kind, f"{cond.vocabulary} applies to world elements, but parameter {key} is "
                      f"a {what}, not a world element", record.file, record.line, param=key,
                relation=cond.vocabulary, expected="an element", actual=what)
        return
    if not exprs:
        return
    iri, _shown = ctx.class_of(key)
    if iri is None:
        return
    index = ctx.index
    failing = [e for e in exprs if index.satisfies(iri, e) is False]
    if not failing:
        return
    expected = " and ".join(e.render(index.compact) for e in failing)
    actual = index.compact(iri)
    wanted = every(exprs)
    possible = index.can_satisfy(iri, wanted)
    if possible is None:  # undecidable below the declared class: report nothing
        return
    if possible:
        example = index.compact(str(index.witness(iri, wanted)))
        ctx.add(f"{kind}-unproven",
                f"{cond.vocabulary} expects {side} of class {expected}, but parameter {key} "
                f"is {actual}, which only some elements are ({example} is): narrow the "
                f"parameter's type (e.g. to {example}) to be sure", record.file,
                record.line, param=key, relation=cond.vocabulary, expected=expected,
                actual=actual)
        return
    ctx.add(kind, f"{cond.vocabulary} expects {side} of class {expected}, but parameter "
                  f"{key} is {actual}", record.file, record.line, param=key,
            relation=cond.vocabulary, expected=expected, actual=actual)


def _datatypes(ranges: Sequence[Any]) -> list[tuple[str, tuple[type, ...]]]:
    """(compact xsd name, accepted Python types) for every XSD range we understand."""
    found = []
    for expr in ranges:
        iri = getattr(expr, "iri", None)
        if isinstance(iri, str) and iri.startswith(XSD) and iri[len(XSD):] in XSD_PYTHON:
            found.append((f"xsd:{iri[len(XSD):]}", XSD_PYTHON[iri[len(XSD):]]))
    return found


def _check_value(ctx: CheckContext, record: Recorded, cond: Cond, ranges: Sequence[Any]
                 ) -> None:
    datatypes = _datatypes(ranges)
    value_type = type(cond.value)
    for name, accepted in datatypes:
        if value_type not in accepted:
            ctx.add("value-type",
                    f"{cond.vocabulary} expects a {name} value, but the condition compares "
                    f"{cond.subject} with {cond.value!r} ({value_type.__name__})",
                    record.file, record.line, param=cond.subject, relation=cond.vocabulary,
                    expected=name, actual=value_type.__name__)
    if cond.operator in ORDERING:
        for name, accepted in datatypes:
            if float not in accepted and int not in accepted:
                ctx.add("operator",
                        f"{cond.vocabulary} is {name}: operator {cond.operator!r} needs a "
                        "numeric property (xsd:int, xsd:float, ...)", record.file,
                        record.line, param=cond.subject, relation=cond.vocabulary,
                        expected="numeric", actual=name)


def _check_condition(ctx: CheckContext, record: Recorded, cond: Cond) -> None:
    kind = cond.kind
    if kind == "property" and cond.operator not in OPERATORS:
        ctx.add("unknown-operator",
                f"{cond.vocabulary}: operator {cond.operator!r} is none of "
                f"{', '.join(OPERATORS)} (SkiROS2 does not validate it)", record.file,
                record.line, param=cond.subject, relation=cond.vocabulary)
    if kind not in ("relation", "abstract_relation", "property", "has_property"):
        return
    iri = to_iri(ctx.index, cond.vocabulary or "")
    info = ctx.index.property(iri) if iri is not None else None
    if info is None or info.kind not in ("object", "data"):
        return
    relational = kind in ("relation", "abstract_relation")
    local = (cond.vocabulary or "").partition(":")[2]
    if relational and info.kind == "data":
        ctx.add("property-kind",
                f"{cond.vocabulary} is a datatype property: compare it with a value "
                f"({cond.subject}.{local} == ...) instead of "
                "relating two parameters", record.file, record.line, param=cond.subject,
                relation=cond.vocabulary, expected="object property", actual="data property")
        return
    if kind == "property" and info.kind == "object":
        ctx.add("property-kind",
                f"{cond.vocabulary} is an object property: relate two parameters "
                f"({cond.subject}.{local}(Other)) instead of "
                "comparing with a value", record.file, record.line, param=cond.subject,
                relation=cond.vocabulary, expected="data property", actual="object property")
        return
    _check_side(ctx, record, cond, cond.subject, info.domains, "subject")
    if relational:
        _check_side(ctx, record, cond, cond.object, info.ranges, "object")
    elif kind == "property":
        _check_value(ctx, record, cond, info.ranges)


def check_condition_types(ctx: CheckContext) -> None:
    """Domain/range, property kind, value type and operator of every recorded condition."""
    for record in ctx.trace.recorded:
        for cond in walk(record.condition):
            _check_condition(ctx, record, cond)


__all__ = ["OPERATORS", "ORDERING", "XSD_PYTHON", "check_condition_types"]
