"""Python 3.12's f-strings (PEP 701) spelt so that an older Python's ``ast`` reads them.

Since 3.12 a replacement field may reuse its f-string's quote: ``f"{d["k"]}"``. Before
3.12 the tokenizer ends the literal at that quote, and ``ast.parse`` refuses the file; the
codemod then reads it with libcst (which reads newer syntax under any Python), and
``check`` pays libcst's import for a file it would otherwise read in a millisecond.

``older_spelling`` gives the same bytes with each such nested string's quotes swapped
(``f"{d['k']}"``), when that is all it takes: a nested string with no backslash, no quote
of the other kind inside it, and no other f-string around it using that other quote. The
swap changes one byte for one at the same offsets, and no string's value, so the tree
Python reads from the new bytes is the tree Python 3.12 reads from the old ones, node for
node and position for position. Anything else PEP 701 allows that older Pythons refuse (a
backslash or a comment inside a field, a field over lines in a one-line f-string, nested
f-strings reusing quotes) gives None: the codemod reads the file as before.

A scanner, not a parser: it finds strings and fields the way Python 3.12's tokenizer does,
and gives up (None) on anything it does not follow; ``ast.parse`` of its answer is the
only judge of the result.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

_QUOTES = b"'\""
_PREFIXES = frozenset({b"", b"r", b"u", b"b", b"br", b"rb", b"f", b"fr", b"rf"})
_OPEN = b"([{"
_CLOSE = b")]}"
_F_PREFIX = re.compile(rb"[fF][rR]?['\"]|[rR][fF]['\"]")


class _GiveUp(Exception):
    """The scanner does not follow this text (or it needs more than a swap)."""


@dataclass
class _Scan:
    data: bytes
    swaps: list[tuple[int, int]] = field(default_factory=list)
    """(start, end) of each nested string whose quotes are swapped."""

    def module(self) -> None:
        """Every token of the module; strings and f-strings scanned in full."""
        data, at = self.data, 0
        while at < len(data):
            byte = data[at:at + 1]
            if byte == b"#":
                at = _line_end(data, at)
            elif byte == b"\\":
                at += 2
            elif byte in _QUOTES or _word_start(byte):
                at = self.token(at, ())
            else:
                at += 1

    def token(self, at: int, around: tuple[bytes, ...]) -> int:
        """A word, a number or a string starting at ``at``; its end. ``around``: the quotes
        of the f-strings whose field holds it."""
        data = self.data
        end = at
        while end < len(data) and _word_byte(data[end:end + 1]):
            end += 1
        prefix = data[at:end].lower()
        if end < len(data) and data[end:end + 1] in _QUOTES and prefix in _PREFIXES:
            return self.string(at, end, prefix, around)
        return max(end, at + 1)

    def string(self, start: int, at: int, prefix: bytes, around: tuple[bytes, ...]) -> int:
        """The string literal whose prefix starts at ``start`` and quote at ``at``; its end."""
        data = self.data
        quote = data[at:at + 1]
        triple = data[at:at + 3] == quote * 3
        closing = quote * 3 if triple else quote
        body = at + len(closing)
        if around:
            self.nested(start, body, quote, triple, prefix, around)
        if b"f" in prefix:
            return self.fstring(body, closing, b"r" in prefix, (*around, quote))
        pos = body
        while True:
            if pos >= len(data) or (not triple and data[pos:pos + 1] == b"\n"):
                raise _GiveUp  # unterminated: not this scanner's business
            if data[pos:pos + 1] == b"\\":
                pos += 2
            elif data.startswith(closing, pos):
                return pos + len(closing)
            else:
                pos += 1

    def nested(self, start: int, body: int, quote: bytes, triple: bool, prefix: bytes,
               around: tuple[bytes, ...]) -> None:
        """A string inside a field: swapped when it reuses a quote of the f-strings around
        it and a swap is all it takes."""
        if quote not in around:
            return
        other = b"'" if quote == b'"' else b'"'
        if triple or b"f" in prefix or other in around:
            raise _GiveUp
        end = self.data.find(quote, body)
        if end < 0:
            raise _GiveUp
        inside = self.data[body:end]
        if b"\\" in inside or other in inside or b"\n" in inside:
            raise _GiveUp
        self.swaps.append((body - 1, end))

    def fstring(self, at: int, closing: bytes, raw: bool, around: tuple[bytes, ...]) -> int:
        """The rest of an f-string from its first literal byte; its end."""
        data = self.data
        triple = len(closing) == 3
        pos = at
        while True:
            if pos >= len(data) or (not triple and data[pos:pos + 1] == b"\n"):
                raise _GiveUp
            two = data[pos:pos + 2]
            if data.startswith(closing, pos):
                return pos + len(closing)
            if two in (b"{{", b"}}"):
                pos += 2
            elif data[pos:pos + 1] == b"\\":
                if not raw and data[pos + 1:pos + 3] == b"N{":
                    pos = data.find(b"}", pos)
                    if pos < 0:
                        raise _GiveUp
                    pos += 1
                else:
                    pos += 2
            elif data[pos:pos + 1] == b"{":
                pos = self.field(pos + 1, triple, raw, around)
            else:
                pos += 1

    def field(self, at: int, triple: bool, raw: bool, around: tuple[bytes, ...]) -> int:
        """A replacement field from the byte after its ``{``; the byte after its ``}``."""
        data = self.data
        depth = 0
        pos = at
        while pos < len(data):
            byte = data[pos:pos + 1]
            if byte in (b"\\", b"#") or (byte == b"\n" and not triple):
                raise _GiveUp  # Python before 3.12 refuses these in a field
            if byte in _QUOTES or _word_start(byte):
                pos = self.token(pos, around)
                continue
            if byte in _OPEN:
                depth += 1
            elif byte in _CLOSE:
                if depth == 0:
                    if byte != b"}":
                        raise _GiveUp
                    return pos + 1
                depth -= 1
            elif depth == 0 and byte == b"!" and data[pos + 1:pos + 2] != b"=":
                pos += 1  # the conversion: a letter, then ``:`` or ``}``
                continue
            elif depth == 0 and byte == b":":
                return self.spec(pos + 1, triple, raw, around)
            pos += 1
        raise _GiveUp

    def spec(self, at: int, triple: bool, raw: bool, around: tuple[bytes, ...]) -> int:
        """A format spec from its first byte; the byte after its field's ``}``."""
        data = self.data
        pos = at
        while pos < len(data):
            byte = data[pos:pos + 1]
            if byte in _QUOTES or byte == b"\\" or (byte == b"\n" and not triple):
                raise _GiveUp
            if byte == b"{":
                pos = self.field(pos + 1, triple, raw, around)
                continue
            if byte == b"}":
                return pos + 1
            pos += 1
        raise _GiveUp


