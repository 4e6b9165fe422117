"""The runtime's early checks, run on a legacy description without importing user code.

The facts extracted from ``createDescription`` become the same ``Trace`` the EzSkiROS
runtime builds when it traces a migrated description, so a legacy skill gets exactly the
findings its migrated form would get at load time (domain/range, property kinds, value
types, unknown vocabulary with suggestions, undeclared keys...). Legacy code also has
mistakes the DSL makes impossible, checked here: duplicate keys, a mistyped prefix
(``"skiros;:Parameter"``), and an Element type spelt like a known class but not exactly.
"""

from __future__ import annotations

import builtins
import difflib
import re
from collections.abc import Iterable
from dataclasses import replace
from types import SimpleNamespace
from typing import TYPE_CHECKING, Any, cast

from ezskiros_runtime.codes import rule_for
from ezskiros_runtime.diagnostics import Finding
from ezskiros_runtime.dsl.check_context import CheckContext, Trace
from ezskiros_runtime.dsl.checking import CHECKS
from ezskiros_runtime.dsl.collectors import Recorded
from ezskiros_runtime.dsl.conditions import Cond
from ezskiros_runtime.dsl.parameters import ParamSpec

from ..report.static_facts import CondFact, StaticDescription

if TYPE_CHECKING:
    from ezskiros_runtime.ontology.index import OntologyIndex

UNKNOWN_TYPE = "Unknown"
_QUALIFIED = re.compile(r"[A-Za-z][\w.-]*:[A-Za-z_][\w.-]*\Z")
_NO_SOURCE = cast(Any, SimpleNamespace())
"""The traced function: none (no ``__code__``), so parameter findings take our lines."""
_SPELLING_KINDS = frozenset({"prefix-typo", "class-spelling", "element-type-spelling"})


def _cond(fact: CondFact) -> Cond:
    return Cond(fact.kind, subject=fact.subject, vocabulary=fact.vocabulary,
                object=fact.object, operator=fact.operator, value=fact.value,
                desired=fact.desired, label=fact.label,
                children=tuple(_cond(c) for c in fact.children))


def _spec(fact: Any) -> ParamSpec:
    value = fact.value
    if fact.mode == "type":
        found = getattr(builtins, fact.type_name or "", None)
        value = found if isinstance(found, type) else None
    element_type = fact.element_type if fact.mode == "element" else None
    return ParamSpec(name=fact.key, key=fact.key, kind=fact.kind, value_mode=fact.mode,
                     value=value, element_type=element_type, options=fact.options)


def trace_of(skill: str, path: str, facts: StaticDescription) -> Trace:
    """The trace the runtime would record for the migrated form of this description."""
    recorded = tuple(Recorded(which, _cond(c), path, c.line) for which, c in facts.conditions)
    return Trace(skill, _NO_SOURCE, tuple(_spec(p) for p in facts.params), recorded)


def _walk(fact: CondFact) -> Iterable[CondFact]:
    yield fact
    for child in fact.children:
        yield from _walk(child)


def _terms(facts: StaticDescription) -> list[tuple[str, str, int]]:
    """``(term, "class" | "property", line)`` for every name the description uses."""
    terms = [(p.element_type, "class", p.line) for p in facts.params
             if p.mode == "element" and p.element_type not in (None, UNKNOWN_TYPE)]
    for _, top in facts.conditions:
        for c in _walk(top):
            if c.vocabulary is not None and c.kind != "or":
                terms.append((c.vocabulary, "class" if c.kind == "on_type" else "property",
                              c.line))
    return [(str(t), what, line) for t, what, line in terms]


def _squash(name: str) -> str:
    return re.sub(r"[\W_]", "", name).casefold()


class _Spellings:
    """The loaded classes keyed by prefix and squashed local name, built once per index."""

    def __init__(self, index: OntologyIndex) -> None:
        self.prefixes = sorted(index.prefixes)
        self.classes: dict[tuple[str, str], str] = {}
        for iri in index.classes:
            qname = index.compact(iri)
            prefix, colon, local = qname.partition(":")
            if colon:
                self.classes.setdefault((prefix, _squash(local)), qname)


_CACHE: dict[int, tuple[OntologyIndex, _Spellings]] = {}


