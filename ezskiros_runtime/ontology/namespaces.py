"""OWL classes as Python types, and the prefix namespaces that hand them out.

``skiros.Product`` is a Python class so that annotations read naturally and ``issubclass``
can answer ontology questions: the metaclass answers ``issubclass`` from the index's
``rdfs:subClassOf`` closure instead of real Python bases, because OWL hierarchies (multiple
parents, equivalences, cycles in odd files) easily produce MRO conflicts.

A namespace resolves every attribute against the ontology that is active *at that moment*,
so code written once keeps working after ``use_ontology`` swaps the index (tests do). Types
are cached per index and qualified name, so ``skiros.Product is skiros.Product`` holds.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from ..diagnostics import UnknownVocabularyError, did_you_mean

if TYPE_CHECKING:
    from .index import OntologyIndex


_ACTIVE: list[Callable[[], OntologyIndex]] = []


def _active() -> OntologyIndex:
    """The active index; ``active`` is imported on first use so importing this is free."""
    if not _ACTIVE:
        from .active import active_index

        _ACTIVE.append(active_index)
    return _ACTIVE[0]()


class OwlClassMeta(type):
    """Metaclass of OWL class types: subclass tests come from the ontology index."""

    iri: str
    qname: str
    index: OntologyIndex

    def __subclasscheck__(cls, sub: type) -> bool:
        if not hasattr(cls, "iri"):  # the abstract root OwlClass
            return isinstance(sub, OwlClassMeta)
        if not isinstance(sub, OwlClassMeta) or not hasattr(sub, "iri"):
            return False
        return sub.iri == cls.iri or cls.index.is_subclass(sub.iri, cls.iri)

    def __instancecheck__(cls, instance: Any) -> bool:
        return cls.__subclasscheck__(type(instance))

    def __repr__(cls) -> str:
        if not hasattr(cls, "iri"):
            return "<OWL class root>"
        return f"<OWL class {cls.qname}>"


class OwlClass(metaclass=OwlClassMeta):
    """Root of every OWL class type; the concrete ones carry ``iri``, ``qname``, ``index``."""


class PropertyRef:
    """``skiros.contain``: an ontology property, usable where a property name is expected
    (``O.has(skiros.Position)``, ``A.relation(cora.robotPart, B)``)."""

    __slots__ = ("iri", "kind", "qname")

    def __init__(self, qname: str, iri: str, kind: str) -> None:
        self.qname = qname
        self.iri = iri
        self.kind = kind

    def __repr__(self) -> str:
        return f"<OWL {self.kind} property {self.qname}>"

    def __eq__(self, other: object) -> bool:
        return isinstance(other, PropertyRef) and (self.qname, self.iri) == (other.qname,
                                                                              other.iri)

    def __hash__(self) -> int:
        return hash((self.qname, self.iri))


_TYPES: dict[tuple[str, str], tuple[OntologyIndex, type]] = {}


def owl_class(index: OntologyIndex, prefix: str, local: str) -> type:
    """The Python type of class ``prefix:local`` in ``index`` (cached)."""
    qname = f"{prefix}:{local}"
    iri = index.prefixes[prefix] + local
    cached = _TYPES.get((qname, iri))
    if cached is not None and cached[0] is index:
        return cached[1]
    new = OwlClassMeta(local, (OwlClass,), {
        "iri": iri, "qname": qname, "index": index, "__module__": f"ontology.{prefix}",
        "__qualname__": local, "__doc__": f"OWL class {qname} ({iri})",
    })
    _TYPES[(qname, iri)] = (index, new)
    return new


def _dotted(name: str) -> str:
    return name.replace(":", ".", 1)


class Namespace:
    """One ontology prefix (``skiros``, ``cora``...): attributes are its classes and
    properties in the active ontology; anything else fails with suggestions."""

    __slots__ = ("_cache", "_prefix")

    def __init__(self, prefix: str) -> None:
        self._prefix = prefix
        self._cache: dict[str, tuple[OntologyIndex, Any]] = {}

    @property
    def prefix(self) -> str:
        return self._prefix

    def __repr__(self) -> str:
        return f"<ontology namespace {self._prefix}>"

    def __getattr__(self, local: str) -> Any:
        if local.startswith("_"):  # dunders, and our own slots while being copied
            raise AttributeError(local)
        index = _active()
        cached = self._cache.get(local)
        if cached is not None and cached[0] is index:
            return cached[1]
        found = self._lookup(index, local)
        self._cache[local] = (index, found)
        return found

    def _lookup(self, index: OntologyIndex, local: str) -> Any:
        namespace = index.prefixes.get(self._prefix)
        if namespace is None:
            raise UnknownVocabularyError(
                f"prefix {self._prefix!r} is not defined by the active ontology "
                f"(prefixes: {', '.join(sorted(index.prefixes))})", name=self._prefix)
        iri = namespace + local
        if index.is_class(iri):
            return owl_class(index, self._prefix, local)
        info = index.property(iri)
        if info is not None:
            return PropertyRef(f"{self._prefix}:{local}", iri, info.kind)
        hints = tuple(_dotted(s) for s in index.suggest(f"{self._prefix}:{local}"))
        raise UnknownVocabularyError(
            f"{self._prefix}.{local} is not a class or property of the active ontology"
            f"{did_you_mean(hints)}", name=f"{self._prefix}.{local}", suggestions=hints)

    def __dir__(self) -> list[str]:
        return _active().local_names(self._prefix)


_NAMESPACES: dict[str, Namespace] = {}


def namespace(prefix: str) -> Namespace:
    """The namespace object of ``prefix`` after checking the active ontology defines it."""
    index = _active()
    if prefix not in index.prefixes:
        from .suggest import closest_names

        hints = closest_names(prefix, index.prefixes, limit=3)
        raise UnknownVocabularyError(
            f"no ontology prefix {prefix!r} in the active ontology{did_you_mean(hints)} "
            f"(prefixes: {', '.join(sorted(index.prefixes))})", name=prefix,
            suggestions=hints)
    found = _NAMESPACES.get(prefix)
    if found is None:
        found = _NAMESPACES[prefix] = Namespace(prefix)
    return found


__all__ = ["Namespace", "OwlClass", "OwlClassMeta", "PropertyRef", "namespace", "owl_class"]
