"""Class expressions: what an rdfs:domain or rdfs:range can be.

Domains and ranges are usually named classes, but OWL allows anonymous ones (blank nodes
with owl:unionOf, owl:intersectionOf, owl:complementOf, restrictions, ...). The index
keeps them as these small frozen dataclasses, which are plain picklable data (no rdflib
terms), so the index can be cached and checked without rdflib. Anything we do not
understand becomes `Unsupported`: a checker can then say "cannot decide" instead of
crashing or guessing.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass


class ClassExpr:
    """Base of all class expressions (domains, ranges, and their parts)."""

    __slots__ = ()

    def render(self, compact: Callable[[str], str] = str) -> str:
        """A short human-readable form; `compact` turns IRIs into prefixed names."""
        raise NotImplementedError


@dataclass(frozen=True)
class Named(ClassExpr):
    """A named class (or, for data properties, a datatype such as xsd:float)."""

    iri: str

    def render(self, compact: Callable[[str], str] = str) -> str:
        return compact(self.iri)


@dataclass(frozen=True)
class UnionOf(ClassExpr):
    """owl:unionOf: satisfied when any member is."""

    members: tuple[ClassExpr, ...]

    def render(self, compact: Callable[[str], str] = str) -> str:
        return "(" + " | ".join(m.render(compact) for m in self.members) + ")"


@dataclass(frozen=True)
class IntersectionOf(ClassExpr):
    """owl:intersectionOf: satisfied when every member is."""

    members: tuple[ClassExpr, ...]

    def render(self, compact: Callable[[str], str] = str) -> str:
        return "(" + " & ".join(m.render(compact) for m in self.members) + ")"


@dataclass(frozen=True)
class ComplementOf(ClassExpr):
    """owl:complementOf: satisfied when the inner expression is not."""

    expr: ClassExpr

    def render(self, compact: Callable[[str], str] = str) -> str:
        return "~" + self.expr.render(compact)


@dataclass(frozen=True)
class Unsupported(ClassExpr):
    """An anonymous class we cannot reason about (restriction, oneOf, broken list, ...).

    `text` describes it for messages; checks against it are undecidable.
    """

    text: str

    def render(self, compact: Callable[[str], str] = str) -> str:
        return self.text


def every(exprs: Sequence[ClassExpr]) -> ClassExpr:
    """One expression that all of ``exprs`` hold for at once: several ``rdfs:domain`` (or
    ranges) must be met by one element, not each by a different one."""
    return exprs[0] if len(exprs) == 1 else IntersectionOf(tuple(exprs))


__all__ = ["ClassExpr", "ComplementOf", "IntersectionOf", "Named", "UnionOf", "Unsupported",
           "every"]
