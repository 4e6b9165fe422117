"""``core/python2.py``: Python 2's ``except X, e:`` found by the tokens gives the line and
column libcst's tree and position pass give, on hand-written shapes and on thousands of
modules put together at random; where the tokens cannot tell, the tree still answers."""

from __future__ import annotations

import ast
import random

import libcst as cst
import pytest

from ezmigrate.codemod.core.python2 import comma_handler, python2_refusal
from ezmigrate.codemod.migrate import (
    Settings,
    _migrate_text,
    _python2_except,
    _python2_except_in_tree,
    migrate,
)


def _tree(text: str) -> tuple[int, int] | None:
    return _python2_except_in_tree(cst.parse_module(text))


SHAPES = {
    "the plain clause": "try:\n    x()\nexcept ValueError, e:\n    pass\n",
    "a tuple, then the name": "try:\n    x()\nexcept (A, B), e:\n    pass\n",
    "after a Python 3 clause": "try:\n    x()\nexcept (A, B):\n    pass\n"
                               "except C, e:\n    pass\n",
    "nested, with tabs": "def f():\n\ttry:\n\t\tx()\n\texcept IOError, e:\n\t\tpass\n",
    "a comment between": "try:\n    x()\n# about it\nexcept A, e:  # py2\n    pass\n",
    "a string that says it first": "s = 'except A, b:'\ntry:\n    x()\nexcept A, e:\n"
                                   "    pass\n",
    "an attribute and a call": "try:\n    x()\nexcept mod.Error(1, 2), e:\n    pass\n",
    "on one line": "try: x()\nexcept A, e: pass\n",
    "a colon inside brackets": "try:\n    x()\nexcept {1: A}[1], e:\n    pass\n",
    "a bracket over lines": "try:\n    x()\nexcept (A,\n        B), e:\n    pass\n",
    "non-ASCII before it": "# é\ns = 'ünïcode'\ntry:\n    x()\nexcept A, e:\n    pass\n",
}


@pytest.mark.parametrize("text", SHAPES.values(), ids=SHAPES.keys())
def test_the_tokens_name_the_clause_the_tree_names(text: str) -> None:
    found = _tree(text)
    assert found is not None and comma_handler(text.encode()) == found


def test_without_such_a_clause_the_tokens_leave_it_to_the_tree() -> None:
    assert comma_handler(b"try:\n    x()\nexcept (A, B):\n    pass\n") is None
    assert comma_handler(b"try:\n    x()\nexcept A as e:\n    pass\n") is None
    assert comma_handler(b"x = (\n") is None  # does not tokenize


PIECES = ["ValueError", "(A, B)", "mod.Error", "f(1, 2)", "[a, b][0]", "A"]


def test_modules_at_random_get_the_same_answer_both_ways() -> None:
    chance = random.Random(7)
    compared = 0
    for _ in range(1000):
        lines: list[str] = []
        for _ in range(chance.randint(1, 4)):
            indent = chance.choice(["", "    ", "\t"])
            if indent:
                lines.append("def f():" if indent == "    " else "class C:")
            lines += [f"{indent}try:", f"{indent}    x = '{chance.choice(PIECES)}, e:'"]
            for _ in range(chance.randint(1, 3)):
                kind = chance.choice(PIECES)
                tail = chance.choice([", e", " as e", "", ", e  # old"])
                lines += [f"{indent}except {kind}{tail}:", f"{indent}    pass"]
        text = "\n".join(lines) + "\n"
        try:
            module = cst.parse_module(text)
        except cst.ParserSyntaxError:
            continue
        tree = _python2_except_in_tree(module)
        tokens = comma_handler(text.encode())
        assert tokens is None or tokens == tree, text
        if tree is not None:
            assert tokens == tree, text
            assert _python2_except(module, text) == tree
            compared += 1
    assert compared > 150, compared


def test_the_answer_before_libcst_is_the_one_libcst_led_to() -> None:
    """``python2_refusal`` answers before libcst parses the file; where libcst does parse
    it, the codemod's reading after the parse (``_syntax_facts``) gives the same result."""
    compared = 0
    for text in SHAPES.values():
        source = ("from skiros2_skill.core.skill import SkillDescription\n\n" + text).encode()
        try:
            ast.parse(source)
        except SyntaxError as error:
            early = python2_refusal("a.py", source, error)
        else:
            continue
        late = _migrate_text(source, source, Settings(), "a.py", None, None)
        if early is None:  # Python stopped elsewhere, or the tokens do not tell
            continue
        assert late == early == migrate(source, Settings(), "a.py"), text
        compared += 1
    assert compared >= len(SHAPES) - 1
