"""Is the lab's own ontology consistent with what SkiROS2's world model does with it?

Three mistakes the world model accepts silently and then misbehaves on:

- an ``rdfs:subClassOf``, ``rdfs:subPropertyOf``, ``rdfs:domain`` or ``rdfs:range`` naming
  an IRI no loaded ontology defines, in a namespace that does define terms (a typo): the
  lab's class falls outside ``WorldModel.get_sub_classes`` of its intended parent, so
  parameters typed by that parent never match its elements (``ontology-undefined-reference``);
- a property declared with the IRI of a class (SkiROS2 pull request #114: a
  ``owl:DatatypeProperty`` written ``rdf:about="...#Skill"``): the class's IRI is now
  also a predicate, and ``get_sub_classes``/``get_sub_properties`` answer for both
  (``ontology-property-is-class``);
- a scene predicate no ontology declares: ``WorldModel.get_individual`` logs "Predicate is
  not defined in the ontology" and drops the value (``scene-unknown-predicate``).

Runs on the robot too (Python 3.8, rdflib only for the files checked); the linter calls
``ontology_findings`` and ``unknown_predicates`` from its world-model pass.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import TYPE_CHECKING, Iterable, List, Sequence, Set, Tuple

from ..diagnostics import Finding
from ..world.findings import finding
from .naming import OWL, RDF_TYPE, WELL_KNOWN_PREFIXES, split_iri
from .suggest import closest_names

if TYPE_CHECKING:
    from ..world.scene import Scene
    from .index import OntologyIndex

RDFS = WELL_KNOWN_PREFIXES["rdfs"]
REFERENCES = {RDFS + "subClassOf": "class", RDFS + "domain": "class",
              RDFS + "range": "class", RDFS + "subPropertyOf": "property"}
"""The axioms whose object must be a defined term, and the kind of term it must be."""
PROPERTY_TYPES = frozenset({OWL + "ObjectProperty", OWL + "DatatypeProperty",
                            OWL + "AnnotationProperty",
                            WELL_KNOWN_PREFIXES["rdf"] + "Property"})
CLASS_TYPES = frozenset({OWL + "Class", RDFS + "Class"})
BUILT_IN = tuple(WELL_KNOWN_PREFIXES[p] for p in ("rdf", "rdfs", "owl", "xsd")
                 if p in WELL_KNOWN_PREFIXES)
"""Namespaces whose terms (``owl:Thing``, ``xsd:float``) no lab file has to define."""

Triple = Tuple[str, str, str]
Declarations = Tuple[List[Triple], Set[str], Set[str]]
"""One file's reference axioms, and the classes and properties it declares."""


def ontology_findings(files: Sequence[Path], index: OntologyIndex,
                      loaded: Sequence[Path] = ()) -> list[Finding]:
    """Findings of the ontology ``files`` (the repository's own) against ``index`` (every
    file loaded, ``loaded`` besides ``files``): undefined references and properties
    declared with a class's IRI. The index alone cannot tell a defined class from one an
    axiom only names (it counts both as classes), so every file's declarations are read."""
    declared = [(path, _declarations(path)) for path in files]
    others = [_declarations(path) for path in loaded if path not in files]
    defined = _Defined([d for _, d in declared] + others)
    found: list[Finding] = []
    for path, (triples, _classes, _properties) in declared:
        found += _undefined_references(str(path), _text(path), triples, index, defined)
    found += _property_class_clashes(declared, index)
    return found


class _Defined:
    """The terms some loaded file declares: typed as a class or property, or the subject
    of a sub-class or sub-property axiom (which makes it one)."""

    def __init__(self, declarations: Sequence[Declarations]) -> None:
        self.classes: set[str] = set()
        self.properties: set[str] = set()
        for triples, classes, properties in declarations:
            self.classes |= classes
            self.properties |= properties
            for subject, predicate, _obj in triples:
                if predicate == RDFS + "subClassOf":
                    self.classes.add(subject)
                elif predicate == RDFS + "subPropertyOf":
                    self.properties.add(subject)

    def has(self, iri: str, kind: str) -> bool:
        return iri in (self.classes if kind == "class" else self.properties)


def unknown_predicates(scene: Scene, index: OntologyIndex) -> list[Finding]:
    """One finding per predicate of ``scene`` that no loaded ontology declares, at its
    first use (one cause, one finding), with the nearest declared property."""
    uses: dict[str, list[int]] = {}
    written = [(r.property, r.line) for r in scene.relations] + [
        (v.property, v.line) for v in scene.values]
    for predicate, line in written:
        if index.property(predicate) is None and not predicate.startswith(BUILT_IN):
            uses.setdefault(predicate, []).append(line)
    found = []
    for iri, lines in uses.items():
        name = scene.compact(iri)
        more = f" ({len(lines)} uses in this scene)" if len(lines) > 1 else ""
        found.append(finding(
            "scene-unknown-predicate", scene.path, min(lines),
            f"predicate {name} is not defined in the loaded ontology{more}: the world model "
            "logs \"Predicate is not defined in the ontology\" and drops the value when it "
            f"loads the scene{_did_you_mean(iri, index.properties, index)}", name,
            "Fix the predicate's name (see the suggestion), or declare the property in the "
            "lab's ontology."))
    return found


