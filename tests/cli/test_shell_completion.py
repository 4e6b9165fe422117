"""The README's shell-completion lines work (issue 43: completion worked, but nobody was
told). Each of bash, zsh and fish has one line; the part that asks ``ezmigrate`` for its
script is run with the installed command, and the script it prints completes
``ezmigrate rew`` to ``rewrite`` through click's protocol."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
COMMAND = Path(sys.executable).parent / "ezmigrate"
ASKS = re.compile(r"_EZMIGRATE_COMPLETE=(\w+)_source ezmigrate")


def _readme_lines() -> dict[str, str]:
    """The README's completion line of each shell, by the shell it names."""
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    found: dict[str, str] = {}
    for line in text.splitlines():
        match = ASKS.search(line)
        if match:
            assert match.group(1) not in found, f"two lines for {match.group(1)}"
            found[match.group(1)] = line
    return found


def test_the_readme_has_one_line_per_shell() -> None:
    lines = _readme_lines()
    assert sorted(lines) == ["bash", "fish", "zsh"]
    assert lines["bash"].endswith("~/.bashrc") and lines["zsh"].endswith("~/.zshrc")
    assert lines["fish"].endswith("~/.config/fish/completions/ezmigrate.fish")


@pytest.mark.skipif(not COMMAND.exists(), reason="the ezmigrate command is not installed")
@pytest.mark.parametrize("shell", ["bash", "zsh", "fish"])
def test_each_line_prints_a_completion_script(shell: str) -> None:
    env = {**os.environ, "_EZMIGRATE_COMPLETE": f"{shell}_source"}
    script = subprocess.run([str(COMMAND)], env=env, capture_output=True, text=True,
                            timeout=60, check=True).stdout
    assert "_ezmigrate_completion" in script and "_EZMIGRATE_COMPLETE" in script, script


@pytest.mark.skipif(not COMMAND.exists() or shutil.which("bash") is None,
                    reason="needs the ezmigrate command and bash")
def test_the_bash_script_completes_a_command() -> None:
    env = {**os.environ, "PATH": f"{COMMAND.parent}{os.pathsep}{os.environ.get('PATH', '')}"}
    line = _readme_lines()["bash"]
    evaluated = re.search(r"'(eval .*)'", line)
    assert evaluated is not None, line
    shell = (f"{evaluated.group(1)}\nCOMP_WORDS=(ezmigrate rew); COMP_CWORD=1\n"
             "_ezmigrate_completion ezmigrate\nprintf '%s\\n' \"${COMPREPLY[@]}\"\n")
    run = subprocess.run(["bash", "--norc", "-c", shell], env=env, capture_output=True,
                         text=True, timeout=60)
    assert run.stdout.split() == ["rewrite"], run.stdout + run.stderr
