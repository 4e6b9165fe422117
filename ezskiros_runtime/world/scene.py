"""A world-model scene (``*.turtle``) read into plain data: elements, their types,
relations and data properties, each with the line of the Turtle file it is written on.

SkiROS2's world model loads a scene with rdflib and keeps it as a graph; the checks and the
grounding here only need who is what, who relates to whom and which values an element has,
so the graph is read once into ``Scene`` and rdflib is not needed afterwards. rdflib gives no
positions, so lines are found in the text: each subject's block (a statement starting at
column 0) is located, and a triple's line is the first line of that block naming its object
(or property); a finding then points where a person would look.

Runs on the robot's Python 3.8 with rdflib 4.2.2 as well as on rdflib 7.
"""

from __future__ import annotations

import contextlib
import functools
import logging
import os
import re
import warnings
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Iterable, Iterator

from ..ontology.individuals import NOT_CLASSES, add_individuals
from ..ontology.naming import OWL, RDF_TYPE, WELL_KNOWN_PREFIXES
from .terms import IRI, LITERAL, Triple, from_rdflib
from .turtle_subset import read_triples

if TYPE_CHECKING:
    from ..ontology.index import OntologyIndex

RDFS_LABEL = WELL_KNOWN_PREFIXES["rdfs"] + "label"
SCHEMA = (OWL, WELL_KNOWN_PREFIXES["rdfs"], WELL_KNOWN_PREFIXES["rdf"])
"""Vocabulary about vocabulary: a subject typed with it (the ``owl:Ontology`` header, a
class the scene declares) is no element of the world, and a predicate from it
(``owl:imports``, ``rdfs:seeAlso``) no relation between elements."""

_PREFIX = re.compile(r"^\s*(?:@prefix|PREFIX)\s+([\w.-]*):\s*<([^>]*)>", re.IGNORECASE)
_QUOTED = re.compile(r'"((?:[^"\\]|\\.)*)"')
_TERM = re.compile(r"<[^>]*>|[\w.-]*:[\w.-]*")


class SceneError(ValueError):
    """A scene that cannot be read: ``path`` and ``line`` (0 when unknown) say where."""

    def __init__(self, path: str, line: int, message: str) -> None:
        super().__init__(f"{path}:{line}: {message}" if line else f"{path}: {message}")
        self.path = path
        self.line = line
        self.reason = message


@dataclass(frozen=True)
class Relation:
    """``subject property object`` between two IRIs, at ``line`` of the file."""

    subject: str
    property: str
    object: str
    line: int


@dataclass(frozen=True)
class Value:
    """A data property's value: the lexical form, its declared datatype IRI (None when
    plain), the Python value rdflib reads (None when the lexical form does not fit)."""

    subject: str
    property: str
    lexical: str
    datatype: str | None
    value: object
    line: int


@dataclass
class SceneElement:
    """One individual of the scene: its IRI, its classes (owl:NamedIndividual left out),
    its label and the line its block starts on."""

    iri: str
    line: int
    types: list[str] = field(default_factory=list)
    label: str = ""


@dataclass
class Scene:
    """A scene file: elements by IRI, every relation and value, the file's own prefixes."""

    path: str
    elements: dict[str, SceneElement] = field(default_factory=dict)
    relations: list[Relation] = field(default_factory=list)
    values: list[Value] = field(default_factory=list)
    prefixes: dict[str, str] = field(default_factory=dict)

    def compact(self, iri: str) -> str:
        """``skiros:Location-1`` for an IRI in one of the file's namespaces (the longest
        wins), else the IRI itself: names as the file writes them."""
        best, found = "", iri
        for prefix, namespace in self.prefixes.items():
            if iri.startswith(namespace) and len(namespace) > len(best) \
                    and len(iri) > len(namespace):
                best = namespace
                found = f"{prefix}:{iri[len(namespace):]}"
        return found

    def values_of(self, subject: str, prop: str) -> list[Value]:
        """The values ``subject`` has for data property ``prop``."""
        return [v for v in self.values if v.subject == subject and v.property == prop]