DECLARATIONS_PATTERN = "ontology-declarations-*.json"
"""The entries of the ontology cache (``cache``) that keep one file's ``Declarations``:
a ``check`` run need not parse the files of an unchanged ontology again to check them."""


def _declarations(path: Path) -> Declarations:
    """The reference axioms of one file, and the classes and properties it declares; kept
    in the ontology cache by the file's bytes and the runtime's code (JSON, checked field
    by field when read: a damaged or foreign entry is parsed again)."""
    import hashlib
    import json

    # the submodule itself: ``from . import cache`` would ask the package for a prefix
    from .cache import _code_digest, _store, default_cache_dir

    data = path.read_bytes()
    key = hashlib.sha256(b"declarations\0" + _code_digest().encode() + b"\0" + data)
    entry = default_cache_dir() / DECLARATIONS_PATTERN.replace("*", key.hexdigest())
    try:
        kept = _checked(json.loads(entry.read_text(encoding="utf-8")))
    except (OSError, ValueError):
        kept = None
    if kept is not None:
        return kept
    found = _parsed_declarations(path)
    triples, classes, properties = found
    _store(entry, json.dumps({"triples": triples, "classes": sorted(classes),
                              "properties": sorted(properties)}).encode("utf-8"),
           DECLARATIONS_PATTERN)
    return found


def _checked(data: object) -> Declarations | None:
    """Kept declarations, or None when ``data`` is not what ``_declarations`` wrote."""
    if not isinstance(data, dict):
        return None
    triples, classes, properties = (data.get(k) for k in ("triples", "classes",
                                                           "properties"))
    if not (isinstance(triples, list) and all(
            isinstance(t, list) and len(t) == 3 and all(isinstance(x, str) for x in t)
            for t in triples)):
        return None
    if not all(isinstance(v, list) and all(isinstance(x, str) for x in v)
               for v in (classes, properties)):
        return None
    return ([(t[0], t[1], t[2]) for t in triples], set(classes),  # type: ignore[arg-type]
            set(properties))  # type: ignore[arg-type]


def _parsed_declarations(path: Path) -> Declarations:
    """``_declarations`` of one file, parsed with rdflib."""
    from .parsing import OntologyFile, format_for, parse_ontology_file, read_ontology_files

    [entry] = read_ontology_files([OntologyFile(path, format_for(path))])
    graph = parse_ontology_file(entry)
    triples: list[Triple] = []
    classes: set[str] = set()
    properties: set[str] = set()
    for s, p, o in graph:
        if not (_is_iri(s) and _is_iri(o)):
            continue
        if str(p) in REFERENCES:
            triples.append((str(s), str(p), str(o)))
        elif str(p) == RDF_TYPE and str(o) in CLASS_TYPES:
            classes.add(str(s))
        elif str(p) == RDF_TYPE and str(o) in PROPERTY_TYPES:
            properties.add(str(s))
    return sorted(triples), classes, properties


def _is_iri(term: object) -> bool:
    return type(term).__name__ == "URIRef"


def _undefined_references(path: str, text: str, triples: Iterable[Triple],
                          index: OntologyIndex, defined: _Defined) -> list[Finding]:
    """An axiom naming a term no loaded file defines, in a namespace that defines some:
    what a typo looks like (a namespace nothing defines is another ontology not loaded)."""
    found = []
    for subject, predicate, obj in triples:
        kind = REFERENCES[predicate]
        if obj.startswith(BUILT_IN) or defined.has(obj, kind):
            continue
        namespace = split_iri(obj)[0]
        candidates = _same_namespace(namespace, kind, defined)
        if not candidates:
            continue
        axiom = index.compact(predicate)
        lowered = _lowered(kind, obj, candidates, index)
        found.append(finding(
            "ontology-undefined-reference", path, _line_of(text, obj),
            f"{index.compact(subject)} {axiom} {index.compact(obj)}: no loaded ontology "
            f"defines {index.compact(obj)}{_why(kind, predicate)}"
            f"{_did_you_mean(obj, candidates, index)}{lowered or ''}", subject,
            f"Name a defined {kind} (see the suggestion), or define {index.compact(obj)}.",
            severity="info" if lowered else None))
    return found


