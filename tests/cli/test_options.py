"""``Options.resolve``: the command line beats ``[tool.ezmigrate]``, which beats the default,
for every key and every command (``rewrite -`` included), read by one ``pyproject.toml``
reader with one error rule."""

from __future__ import annotations

import dataclasses
import os
import stat
import subprocess
import sys
from pathlib import Path

import pytest

from ezmigrate.cli.config import ConfigError, ProjectConfig, load_project_config
from ezmigrate.cli.options import DEFAULT_TIMEOUT, CommandLine, Options
from ezmigrate.verify.pool_config import default_jobs
from ezskiros_runtime.ontology.config import find_tool_config, resolve_ontology_paths
from ezskiros_runtime.ontology.errors import OntologyConfigError
from ezskiros_runtime.pyproject import find_tool_table

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures"
PICK = FIXTURES / "legacy" / "pick_and_place.py"


def project(tmp_path: Path, **values: object) -> ProjectConfig:
    """A ``ProjectConfig`` read from ``tmp_path/pyproject.toml``, as the commands read it."""
    return dataclasses.replace(ProjectConfig(source=tmp_path / "pyproject.toml"), **values)


def executable(path: Path) -> str:
    path.write_text("#!/bin/sh\nexit 0\n", encoding="utf-8")
    path.chmod(path.stat().st_mode | stat.S_IXUSR)
    return str(path)


# --- the precedence, key by key ------------------------------------------------------------

@pytest.mark.parametrize(("given", "configured", "expected"), [
    (5.0, 7.0, 5.0), (None, 7.0, 7.0), (None, None, DEFAULT_TIMEOUT)])
def test_timeout(tmp_path: Path, given: float | None, configured: float | None,
                 expected: float) -> None:
    options = Options.resolve(CommandLine(timeout=given), project(tmp_path, timeout=configured))
    assert options.timeout == expected


@pytest.mark.parametrize(("given", "configured", "expected"), [
    (3, 5, 3), (None, 5, 5), (None, None, default_jobs())])
def test_jobs(tmp_path: Path, given: int | None, configured: int | None, expected: int) -> None:
    options = Options.resolve(CommandLine(jobs=given), project(tmp_path, jobs=configured))
    assert options.jobs == expected


def test_python_from_the_command_line_beats_the_project(tmp_path: Path) -> None:
    mine = executable(tmp_path / "mine")
    theirs = executable(tmp_path / "theirs")
    assert Options.resolve(CommandLine(python=mine),
                           project(tmp_path, python=theirs)).python == mine
    assert Options.resolve(CommandLine(), project(tmp_path, python=theirs)).python == theirs
    assert Options.resolve(CommandLine(), project(tmp_path)).python is None


def test_an_interpreter_that_does_not_exist_names_where_it_was_given(tmp_path: Path) -> None:
    missing = str(tmp_path / "no-such-python")
    with pytest.raises(ConfigError, match=r"^--python: .*no such interpreter"):
        Options.resolve(CommandLine(python=missing), project(tmp_path))
    with pytest.raises(ConfigError, match=r"pyproject\.toml: \[tool\.ezmigrate\] python: "):
        Options.resolve(CommandLine(), project(tmp_path, python=missing))
    # the command line's choice wins even over a broken project setting
    assert Options.resolve(CommandLine(python=sys.executable),
                           project(tmp_path, python=missing)).python == sys.executable


def test_excludes_add_up_command_line_first(tmp_path: Path) -> None:
    options = Options.resolve(CommandLine(exclude=("build",)),
                              project(tmp_path, exclude=("vendor", "legacy/*")))
    assert options.exclude == ("build", "vendor", "legacy/*")
    assert Options.resolve(CommandLine(), project(tmp_path)).exclude == ()


def test_select_on_the_command_line_replaces_the_whole_selection(tmp_path: Path) -> None:
    configured = project(tmp_path, select=("EZ2",), ignore=("EZ212",), extend_select=("EZ901",))
    options = Options.resolve(CommandLine(select=("EZ1",), ignore=("EZ101",)), configured)
    assert (options.select, options.ignore, options.extend_select) == (("EZ1",), ("EZ101",), ())
    assert options.select_from == "--select"


def test_without_select_ignore_and_extend_select_add_to_the_project(tmp_path: Path) -> None:
    configured = project(tmp_path, select=("EZ2",), ignore=("EZ212",), extend_select=("EZ901",))
    options = Options.resolve(CommandLine(ignore=("EZ209",), extend_select=("EZ3",)), configured)
    assert options.select == ("EZ2",)
    assert options.select_from == str(tmp_path / "pyproject.toml")
    assert options.ignore == ("EZ212", "EZ209")
    assert options.extend_select == ("EZ901", "EZ3")
    default = Options.resolve(CommandLine(), ProjectConfig())
    assert (default.select, default.ignore, default.extend_select) == (None, (), ())


def test_skill_libraries_and_the_project_folder_come_from_the_project(tmp_path: Path) -> None:
    options = Options.resolve(CommandLine(),
                              project(tmp_path, skill_libraries=(tmp_path / "lib",)))
    assert options.skill_libraries == (tmp_path / "lib",)
    assert options.project == tmp_path
    bare = Options.resolve(CommandLine(), ProjectConfig())
    assert bare.skill_libraries == () and bare.project is None