def read_scene(path: str | Path, text: str | None = None) -> Scene:
    """Parse a Turtle scene (``text`` if given, else the file). Raises ``SceneError`` with
    the file and line when rdflib cannot read it.

    A run reads the same scene for several passes (its checks, the classes it types, the
    elements EZ105 counts): the parse is kept per path and text, and callers treat the
    ``Scene`` as read-only."""
    where = str(path)
    if text is None:
        try:
            text = Path(path).read_text(encoding="utf-8")
        except (OSError, UnicodeError) as error:
            raise SceneError(where, 0, f"cannot be read: {error}") from error
    found = _KNOWN.get((where, text))
    if found is None:
        found = _parsed(where, text)
        seed_scene(where, text, found)
    return found


_KNOWN: dict[tuple[str, str], Scene] = {}
"""Scenes parsed, or handed in, by path and text."""


def seed_scene(path: str | Path, text: str, scene: Scene) -> None:
    """``scene`` is what ``read_scene`` makes of ``text`` at ``path`` (parsed in an earlier
    run and kept by a tool's cache, by content): it is returned instead of parsing again."""
    if len(_KNOWN) >= 256:  # one run's scenes; a long-lived process does not grow
        _KNOWN.clear()
    _KNOWN[(str(path), text)] = scene


def known_scene(path: str | Path, text: str) -> Scene | None:
    """The scene ``read_scene`` made of ``text`` at ``path`` in this process, if it did."""
    return _KNOWN.get((str(path), text))


def _triples(where: str, text: str) -> Iterable[Triple]:
    """The file's triples (``terms``): read as SkiROS2 saves scenes (``turtle_subset``),
    else by rdflib's parser, whose error says where the file is wrong."""
    with _quiet_rdflib():  # a value that does not fit its datatype is a finding
        plain = read_triples(text)
    if plain is not None:
        return plain
    from rdflib import Graph

    graph = Graph()
    try:
        with _quiet_rdflib():
            graph.parse(data=text, format="turtle")
    except Exception as error:  # rdflib's BadSyntax and friends: say where, as rdflib does
        line = getattr(error, "lines", None)
        reason = str(error).splitlines()
        message = next((r for r in reason if "Bad syntax" in r), reason[0] if reason else "")
        message = message.split(" at ^ in:")[0]
        raise SceneError(where, line + 1 if isinstance(line, int) else 0,
                         f"not valid Turtle: {message.strip() or type(error).__name__}"
                         ) from error
    with _quiet_rdflib():
        return [(from_rdflib(s), from_rdflib(p), from_rdflib(o)) for s, p, o in graph]


def _order(triple: Triple) -> tuple[str, ...]:
    """Triples in the order of their text, a literal's datatype and language last: the
    same order whichever reader read them."""
    s, p, o = triple
    return s.text, p.text, o.text, o.datatype or "", o.language or ""


def _parsed(where: str, text: str) -> Scene:
    scene = Scene(where, prefixes=_prefixes(text))
    blocks = _Blocks(text, scene.prefixes)
    triples = sorted(_triples(where, text), key=_order)
    schema = {s.text for s, p, o in triples if p.text == RDF_TYPE
              and o.text.startswith(SCHEMA) and o.text not in NOT_CLASSES}
    for s, p, o in triples:
        if s.kind != IRI or s.text in schema:
            continue
        subject = s.text
        element = scene.elements.get(subject)
        if element is None:
            element = scene.elements[subject] = SceneElement(subject, blocks.start(subject))
        prop = p.text
        if prop == RDF_TYPE and o.kind == IRI:
            if o.text not in NOT_CLASSES and o.text not in element.types:
                element.types.append(o.text)
        elif prop == RDFS_LABEL:
            element.label = o.text
        elif prop.startswith(SCHEMA):
            continue
        elif o.kind == IRI:
            scene.relations.append(Relation(subject, prop, o.text,
                                            blocks.line(subject, o.text, prop)))
        elif o.kind == LITERAL:
            line = blocks.line(subject, None, prop)
            scene.values.append(Value(subject, prop, blocks.written(line, o.text), o.datatype,
                                      o.value, line))
    return scene


@contextlib.contextmanager
def _quiet_rdflib() -> Iterator[None]:
    """rdflib 7 logs a traceback and warns for each value that does not fit its datatype;
    those values are findings here, not noise on stderr."""
    logger = logging.getLogger("rdflib.term")
    level = logger.level
    logger.setLevel(logging.CRITICAL)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            yield
    finally:
        logger.setLevel(level)


def _prefixes(text: str) -> dict[str, str]:
    found: dict[str, str] = {}
    for line in text.splitlines():
        match = _PREFIX.match(line)
        if match:
            found[match.group(1)] = match.group(2)
    return found


