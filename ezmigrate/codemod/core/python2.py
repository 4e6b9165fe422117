"""Python 2's ``except X, e:`` found by the tokens, without libcst's position pass.

libcst reads ``except X, e:`` as PEP 758's unparenthesised ``except A, B:`` (Python 3.14);
in a SkiROS2 module it is Python 2 code that no supported Python imports, and the file is
refused with the clause's line and column. Finding the clause in libcst's tree needs its
position pass, which costs a Python 2 file as much as the rest of its migration; the
tokens say the same at a fraction of it: an ``except`` clause whose expression has a comma
outside any bracket and no ``as``. When the tokens cannot be read (the file does not
tokenize) or hold no such clause, ``None`` leaves the answer to libcst's tree.
"""

from __future__ import annotations

import io
import tokenize

_OPEN = frozenset("([{")
_CLOSE = frozenset(")]}")
_LINE_STARTS = frozenset({tokenize.NEWLINE, tokenize.NL, tokenize.INDENT, tokenize.DEDENT,
                          tokenize.ENCODING})


def comma_handler(raw: bytes) -> tuple[int, int] | None:
    """Line and 1-based column of the first ``except X, e:`` clause, or None (see the
    module doc)."""
    try:
        tokens = [t for t in tokenize.tokenize(io.BytesIO(raw).readline)
                  if t.type != tokenize.COMMENT]
    except (tokenize.TokenError, SyntaxError, UnicodeError, LookupError):
        return None
    for number, token in enumerate(tokens):
        if token.type != tokenize.NAME or token.string != "except" or (
                number and tokens[number - 1].type not in _LINE_STARTS):
            continue
        depth, comma = 0, False
        for following in tokens[number + 1:]:
            text = following.string
            if following.type == tokenize.OP and text in _OPEN:
                depth += 1
            elif following.type == tokenize.OP and text in _CLOSE:
                depth -= 1
            elif depth == 0 and (following.type == tokenize.NEWLINE
                                 or (following.type == tokenize.NAME and text == "as")
                                 or (following.type == tokenize.OP and text in ":*")):
                break
            elif depth == 0 and following.type == tokenize.OP and text == ",":
                comma = True
        else:
            continue
        if comma and following.string == ":":
            return token.start[0], token.start[1] + 1
    return None