def test_options_are_frozen(tmp_path: Path) -> None:
    options = Options.resolve(CommandLine(), project(tmp_path))
    with pytest.raises(dataclasses.FrozenInstanceError):
        options.timeout = 1.0  # type: ignore[misc]


# --- one reader of pyproject.toml, one error rule -------------------------------------------

def test_the_project_config_and_the_ontology_read_the_same_file(tmp_path: Path) -> None:
    (tmp_path / "pyproject.toml").write_text(
        '[tool.ezmigrate]\ntimeout = 3\nexclude = ["vendor"]\nontology = "onto.ttl"\n',
        encoding="utf-8")
    (tmp_path / "src").mkdir()
    found = find_tool_table(tmp_path / "src")
    assert found is not None and found[0] == tmp_path / "pyproject.toml"
    assert find_tool_config(tmp_path / "src") == found
    config = load_project_config(tmp_path / "src")
    assert config.source == found[0] and config.timeout == 3.0 and config.exclude == ("vendor",)


@pytest.mark.parametrize(("text", "complaint"), [
    ("[tool.ezmigrate\ntimeout = 3\n", "invalid TOML"),
    ("[tool]\nezmigrate = 3\n", "[tool.ezmigrate] must be a table"),
    ("tool = 3\n", "[tool] must be a table"),
])
def test_an_unusable_pyproject_is_an_error_for_both_readers(tmp_path: Path, text: str,
                                                            complaint: str) -> None:
    """Never "no configuration": that would forget the project's excludes and ontology."""
    pyproject = tmp_path / "pyproject.toml"
    pyproject.write_text(text, encoding="utf-8")
    with pytest.raises(ConfigError) as config_error:
        load_project_config(tmp_path)
    with pytest.raises(OntologyConfigError) as ontology_error:
        resolve_ontology_paths(environ={}, start=tmp_path)
    for error in (config_error.value, ontology_error.value):
        assert str(error).startswith(f"{pyproject}: ") and complaint in str(error)


def test_a_pyproject_that_is_not_utf8_is_invalid_toml(tmp_path: Path) -> None:
    (tmp_path / "pyproject.toml").write_bytes(b"[tool.ezmigrate]\nexclude = ['caf\xe9']\n")
    with pytest.raises(ConfigError, match="invalid TOML: not UTF-8"):
        load_project_config(tmp_path)


# --- the real command: `rewrite -` honours the project like `rewrite PATH` ------------------

def ezmigrate(*args: str | Path, cwd: Path,
              stdin: bytes | None = None) -> subprocess.CompletedProcess[bytes]:
    env = {k: v for k, v in os.environ.items() if k != "EZSKIROS_ONTOLOGY"}
    return subprocess.run([sys.executable, "-m", "ezmigrate", *map(str, args)], input=stdin,
                          capture_output=True, cwd=cwd, env=env, check=False, timeout=300)


def looping_skill(tmp_path: Path) -> bytes:
    """Legacy skills in a module that never finishes loading: verification must stop it at
    the timeout in force, and says which (``loading took longer than 0.5 s``). It loops
    forever, so the timeout always fires: nothing races."""
    data = PICK.read_bytes() + b"\nwhile True:\n    pass\n"
    (tmp_path / "loop.py").write_bytes(data)
    return data


def test_stdin_honours_the_project_timeout(tmp_path: Path) -> None:
    (tmp_path / "pyproject.toml").write_text("[tool.ezmigrate]\ntimeout = 0.5\n",
                                             encoding="utf-8")
    data = looping_skill(tmp_path)
    proc = ezmigrate("rewrite", "-", stdin=data, cwd=tmp_path)
    stderr = proc.stderr.decode()
    assert proc.returncode == 1 and proc.stdout == data, stderr  # the input, unchanged
    assert "loading took longer than 0.5 s" in stderr, stderr
    given = ezmigrate("rewrite", "--timeout", "0.7", "-", stdin=data, cwd=tmp_path)
    assert "loading took longer than 0.7 s" in given.stderr.decode(), given.stderr
    assert "0.5 s" not in given.stderr.decode()


@pytest.mark.parametrize(("setting", "complaint"), [
    ("timeout = -1", "[tool.ezmigrate] timeout must be a positive number of seconds"),
    ('python = "no-such-python-here"', "[tool.ezmigrate] python: no-such-python-here: "
                                        "no such interpreter"),
    ("[tool.ezmigrate", "invalid TOML"),
])
def test_stdin_refuses_an_unusable_project_setting_as_a_path_does(tmp_path: Path,
                                                                  setting: str,
                                                                  complaint: str) -> None:
    (tmp_path / "pyproject.toml").write_text(f"[tool.ezmigrate]\n{setting}\n",
                                             encoding="utf-8")
    data = looping_skill(tmp_path)
    for args in (("-",), ("--no-verify", "-"), ("loop.py",)):
        proc = ezmigrate("rewrite", "--check", *args, stdin=data, cwd=tmp_path)
        stderr = proc.stderr.decode()
        assert proc.returncode == 2, (args, stderr)
        assert complaint in stderr and "Traceback" not in stderr, (args, stderr)
        assert proc.stdout == b"", args
