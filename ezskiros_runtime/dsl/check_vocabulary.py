"""Check: does every name the description uses exist in the loaded ontology?

SkiROS2 accepts unknown vocabulary silently, and real projects use names from files the
checker may not have, so an unknown name is a warning by default (an error in strict mode).
A local name that several prefixes define (``A.robotPart``) cannot be lowered faithfully and
is an error that points to the verbatim form.
"""

from __future__ import annotations

from collections.abc import Iterator

from ..diagnostics import did_you_mean
from .check_context import CheckContext
from .collectors import Recorded
from .conditions import Cond
from .vocabulary import normalized_name, suggestions, to_iri

_PROPERTY_KINDS = ("object", "data")
_WHAT = {
    "relation": "relation",
    "abstract_relation": "relation",
    "property": "property",
    "has_property": "property",
    "on_type": "class",
}


def walk(cond: Cond) -> Iterator[Cond]:
    """The condition and, for or-conditions, all its descendants."""
    yield cond
    for child in cond.children:
        yield from walk(child)


def _known_class(ctx: CheckContext, name: str) -> bool:
    iri = to_iri(ctx.index, name)
    return iri is not None and ctx.index.is_class(iri)


def _known_property(ctx: CheckContext, name: str) -> bool:
    iri = to_iri(ctx.index, name)
    return iri is not None and ctx.index.property(iri) is not None


_PROPERTY_NOUNS = {"object": "an object property", "data": "a datatype property",
                   "annotation": "an annotation property"}


def _other_kind(ctx: CheckContext, name: str) -> str | None:
    """What the ontology does define ``name`` as ("a class", "an object property"), for a
    name used as something else (``A.has(skiros.Product)``), else None."""
    iri = to_iri(ctx.index, name)
    if iri is None:
        return None
    if ctx.index.is_class(iri):
        return "a class"
    info = ctx.index.property(iri)
    return _PROPERTY_NOUNS.get(info.kind) if info is not None else None


def _undefined_prefix(ctx: CheckContext, name: str) -> bool:
    """Whether ``name``'s prefix is one no loaded file defines (a full IRI has none)."""
    prefix = normalized_name(ctx.index, name).partition(":")[0]
    return prefix not in ctx.index.prefixes and "://" not in name


def _unknown_reason(ctx: CheckContext, name: str, what: str) -> str:
    if _undefined_prefix(ctx, name):
        prefix = normalized_name(ctx.index, name).partition(":")[0]
        return f"{what} {name}: prefix {prefix!r} is not defined by the loaded ontology"
    other = _other_kind(ctx, name)
    if other is not None:
        return f"{what} {name}: {name} is {other} in the loaded ontology, not a {what}"
    return f"{what} {name} is not in the loaded ontology"


def check_parameter_classes(ctx: CheckContext) -> None:
    """Every Element parameter's type string names a known class (``Element()`` aside)."""
    for spec in ctx.trace.specs:
        name = spec.element_type
        if not spec.is_element or name is None or name == "Unknown":
            continue
        if _known_class(ctx, name):
            continue
        hints = suggestions(ctx.index, normalized_name(ctx.index, name), ("class",))
        file, line = ctx.param_location(spec.name)
        ctx.add("unknown-vocabulary",
                f"parameter {spec.key}: {_unknown_reason(ctx, name, 'class')}"
                f"{did_you_mean(hints)}", file, line, _undefined_prefix(ctx, name),
                param=spec.key, actual=name, suggestions=hints)


def _check_condition(ctx: CheckContext, record: Recorded, cond: Cond) -> None:
    what = _WHAT.get(cond.kind)
    if what is None or cond.vocabulary is None:
        return
    note = cond.note
    if note is not None and note.status == "ambiguous":
        options = " or ".join(f'{cond.subject}.relation("{c}", ...)' if cond.kind != "property"
                              else f'{cond.subject}.property("{c}", ...)'
                              for c in note.candidates)
        ctx.add("ambiguous-vocabulary",
                f"{cond.subject}.{note.written}: {note.written!r} is defined under several "
                f"prefixes ({', '.join(note.candidates)}); write {options}",
                record.file, record.line, param=cond.subject, relation=note.written,
                suggestions=note.candidates)
        return
    if what == "class":
        known = _known_class(ctx, cond.vocabulary)
        kinds: tuple[str, ...] = ("class",)
    else:
        known = _known_property(ctx, cond.vocabulary)
        kinds = _PROPERTY_KINDS
    if known:
        return
    hints = suggestions(ctx.index, normalized_name(ctx.index, note.written if note
                                                   else cond.vocabulary), kinds)
    if note is not None:
        message = (f"{cond.subject}.{note.written}: no object or datatype property named "
                   f"{note.written!r} in the loaded ontology; lowered as {cond.vocabulary}"
                   f"{did_you_mean(hints)}")
    else:
        message = f"{_unknown_reason(ctx, cond.vocabulary, what)}{did_you_mean(hints)}"
    ctx.add("unknown-vocabulary", message, record.file, record.line,
            note is None and _undefined_prefix(ctx, cond.vocabulary), param=cond.subject,
            relation=cond.vocabulary if what != "class" else None,
            actual=cond.vocabulary, suggestions=hints)


def check_condition_vocabulary(ctx: CheckContext) -> None:
    """Relations, properties and types in every recorded condition are known and unique."""
    for record in ctx.trace.recorded:
        for cond in walk(record.condition):
            _check_condition(ctx, record, cond)


__all__ = ["check_condition_vocabulary", "check_parameter_classes", "walk"]
