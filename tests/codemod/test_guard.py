"""The line guard (``core/guard.py``), tested with deliberately lossy transforms.

A transform that loses a comment only in the stand-in reading costs a whole-file reading;
one that loses it in every reading makes the file EZ906: not written by ``rewrite``, not
shown by ``--dry-run``, not counted by ``--check``, the original back from ``rewrite -``.
"""

from __future__ import annotations

import ast
import json
import subprocess
import sys
from dataclasses import replace
from pathlib import Path

import libcst as cst
import pytest
from codemod_case import settings
from hypothesis import HealthCheck, given
from hypothesis import settings as hypothesis_settings
from test_byte_exact_property import Module, modules

import ezmigrate.codemod.migrate as core
from ezmigrate.codemod.core.guard import first_changed, protected_lines, protected_lines_cst
from ezmigrate.codemod.core.holes import Holes
from ezmigrate.codemod.migrate import guarded_readings, migrate
from ezskiros_runtime.codes import code_for

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures"
SOURCE = (b"from skiros2_common.core.abstract_skill import SkillDescription\n"
          b"from skiros2_common.core.params import ParamTypes\n"
          b"\n"
          b"# the helpers below are kept\n"
          b"LIMIT = 3\n"
          b"\n"
          b"\n"
          b"class Pick(SkillDescription):\n"
          b"    def createDescription(self):\n"
          b"        self.addParam('A', 1, ParamTypes.Required)\n"
          b"\n"
          b"\n"
          b"def helper():\n"
          b"    return LIMIT\n")
LOST = 4  # the comment line
LOSSY = '''
import libcst as _cst
import ezmigrate.codemod.migrate as _core

_update_imports = _core.update_imports


def _lossy(*args, **kwargs):
    """update_imports, then every comment line before a top-level statement dropped."""
    module = _update_imports(*args, **kwargs)
    return module.with_changes(body=[
        stmt.with_changes(leading_lines=[line for line in stmt.leading_lines
                                         if line.comment is None])
        for stmt in module.body])
'''
INSTALL = "\n_core.update_imports = _lossy\n"


def _lossy_everywhere(monkeypatch: pytest.MonkeyPatch) -> None:
    scope: dict[str, object] = {}
    exec(LOSSY, scope)  # the same transform the command-line tests install
    monkeypatch.setattr(core, "update_imports", scope["_lossy"])


# -- the comparison --------------------------------------------------------------------

@pytest.mark.parametrize(("new", "protected", "expected"), [
    ("a\nb\nc\n", set(), None),
    ("a\nnew\nb\nc\n", set(), None),  # insertions are allowed
    ("a\nc\n", set(), 2),  # a lost line
    ("a\nB\nc\n", set(), 2),  # a changed line
    ("a\nB\nc\n", {2}, None),  # ... where a migration may change it
    ("a\nc\nb\n", set(), 3),  # a moved line (c, found before b)
    ("a\nb\r\nc\n", set(), 2),  # a changed line ending
    ("a\nb\nc", set(), 3),  # a lost final newline
])
def test_the_guard_names_the_first_line_that_changes(new: str, protected: set[int],
                                                      expected: int | None) -> None:
    assert first_changed("a\nb\nc\n", new, protected) == expected


def test_a_lost_blank_line_is_named_even_where_a_later_blank_line_could_stand_for_it() -> None:
    assert first_changed("a\n\nb\n\nc\n", "a\nb\n\nc\n", set()) == 2


def test_a_form_feed_ends_no_line_and_a_lost_one_is_seen() -> None:
    assert first_changed("a\fb\n", "a\fb\n", set()) is None
    assert first_changed("x\n\f\ny\n", "x\ny\n", set()) == 2
    assert first_changed("x\n\f    y\n", "x\n    y\n", set()) == 2


def test_the_protected_lines_are_imports_headers_and_create_description() -> None:
    tree = ast.parse(SOURCE)
    lines = SOURCE.count(b"\n")
    assert protected_lines(tree, {8}, lines) == {1, 2, 8, 9, 10, 11, 12}
    assert protected_lines(tree, set(), lines) == {1, 2}  # nothing converted
    assert protected_lines_cst(cst.parse_module(SOURCE), {8}, lines) == \
        protected_lines(tree, {8}, lines)


def _python_fixtures() -> list[Path]:
    found = []
    for path in sorted(FIXTURES.rglob("*.py")):
        try:
            ast.parse(path.read_bytes())
        except (SyntaxError, ValueError):
            continue
        found.append(path)
    return found


def test_ast_and_libcst_protect_the_same_lines_on_every_fixture() -> None:
    compared = 0
    for path in _python_fixtures():
        data = path.read_bytes()
        result = migrate(data, settings(), path.name)
        converted = {s.line for s in result.skills if s.status == "converted"}
        if not converted:
            continue
        count = data.count(b"\n") + 1
        assert protected_lines_cst(cst.parse_module(data), converted, count) == \
            protected_lines(ast.parse(data), converted, count), path
        compared += 1
    assert compared >= 15


