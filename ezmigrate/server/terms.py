"""The ontology's knowledge at a cursor: which term is there, what the ontology says of it,
where it is defined, and which terms may be typed next.

A term is read from the line as written, in both forms: EzSkiROS attributes of a loaded
prefix (``skiros.Location``, and relations after a parameter, ``Gripper.contain``, are
found by their local name) and legacy strings (``"skiros:Product"``). What the ontology
says (label, comment, superclasses, domain and range) comes from the index and from one
rdflib reading of its files, made on the first question and kept; where a term is defined
is the first line of its file that defines it (``rdf:about``/``rdf:ID`` or a Turtle
subject).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from ezskiros_runtime.ontology.index import OntologyIndex

_STRING_TERM = re.compile(r"""(["'])([A-Za-z_][\w.-]*):([A-Za-z_][\w.-]*)\1""")
_ATTRIBUTE = re.compile(r"\b([A-Za-z_]\w*)\.([A-Za-z_]\w*)\b")
_DEFINES = (
    re.compile(r"""rdf:(?:about|ID)\s*=\s*["'][^"'#;]*[#;/]?([A-Za-z_][\w.-]*)["']"""),
    re.compile(r"""^\s*(?:[A-Za-z_][\w-]*)?:([A-Za-z_][\w.-]*)\s"""),
    re.compile(r"""^\s*<[^>]*[#/]([A-Za-z_][\w.-]*)>\s"""),
)


@dataclass(frozen=True)
class Term:
    """A term under the cursor: its compact name, its IRI and the span it was read from
    (0-based line, start and end character)."""

    compact: str
    iri: str
    line: int
    start: int
    end: int


@dataclass(frozen=True)
class Definition:
    path: str
    line: int
    """0-based, as the protocol counts."""


@dataclass
class Notes:
    """What the ontology's files say of each term: labels, comments, defining lines."""

    labels: dict[str, str] = field(default_factory=dict)
    comments: dict[str, str] = field(default_factory=dict)
    defined: dict[str, Definition] = field(default_factory=dict)
    """By local name: the first line that defines it."""


def term_at(index: OntologyIndex, text: str, line: int, character: int) -> Term | None:
    """The ontology term at (``line``, ``character``) of ``text``, in either form."""
    lines = text.splitlines()
    if not 0 <= line < len(lines):
        return None
    row = lines[line]
    for match in _STRING_TERM.finditer(row):
        if match.start() <= character <= match.end():
            compact = f"{match.group(2)}:{match.group(3)}"
            iri = index.expand(compact)
            if iri is not None and (index.is_class(iri) or index.property(iri) is not None):
                return Term(compact, iri, line, match.start(2), match.end(3))
    for match in _ATTRIBUTE.finditer(row):
        if not match.start() <= character <= match.end():
            continue
        owner, local = match.group(1), match.group(2)
        if owner in index.prefixes:
            iri = index.prefixes[owner] + local
            if index.is_class(iri) or index.property(iri) is not None:
                return Term(f"{owner}:{local}", iri, line, match.start(1), match.end(2))
        if character >= match.start(2):  # a relation or property after a parameter
            named = index.properties_named(local)
            if named:
                return Term(index.compact(named[0]), named[0], line, match.start(2),
                            match.end(2))
    return None


def read_notes(index: OntologyIndex) -> Notes:
    """Labels and comments (rdflib) and defining lines (the text) of the index's files."""
    import rdflib
    from rdflib.namespace import RDFS

    notes = Notes()
    for source in index.sources:
        path = Path(source)
        try:
            text = path.read_text(encoding="utf-8", errors="replace")
        except OSError:
            continue
        for number, row in enumerate(text.splitlines()):
            for pattern in _DEFINES:
                match = pattern.search(row)
                if match is not None:
                    notes.defined.setdefault(match.group(1), Definition(str(path), number))
                    break
        graph = rdflib.Graph()
        try:
            graph.parse(data=text, format="turtle" if path.suffix in (".ttl", ".turtle")
                        else "xml", publicID=path.as_uri())
        except Exception:  # the loader already said why a file does not read
            continue
        for subject, label in graph.subject_objects(RDFS.label):
            notes.labels.setdefault(str(subject), str(label))
        for subject, comment in graph.subject_objects(RDFS.comment):
            notes.comments.setdefault(str(subject), str(comment))
    return notes


def _local(iri: str) -> str:
    return re.split(r"[#/]", iri)[-1]


def definition(notes: Notes, term: Term) -> Definition | None:
    """Where ``term`` is defined, when a file of the ontology defines it on a line."""
    return notes.defined.get(_local(term.iri))


def hover_text(index: OntologyIndex, notes: Notes, term: Term) -> str:
    """Markdown: the term, its label and comment, superclasses or domain and range, and
    where it is defined."""
    parts = [f"**{term.compact}**"]
    label, comment = notes.labels.get(term.iri), notes.comments.get(term.iri)
    if label and label != _local(term.iri):
        parts.append(f"*{label}*")
    if comment:
        parts.append(comment.strip())
    prop = index.property(term.iri)
    if prop is None:
        parents = sorted(index.compact(c) for c in index.direct_superclasses(term.iri))
        parts.append("class" + (f"; subclass of {', '.join(parents)}" if parents else ""))
    else:
        parts.append(f"{prop.kind}")
        if prop.domains:
            parts.append("domain: " + ", ".join(index.render(d) for d in prop.domains))
        if prop.ranges:
            parts.append("range: " + ", ".join(index.render(r) for r in prop.ranges))
    where = definition(notes, term)
    if where is not None:
        parts.append(f"defined at {where.path}:{where.line + 1}")
    return "\n\n".join(parts)


@dataclass(frozen=True)
class Completion:
    label: str
    detail: str
    """"class" or the property's kind."""


_AFTER_PREFIX = re.compile(r"""(?:(["'])([A-Za-z_][\w-]*):|\b([A-Za-z_]\w*)\.)([\w.-]*)$""")


def completions(index: OntologyIndex, text: str, line: int, character: int
                ) -> list[Completion]:
    """The terms that may be typed at the cursor: the classes and properties of a prefix
    after ``skiros.`` or inside ``"skiros:``; relations and properties after a parameter
    (``Gripper.``), their names only."""
    lines = text.splitlines()
    if not 0 <= line < len(lines):
        return []
    match = _AFTER_PREFIX.search(lines[line][:character])
    if match is None:
        return []
    prefix = match.group(2) or match.group(3)
    typed = match.group(4)
    if prefix in index.prefixes:
        namespace = index.prefixes[prefix]
        found = []
        for local in index.local_names(prefix):
            if local.startswith(typed):
                prop = index.property(namespace + local)
                found.append(Completion(local, "class" if prop is None else prop.kind))
        return found
    if match.group(3) is None:
        return []
    cls = _annotated_class(index, text, prefix)
    kinds: dict[str, tuple[str, int]] = {}
    for iri, info in index.properties.items():
        tier = _admits(index, cls, info.domains)
        if tier < kinds.get(_local(iri), ("", 3))[1]:
            kinds[_local(iri)] = (info.kind, tier)
    ordered = sorted(kinds.items(), key=lambda item: (item[1][1], item[0]))
    return [Completion(local, kind) for local, (kind, _) in ordered if local.startswith(typed)]


def _annotated_class(index: OntologyIndex, text: str, name: str) -> str | None:
    """The class IRI a parameter ``name`` is annotated with in ``text``
    (``Gripper: rparts.GripperEffector``, also inside ``INFERRED[...]`` and the like)."""
    found = re.search(rf"\b{re.escape(name)}\s*:\s*(?:[A-Z_]+\[)*([A-Za-z_]\w*)\.([A-Za-z_]\w*)",
                      text)
    if found is None or found.group(1) not in index.prefixes:
        return None
    iri = index.prefixes[found.group(1)] + found.group(2)
    return iri if index.is_class(iri) else None


def _admits(index: OntologyIndex, cls: str | None, domains: tuple[Any, ...]) -> int:
    """How a property's domain takes the parameter's class, best first: 0 admits it by
    name, 1 has no domain (or the class is not known), 2 excludes it."""
    if cls is None or not domains:
        return 1
    return 0 if any(index.satisfies(cls, domain) for domain in domains) else 2