class _Blocks:
    """Where each subject's statements are in the text: ``{iri: (first line, last line)}``."""

    def __init__(self, text: str, prefixes: dict[str, str]) -> None:
        self.prefixes = prefixes
        self.lines = text.splitlines()
        self.blocks: dict[str, tuple[int, int]] = {}
        self._firsts: dict[str, dict[str | None, int]] = {}
        starts: list[tuple[int, str]] = []
        for number, line in enumerate(self.lines, 1):
            if not line or line[0] in " \t#@" or line.upper().startswith(("PREFIX", "BASE")):
                continue
            match = _TERM.match(line)
            iri = self.expand(match.group(0)) if match else None
            if iri is not None:
                starts.append((number, iri))
        for i, (number, iri) in enumerate(starts):
            end = starts[i + 1][0] - 1 if i + 1 < len(starts) else len(self.lines)
            self.blocks.setdefault(iri, (number, end))

    def expand(self, term: str) -> str | None:
        if term.startswith("<"):
            return term[1:-1]
        prefix, _, local = term.rstrip(".").partition(":")
        namespace = self.prefixes.get(prefix)
        return namespace + local if namespace is not None else None

    def written(self, line: int, parsed: str) -> str:
        """A value as the file writes it (rdflib 7 rewrites a boolean ``"yes"`` as
        ``"false"``): the quoted text on its line when there is exactly one."""
        if not 1 <= line <= len(self.lines):
            return parsed
        quoted = _QUOTED.findall(self.lines[line - 1])
        return quoted[0] if len(quoted) == 1 else parsed

    def start(self, subject: str) -> int:
        return self.blocks.get(subject, (0, 0))[0]

    def line(self, subject: str, obj: str | None, prop: str) -> int:
        """The first line of ``subject``'s block naming ``obj`` (else ``prop``)."""
        firsts = self._firsts.get(subject)
        if firsts is None:
            firsts = self._firsts[subject] = self._index(subject)
        for wanted in (obj, prop):
            if wanted is not None and wanted in firsts:
                return firsts[wanted]
        return self.start(subject)

    def _index(self, subject: str) -> dict[str | None, int]:
        """Each term ``subject``'s block names, expanded, at the first line naming it: the
        block is read once, not once for each of its statements."""
        first, last = self.blocks.get(subject, (0, -1))
        found: dict[str | None, int] = {}
        for number in range(first, last + 1):
            for term in _TERM.findall(self.lines[number - 1]):
                found.setdefault(self.expand(term), number)
        return found


def ontology_individuals(paths: list[str]) -> dict[str, list[str]]:
    """``{iri: [classes]}`` of the individuals the ontology files declare (a robot
    description in ``owl/robot.owl``): the world model loads them with the ontology, so a
    scene may relate to them without defining them. Files that cannot be read add nothing
    (loading the ontology already reported them). Every scene of a run asks for the same
    files: they are parsed once per state of the files (path, size, modification time)."""
    def state(path: str) -> tuple[str, int, int]:
        try:
            stat = os.stat(path)
        except OSError:
            return path, -1, -1
        return path, stat.st_size, stat.st_mtime_ns
    return dict(_individuals(tuple(state(p) for p in paths)))


@functools.lru_cache(maxsize=8)
def _individuals(states: tuple[tuple[str, int, int], ...]) -> dict[str, list[str]]:
    from ..ontology.errors import OntologyError
    from ..ontology.parsing import (
        collect_ontology_files,
        parse_ontology_file,
        read_ontology_files,
    )

    found: dict[str, list[str]] = {}
    try:
        files = read_ontology_files(collect_ontology_files([Path(p) for p, _, _ in states]))
    except OntologyError:
        return found
    for entry in files:
        try:
            add_individuals(parse_ontology_file(entry), found)
        except OntologyError:
            continue
    return found


def individuals_of(index: OntologyIndex) -> dict[str, list[str]]:
    """The individuals the index's files declare: kept by the index since it was built
    (a cached index answers without rdflib), else parsed (``ontology_individuals``)."""
    if index.individuals is not None:
        return dict(index.individuals)
    return ontology_individuals(list(index.sources))


__all__ = ["Relation", "Scene", "SceneElement", "SceneError", "Value", "individuals_of",
           "ontology_individuals", "read_scene"]
