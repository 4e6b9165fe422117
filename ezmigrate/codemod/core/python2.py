"""Python 2 leftovers: the file's answer from Python's own error, and ``except X, e:``
found by the tokens, without libcst's position pass.

``python2_refusal`` answers, before libcst is asked, the files Python refuses for Python 2
syntax that no Python 3 reads: the codemod (``migrate``) and ``check``'s reading pool
(``file_facts``) both take their answer from it, so they agree by construction and
``check`` needs no libcst for such a file.

libcst reads ``except X, e:`` as PEP 758's unparenthesised ``except A, B:`` (Python 3.14);
in a SkiROS2 module it is Python 2 code that no supported Python imports, and the file is
refused with the clause's line and column. Finding the clause in libcst's tree needs its
position pass, which costs a Python 2 file as much as the rest of its migration; the
tokens say the same at a fraction of it: an ``except`` clause whose expression has a comma
outside any bracket and no ``as``. When the tokens cannot be read (the file does not
tokenize) or hold no such clause, ``None`` leaves the answer to libcst's tree.
"""

from __future__ import annotations

import ast
import io
import re
import tokenize
from dataclasses import replace

from ...report.results import FileResult, unparsable

_OPEN = frozenset("([{")
_CLOSE = frozenset(")]}")
_LINE_STARTS = frozenset({tokenize.NEWLINE, tokenize.NL, tokenize.INDENT, tokenize.DEDENT,
                          tokenize.ENCODING})

_STATEMENT = re.compile(r"Missing parentheses in call to '(print|exec)'")
"""Python's words for Python 2's ``print x`` and ``exec code`` statements."""

_TUPLE_CLAUSE = "multiple exception types must be parenthesized"
"""Python's words (3.10 on) for an ``except`` clause whose types are not parenthesised."""

EXCEPT_COMMA = re.compile(rb"\bexcept\b[^:\n]*,")
"""A line that may hold ``except X, e:``: the cheap test before the tokens."""



def python2_refusal(path: str, raw: bytes, error: SyntaxError) -> FileResult | None:
    """The result for a file Python refused with ``error``, when that error is Python 2
    syntax no Python 3 grammar has: a ``print x`` or ``exec code`` statement (worded as
    Python words it: libcst refuses it too, and its error is then reported in Python's
    words, ``migrate.syntax_error_location``), or an ``except X, e:`` clause that Python
    met first (named as Python 2 whatever else the file holds: libcst reads the clause as
    Python 3.14's ``except A, B:``, but the file is Python 2 either way). None for any
    other error: the codemod reads the file with libcst, which reads newer syntax.
    """
    if not error.lineno or b"\0" in raw:
        return None  # a NUL byte is reported as binary data (``syntax_error_location``)
    if python2_statement(error.msg or ""):
        return replace(unparsable(path, error.msg, error.lineno, error.offset or 1),
                       python2=True)
    if error.msg != _TUPLE_CLAUSE or not EXCEPT_COMMA.search(raw):
        return None  # (``error`` is Python's own parse failing: no need to parse again)
    found = comma_handler(raw)
    if found is None or found[0] != error.lineno:
        return None  # the tokens do not tell, or Python stopped elsewhere first
    return except_comma(path, *found)


def python2_statement(message: str) -> bool:
    """Whether Python's own error message (``SyntaxError.msg``) is its word for a Python 2
    ``print`` or ``exec`` statement."""
    return bool(_STATEMENT.match(message))


def except_comma(path: str, line: int, column: int) -> FileResult:
    """The result for a file with Python 2's ``except X, e:`` at ``line``, ``column``."""
    return replace(unparsable(path, "Python 2 syntax `except X, e:`", line, column,
                              "port the file to Python 3 (`except X as e:`) first"),
                   python2=True)


def python_parses(raw: bytes) -> bool:
    """Python's own parser (C speed) accepts the module: no Python 2 syntax in it."""
    try:
        ast.parse(raw)
    except (SyntaxError, ValueError, MemoryError, RecursionError):
        return False
    return True


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