def _lowered(kind: str, obj: str, candidates: list[str], index: OntologyIndex
             ) -> str | None:
    """Why a dangling ``rdfs:subPropertyOf`` is only info: SkiROS2 asks for the
    sub-properties of the spatial ones alone (``skiros:spatiallyRelated``: the GUI's tree,
    ``wm_move_object``, the spatial reasoner), so a property meant below another parent
    misbehaves nowhere (the core's own ``skiros:RobotProperty`` and ``skiros:Velocity``)."""
    if kind != "property":
        return None
    from ..world.vocabulary import spatial_properties

    names = {index.compact(c): c for c in candidates}
    best = closest_names(index.compact(obj), names, limit=1)
    if best and names[best[0]] in spatial_properties(index):
        return None
    return "; info: SkiROS2 asks for sub-properties of the spatial properties only"


def _why(kind: str, predicate: str) -> str:
    """What the world model then does, by axiom."""
    if predicate == RDFS + "subClassOf":
        return (" (WorldModel.get_sub_classes of the intended parent leaves this class out, "
                "so parameters typed by it never match its elements)")
    if kind == "property":
        return (" (WorldModel.get_sub_properties of the intended parent leaves this property "
                "out)")
    return " (the description checks and the scene checks cannot use it)"


def _same_namespace(namespace: str, kind: str, defined: _Defined) -> list[str]:
    """The defined terms of ``kind`` in ``namespace``."""
    terms = defined.classes if kind == "class" else defined.properties
    return sorted(t for t in terms if split_iri(t)[0] == namespace)


def _did_you_mean(iri: str, candidates: Iterable[str], index: OntologyIndex) -> str:
    """``" (did you mean p:Name?)"`` for the nearest term of ``candidates`` in the same
    namespace, or nothing."""
    namespace = split_iri(iri)[0]
    names = {index.compact(c): c for c in candidates if split_iri(c)[0] == namespace}
    best = closest_names(index.compact(iri), names, limit=1)
    return f" (did you mean {best[0]}?)" if best else ""


def _property_class_clashes(declared: Sequence[tuple[Path, tuple[list[Triple], set[str],
                                                                    set[str]]]],
                            index: OntologyIndex) -> list[Finding]:
    """A property a repository file declares with the IRI of a class (its own, another
    file's, or the core's), at the property's declaration, naming the class's."""
    class_at: dict[str, Path] = {}  # the first file declaring each class
    for path, (_triples, classes, _properties) in declared:
        for cls in classes:
            class_at.setdefault(cls, path)
    texts: dict[Path, str] = {}  # each file read once, and only for a clash

    def text(path: Path) -> str:
        if path not in texts:
            texts[path] = _text(path)
        return texts[path]

    found = []
    for path, (_triples, _classes, properties) in declared:
        for iri in sorted(properties):
            home = class_at.get(iri)
            if home is None and not index.is_class(iri):
                continue
            where = f"{home.name}:{_line_of(text(home), iri)}" if home is not None \
                else "the loaded ontology"
            name = index.compact(iri)
            found.append(finding(
                "ontology-property-is-class", str(path),
                _line_of(text(path), iri, declaring=True),
                f"{name} is declared a property here and a class in {where}: SkiROS2 then "
                f"answers for both under one IRI (elements typed {name} and values of the "
                "property mix in the world model; SkiROS2 pull request #114)", iri,
                f"Give the property its own IRI (one that is not the class {name})."))
    return found


def _text(path: Path) -> str:
    try:
        return path.read_text(encoding="utf-8", errors="replace")
    except OSError:
        return ""


def _line_of(text: str, iri: str, declaring: bool = False) -> int:
    """The first line that names ``iri`` (its full form, ``#Local`` or ``prefix:Local``);
    ``declaring``: the first that declares it a property (as the subject of a Turtle
    statement, or ``rdf:about``/``rdf:ID`` in RDF/XML, beside the word ``Property``), else
    the first that names it. 0 when none does (the finding then names the file)."""
    local = split_iri(iri)[1]
    if not local:
        return 0
    name = r"(?:<" + re.escape(iri) + r">|[#:;]" + re.escape(local) + r"(?![\w.-]))"
    named = re.compile(name)
    subject = re.compile(r"^\s*(?:<" + re.escape(iri) + r">|[\w-]*:" + re.escape(local)
                         + r"(?![\w.-]))|rdf:(?:about|ID)\s*=\s*\"[^\"]*?#?"
                         + re.escape(local) + "\"")
    first = 0
    for number, line in enumerate(text.splitlines(), start=1):
        if local not in line:
            continue  # (both patterns name it)
        if declaring and "Property" in line and subject.search(line):
            return number
        if named.search(line):
            if not declaring:
                return number
            first = first or number
    return first


__all__ = ["ontology_findings", "unknown_predicates"]
