"""Can this skill start from this scene? Grounding as SkiROS2's skill manager does it.

The skill manager (``skill_utils.py``, ``_autoParametrizeBB``) gives every non-Optional
Element parameter without a value an element of its class (subclass closure), with the
pre-conditions as constraints: the relation and property conditions must all hold for the
choice. Scenes are small, so the assignments are searched: the pre-conditions are taken in
order, and the choices that satisfy every condition so far are extended by the parameters
the next one mentions. The first condition that leaves no choice is the reason the skill
cannot start; a parameter of a class no element has is a reason before any condition.

Not being able to start from a scene is no bug in itself (skills often run after others
changed the world), so the linter says it as ``info``; a lab's test can demand it instead:

    from ezskiros_runtime.world import can_start
    assert can_start(PaintPart, "owl/scenes/cell.turtle"), can_start(PaintPart, ...).reason
"""

from __future__ import annotations

import operator
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, Callable, Dict

from ..model import Condition, SkillModel, untyped
from .scene import Scene, read_scene
from .vocabulary import sub_properties

if TYPE_CHECKING:
    from ..ontology.index import OntologyIndex

Assignment = Dict[str, str]
MAX_CHOICES = 200_000
"""Choices tried in one search; beyond it the search gives up (``undecided``)."""
_COMPARE: dict[str, Callable[[Any, Any], bool]] = {
    "=": operator.eq, "==": operator.eq, "!=": operator.ne, ">": operator.gt,
    "<": operator.lt, ">=": operator.ge, "<=": operator.le}


@dataclass
class Grounding:
    """The answer: ``ok`` with one ``assignment`` (parameter key -> element IRI), or the
    ``reason`` it cannot start and the ``blocking`` pre-condition (None when a parameter has
    no candidate at all). ``undecided``: too many choices to search; ``ok`` is then True."""

    skill: str
    ok: bool
    assignment: Assignment = field(default_factory=dict)
    reason: str = ""
    blocking: Condition | None = None
    undecided: bool = False

    def __bool__(self) -> bool:
        return self.ok


def can_start(skill: Any, scene: Scene | str | Path,
              index: OntologyIndex | None = None) -> Grounding:
    """Whether ``skill`` (a ``SkillModel``, or a description class or instance, legacy or
    EzSkiROS) can be grounded in ``scene`` (a ``Scene`` or the path of a Turtle file).
    ``index``: the ontology for the subclass closure (default: the active one)."""
    if not isinstance(scene, Scene):
        scene = read_scene(scene)
    if index is None:
        from ..ontology.active import active_index

        index = active_index()
    return _Search(_model(skill), scene, index).run()


def _model(skill: Any) -> SkillModel:
    if isinstance(skill, SkillModel):
        return skill
    from ..legacy.extract import model_of

    return model_of(skill() if isinstance(skill, type) else skill)


def to_ground(model: SkillModel) -> list[tuple[str, str]]:
    """``(key, element type)`` of the parameters the skill manager grounds."""
    return [(p.key, p.element_type or "") for p in model.params
            if p.data_type == "Element" and p.kind != "Optional" and not p.values]


def describe(c: Condition) -> str:
    """A pre-condition as a person reads it: ``'RobotAtStation' (Robot skiros:at Station)``."""
    negation = "not " if c.desired_state is not None and untyped(c.desired_state) is False \
        else ""
    if c.kind in ("relation", "abstract_relation"):
        what = f"{negation}{c.subject} {c.vocabulary} {c.object}"
    elif c.kind == "property":
        value = untyped(c.value) if c.value is not None else None
        what = f"{negation}{c.subject}.{c.vocabulary} {c.operator} {value!r}"
    elif c.kind == "has_property":
        what = f"{c.subject} {'lacks' if negation else 'has'} {c.vocabulary}"
    elif c.kind == "on_type":
        what = f"{c.subject} is a {c.vocabulary}"
    elif c.kind == "or":
        what = " or ".join(describe(child) for child in c.children)
    else:
        what = f"{c.kind} {c.subject}"
    return f"{c.label!r} ({what})"


