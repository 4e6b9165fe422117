"""``literal_of``'s short cuts (one-token literals read without compiling them) give what
``ast.literal_eval`` gives, value and type, for every spelling Python allows."""

from __future__ import annotations

import ast

import libcst as cst
import pytest

from ezmigrate.codemod.core.context import literal_of

SPELLINGS = [
    "0", "7", "1_000", "0x1F", "0o17", "0b101", "0X_ff", "10**3",
    "0.5", "5.", ".5", "1e-3", "1E5", "1_0.2_5", "3.14e+2", "0e0",
    '"plain"', "'single'", '""', "''", '"it\'s"', "'say \"hi\"'", '"tab\\there"',
    'r"raw\\n"', 'b"bytes"', 'f"{x}"', '"""triple"""', "u'unicode'", '"a" "b"',
    "True", "False", "None", "-1", "+2.5", "(3)", "[1, 2.5, 'x']", "{'k': 0x10}",
]


@pytest.mark.parametrize("text", SPELLINGS)
def test_a_literal_reads_as_python_reads_it(text: str) -> None:
    module = cst.parse_module(f"x = {text}\n")
    statement = module.body[0]
    assert isinstance(statement, cst.SimpleStatementLine)
    assign = statement.body[0]
    assert isinstance(assign, cst.Assign)
    found = literal_of(assign.value, module)
    try:
        expected = ast.literal_eval(text)
    except ValueError:  # not literal syntax (an f-string, an operation)
        assert found is None
        return
    assert found is not None
    assert (found.value, type(found.value), found.code) == (expected, type(expected), text)
