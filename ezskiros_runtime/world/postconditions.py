"""Post-conditions that leave an element with two parents or a subject in two places.

SkiROS2's task manager turns a skill's post-conditions into the effects of its PDDL action
(``skiros2_task``: ``pddl.Action(skill, params, preconds, holdconds, postconds)``). When the
pre-conditions require ``Container contain Object`` and the post-conditions add ``Gripper
contain Object`` without retracting the first, the planner believes the object is in both
places after the skill. For a relation the world model keeps single-valued
(``vocabulary.single_valued``) that is a finding, with the retraction as a suggestion (never
applied automatically: it changes what the planner believes). Not findings: the retraction
is there, both ends are the same parameter key (names remapped onto keys compare as keys),
or the first relation is required *not* to hold.

Works on ``RelationUse`` (plain data), so legacy descriptions read statically and loaded
EzSkiROS models are checked by the same code.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Iterable

from ..model import SkillModel, untyped
from .vocabulary import SingleValued

if TYPE_CHECKING:
    from ..ontology.index import OntologyIndex


@dataclass(frozen=True)
class RelationUse:
    """One relation condition: which list, relation as written, keys, desired state, and
    the source line (0 when unknown)."""

    which: str
    relation: str
    subject: str
    object: str
    desired: bool
    line: int = 0
    label: str = ""


@dataclass(frozen=True)
class DoublePlace:
    """A post-condition ``second`` that adds a single-valued relation the pre-condition
    ``first`` requires to another element, with no retraction of ``first``."""

    first: RelationUse
    second: RelationUse
    entry: SingleValued

    @property
    def unique(self) -> str:
        """The key that ends up with two: the object (two parents) or the subject."""
        return self.first.object if self.entry.per == "object" else self.first.subject

    def message(self) -> str:
        what = "parents" if self.entry.per == "object" else "places"
        other = (self.first.subject, self.second.subject) if self.entry.per == "object" \
            else (self.first.object, self.second.object)
        return (f"post-condition {self.second.subject} {self.second.relation} "
                f"{self.second.object} leaves {self.unique} with two {what}: the "
                f"pre-condition {self.first.subject} {self.first.relation} "
                f"{self.first.object} is never retracted, so after the skill the planner "
                f"believes both {other[0]} and {other[1]} ({self.entry.name} is "
                "single-valued)")

    def fix(self, form: str) -> str:
        """The missing retraction, written as the file writes conditions: ``legacy``
        (``getRelationCond(..., False)``) or ``ezskiros`` (``~ A.contain(B)``)."""
        return "Add the retraction: " + retraction(self.first, form)


def retraction(use: RelationUse, form: str) -> str:
    """The post-condition that retracts ``use``, in the file's own form."""
    if form == "legacy":
        local = use.relation.rpartition(":")[2]
        label = f"Not{use.subject}{local[:1].upper()}{local[1:]}{use.object}"
        return (f"self.addPostCondition(self.getRelationCond({label!r}, {use.relation!r}, "
                f"{use.subject!r}, {use.object!r}, False))").replace("'", '"')
    subject, obj = _name(use.subject), _name(use.object)
    local = use.relation.rpartition(":")[2]
    call = f"{subject}.{local}({obj})" if local.isidentifier() \
        else f'{subject}.relation("{use.relation}", {obj})'
    return f"self.post_conditions += ~ {call}"


def _name(key: str) -> str:
    return key if key.isidentifier() else f'self.param("{key}")'


def double_places(uses: Iterable[RelationUse], entries: list[SingleValued],
                  index: OntologyIndex | None) -> list[DoublePlace]:
    """Every post-condition that leaves two parents or two places, once per pair."""
    listed = list(uses)

    def covered(use: RelationUse, entry: SingleValued) -> bool:
        iri = (index.expand(use.relation) if index is not None else None) or use.relation
        return iri in entry.members or use.relation in entry.members

    found = []
    for entry in entries:
        def ends(use: RelationUse, entry: SingleValued = entry) -> tuple:
            return (use.object, use.subject) if entry.per == "object" \
                else (use.subject, use.object)

        pres = [u for u in listed if u.which == "pre" and u.desired and covered(u, entry)]
        posts = [u for u in listed if u.which == "post" and covered(u, entry)]
        misspelt = [u for u in listed if u.which == "post" and not u.desired
                    and not covered(u, entry) and _misspells(u.relation, pres, index)]
        for first in pres:
            key, old = ends(first)
            if any(not p.desired and ends(p) == (key, old) for p in [*posts, *misspelt]):
                continue  # retracted (a misspelt retraction is its own finding, EZ209)
            for second in posts:
                if second.desired and ends(second)[0] == key and ends(second)[1] != old:
                    found.append(DoublePlace(first, second, entry))
    unique = {(d.first, d.second): d for d in found}
    return sorted(unique.values(), key=lambda d: (d.second.line, d.first.line))


def past_typos(uses: Iterable[RelationUse], declared: Iterable[str]) -> list[RelationUse]:
    """``uses`` with each key no parameter declares read as the one declared key it
    misspells by one letter (``tartLocation`` for ``StartLocation``): the typo is its own
    finding (EZ104), and the conditions beside it are judged as meant, not reported again
    for what the typo breaks (one cause, one finding)."""
    known = set(declared) | {"Robot"}

    def meant(key: str) -> str:
        if key in known:
            return key
        close = [k for k in known if one_edit(key, k)]
        return close[0] if len(close) == 1 else key

    return [replace(u, subject=meant(u.subject), object=meant(u.object)) for u in uses]


def _misspells(relation: str, uses: list[RelationUse], index: OntologyIndex | None) -> bool:
    """Whether ``relation`` is a name the ontology does not define, spelt like the relation
    of one of ``uses``: a typo reported as such (EZ209), so that the retraction it was
    meant to be is not reported again as missing (one cause, one finding)."""
    if index is None or index.property(index.expand(relation) or relation) is not None:
        return False
    return any(one_edit(relation, u.relation) for u in uses)


def one_edit(a: str, b: str) -> bool:
    """Whether two different names differ by one letter dropped, added, changed, or two
    neighbours swapped (the prefix, before ``:``, the same)."""
    if a == b or a.rpartition(":")[0] != b.rpartition(":")[0]:
        return False
    x, y = a.rpartition(":")[2], b.rpartition(":")[2]
    if abs(len(x) - len(y)) > 1:
        return False
    start = next((i for i, (p, q) in enumerate(zip(x, y)) if p != q), min(len(x), len(y)))
    if len(x) == len(y):
        return x[start + 1:] == y[start + 1:] or (
            x[start + 2:] == y[start + 2:] and x[start:start + 2] == y[start:start + 2][::-1])
    longer, shorter = (x, y) if len(x) > len(y) else (y, x)
    return longer[start + 1:] == shorter[start:]


def uses_of(model: SkillModel) -> list[RelationUse]:
    """The relation conditions of a loaded model (lines unknown: 0)."""
    found = []
    for which in ("pre", "post"):
        for c in model.conditions(which):
            if c.kind == "relation" and c.subject and c.object and c.vocabulary:
                desired = untyped(c.desired_state) if c.desired_state is not None else True
                found.append(RelationUse(which, c.vocabulary, c.subject, c.object,
                                         desired is not False, 0, c.label))
    return found


__all__ = ["DoublePlace", "RelationUse", "double_places", "one_edit", "past_typos", "retraction",
           "uses_of"]
