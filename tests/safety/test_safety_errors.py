"""No traceback ever reaches the user for a problem in their files: each is a line on
stderr (and an entry in the report). Internal errors print one short line and a hint to
rerun with ``--debug``, which then shows the traceback."""

from __future__ import annotations

import json
import resource
import shutil
import subprocess

import pytest
from safety_support import (
    BROKEN,
    ISOLATION,
    LEGACY,
    assert_no_traceback,
    cli,
    copy_fixtures,
    no_newer_python,
)


@pytest.fixture(scope="module")
def messy(tmp_path_factory):
    """Broken files, hostile modules, deep nesting, binary junk and good files together."""
    folder = tmp_path_factory.mktemp("messy")
    originals = copy_fixtures(folder, [*sorted(BROKEN.glob("*.py")),
                                       *sorted(ISOLATION.glob("*.py")),
                                       LEGACY / "pick_and_place.py"])
    descriptions = (LEGACY / "descriptions.py").read_bytes()
    extra = {
        "deep_nesting.py": descriptions + b"\nX = " + b"-" * 1000 + b"1\n",
        "binary.py": bytes(range(256)) * 8,
        "empty.py": b"",
        "nul_in_middle.py": descriptions[:500] + b"\0" + descriptions[500:],
        "only_bom.py": b"\xef\xbb\xbf",
        "lone_cr_endings.py": descriptions.replace(b"\n", b"\r"),
    }
    for name, data in extra.items():
        (folder / name).write_bytes(data)
    return folder, originals | extra


def test_rewrite_with_verification_over_messy_files_shows_no_traceback(messy, tmp_path):
    folder, originals = messy
    work = tmp_path / "work"
    shutil.copytree(folder, work)
    report = tmp_path / "report.json"
    run = cli("rewrite", work, "--timeout", "5", "--report", report)
    assert run.returncode == 1
    assert_no_traceback(run.stdout, run.stderr)
    files = {f["file"]: f for f in json.loads(report.read_text(encoding="utf-8"))["files"]}
    for name in ("py2_print_statement.py", "invalid_utf8_no_cookie.py", "deep_nesting.py",
                 "truncated_mid_call.py", "py2_except_comma.py"):
        assert files[name]["error"], name  # a finding in the report...
        assert f"{work / name}: " in run.stderr, name  # ...and one line on stderr
    for name in ("binary.py", "empty.py", "only_bom.py"):  # no skill in them: not touched
        assert name not in files
    for name in ("binary.py", "empty.py", "only_bom.py", "nul_in_middle.py",
                 "py2_print_statement.py", "invalid_utf8_no_cookie.py", "deep_nesting.py",
                 "truncated_mid_call.py", "py2_except_comma.py", "loops_forever.py",
                 "raises_on_import.py", "fstring_pep701.py"):
        assert (work / name).read_bytes() == originals[name], name
    assert "nested too deeply" in files["deep_nesting.py"]["error"]  # the file's problem
    assert "internal error" not in run.stderr


def test_rewrite_without_verification_and_dry_run_show_no_traceback(messy, tmp_path):
    folder, _originals = messy
    for extra in (["--no-verify"], ["--no-verify", "--dry-run"]):
        work = tmp_path / "-".join(extra)
        shutil.copytree(folder, work)
        run = cli("rewrite", work, "--timeout", "5", *extra)
        assert run.returncode == 1, run.stderr
        assert_no_traceback(run.stderr)
        if "--dry-run" not in extra:
            assert_no_traceback(run.stdout)


def test_a_file_nested_too_deeply_is_its_own_problem_not_an_internal_error(messy, tmp_path):
    """libcst's recursion limit is a property of the file: reported with its line, even with
    ``--debug`` (internal errors and their tracebacks: the file-descriptor test below)."""
    folder, _ = messy
    work = tmp_path / "work"
    work.mkdir()
    shutil.copy(folder / "deep_nesting.py", work)
    run = cli("rewrite", work, "--no-verify", "--debug")
    assert run.returncode == 1, run.stderr
    assert f"{work / 'deep_nesting.py'}: " in run.stderr and "nested too deeply" in run.stderr
    assert "internal error" not in run.stderr and "Traceback" not in run.stderr


def test_verify_command_over_messy_files_shows_no_traceback(messy, tmp_path):
    folder, _ = messy
    run = cli("verify", folder, folder, "--timeout", "5")
    assert run.returncode == 0, run.stderr  # identical on both sides: nothing differs
    assert_no_traceback(run.stdout, run.stderr)
    assert "raises_on_import.py: unchanged, not loadable" in run.stderr  # but it is said


@pytest.mark.parametrize("name", ["py2_print_statement.py", "invalid_utf8_no_cookie.py",
                                  "fstring_pep701.py", "truncated_mid_call.py"])
def test_stdin_mode_passes_a_broken_file_through_whole(name, tmp_path):
    data = (BROKEN / name).read_bytes()
    run = subprocess.run([*_python_m(), "rewrite", "-"], input=data, capture_output=True,
                         timeout=300, check=False, cwd=tmp_path,  # no owl/ folder around
                         env=no_newer_python(tmp_path))  # the PEP 701 file stays unloadable
    assert run.returncode == 1
    assert run.stdout == data  # an editor replacing its buffer with our output loses nothing
    assert_no_traceback(run.stderr.decode("utf-8", "replace"))
    # the ontology used, then one line per problem, naming the input "-" as a path run names
    # the file: "-: ..." for the file, "-:LINE: Class: ..." for a skill (a PEP 701 file
    # parses, fails to import)
    first, second = run.stderr.splitlines()[:2]
    assert first.startswith(b"ezmigrate: ontology from the bundled default")
    assert second.startswith(b"-:")


def _python_m() -> list[str]:
    import sys

    return [sys.executable, "-m", "ezmigrate"]


def _few_descriptors(limit: int):
    def apply() -> None:
        resource.setrlimit(resource.RLIMIT_NOFILE, (limit, limit))
    return apply


def test_an_internal_error_is_one_line_and_a_debug_hint(tmp_path):
    """Too few file descriptors to start a verification worker: a real internal error."""
    copy_fixtures(tmp_path, [LEGACY / "descriptions.py"])
    hinted = 0
    for limit in (6, 8, 10, 12):
        run = cli("rewrite", tmp_path, "--dry-run", preexec_fn=_few_descriptors(limit))
        assert run.returncode in (0, 1, 2), run.stderr
        assert_no_traceback(run.stderr)
        if "internal error" in run.stderr:
            assert "rerun with --debug for details" in run.stderr
            hinted += 1
    assert hinted, "no limit produced an internal error"
    debug = cli("rewrite", tmp_path, "--dry-run", "--debug", preexec_fn=_few_descriptors(8))
    assert "Traceback (most recent call last)" in debug.stderr
    assert "Too many open files" in debug.stderr


def test_a_report_that_cannot_be_written_is_a_clean_error(tmp_path):
    copy_fixtures(tmp_path, [LEGACY / "descriptions.py"])
    run = cli("rewrite", tmp_path, "--dry-run", "--no-verify", "--report",
              tmp_path / "no" / "such" / "folder" / "report.json")
    assert run.returncode == 2
    assert_no_traceback(run.stderr)
    assert "cannot write the report" in run.stderr
