"""A file only Python 2 reads (``print x``, ``exec code``, ``except X, e:``) gets the
codemod's answer from ``ast``'s error alone (``python2_refusal``, which ``file_facts``
and the codemod share), without libcst: the oracle is the real codemod
(``runner.migrate_file``) on the same bytes, on every such file this project has, on
generated repositories with Python 2 files, and on statements written here.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest
from bench_generator import generator

from ezmigrate.codemod.core.python2 import python2_refusal as refused
from ezmigrate.codemod.migrate import _migrate_text
from ezmigrate.codemod.settings import Settings
from ezmigrate.project.runner import migrate_file
from ezmigrate.report.results import FileResult

REPO = Path(__file__).resolve().parents[2]
SETTINGS = Settings()
HEADER = b"from skiros2_skill.core.skill import SkillDescription\n\n"


def _error(data: bytes) -> SyntaxError | None:
    try:
        ast.parse(data)
    except SyntaxError as error:
        return error
    return None


def _libcst_reading(name: str, data: bytes) -> FileResult | None:
    """What the codemod made of the file by libcst's reading, before it asked
    ``python2_refusal`` first: libcst's error in Python's words, or its answer once
    libcst read the file (``except X, e:`` read as Python 3.14's ``except A, B:``)."""
    return _migrate_text(data, data, SETTINGS, name, None, None)


def _agrees(name: str, data: bytes, found: FileResult) -> None:
    """``found`` is what ``rewrite`` says, and what libcst's reading said wherever it
    said Python 2 too: a ``print x`` statement always (libcst refuses it, in Python's
    words), an ``except X, e:`` when libcst read the rest of the file."""
    assert found == migrate_file(name, data, SETTINGS)
    by_libcst = _libcst_reading(name, data)
    assert by_libcst is not None and by_libcst.error is not None
    if found.error is not None and "Python 2 syntax `except" in found.error \
            and "Python 2 syntax" not in by_libcst.error:
        return  # libcst refused a later line: the clause Python met first names the file
    assert found == by_libcst


def _compare(paths: list[Path]) -> int:
    """How many files ``refused`` answered; asserts each answer is the codemod's."""
    answered = 0
    for path in paths:
        data = path.read_bytes()
        error = _error(data)
        if error is None:
            continue
        found = refused(path.name, data, error)
        if found is not None:
            answered += 1
            _agrees(path.name, data, found)
    return answered


def test_the_fixtures_refused_statements_read_as_the_codemod_reads_them() -> None:
    assert _compare(sorted((REPO / "fixtures").rglob("*.py"))) >= 2


def test_generated_python2_files_read_as_the_codemod_reads_them(tmp_path: Path) -> None:
    generator().generate(tmp_path / "repo", 80, skill_share=1.0, seed=5, py2_share=0.5)
    assert _compare(sorted((tmp_path / "repo").rglob("*.py"))) >= 5


@pytest.mark.parametrize("body", [
    b'print "done"\n',
    b"print x\n",
    b"def f():\n    print 'a', 1\n",
    b"exec code in scope\n",
    b"x = 1\n\n\nclass A(SkillDescription):\n    def createDescription(self):\n"
    b"        print 'hello %s' % self\n",
    b"# -*- coding: latin-1 -*-\nname = '\xe9'\nprint name\n",  # its cookie opens the file
    b"try:\n    pass\nexcept ValueError, e:\n    pass\n",  # libcst reads it (PEP 758)
    b"try:\n    pass\nexcept (A,\n        B), e:\n    pass\n",
    b"def f():\n    try:\n        pass\n    except IOError, e:\n        print e\n",
])
def test_a_statement_no_python_3_reads_is_answered_here(tmp_path: Path, body: bytes) -> None:
    data = body if body.startswith(b"#") else HEADER + body
    error = _error(data)
    assert error is not None
    found = refused("a.py", data, error)
    assert found is not None and found.error is not None
    _agrees("a.py", data, found)


@pytest.mark.parametrize("body", [
    b"x = (\n",
    b"x = (\ntry:\n    pass\nexcept ValueError, e:\n    pass\n",  # Python stops first
    b'x = f"{d["k"]}"\ntry:\n    pass\nexcept A, e:\n    pass\n',  # elsewhere
    b'x = f"{d["k"]}"\n',  # Python 3.12 syntax: libcst reads it under any Python
    b"print >>out, x\nx = (\n",  # a valid expression, then another error
])
def test_any_other_error_is_left_to_the_codemod(body: bytes) -> None:
    data = HEADER + body
    error = _error(data)
    if error is None:  # newer syntax this Python reads: nothing refused at all
        return
    assert refused("a.py", data, error) is None


def test_python_2_is_named_whatever_else_the_file_holds() -> None:
    """The ``except X, e:`` Python meets first names the file Python 2, in ``check`` and in
    the codemod alike, even where libcst would have refused the file for a later line
    (a ``print x``): before, the codemod then reported Python's words for the clause."""
    data = HEADER + b"try:\n    pass\nexcept ValueError, e:\n    pass\nprint 'done'\n"
    error = _error(data)
    assert error is not None
    found = refused("a.py", data, error)
    assert found is not None and found.error is not None
    assert found.error.startswith("cannot parse: Python 2 syntax `except X, e:` (line 5, ")
    assert found == migrate_file("a.py", data, SETTINGS)
    by_libcst = _libcst_reading("a.py", data)
    assert by_libcst is not None and by_libcst.error is not None
    assert by_libcst.error.startswith("cannot parse: multiple exception types")
