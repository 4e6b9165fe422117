"""What an ontology file's DTD may declare before rdflib's RDF/XML reader sees it.

Why: rdflib reads RDF/XML with expat (through ``xml.sax``), which expands every entity the
document declares. A 1 KB file whose entities nest (``<!ENTITY b "&a;&a;...">``, the
"billion laughs") expands to gigabytes and never finishes; an external entity or DTD subset
points the reader outside the file. Ontology files come from repositories nobody vetted
(every ``owl/`` folder is discovered), so this module reads the prolog, everything before
the root element, and refuses a DTD unless it only abbreviates, as real OWL files do
(``<!ENTITY owl "http://www.w3.org/2002/07/owl#">``).

Refused, each with the line of its declaration:
- an external DTD subset (``<!DOCTYPE rdf:RDF SYSTEM "...">``, or ``PUBLIC``);
- an external entity (``<!ENTITY x SYSTEM "...">``, or ``PUBLIC``);
- a parameter entity (``<!ENTITY % x ...>``) or a reference to one (``%x;``);
- an entity whose replacement text refers to another entity (``&x;``, also when spelt with
  character references, ``&#38;x;``), the five predefined ones (``&amp;`` ...) aside, and
  a redeclaration of those five;
- an entity longer than ``MAX_ENTITY_TEXT`` characters: a long flat entity repeated
  expands quadratically, the other way to blow up;
- more entity references in the document than ``limits.MAX_ENTITY_REFERENCES``, or
  references that expand to more than ``limits.MAX_ENTITY_EXPANSION`` characters in all
  (the count and the size, not only the nesting: see ``_references``);
- any other markup inside the DTD: what this reader does not know it cannot vouch for.

The prolog is read for the declarations; the rest of the file only once, by one regular
expression that counts the references, so the cost grows linearly with the file. Anything
unexpected *before* the DTD or after it (text that is not XML, a Turtle file whose format
is being guessed, the root element) ends the reading of the prolog without a verdict: the
XML parser stops there too, before it could expand anything, and reports its own error.
"""

from __future__ import annotations

import codecs
import re
from typing import NamedTuple

from .limits import MAX_ENTITY_EXPANSION, MAX_ENTITY_REFERENCES, Limit

MAX_ENTITY_TEXT = 256
"""Longest entity replacement text accepted (namespace IRIs are well below 100)."""

PREDEFINED = frozenset({"amp", "lt", "gt", "apos", "quot"})
"""The entities every XML parser knows: one character each, they cannot amplify."""

FIRST_READ = 1 << 12
"""Bytes decoded for the first look; a longer prolog is read again four times as far."""

_SPACE = re.compile(r"[ \t\r\n]*")
_NAME = re.compile(r"[^\s\"'<>%&;\[\]]+")
_CHAR_REFERENCE = re.compile(r"&#(x[0-9a-fA-F]+|[0-9]+);")
_ENTITY_REFERENCE = re.compile(r"([&%])([^\s\"'<>%&;#][^\s\"'<>%&;]*);")
_ANY_REFERENCE = re.compile(r"&(#x[0-9a-fA-F]+|#[0-9]+|[^\s\"'<>%&;#][^\s\"'<>%&;]*);")
_UNQUOTED = re.compile(r"[^\"'%>]*")
_LINE_BREAK = re.compile(r"\r\n?|\n")
_DECLARED_ENCODING = re.compile(
    rb"<\?xml[^>]*?\sencoding\s*=\s*([\"'])([A-Za-z][A-Za-z0-9._-]*)\1[^>]*?\?>")
_UTF16_BY_START = ((codecs.BOM_UTF16_LE, "utf-16"), (codecs.BOM_UTF16_BE, "utf-16"),
                   (b"<\x00?\x00", "utf-16-le"), (b"\x00<\x00?", "utf-16-be"))


class Refusal(NamedTuple):
    """Why a file's DTD is refused, and the 1-based line of the declaration at fault;
    ``limit`` is the limit the file is over when that is the reason (else None)."""

    line: int
    reason: str
    limit: Limit | None = None


def refusal(data: bytes) -> Refusal | None:
    """Why the DTD of this RDF/XML document must not reach the parser, or None."""
    size = FIRST_READ
    while True:
        whole = size >= len(data)
        try:
            declared: list[tuple[int, dict[str, int]]] = []
            for text in _readings(data[:size], whole):
                prolog = _Prolog(text, whole)
                found = prolog.read()
                if found is not None:
                    return found
                declared.append((prolog.pos, prolog.entities))
            break
        except _Incomplete:
            size *= 4
    for text, (start, entities) in zip(_readings(data, True), declared):
        found = _references(text, start, entities)
        if found is not None:
            return found
    return None