def _spellings(index: OntologyIndex) -> _Spellings:
    cached = _CACHE.get(id(index))
    if cached is None or cached[0] is not index:
        cached = _CACHE[id(index)] = (index, _Spellings(index))
    return cached[1]


def _prefix_typo(term: str, spell: _Spellings) -> str | None:
    """The corrected term when its prefix is a typo of a defined one, else None."""
    prefix, colon, local = term.partition(":")
    if not colon or "://" in term or not prefix:
        return None
    stripped = local.lstrip(":;,. ")
    if prefix in spell.prefixes and stripped == local:
        return None
    fixed = prefix if prefix in spell.prefixes else None
    if fixed is None:
        cleaned = re.sub(r"\W", "", prefix)
        close = difflib.get_close_matches(prefix, spell.prefixes, n=1, cutoff=0.75)
        fixed = cleaned if cleaned in spell.prefixes else close[0] if close else None
    return f"{fixed}:{stripped}" if fixed is not None and stripped else None


def _found(kind: str, line: int, message: str, fix: str | None = None) -> Finding:
    """A finding of a legacy description's own checks; ``legacy_hits`` says whose."""
    return Finding(kind, rule_for(kind).severity, message, None, line, "", fix=fix)


def spelling_hits(facts: StaticDescription, index: OntologyIndex) -> list[tuple[str, Finding]]:
    """``(term, finding)``: mistyped prefixes, unqualified Element types, misspelt classes."""
    spell = _spellings(index)
    found: list[tuple[str, Finding]] = []
    for term, what, line in _terms(facts):
        fixed = _prefix_typo(term, spell)
        is_type = any(p.element_type == term for p in facts.params)
        if fixed is not None:
            found.append((term, _found("prefix-typo", line,
                                    f"{what} {term!r}: the prefix is mistyped; SkiROS2 "
                                    f"stores it verbatim and matches nothing (did you mean "
                                    f"{fixed}?)", f"Write {fixed!r}.")))
            continue
        if is_type and not _QUALIFIED.match(term):
            found.append((term, _found("element-type-spelling", line,
                                    f"Element type {term!r} is not written as prefix:Name; "
                                    "SkiROS2 stores it verbatim")))
            continue
        iri = index.expand(term)
        if what == "class" and (iri is None or not index.is_class(iri)):
            prefix, _, local = term.partition(":")
            exact = spell.classes.get((prefix, _squash(local)))
            if exact is not None and exact != term:
                found.append((term, _found("class-spelling", line,
                                        f"class {term!r} differs from {exact} only in "
                                        f"spelling; SkiROS2 compares type strings exactly",
                                        f"Write {exact!r}.")))
    return found


def _duplicates(facts: StaticDescription) -> list[Finding]:
    """Keys declared twice by the class itself (redeclaring a base's key is an override)."""
    first: dict[str, int] = {}
    hits = []
    for p in facts.params:
        if not p.own:
            continue
        if p.key in first:
            hits.append(_found("duplicate-key", p.line,
                            f"addParam({p.key!r}) declares the key again (first at line "
                            f"{first[p.key]}); SkiROS2 keeps only this one"))
        first.setdefault(p.key, p.line)
    return hits


def legacy_hits(skill: str, path: str, facts: StaticDescription,
                index: OntologyIndex | None) -> list[Finding]:
    """Every finding for one converted legacy description, in source order."""
    hits = [replace(h, file=path, skill=skill) for h in _duplicates(facts)]
    if index is None:
        return hits
    spelled = spelling_hits(facts, index)
    hits += [replace(h, file=path, skill=skill) for _, h in spelled]
    flagged = {term for term, _ in spelled}
    lines = {p.key: p.line for p in facts.params}
    ctx = CheckContext(trace_of(skill, path, facts), index)
    for check in CHECKS:
        check(ctx)
    for f in ctx.findings:
        if f.kind == "unknown-vocabulary" and f.actual in flagged:
            continue  # said more precisely by a spelling finding
        hits.append(replace(f, line=f.line or lines.get(f.param or "", 0)))
    return sorted(hits, key=lambda h: h.line or 0)


__all__ = ["legacy_hits", "spelling_hits", "trace_of"]