# -- deliberately lossy transforms ---------------------------------------------------------

def test_a_stand_in_reading_that_loses_a_line_costs_a_whole_file_reading(
        monkeypatch: pytest.MonkeyPatch) -> None:
    whole = migrate(SOURCE, settings(), "m.py")
    real = core.stand_in

    def lossy(*args: object) -> Holes | None:
        holes = real(*args)  # type: ignore[arg-type]
        assert holes is not None and holes.filled
        (placeholder, original), *rest = holes.filled
        return replace(holes, filled=((placeholder, original.replace(b"LIMIT", b"LIMIT + 1")),
                                      *rest))

    monkeypatch.setattr(core, "stand_in", lossy)
    assert [lost for _, lost in guarded_readings(SOURCE, settings(), "m.py")] == [14, None]
    assert migrate(SOURCE, settings(), "m.py") == whole


@pytest.mark.parametrize("source", [SOURCE, SOURCE.decode()])
def test_a_file_every_reading_would_damage_is_refused_with_ez906(
        source: bytes | str, monkeypatch: pytest.MonkeyPatch) -> None:
    _lossy_everywhere(monkeypatch)
    assert [lost for _, lost in guarded_readings(source, settings(), "m.py")] == [LOST, LOST]
    result = migrate(source, settings(), "m.py")
    assert result.new_source is None
    assert (result.error_line, result.error_kind, result.error_code) == (
        LOST, "lossy-rewrite", "EZ906")
    assert f"line {LOST} would change" in (result.error or "")
    assert [(s.name, s.status) for s in result.skills] == [("Pick", "failed")]
    assert code_for("lossy-rewrite") == "EZ906"


# -- the command line applies the same guard --------------------------------------------------

def _ezmigrate(*args: str, stdin: bytes | None = None) -> subprocess.CompletedProcess[bytes]:
    """The command, with the lossy transform installed before it starts."""
    program = LOSSY + INSTALL + "from ezmigrate.cli.commands import main\nmain()\n"
    return subprocess.run([sys.executable, "-c", program, *args], input=stdin,
                          capture_output=True, timeout=300, check=False)


@pytest.fixture
def skill_file(tmp_path: Path) -> Path:
    path = tmp_path / "skills.py"
    path.write_bytes(SOURCE)
    return path


@pytest.mark.parametrize("mode", [[], ["--dry-run"], ["--check"], ["--dry-run", "--check"]])
def test_rewrite_refuses_the_file_in_every_mode(skill_file: Path, tmp_path: Path,
                                                mode: list[str]) -> None:
    report = tmp_path / "report.json"
    proc = _ezmigrate("rewrite", "--no-verify", "--jobs", "1", *mode, "--report", str(report),
                      str(skill_file))
    assert proc.returncode == 1, proc.stderr
    assert skill_file.read_bytes() == SOURCE
    assert proc.stdout == b""  # no diff, no "would rewrite"
    assert f"line {LOST} would change".encode() in proc.stderr
    files = json.loads(report.read_text())["files"]
    assert [(f["code"], f["error_line"], f["changed"]) for f in files] == [("EZ906", LOST,
                                                                            False)]


def test_rewrite_from_stdin_gives_the_original_back(skill_file: Path) -> None:
    proc = _ezmigrate("rewrite", "--no-verify", "-", stdin=SOURCE)
    assert proc.stdout == SOURCE
    assert proc.returncode == 1, proc.stderr


def test_check_reports_a_file_the_migration_would_damage_as_ez906(skill_file: Path) -> None:
    """A decorated class is no plain description (``lint/plain_reader.py``), so ``check``
    reads it with the codemod, and the guard's verdict is a finding."""
    skill_file.write_bytes(SOURCE.replace(b"class Pick", b"@register\nclass Pick"))
    proc = _ezmigrate("check", "--select", "EZ9", "--jobs", "1", str(skill_file))
    assert f"skills.py:{LOST}:1: EZ906 ".encode() in proc.stdout, proc.stdout + proc.stderr
    assert proc.returncode == 1


def test_the_stand_in_reading_passes_the_guard_on_generated_modules() -> None:
    """The guard stays quiet where the causes are fixed: on the modules of the byte-exact
    property the first reading is never refused."""

    @hypothesis_settings(max_examples=200, deadline=None, database=None,
                         suppress_health_check=[HealthCheck.too_slow])
    @given(modules())
    def first_reading_kept(module: Module) -> None:
        _, lost = next(guarded_readings(module.source(), settings(), "generated.py"))
        assert lost is None

    first_reading_kept()