def _references(text: str, start: int, entities: dict[str, int]) -> Refusal | None:
    """Whether the references after the prolog stay within ``MAX_ENTITY_REFERENCES`` and
    ``MAX_ENTITY_EXPANSION``: flat entities cannot nest, but rdflib gathers a literal by
    concatenating every expansion onto what came before, so 80,000 uses of a 256-character
    entity in one literal take minutes. Character and predefined references count as one
    reference of one character. A reference inside a comment or CDATA section is counted
    too: the bound errs on the safe side, and real files are far below it."""
    most_references = MAX_ENTITY_REFERENCES.value()
    most_characters = MAX_ENTITY_EXPANSION.value()
    characters = 0
    for references, match in enumerate(_ANY_REFERENCE.finditer(text, start), start=1):
        characters += entities.get(match.group(1), 1)
        if references > most_references:
            return Refusal(_line_at(text, match.start()),
                           f"it uses more than {most_references:,} entity references",
                           MAX_ENTITY_REFERENCES)
        if characters > most_characters:
            return Refusal(_line_at(text, match.start()),
                           f"its entity references expand to more than "
                           f"{most_characters:,} characters", MAX_ENTITY_EXPANSION)
    return None


def _line_at(text: str, at: int) -> int:
    return len(_LINE_BREAK.findall(text, 0, at)) + 1


def _readings(head: bytes, whole: bool) -> list[str]:
    """The bytes as text, every way expat might read them: UTF-16 by its byte order mark
    or first characters; else UTF-8 and, when the XML declaration names another encoding,
    that one too (the declaration itself read in ASCII, as expat reads it). Both are
    checked, so no doubt about which one the parser picks can let a declaration through.
    A character cut off at the end of ``head`` is left out."""
    for start, name in _UTF16_BY_START:
        if head.startswith(start):
            return [_decode(head, name, whole)]
    if head.startswith(codecs.BOM_UTF8):
        head = head[len(codecs.BOM_UTF8):]
    readings = [_decode(head, "utf-8", whole)]
    declared = _DECLARED_ENCODING.match(head)
    if declared is not None:
        end = declared.end()
        encoding = declared.group(2).decode("ascii")
        readings.append(head[:end].decode("ascii", "replace")
                        + _decode(head[end:], encoding, whole))
    return readings


def _decode(data: bytes, encoding: str, whole: bool) -> str:
    try:
        text: object = codecs.getincrementaldecoder(encoding)("replace").decode(data, whole)
    except (LookupError, TypeError, ValueError):
        text = None  # no codec by that name: expat has none either and will refuse the file
    if not isinstance(text, str):  # a bytes-to-bytes codec (base64): the same
        text = codecs.getincrementaldecoder("utf-8")("replace").decode(data, whole)
    return str(text)


class _Incomplete(Exception):
    """The text read so far ends before the prolog does."""


class _Refused(Exception):
    def __init__(self, found: Refusal) -> None:
        super().__init__(found.reason)
        self.found = found