def older_spelling(data: bytes) -> bytes | None:
    """``data`` with the nested strings of its f-strings that reuse their quotes swapped
    (see the module doc); None when there are none, or when a swap is not enough."""
    if not _F_PREFIX.search(data) or not _utf8(data):
        return None
    scan = _Scan(data)
    try:
        scan.module()
    except _GiveUp:
        return None
    if not scan.swaps:
        return None
    out = bytearray(data)
    for start, end in scan.swaps:
        other = b"'"[0] if data[start] == b'"'[0] else b'"'[0]
        out[start] = out[end] = other
    return bytes(out)


def _utf8(data: bytes) -> bool:
    """UTF-8 text: one byte is one byte of the text Python reads (a coding line naming
    another encoding promises nothing of the kind)."""
    head = data.split(b"\n", 2)[:2]
    if any(b"coding" in line and b"utf-8" not in line.lower() and b"utf8" not in line.lower()
           for line in head):
        return False
    try:
        data.decode("utf-8")
    except UnicodeDecodeError:
        return False
    return True


def _line_end(data: bytes, at: int) -> int:
    end = data.find(b"\n", at)
    return len(data) if end < 0 else end


def _word_start(byte: bytes) -> bool:
    return bool(byte) and (byte.isalpha() or byte == b"_" or byte[0] >= 0x80)


def _word_byte(byte: bytes) -> bool:
    return bool(byte) and (byte.isalnum() or byte == b"_" or byte[0] >= 0x80)
