"""Resolving the names a description writes against the active ontology index.

``A.contain`` says only ``contain``; docs/dsl.md fixes how that becomes ``skiros:contain``:
the unique object or datatype property with that local name, else the default prefix with an
unknown-vocabulary note, and an ambiguity when several prefixes define it. Verbatim strings
(``":Product"``, ``"cora:robotPart"``) are kept as written and only *looked up* here, for
the checks. Every lookup goes through a small per-index cache because tracing 1,000 skills
asks for the same few names again and again.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from ..diagnostics import DescriptionError
from .conditions import VocabularyNote

if TYPE_CHECKING:
    from ..ontology.index import OntologyIndex

_LINKING_KINDS = ("object", "data")


class _IndexCache:
    """Per-index memo of name resolutions (the index is immutable, so memoizing is safe)."""

    def __init__(self, index: OntologyIndex) -> None:
        self.index = index
        self.properties: dict[str, tuple[str, VocabularyNote | None]] = {}
        self.iris: dict[str, str | None] = {}


_CACHE: list[_IndexCache] = []


def _cache(index: OntologyIndex) -> _IndexCache:
    if _CACHE and _CACHE[0].index is index:
        return _CACHE[0]
    entry = _IndexCache(index)
    _CACHE[:] = [entry]
    return entry


_ACTIVE: list[Callable[[], OntologyIndex]] = []


def active() -> OntologyIndex:
    """The active ontology index (its module is imported on first use only)."""
    if not _ACTIVE:
        from ..ontology.active import active_index

        _ACTIVE.append(active_index)
    return _ACTIVE[0]()


def resolve_property(index: OntologyIndex, local: str) -> tuple[str, VocabularyNote | None]:
    """``contain`` -> (``"skiros:contain"``, note-or-None) following docs/dsl.md."""
    memo = _cache(index).properties
    found = memo.get(local)
    if found is None:
        iris = []
        for iri in index.properties_named(local):
            info = index.property(iri)
            if info is not None and info.kind in _LINKING_KINDS and iri not in iris:
                iris.append(iri)
        names = sorted({index.compact(iri) for iri in iris})
        if len(names) == 1:
            found = (names[0], None)
        elif not names:
            found = (f"{index.default_prefix}:{local}", VocabularyNote(local, "unknown"))
        else:
            found = (names[0], VocabularyNote(local, "ambiguous", tuple(names)))
        memo[local] = found
    return found


def to_iri(index: OntologyIndex, name: str) -> str | None:
    """The IRI a SkiROS2 name means (``":X"`` and ``"X"`` use the default prefix), or None
    when its prefix is unknown. Existence of the IRI is not checked here."""
    memo = _cache(index).iris
    if name in memo:
        return memo[name]
    iri = index.expand(name)
    memo[name] = iri
    return iri


def normalized_name(index: OntologyIndex, name: str) -> str:
    """``":X"`` / ``"X"`` -> ``"skiros:X"``; other names unchanged (for messages)."""
    if ":" not in name:
        return f"{index.default_prefix}:{name}"
    return f"{index.default_prefix}{name}" if name.startswith(":") else name


def qname_of(value: Any, what: str) -> str:
    """A vocabulary argument as its string: verbatim str, or an OWL class / property
    reference by its ``qname``."""
    if isinstance(value, str):
        return value
    qname = getattr(value, "qname", None)
    if isinstance(qname, str):
        return qname
    raise DescriptionError(f"{what} needs a vocabulary name such as skiros.Product or "
                           f'"skiros:Product", got {value!r}')


def suggestions(index: OntologyIndex, name: str, kinds: tuple[str, ...]) -> tuple[str, ...]:
    """Closest known names (``prefix:Local``) for a misspelt one, best first."""
    try:
        found = index.suggest(name, kinds=kinds, limit=3)
    except Exception:  # a suggestion must never turn a finding into a crash
        return ()
    return tuple(s if "://" not in s else index.compact(s) for s in found)


__all__ = ["active", "normalized_name", "qname_of", "resolve_property", "suggestions",
           "to_iri"]
