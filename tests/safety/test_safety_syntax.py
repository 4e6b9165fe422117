"""A file libcst cannot parse is reported with file, line and column and skipped, and the
run goes on; newer syntax libcst parses but this Python cannot import (PEP 701 f-strings on
3.11) is rewritten without verification, and verification says it cannot be imported."""

from __future__ import annotations

import sys

import pytest
from safety_support import (
    BROKEN,
    LEGACY,
    PYTHON_VERSION,
    assert_no_traceback,
    cli,
    copy_fixtures,
    expected_migration,
    libcst_parses,
    no_newer_python,
    python_parses,
)

UNPARSABLE = {  # file -> what stderr must say, with line and column
    "py2_print_statement.py": "cannot parse: Missing parentheses in call to 'print'. Did you "
                              "mean print(...)? (line 23, column 9)",
    "py2_except_comma.py": "cannot parse: Python 2 syntax `except X, e:` (line 26, column 9)",
    "truncated_mid_call.py": "cannot parse: '(' was never closed (line 14, column 47)",
}


@pytest.fixture
def folder(tmp_path):
    originals = copy_fixtures(tmp_path, [BROKEN / n for n in UNPARSABLE]
                              + [BROKEN / "fstring_pep701.py", LEGACY / "descriptions.py"])
    return tmp_path, originals


def _line_for(stderr: str, path) -> str:
    return next(li for li in stderr.splitlines() if li.startswith(f"{path}:"))


def test_unparsable_files_are_reported_with_line_and_column_and_the_run_goes_on(folder):
    path, originals = folder
    run = cli("rewrite", path, "--no-verify")
    assert run.returncode == 1
    assert_no_traceback(run.stderr, run.stdout)
    for name, message in UNPARSABLE.items():
        assert message in _line_for(run.stderr, path / name)
        assert (path / name).read_bytes() == originals[name]
    good = (path / "descriptions.py").read_bytes()
    assert good == expected_migration(originals["descriptions.py"]) != originals["descriptions.py"]
    assert "3 files could not be processed" in run.stderr


@pytest.mark.skipif(sys.version_info >= (3, 12), reason="PEP 701 f-strings import on 3.12+")
def test_pep701_file_is_rewritten_without_verification(folder):
    path, originals = folder
    run = cli("rewrite", path / "fstring_pep701.py", "--no-verify")
    assert_no_traceback(run.stderr, run.stdout)
    new = (path / "fstring_pep701.py").read_bytes()
    assert new != originals["fstring_pep701.py"] and b"def description(self" in new
    assert new == expected_migration(originals["fstring_pep701.py"])
    assert libcst_parses(new) and not python_parses(new)  # still 3.12 syntax, as it was
    assert run.returncode == 0, run.stderr


@pytest.mark.skipif(sys.version_info >= (3, 12), reason="PEP 701 f-strings import on 3.12+")
def test_pep701_file_with_verification_cannot_import_and_is_left_alone(folder):
    path, originals = folder
    run = cli("rewrite", path / "fstring_pep701.py", "--timeout", "60",
              env=no_newer_python(path))
    assert run.returncode == 1
    assert_no_traceback(run.stderr, run.stdout)
    line = _line_for(run.stderr, path / "fstring_pep701.py")
    assert f"cannot import under Python {PYTHON_VERSION}" in line
    assert (path / "fstring_pep701.py").read_bytes() == originals["fstring_pep701.py"]


def test_check_and_dry_run_report_the_same_problems(folder):
    path, originals = folder
    for mode in ("--check", "--dry-run"):
        run = cli("rewrite", path, "--no-verify", mode)
        assert run.returncode == 1
        assert_no_traceback(run.stderr, run.stdout)
        for name, message in UNPARSABLE.items():
            assert message in _line_for(run.stderr, path / name)
    assert {n: (path / n).read_bytes() for n in originals} == originals
