"""Colour on a terminal only, as no-color.org and ruff have it (issue 43): the real CLI in
a child process whose stdout is a pseudo-terminal (a real one, from ``pty``) or a pipe.

``check``'s text findings carry their code and severity in the severity's colour on a
terminal; ``rewrite --dry-run`` colours its diffs there. ``NO_COLOR`` set to anything but
the empty string turns both off, a pipe never gets colour, and ``--color``/``--no-color``
(``rewrite``'s) wins over both."""

from __future__ import annotations

import os
import pty
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
ESC = "\x1b["
RED, YELLOW = "\x1b[31m", "\x1b[33m"


def _env(tmp_path: Path, no_color: str | None) -> dict[str, str]:
    env = {"PATH": os.environ.get("PATH", "/usr/bin:/bin"), "TERM": "xterm",
           "EZMIGRATE_CACHE_DIR": str(tmp_path / "cache")}
    if no_color is not None:
        env["NO_COLOR"] = no_color
    return env


def _on_terminal(args: list[str], cwd: Path, env: dict[str, str]) -> str:
    """stdout of ``ezmigrate ARGS`` written to a pseudo-terminal, read until the child
    closes it (no timing involved: reading ends when the last writer is gone)."""
    controller, terminal = pty.openpty()
    with open(cwd / "stderr.txt", "wb") as stderr:
        child = subprocess.Popen([sys.executable, "-m", "ezmigrate", *args], cwd=cwd,
                                 env=env, stdin=subprocess.DEVNULL, stdout=terminal,
                                 stderr=stderr)
    os.close(terminal)
    chunks = []
    while True:
        try:
            chunk = os.read(controller, 65536)
        except OSError:  # EIO: every writer closed the terminal
            break
        if not chunk:
            break
        chunks.append(chunk)
    os.close(controller)
    assert child.wait(timeout=300) in (0, 1), (cwd / "stderr.txt").read_text()
    return b"".join(chunks).decode().replace("\r\n", "\n")


def _in_pipe(args: list[str], cwd: Path, env: dict[str, str]) -> str:
    run = subprocess.run([sys.executable, "-m", "ezmigrate", *args], cwd=cwd, env=env,
                         capture_output=True, text=True, timeout=300)
    assert run.returncode in (0, 1), run.stderr
    return run.stdout


@pytest.fixture()
def repo(tmp_path: Path) -> Path:
    """A repository of one legacy file with findings at error and at warning severity."""
    root = tmp_path / "repo"
    root.mkdir()
    shutil.copy(ROOT / "fixtures" / "legacy" / "param_values.py", root / "param_values.py")
    return root


def test_check_colours_code_and_severity_on_a_terminal(repo: Path, tmp_path: Path) -> None:
    out = _on_terminal(["check", "param_values.py"], repo, _env(tmp_path, None))
    assert f"{RED}" in out and "EZ212 [error]" in out, out
    error = next(line for line in out.splitlines() if "EZ212 [error]" in line)
    warning = next(line for line in out.splitlines() if "EZ211 [warning]" in line)
    assert re.search(r"\x1b\[31m(\x1b\[1m)?EZ212 \[error\]", error), repr(error)
    assert re.search(r"\x1b\[33m(\x1b\[1m)?EZ211 \[warning\]", warning), repr(warning)
    plain = re.sub(r"\x1b\[[0-9;]*m", "", out)  # the colours are all that differs
    assert plain == _in_pipe(["check", "param_values.py"], repo, _env(tmp_path, None))


@pytest.mark.parametrize("no_color", ["1", "0", "false"])
def test_no_color_turns_check_colour_off(repo: Path, tmp_path: Path, no_color: str) -> None:
    out = _on_terminal(["check", "param_values.py"], repo, _env(tmp_path, no_color))
    assert "EZ212 [error]" in out and ESC not in out, repr(out)


def test_an_empty_no_color_is_not_set(repo: Path, tmp_path: Path) -> None:
    out = _on_terminal(["check", "param_values.py"], repo, _env(tmp_path, ""))
    assert RED in out, repr(out)


def test_a_pipe_gets_no_colour(repo: Path, tmp_path: Path) -> None:
    out = _in_pipe(["check", "param_values.py"], repo, _env(tmp_path, None))
    assert "EZ212 [error]" in out and ESC not in out


def test_machine_formats_are_never_coloured(repo: Path, tmp_path: Path) -> None:
    out = _on_terminal(["check", "param_values.py", "--output-format", "json"], repo,
                       _env(tmp_path, None))
    assert '"code": "EZ212"' in out and ESC not in out


def _legacy(tmp_path: Path) -> Path:
    root = tmp_path / "legacy"
    shutil.copytree(ROOT / "fixtures" / "legacy", root)
    return root


def test_dry_run_diffs_are_coloured_on_a_terminal(tmp_path: Path) -> None:
    root = _legacy(tmp_path)
    out = _on_terminal(["rewrite", "--dry-run", "--no-verify", "conditions.py"], root,
                       _env(tmp_path, None))
    assert "\x1b[32m+" in out and "\x1b[31m-" in out, repr(out[:400])


def test_no_color_turns_dry_run_colour_off(tmp_path: Path) -> None:
    root = _legacy(tmp_path)
    out = _on_terminal(["rewrite", "--dry-run", "--no-verify", "conditions.py"], root,
                       _env(tmp_path, "1"))
    assert "+++ " in out and ESC not in out, repr(out[:400])


def test_the_flag_wins_over_no_color_and_over_a_pipe(tmp_path: Path) -> None:
    root = _legacy(tmp_path)
    args = ["rewrite", "--dry-run", "--no-verify", "conditions.py"]
    coloured = _in_pipe([*args, "--color"], root, _env(tmp_path, "1"))
    assert "\x1b[32m+" in coloured
    plain = _on_terminal([*args, "--no-color"], root, _env(tmp_path, None))
    assert "+++ " in plain and ESC not in plain
