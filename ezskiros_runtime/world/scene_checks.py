"""Is this scene what the robot is supposed to see? The checks of a world-model scene.

With the ontology in force: the scene parses; each element has at most one spatial parent
(any sub-property of ``skiros:spatiallyRelated`` counts); every relation's object is defined
in the scene; relations respect domain and range (with the subclass closure, as the
description checks do); data values fit their property's datatype; an individual's type
the ontology does not know is ``info`` (the scene may be its only declaration); and an
element outside the spatial tree is ``info`` (the GUI, which reads the scene as a tree, does
not show it). What SkiROS2 saves about itself (skills, parameters, conditions) is left alone.

``check_scene_file`` is the entry point for anything that has a scene's path: the linter's
``owl/*.turtle`` files, a scene named on the command line, a launch file's ``init_scene``.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from ..diagnostics import Finding
from ..ontology.naming import XSD
from .findings import finding
from .scene import (
    Relation,
    Scene,
    SceneError,
    Value,
    individuals_of,
    read_scene,
)
from .vocabulary import (
    BOOKKEEPING_CLASSES,
    BOOKKEEPING_PROPERTIES,
    SKIROS,
    spatial_properties,
)

if TYPE_CHECKING:
    from ..ontology.index import OntologyIndex

SCENE_CLASS = SKIROS + "Scene"
CORE_SPATIAL = frozenset({SKIROS + "contain", SKIROS + "hasA", SKIROS + "spatiallyRelated"})
"""The core's spatial properties; another one in ``spatial_properties`` is the lab's."""
POSE = ("FrameId", "PositionX", "PositionY", "PositionZ")
"""Properties that give an element a pose of its own (the spatial reasoner publishes it)."""
_NUMBERS = ("float", "double", "decimal")
_INTEGERS = ("int", "integer", "long", "short", "byte", "nonNegativeInteger",
             "positiveInteger", "unsignedInt", "unsignedLong")


def check_scene_file(path: str | Path, index: OntologyIndex | None,
                     text: str | None = None,
                     elsewhere: dict[str, list[str]] | None = None) -> list[Finding]:
    """Every finding of the scene at ``path`` (``text``: its content, when already read);
    a scene that does not parse is one finding at the line rdflib names. ``elsewhere``:
    individuals the ontology files declare (by default those the index holds:
    ``individuals_of``)."""
    try:
        scene = read_scene(path, text)
    except SceneError as error:
        return [unreadable(error)]
    return check_scene(scene, index, elsewhere)


def unreadable(error: SceneError) -> Finding:
    """The one finding of a scene the world model cannot load (EZ402)."""
    return finding("scene-syntax", error.path, error.line,
                   f"scene {Path(error.path).name} cannot be loaded: {error.reason}")


def check_scene(scene: Scene, index: OntologyIndex | None,
                elsewhere: dict[str, list[str]] | None = None) -> list[Finding]:
    """Every finding of a scene already read, in line order."""
    if elsewhere is None:
        elsewhere = individuals_of(index) if index is not None else {}
    checker = _SceneChecker(scene, index, elsewhere)
    found = (checker.parents() + checker.dangling() + checker.types()
             + checker.datatypes() + checker.unknown_types() + checker.unattached())
    return sorted(found, key=lambda f: (f.line, f.kind, f.message))


def bookkeeping(scene: Scene, index: OntologyIndex | None) -> set[str]:
    """Elements SkiROS2 saves about itself: typed as a skill, parameter or condition (or
    below), or reached from one through ``hasSkill``/``hasParam``/``has*Condition``."""
    marked = {e.iri for e in scene.elements.values()
              if any(_below(index, t, c) for t in e.types for c in BOOKKEEPING_CLASSES)}
    marked |= {r.object for r in scene.relations if r.property in BOOKKEEPING_PROPERTIES}
    grew = True
    while grew:
        more = {r.object for r in scene.relations if r.subject in marked
                and r.property not in spatial_properties(index)} - marked
        grew = bool(more & set(scene.elements))
        marked |= more
    return marked


def _below(index: OntologyIndex | None, cls: str, sup: str) -> bool:
    return cls == sup or (index is not None and index.is_subclass(cls, sup))


class _SceneChecker:
    """One scene against one ontology; each method is one check."""

    def __init__(self, scene: Scene, index: OntologyIndex | None,
                 elsewhere: dict[str, list[str]]) -> None:
        self.scene = scene
        self.elsewhere = elsewhere
        self.index = index
        self.spatial = spatial_properties(index)
        self.own = bookkeeping(scene, index)

    def name(self, iri: str) -> str:
        return self.scene.compact(iri)

    def vocabulary(self, iri: str) -> str:
        return self.index.compact(iri) if self.index is not None else self.name(iri)

    def parents(self) -> list[Finding]:
        """Elements with two spatial parents. Through the core's ``contain``/``hasA``: a
        warning for an element with a pose of its own (its frame is re-expressed in the
        first parent found), info for one without (a second node in the GUI's tree).
        Through a property the lab's ontology makes spatial (``adjacentLocation`` between
        rooms and doors): one info finding per property at its first use here, counting
        the elements it gives a second parent, since one declaration is the cause."""
        seen: dict[str, list[str]] = {}
        found = []
        declared: dict[str, list[Relation]] = {}
        for r in sorted(self.scene.relations, key=lambda r: r.line):
            if r.property not in self.spatial:
                continue
            first = seen.setdefault(r.object, [])
            if first and r.subject not in first:
                if r.property not in CORE_SPATIAL:
                    declared.setdefault(r.property, []).append(r)
                else:
                    found.append(self._two_parents(r, first[0]))
            if r.subject not in first:
                first.append(r.subject)
        for prop, uses in declared.items():
            elements = sorted({self.name(r.object) for r in uses})
            found.append(finding(
                "scene-spatial-declaration", self.scene.path, uses[0].line,
                f"{self.vocabulary(prop)} is a sub-property of skiros:spatiallyRelated in the "
                f"loaded ontology, so it gives {len(elements)} element(s) of this scene a "
                f"second spatial parent ({', '.join(elements[:3])}"
                f"{', ...' if len(elements) > 3 else ''}); SkiROS2 stores every triple, and "
                "only the GUI's tree shows them twice", prop,
                f"Declare {self.vocabulary(prop)} outside skiros:spatiallyRelated if it is no "
                "containment.", severity="info"))
        return found

    def _two_parents(self, r: Relation, first: str) -> Finding:
        """The finding of ``r.object``'s second parent ``r.subject`` (``first`` the other)."""
        posed = any(self.scene.values_of(r.object, SKIROS + name) for name in POSE)
        tail = ("its pose, in a frame of its own, is expressed in whichever parent "
                "SkiROS2 finds first" if posed else
                "it has no pose of its own, so only the GUI's tree shows it twice")
        return finding(
            "scene-two-parents", self.scene.path, r.line,
            f"{self.name(r.object)} has two spatial parents: {self.name(first)} and "
            f"{self.name(r.subject)} ({self.vocabulary(r.property)}); {tail}", r.object,
            f"Keep one of the two relations to {self.name(r.object)}.",
            severity=None if posed else "info")

    def dangling(self) -> list[Finding]:
        found = []
        for r in self.scene.relations:
            if r.object in self.scene.elements or r.object in self.elsewhere \
                    or r.property in BOOKKEEPING_PROPERTIES \
                    or r.subject in self.own or self._is_vocabulary(r.object):
                continue
            found.append(finding(
                "scene-dangling", self.scene.path, r.line,
                f"{self.name(r.subject)} {self.vocabulary(r.property)} "
                f"{self.name(r.object)}: {self.name(r.object)} is defined nowhere in the "
                "scene", r.subject,
                f"Define {self.name(r.object)} in the scene, or fix the name."))
        return found

    def _is_vocabulary(self, iri: str) -> bool:
        """A class or property of the ontology (``hasTemplate skiros:LargeBox``)."""
        return self.index is not None and (self.index.is_class(iri)
                                           or self.index.property(iri) is not None)

    def types(self) -> list[Finding]:
        if self.index is None:
            return []
        found = []
        for r in self.scene.relations:
            info = self.index.property(r.property)
            if info is None or info.kind != "object" or r.subject in self.own:
                continue
            for end, iri, exprs in (("domain", r.subject, info.domains),
                                    ("range", r.object, info.ranges)):
                element = self.scene.elements.get(iri)
                types = element.types if element is not None else self.elsewhere.get(iri, [])
                for expr in exprs if types else ():
                    verdicts = [self.index.satisfies(t, expr) for t in types]
                    if verdicts and all(v is False for v in verdicts):
                        found.append(finding(
                            f"scene-{end}", self.scene.path, r.line,
                            f"{self.name(r.subject)} {self.vocabulary(r.property)} "
                            f"{self.name(r.object)}: {self.name(iri)} is a "
                            f"{', '.join(self.vocabulary(t) for t in types)}, "
                            f"outside the {end} {self.index.render(expr)}", iri,
                            f"Relate an element of class {self.index.render(expr)}, or fix "
                            f"the type of {self.name(iri)}."))
                        break
        return found

    def datatypes(self) -> list[Finding]:
        if self.index is None:
            return []
        found = []
        for v in self.scene.values:
            info = self.index.property(v.property)
            if info is None or info.kind != "data":
                continue
            for expr in info.ranges:
                wanted = getattr(expr, "iri", "")
                problem = _misfit(v, wanted) if wanted.startswith(XSD) else None
                if problem is not None:
                    local = wanted[len(XSD):]
                    found.append(finding(
                        "scene-datatype", self.scene.path, v.line,
                        f"{self.name(v.subject)} {self.vocabulary(v.property)} "
                        f"{v.lexical!r}: {problem}; the property's range is xsd:{local}",
                        v.subject, f"Write the value as \"...\"^^xsd:{local}."))
                    break
        return found

    def unknown_types(self) -> list[Finding]:
        if self.index is None:
            return []
        found = []
        for element in self.scene.elements.values():
            if element.iri in self.own:
                continue
            for t in element.types:
                if not self.index.is_class(t):
                    found.append(finding(
                        "scene-unknown-type", self.scene.path, element.line,
                        f"{self.name(element.iri)} is a {self.vocabulary(t)}, a class the "
                        "loaded ontology does not define (the scene may be its only "
                        "declaration)", element.iri,
                        "Load the ontology that defines it (--ontology), or fix the name."))
        return found

    def unattached(self) -> list[Finding]:
        """Elements outside the tree rooted at the scene (only when there is one)."""
        elements = self.scene.elements
        roots = [e for e in elements.values() if any(_below(self.index, t, SCENE_CLASS)
                                                     for t in e.types)]
        if len(roots) != 1:
            return []
        children: dict[str, list[str]] = {}
        for r in self.scene.relations:
            if r.property in self.spatial:
                children.setdefault(r.subject, []).append(r.object)
        reached, todo = set(), [roots[0].iri]
        while todo:
            iri = todo.pop()
            if iri not in reached:
                reached.add(iri)
                todo += children.get(iri, [])
        return [finding("scene-unattached", self.scene.path, e.line,
                        f"{self.name(e.iri)} is not in the scene's spatial tree (no chain of "
                        f"contain/hasA from {self.name(roots[0].iri)}): SkiROS2's GUI does "
                        "not show it", e.iri,
                        f"Relate it to a parent, e.g. {self.name(roots[0].iri)} "
                        f"skiros:contain {self.name(e.iri)}.")
                for e in elements.values() if e.iri not in reached and e.iri not in self.own]


def _misfit(value: Value, wanted: str) -> str | None:
    """Why ``value`` does not fit the XSD datatype ``wanted``, or None when it does."""
    local = wanted[len(XSD):]
    declared = value.datatype[len(XSD):] if value.datatype and value.datatype.startswith(
        XSD) else None
    if local in _NUMBERS or local in _INTEGERS:
        try:
            number = float(value.lexical)
        except ValueError:
            return "not a number"
        if local in _INTEGERS and number != int(number):
            return "not a whole number"
        if declared in ("string", "boolean"):
            return f"written as xsd:{declared}"
        return None
    if local == "boolean":
        if value.lexical.strip() not in ("true", "false", "1", "0"):
            return "not a boolean (true or false)"
        if declared in ("string", *_NUMBERS, *_INTEGERS):
            return f"written as xsd:{declared}"
        return None
    if local == "string" and declared in ("boolean", *_NUMBERS, *_INTEGERS):
        return f"written as xsd:{declared}"
    return None


__all__ = ["bookkeeping", "check_scene", "check_scene_file", "unreadable"]
