"""Text output shows a file name as it is and lets it start no line (issue 41, part C).

A file may be named ``z\\n::error file=README.md,line=1::all good.py``: printed raw, its
line break starts a line with ``::error``, which GitHub's runner takes for a workflow
command, and an ESC in a name is a terminal's escape sequence. Every test here runs the real
CLI in a subprocess on such files in a temporary folder and reads what it printed.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from ezmigrate.cli.output_formats import printable

LEGACY = '''from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


class Place(SkillDescription):
    def createDescription(self):
        self.addParam("Object", Element("skiros:Prodcut"), ParamTypes.Required)
'''
"""A legacy skill with one finding for ``check`` (EZ209, a misspelt class)."""

HOSTILE = ["z\n::error file=README.md,line=1::all good.py", "::warning::x.py",
           "e\x1b[2Jsc.py", "cr\r::notice::x.py"]
"""File names that, printed raw, start a workflow command or drive the terminal."""


@pytest.mark.parametrize(("raw", "shown"), [
    ("a\nb", "a\\nb"), ("a\rb", "a\\rb"), ("a\tb", "a\\tb"), ("a\x1bb", "a\\x1bb"),
    ("a\x00b", "a\\x00b"), ("a\x7fb", "a\\x7fb"), ("a\x85b", "a\\x85b"),
    ("a\u2028b", "a\\u2028b"), ("skills/pick.py", "skills/pick.py"), ("é.py", "é.py"),
])
def test_every_control_character_is_written_as_its_escape(raw, shown):
    assert printable(raw) == shown


@pytest.mark.parametrize(("raw", "shown"), [
    ("::error::x.py", "./::error::x.py"), (" ::x.py", "./ ::x.py"), ("-x.py", "./-x.py"),
    ("pkg/x.py", "pkg/x.py"), ("/abs/x.py", "/abs/x.py"), ("../x.py", "../x.py"),
    ("_x.py", "_x.py"),
])
def test_a_path_that_starts_a_line_starts_it_with_no_text_the_name_chose(raw, shown):
    assert printable(raw, path=True) == shown
    assert printable(raw) == raw  # inside a line, a name is left as it is


def _folder(tmp_path: Path) -> Path:
    """A folder holding the skill under each hostile name, and once under a plain one."""
    folder = tmp_path / "skills"
    folder.mkdir()
    for name in [*HOSTILE, "plain.py"]:
        (folder / name).write_text(LEGACY, encoding="utf-8")
    return folder


def _run(cwd: Path, *arguments: str) -> subprocess.CompletedProcess[str]:
    env = {k: v for k, v in os.environ.items() if not k.startswith("EZSKIROS_")}
    return subprocess.run([sys.executable, "-m", "ezmigrate", *arguments], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=600, check=False)


def _starts_a_command(text: str) -> list[str]:
    """The lines a runner could read as a workflow command (it trims blanks first)."""
    return [line for line in text.splitlines() if line.lstrip().startswith("::")]


def test_check_prints_one_line_per_finding_and_none_starts_a_workflow_command(tmp_path):
    folder = _folder(tmp_path)
    run = _run(folder, "check", ".")
    assert run.returncode in (0, 1), run.stderr
    assert not _starts_a_command(run.stdout), run.stdout
    assert not _starts_a_command(run.stderr), run.stderr
    lines = run.stdout.splitlines()
    assert len(lines) == len(HOSTILE) + 1 and all(" EZ209 " in line for line in lines), lines
    assert "z\\n::error file=README.md,line=1::all good.py:8:" in run.stdout
    assert "./::warning::x.py:8:" in run.stdout
    assert "e\\x1b[2Jsc.py:8:" in run.stdout and "\x1b" not in run.stdout
    assert "cr\\r::notice::x.py:8:" in run.stdout and "\r" not in run.stdout
    assert "plain.py:8:" in run.stdout  # a plain name is printed as it is


def test_the_github_format_still_escapes_as_the_runner_requires(tmp_path):
    run = _run(_folder(tmp_path), "check", "--output-format", "github", ".")
    assert run.returncode in (0, 1), run.stderr
    lines = run.stdout.splitlines()
    assert len(lines) == len(HOSTILE) + 1 and all(line.startswith("::warning file=")
                                                  for line in lines), lines
    assert not any(line.startswith("::error") for line in lines)


@pytest.mark.parametrize("arguments", [["rewrite", "--check", "."], ["rewrite", "--dry-run", "."],
                                       ["verify", ".", "."]],
                         ids=["rewrite --check", "rewrite --dry-run", "verify"])
def test_rewrite_and_verify_print_file_names_escaped(tmp_path, arguments):
    folder = _folder(tmp_path)
    run = _run(folder, *arguments)
    assert run.returncode in (0, 1), run.stderr
    assert not _starts_a_command(run.stdout), run.stdout
    assert not _starts_a_command(run.stderr), run.stderr
    assert "\x1b" not in run.stdout + run.stderr and "\r" not in run.stdout + run.stderr
    if arguments[1] == "--check":
        assert "would rewrite z\\n::error file=README.md,line=1::all good.py" in run.stdout
    if arguments[1] == "--dry-run":
        assert "+++ b/z\\n::error file=README.md,line=1::all good.py" in run.stdout
    assert all(name.read_text(encoding="utf-8") == LEGACY for name in folder.iterdir())


def test_a_message_naming_a_hostile_file_is_escaped_too(tmp_path):
    """A file that cannot be read: the error names it inside the message as well."""
    folder = tmp_path / "skills"
    folder.mkdir()
    name = "y\n::error::broken.py"
    (folder / name).write_bytes(b"class Broken(SkillDescription):\n"
                                b"    def createDescription(self\n")
    run = _run(folder, "rewrite", "--check", ".")
    assert not _starts_a_command(run.stdout + run.stderr), run.stderr
    assert "y\\n::error::broken.py" in run.stderr, run.stderr