class _Search:
    """One skill in one scene."""

    def __init__(self, model: SkillModel, scene: Scene, index: OntologyIndex) -> None:
        self.model = model
        self.scene = scene
        self.index = index
        self.params = dict(to_ground(model))
        self.links = {(r.subject, r.property, r.object) for r in scene.relations}
        self.out_links: dict[str, list[tuple[str, str]]] = {}
        self.in_links: dict[str, list[tuple[str, str]]] = {}
        for r in scene.relations:
            self.out_links.setdefault(r.subject, []).append((r.property, r.object))
            self.in_links.setdefault(r.object, []).append((r.property, r.subject))
        self._below: dict[str, list[str]] = {}

    def candidates(self, element_type: str) -> list[str]:
        wanted = self.index.expand(element_type) if element_type else None
        if wanted is None:
            return []
        return sorted(e.iri for e in self.scene.elements.values()
                      if any(self.index.is_subclass(t, wanted) for t in e.types))

    def run(self) -> Grounding:
        name = self.model.name
        pools = {key: self.candidates(t) for key, t in self.params.items()}
        for key, pool in pools.items():
            if not pool:
                return Grounding(name, False, reason=(
                    f"no element of class {self.params[key] or '?'} for parameter {key} in "
                    f"the scene"))
        judged = [c for c in self.model.pre
                  if self._judged(c) and any(k in self.params for k in _keys(c))]
        found = self._first(judged, pools)
        if found is None:
            return Grounding(name, True, reason="too many choices to search", undecided=True)
        if found:
            chosen = dict(found[0])
            for key, pool in pools.items():
                chosen.setdefault(key, pool[0])
            return Grounding(name, True, assignment=chosen)
        for k in range(1, len(judged) + 1):  # the first prefix no choice satisfies
            if self._first(judged[:k], pools) == []:
                return Grounding(name, False, reason=(
                    "no choice of elements satisfies the pre-condition "
                    f"{describe(judged[k - 1])}"), blocking=judged[k - 1])
        return Grounding(name, True, reason="too many choices to search", undecided=True)

    def _first(self, conditions: list[Condition], pools: dict[str, list[str]]
               ) -> list[Assignment] | None:
        """``[one assignment]`` satisfying every condition, ``[]`` when none does, None
        when the search ran out of its budget (``MAX_CHOICES`` steps). Depth first, the
        parameters in the order the conditions name them; a relation to a parameter already
        chosen narrows the candidates to the elements it links (scenes are small, but a
        product of every pool is not)."""
        order = list(dict.fromkeys(k for c in conditions for k in _keys(c) if k in pools))
        waiting = {k: [c for c in conditions if k in _keys(c)
                       and all(o in order[:i + 1] for o in _keys(c))]
                   for i, k in enumerate(order)}
        budget = [MAX_CHOICES]

        def search(i: int, choice: Assignment) -> Assignment | None:
            if i == len(order):
                return dict(choice)
            key = order[i]
            for element in self._narrowed(key, pools[key], conditions, choice):
                budget[0] -= 1
                if budget[0] < 0:
                    raise _OutOfBudget
                choice[key] = element
                if all(self.holds(c, choice) for c in waiting[key]):
                    found = search(i + 1, choice)
                    if found is not None:
                        return found
                del choice[key]
            return None

        try:
            found = search(0, {})
        except _OutOfBudget:
            return None
        return [] if found is None else [found]

    def _narrowed(self, key: str, pool: list[str], conditions: list[Condition],
                  choice: Assignment) -> list[str]:
        """``pool``, less what a wanted relation to an already chosen parameter excludes."""
        for c in conditions:
            desired = untyped(c.desired_state) if c.desired_state is not None else True
            if c.kind != "relation" or desired is False:
                continue
            if c.object == key and c.subject in choice:
                linked = self._linked(choice[c.subject], c.vocabulary or "", forward=True)
            elif c.subject == key and c.object in choice:
                linked = self._linked(choice[c.object], c.vocabulary or "", forward=False)
            else:
                continue
            pool = [e for e in pool if e in linked]
        return pool

    def _linked(self, end: str, relation: str, forward: bool) -> set[str]:
        wanted = self.index.expand(relation)
        if wanted is None:
            return set()
        if wanted not in self._below:
            self._below[wanted] = sorted(sub_properties(self.index, wanted))
        below = set(self._below[wanted])
        links = (self.out_links if forward else self.in_links).get(end, [])
        return {other for p, other in links if p in below}

    def _judged(self, c: Condition) -> bool:
        """Conditions the world model decides from the scene (relation and property kinds,
        or of them) on grounded parameters only; the rest do not constrain the choice."""
        if c.kind == "or":
            return all(self._judged(child) for child in c.children) and bool(c.children)
        keys = [k for k in (c.subject, c.object) if k is not None]
        return c.kind in ("relation", "property", "has_property", "on_type") \
            and all(k in self.params for k in keys)

    def holds(self, c: Condition, choice: Assignment) -> bool:
        desired = untyped(c.desired_state) if c.desired_state is not None else True
        if c.kind == "or":
            found = any(self.holds(child, choice) for child in c.children)
        elif c.kind == "relation":
            found = self._related(choice[c.subject or ""], c.vocabulary or "",
                                  choice[c.object or ""])
        elif c.kind == "on_type":
            wanted = self.index.expand(c.vocabulary or "")
            element = self.scene.elements[choice[c.subject or ""]]
            return wanted is not None and any(self.index.is_subclass(t, wanted)
                                              for t in element.types)
        else:
            found = self._property(c, choice[c.subject or ""])
        return found is (desired is not False)

    def _related(self, subject: str, relation: str, obj: str) -> bool:
        wanted = self.index.expand(relation)
        if wanted is None:
            return False
        if wanted not in self._below:
            self._below[wanted] = sorted(sub_properties(self.index, wanted))
        return any((subject, p, obj) in self.links for p in self._below[wanted])

    def _property(self, c: Condition, subject: str) -> bool:
        prop = self.index.expand(c.vocabulary or "")
        values = [v for v in self.scene.values if v.subject == subject and v.property == prop]
        if c.kind == "has_property":
            return bool(values)
        compare = _COMPARE.get((c.operator or "=").strip())
        wanted = untyped(c.value) if c.value is not None else None
        for v in values:
            have = v.value if v.value is not None else v.lexical
            try:
                if compare is not None and compare(have, wanted):
                    return True
            except TypeError:
                continue
        return False


def _keys(c: Condition) -> list[str]:
    if c.kind == "or":
        return [k for child in c.children for k in _keys(child)]
    return [k for k in (c.subject, c.object) if k is not None]


class _OutOfBudget(Exception):
    """The search took more than ``MAX_CHOICES`` steps."""


__all__ = ["Grounding", "can_start", "describe", "to_ground"]
