"""The triples of a Turtle file written in the plain form SkiROS2's world model saves
scenes in, read without rdflib's parser; ``None`` for anything else, which rdflib reads.

rdflib's Turtle parser is written in Python, character by character: a run over a lab's
37 scenes spends more time in it than in everything else it does with them. A saved scene
uses a small part of Turtle: ``@prefix`` lines, then statements ``subject predicate
object`` with ``;`` and ``,`` lists, whose terms are absolute IRIs, prefixed names,
``a``, simple quoted strings (with a language tag or a datatype), integers and booleans.

The subset is accepted only when it is certain to mean what rdflib reads: each term is
what rdflib's parser would build (``terms``: a literal of the kinds every rdflib reads
alike is made there, any other by rdflib's ``Literal``), and anything outside the subset
(blank nodes, collections, escapes, long strings, decimals and doubles, ``@base`` and
relative IRIs but an unused prefix's ``<>``, a name that continues past where the subset
stops reading it, an unknown prefix, any syntax error) gives ``None`` and the file goes to
rdflib, which reads it or says where it is wrong. A test holds the two readings equal on
every scene this project has, under each robot's rdflib.

Runs on the robot's Python 3.8 with rdflib 4.2.2 as well as on rdflib 7.
"""

from __future__ import annotations

import re
from typing import Tuple

from ..ontology.naming import RDF_TYPE, XSD
from .terms import Term, Triple, iri, plain_literal, rdflib_literal

_TOKEN = re.compile(r"""
  (?P<space>(?:[ \t\r\n]|\#[^\r\n]*)+)
| (?P<empty><>)
| (?P<iri><[A-Za-z][A-Za-z0-9+.-]*:[^<>"{}|^`\\\x00-\x20\x7f-\U0010ffff]*>)
| (?P<string>"[^"\\\r\n]*")
| (?P<at>@[A-Za-z]+(?:-[A-Za-z0-9]+)*)
| (?P<hats>\^\^)
| (?P<name>(?:[A-Za-z][A-Za-z0-9_-]*)?:(?:[A-Za-z_][A-Za-z0-9_-]*)?)
| (?P<number>-?(?:0|[1-9][0-9]*))
| (?P<word>a|true|false)
| (?P<punct>[.;,])
""", re.VERBOSE)
"""One token of the subset. A prefixed name's local part has no ``.``, ``:``, escape or
leading digit; numbers are integers without a sign ``+`` or leading zeros. ``<>`` is read
only as a prefix's namespace: SkiROS2 saves scenes with ``@prefix : <> .`` lines (and
``default1:`` and so on) that no name uses; a name that uses one is left to rdflib, which
resolves it against a base of its own."""

_ENDS = frozenset(" \t\r\n,;")
"""What may follow a name, a number or a keyword for the subset to have read all of it
(a ``.`` too, when followed by one of these or the end of the file, except after a name
with an empty local part)."""

Token = Tuple[str, str]


def _tokens(text: str) -> list[Token] | None:
    """The file's tokens without spaces and comments, or None when some text is outside
    the subset or a term runs on past what the subset reads of it."""
    found: list[Token] = []
    position, end = 0, len(text)
    spaced = False
    for match in _TOKEN.finditer(text):
        if match.start() != position:
            return None
        kind = match.lastgroup or ""
        position = match.end()
        if spaced and found and ((kind in ("at", "hats") and found[-1][0] == "string")
                                 or found[-1][0] == "hats"):
            return None  # a literal's tag or datatype is read only when written against it
        spaced = kind == "space"
        if spaced:
            continue
        value = match.group()
        if kind in ("name", "number", "word") and position < end:
            after = text[position]
            if after not in _ENDS and not (
                    after == "." and (position + 1 == end or text[position + 1] in _ENDS)
                    and not (kind == "name" and value.endswith(":"))):
                return None  # rdflib 4.2.2 reads ``ex:.`` as one name, and refuses it
        found.append((kind, value))
    if position != end:
        return None
    return found


def read_triples(text: str) -> set[Triple] | None:
    """The set of triples rdflib would read from ``text`` (as ``terms.Term``), or None
    when ``text`` is not in the subset (see the module doc)."""
    tokens = _tokens(text)
    if tokens is None:
        return None
    prefixes: dict[str, str | None] = {}
    triples: set[Triple] = set()
    iris: dict[str, Term] = {}  # one term per text: a scene repeats few of them often
    literals: dict[tuple[str, str, str], Term] = {}

    def uri(text: str) -> Term:
        node = iris.get(text)
        if node is None:
            node = iris[text] = iri(text)
        return node

    def literal(lexical: str, lang: str = "", datatype: str = "") -> Term:
        key = (lexical, lang, datatype)
        node = literals.get(key)
        if node is None:
            node = literals[key] = plain_literal(lexical, lang, datatype) \
                or rdflib_literal(lexical, lang, datatype)
        return node
    count = len(tokens)
    i = 0

    def at(index: int) -> Token:
        return tokens[index] if index < count else ("", "")

    def resource(token: Token) -> str | None:
        kind, value = token
        if kind == "iri":
            return value[1:-1]
        if kind == "name":
            prefix, _, local = value.partition(":")
            namespace = prefixes.get(prefix)
            return None if namespace is None else namespace + local
        return None

    while i < count:
        kind, value = tokens[i]
        if kind == "at":
            if value != "@prefix" or at(i + 1)[0] != "name" or not at(i + 1)[1].endswith(":") \
                    or at(i + 2)[0] not in ("iri", "empty") or at(i + 3) != ("punct", "."):
                return None
            relative = at(i + 2)[0] == "empty"  # no name of the subset may use it
            prefixes[at(i + 1)[1][:-1]] = None if relative else at(i + 2)[1][1:-1]
            i += 4
            continue
        subject = resource(tokens[i])
        if subject is None:
            return None
        i += 1
        while True:  # predicate object (, object)* (; predicate ...)* .
            if at(i) == ("word", "a"):
                predicate: str | None = RDF_TYPE
            else:
                predicate = resource(at(i))
            if predicate is None:
                return None
            i += 1
            while True:
                kind, value = at(i)
                node: Term
                if kind in ("iri", "name"):
                    named = resource(at(i))
                    if named is None:
                        return None
                    node = uri(named)
                    i += 1
                elif kind == "string":
                    lexical = value[1:-1]
                    following = at(i + 1)
                    if following[0] == "at":
                        node = literal(lexical, lang=following[1][1:])
                        i += 2
                    elif following[0] == "hats":
                        datatype = resource(at(i + 2))
                        if datatype is None:
                            return None
                        node = literal(lexical, datatype=datatype)
                        i += 3
                    else:
                        node = literal(lexical)
                        i += 1
                elif kind == "number":
                    node = literal(value, datatype=XSD + "integer")
                    i += 1
                elif kind == "word" and value in ("true", "false"):
                    node = literal(value, datatype=XSD + "boolean")
                    i += 1
                else:
                    return None
                triples.add((uri(subject), uri(predicate), node))
                if at(i) != ("punct", ","):
                    break
                i += 1
            if at(i) == ("punct", ";"):
                i += 1
                continue
            if at(i) == ("punct", "."):
                i += 1
                break
            return None
    return triples