class _Prolog:
    """One pass over the prolog (XML 1.0 productions ``prolog`` and ``doctypedecl``)."""

    def __init__(self, text: str, whole: bool) -> None:
        self.text = text
        self.whole = whole
        self.pos = 1 if text.startswith("\ufeff") else 0
        self.entities: dict[str, int] = {}
        """The declared entities and the length of their replacement text."""

    def read(self) -> Refusal | None:
        """The refusal, or None; _Incomplete when more of the file is needed to decide
        (at the end of the file, nothing more is: the parser refuses the cut-off prolog
        itself, having expanded nothing)."""
        try:
            self._prolog()
        except _Refused as refused:
            return refused.found
        except _Incomplete:
            if not self.whole:
                raise
        return None

    # -- reading primitives -----------------------------------------------------------------

    def _refuse(self, at: int, reason: str) -> _Refused:
        line = len(_LINE_BREAK.findall(self.text, 0, at)) + 1
        return _Refused(Refusal(line, reason))

    def _skip(self, pattern: re.Pattern[str] = _SPACE) -> None:
        """Past what ``pattern`` (which may match nothing) matches here."""
        match = pattern.match(self.text, self.pos)
        self.pos = match.end() if match else self.pos

    def _peek(self) -> str:
        if self.pos >= len(self.text):
            raise _Incomplete
        return self.text[self.pos]

    def _at(self, word: str) -> bool:
        """Whether ``word`` starts here; _Incomplete when the text ends inside it."""
        rest = len(self.text) - self.pos
        if rest < len(word):
            if word.startswith(self.text[self.pos:]):
                raise _Incomplete
            return False
        return self.text.startswith(word, self.pos)

    def _skip_past(self, end: str) -> None:
        found = self.text.find(end, self.pos)
        if found < 0:
            raise _Incomplete
        self.pos = found + len(end)

    def _name(self, start: int, what: str) -> str:
        match = _NAME.match(self.text, self.pos)
        if match is None:
            self._peek()
            raise self._refuse(start, f"the DTD has {what} without a name")
        self.pos = match.end()
        self._peek()  # a name the text ends in may go on
        return match.group()

    def _quoted(self) -> str:
        quote = self._peek()
        found = self.text.find(quote, self.pos + 1)
        if found < 0:
            raise _Incomplete
        value = self.text[self.pos + 1:found]
        self.pos = found + 1
        return value

    # -- the grammar ------------------------------------------------------------------------

    def _prolog(self) -> None:
        while True:
            self._skip()
            self._peek()
            if self._at("<?"):
                self._skip_past("?>")
            elif self._at("<!--"):
                self._skip_past("-->")
            elif self._at("<!DOCTYPE"):
                self._doctype()
            else:
                return  # the root element, or what the XML parser refuses by itself

    def _doctype(self) -> None:
        start = self.pos
        self.pos += len("<!DOCTYPE")
        self._skip()
        self._name(start, "a DOCTYPE")
        self._skip()
        if self._at("SYSTEM") or self._at("PUBLIC"):
            raise self._refuse(start, "the DOCTYPE names an external DTD subset "
                                      f"({self.text[self.pos:self.pos + 6]} ...), which "
                                      "would be read from outside the file")
        if self._peek() == "[":
            self.pos += 1
            self._internal_subset()
        self._skip()
        if self._peek() != ">":
            raise self._refuse(start, "the DOCTYPE declaration does not end where expected")
        self.pos += 1

    def _internal_subset(self) -> None:
        while True:
            self._skip()
            char = self._peek()
            if char == "]":
                self.pos += 1
                return
            start = self.pos
            if char == "%":
                raise self._refuse(start, "the DTD refers to a parameter entity "
                                          f"({self.text[start:start + 40].split()[0]})")
            if self._at("<!--"):
                self._skip_past("-->")
            elif self._at("<?"):
                self._skip_past("?>")
            elif self._at("<!ENTITY"):
                self._entity()
            elif self._at("<!ELEMENT") or self._at("<!ATTLIST") or self._at("<!NOTATION"):
                self._other_declaration()
            else:
                shown = self.text[start:start + 12].split("\n")[0]
                raise self._refuse(start, f"the DTD holds {shown!r}, which this check does "
                                          "not know and so cannot vouch for")

    def _entity(self) -> None:
        start = self.pos
        self.pos += len("<!ENTITY")
        self._skip()
        if self._peek() == "%":
            self.pos += 1
            self._skip()
            name = self._name(start, "a parameter entity")
            raise self._refuse(start, f"the DTD declares the parameter entity {name!r}")
        name = self._name(start, "an entity")
        self._skip()
        if self._at("SYSTEM") or self._at("PUBLIC"):
            raise self._refuse(start, f"the DTD declares the external entity {name!r} "
                                      f"({self.text[self.pos:self.pos + 6]} ...), which "
                                      "would be read from outside the file")
        if self._peek() not in "\"'":
            raise self._refuse(start, f"the DTD's entity {name!r} has no quoted value")
        literal = self._quoted()
        problem = _entity_problem(name, literal)
        if problem is not None:
            raise self._refuse(start, problem)
        self.entities.setdefault(name, len(_CHAR_REFERENCE.sub(_character, literal)))
        self._skip()
        if self._peek() != ">":
            raise self._refuse(start, f"the DTD's entity {name!r} does not end where "
                                      "expected")
        self.pos += 1

    def _other_declaration(self) -> None:
        """``<!ELEMENT``, ``<!ATTLIST``, ``<!NOTATION``: skipped (they expand nothing), up
        to their ``>`` outside quotes; a parameter-entity reference inside is refused."""
        start = self.pos
        self.pos += 2
        while True:
            self._skip(_UNQUOTED)
            char = self._peek()
            if char == ">":
                self.pos += 1
                return
            if char == "%":
                raise self._refuse(start, "the DTD refers to a parameter entity inside "
                                          "a declaration")
            self._quoted()


def _entity_problem(name: str, literal: str) -> str | None:
    """Why entity ``name`` with this quoted value must be refused, or None.

    Character references are replaced first, as the parser does when it stores the
    entity: ``&#38;a;`` becomes ``&a;``, which is parsed again wherever the entity is used.
    """
    if name in PREDEFINED:
        return f"the DTD redeclares the predefined entity {name!r}"
    text = _CHAR_REFERENCE.sub(_character, literal)
    for written in (literal, text):
        for match in _ENTITY_REFERENCE.finditer(written):
            sign, other = match.groups()
            if sign == "%" or other not in PREDEFINED:
                return (f"the DTD's entity {name!r} refers to the entity {other!r}: entities "
                        "that nest can expand without bound (the 'billion laughs')")
    if len(text) > MAX_ENTITY_TEXT:
        return (f"the DTD's entity {name!r} is {len(text)} characters long (at most "
                f"{MAX_ENTITY_TEXT}: a long entity used often expands quadratically)")
    return None


def _character(match: re.Match[str]) -> str:
    number = match.group(1)
    try:
        return chr(int(number[1:], 16) if number.startswith("x") else int(number))
    except (ValueError, OverflowError):
        return ""  # no such character: the parser refuses the file itself


__all__ = ["MAX_ENTITY_TEXT", "PREDEFINED", "Refusal", "refusal"]
