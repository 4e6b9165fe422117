"""Findings about a skill that migration keeps as they were, for the reviewer's attention.

Equivalence says the migrated skill means what the legacy one meant; these say where that
meaning is probably not what the author intended (a condition on a key nobody declares,
vocabulary no loaded ontology defines, an Element type spelt without its prefix).
"""

from __future__ import annotations

import difflib
import re
from collections.abc import Mapping
from typing import TYPE_CHECKING

from ezskiros_runtime.diagnostics import Finding
from ezskiros_runtime.model import Condition, SkillModel

from .results import review_finding

if TYPE_CHECKING:
    from ezskiros_runtime.ontology.index import OntologyIndex

_CANONICAL = re.compile(r"[A-Za-z][\w.-]*:[A-Za-z_][\w.-]*\Z")
UNKNOWN_TYPE = "Unknown"
"""What SkiROS2 stores for ``Element()``: its own default, not a misspelling."""


def _walk(conditions: tuple[Condition, ...]) -> list[Condition]:
    out: list[Condition] = []
    for c in conditions:
        out.append(c)
        out += _walk(c.children)
    return out


def skill_findings(model: SkillModel, index: OntologyIndex | None,
                   lines: Mapping[tuple[str, str], int] | None = None) -> list[Finding]:
    """Findings from the static model of one skill.

    ``lines`` (``ExtractedSkill.source_lines``) gives each finding the line of the
    ``addParam`` or condition that causes it; line 0 stands for the skill as a whole.
    """
    where = lines or {}
    found: list[Finding] = []
    keys = {p.key for p in model.params}
    conditions = [c for which in ("pre", "hold", "post") for c in _walk(model.conditions(which))]
    for cond in conditions:
        for key in (cond.subject, cond.object):
            if key is not None and key not in keys:
                found.append(review_finding("undeclared-key", model.name,
                                            where.get(("key", key), 0),
                                            f"a {cond.kind} condition ({cond.label!r}) refers "
                                            f"to {key!r}, which no addParam declares (SkiROS2 "
                                            "accepts this silently)"))
    types = [p.element_type for p in model.params if p.element_type is not None]
    for type_string in types:
        if not _CANONICAL.match(type_string) and type_string != UNKNOWN_TYPE:
            found.append(review_finding("element-type-spelling", model.name,
                                        where.get(("type", type_string), 0),
                                        f"Element type {type_string!r} is not written as "
                                        "prefix:Name; SkiROS2 stores it verbatim (kept as is)"))
    if index is not None:
        vocabulary = [(t, "class", ("type", t)) for t in types] + [
            (c.vocabulary, "class" if c.kind == "on_type" else "property",
             ("vocabulary", c.vocabulary)) for c in conditions if c.vocabulary and c.kind != "or"]
        for term, what, source in vocabulary:
            iri = index.expand(term)
            known = iri is not None and (index.is_class(iri) if what == "class"
                                         else index.property(iri) is not None)
            if not known and term != UNKNOWN_TYPE:
                hint = _close(term, index.suggest(
                    term, ("class",) if what == "class" else ("object", "data")))
                extra = f"; did you mean {', '.join(hint)}?" if hint else ""
                prefix, colon, _ = term.partition(":")
                unknown = prefix if colon and prefix not in index.prefixes else ""
                found.append(review_finding("unknown-vocabulary", model.name,
                                            where.get(source, 0),
                                            f"{what} {term!r} is not in the loaded ontology"
                                            f"{extra}", unknown))
    return _unique(found)


def _close(term: str, suggestions: list[str]) -> list[str]:
    """Only suggestions that are a typo away, not a guess: of the term's own prefix with a
    close local name, or of another prefix with the same local name (a misspelt prefix,
    ``skirso:Product``); ``scalable:Ur5EndEffector`` is no ``rparts:EndEffector``."""
    prefix, _, local = term.rpartition(":")
    found = []
    for s in suggestions:
        other_prefix, _, other = s.rpartition(":")
        close = difflib.SequenceMatcher(None, local.lower(), other.lower()).ratio() >= 0.8
        if (other_prefix == prefix and close) or \
                (other_prefix != prefix and other.lower() == local.lower()):
            found.append(s)
    return found


def _unique(findings: list[Finding]) -> list[Finding]:
    seen: set[tuple[str, str]] = set()
    out = []
    for f in findings:
        if (f.kind, f.message) not in seen:
            seen.add((f.kind, f.message))
            out.append(f)
    return out
