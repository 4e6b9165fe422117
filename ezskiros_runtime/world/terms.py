"""The terms of a scene's triples as plain data: IRIs, blank nodes and literals, each
literal with the Python value rdflib gives it.

A scene is read into ``Scene`` and nothing of rdflib is kept, so its terms need not be
rdflib's either. rdflib takes a run 40 ms to import and builds each term through checks a
saved scene never needs; the literals SkiROS2 saves (strings, language-tagged strings,
integers, booleans, floats and doubles written as decimals, with or without an exponent, as
SkiROS2 saves a small pose value: ``-2.19e-06``) are read the same way by
every rdflib the robots run (4.2.2, 6.1, 7): the value is Python's ``int``/``float`` of
the text, and the text rdflib keeps is that value written back (``"1.50"`` is ``1.5``,
``"007"`` is ``7``). Those are made here (``plain_literal``); any other literal, and every
term of a file rdflib parses, is rdflib's own, turned into these (``from_rdflib``). A test
holds ``plain_literal`` to rdflib's ``Literal`` on generated texts, under each robot's
rdflib.

Runs on the robot's Python 3.8 with rdflib 4.2.2 as well as on rdflib 7.
"""

from __future__ import annotations

import re
from typing import Tuple

from ..ontology.naming import XSD

IRI, BLANK, LITERAL = "iri", "blank", "literal"

_INTEGER = re.compile(r"[+-]?[0-9]{1,18}")
_DECIMAL = re.compile(r"[+-]?[0-9]{1,15}(?:\.[0-9]{1,25})?(?:[eE][+-]?[0-9]{1,2})?")
_INTEGERS = frozenset({XSD + "integer", XSD + "int"})
_FLOATS = frozenset({XSD + "float", XSD + "double"})


class Term:
    """One term: its ``kind`` (``IRI``, ``BLANK``, ``LITERAL``) and text (a literal's as
    rdflib keeps it), and for a literal its datatype, language and Python value (None
    when the text does not fit the datatype). Equal as rdflib's terms are: by kind, text,
    datatype and language, whose case rdflib keeps but does not compare."""

    __slots__ = ("_key", "datatype", "kind", "language", "text", "value")

    def __init__(self, kind: str, text: str, datatype: str | None = None,
                 language: str | None = None, value: object = None) -> None:
        self.kind = kind
        self.text = text
        self.datatype = datatype
        self.language = language
        self.value = value
        self._key = (kind, text, datatype, language.lower() if language else None)

    def __str__(self) -> str:
        return self.text

    def __repr__(self) -> str:
        return f"Term{self._key!r}"

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Term) and self._key == other._key

    def __hash__(self) -> int:
        return hash(self._key)


Triple = Tuple[Term, Term, Term]


def iri(text: str) -> Term:
    return Term(IRI, text)


def plain_literal(lexical: str, language: str = "", datatype: str = "") -> Term | None:
    """The literal as rdflib reads it, when it is one of the plain kinds every rdflib reads
    alike (see the module doc); None for any other, which rdflib reads
    (``from_rdflib``)."""
    if not datatype:
        if language != language.lower():
            return None  # rdflib releases differ on a tag's case
        return Term(LITERAL, lexical, None, language or None, lexical)
    if datatype == XSD + "string":
        return Term(LITERAL, lexical, datatype, None, lexical)
    if datatype == XSD + "boolean" and lexical in ("true", "false"):
        return Term(LITERAL, lexical, datatype, None, lexical == "true")
    if datatype in _INTEGERS and _INTEGER.fullmatch(lexical):
        number = int(lexical)
        return Term(LITERAL, str(number), datatype, None, number)
    if datatype in _FLOATS and _DECIMAL.fullmatch(lexical):
        decimal = float(lexical)
        return Term(LITERAL, str(decimal), datatype, None, decimal)
    return None


def from_rdflib(term: object) -> Term:
    """An rdflib term (``URIRef``, ``BNode``, ``Literal``) as a ``Term``."""
    from rdflib import BNode, Literal

    if isinstance(term, Literal):
        value = term.toPython()
        return Term(LITERAL, str(term), str(term.datatype) if term.datatype is not None
                    else None, term.language or None,
                    None if isinstance(value, Literal) else value)
    return Term(BLANK if isinstance(term, BNode) else IRI, str(term))


def rdflib_literal(lexical: str, language: str = "", datatype: str = "") -> Term:
    """A literal rdflib reads (``plain_literal`` gave None)."""
    from rdflib import Literal, URIRef

    return from_rdflib(Literal(lexical, lang=language or None,
                               datatype=URIRef(datatype) if datatype else None))
