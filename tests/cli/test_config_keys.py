"""An unknown key of ``[tool.ezmigrate]`` is a warning on stderr that names the
``pyproject.toml`` and the key, with the key it most resembles (issue 43: ``exlude =
[...]`` excluded nothing, and nothing said so). The real CLI in a child process, on real
files in a temporary folder; every command that reads the table says it once."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

LEGACY = '''\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


class Pick(SkillDescription):
    def createDescription(self):
        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)
'''


def _project(root: Path, table: str) -> Path:
    root.mkdir(parents=True, exist_ok=True)
    (root / "pyproject.toml").write_text(f"[tool.ezmigrate]\n{table}", encoding="utf-8")
    (root / "pick.py").write_text(LEGACY, encoding="utf-8")
    return root


def _ezmigrate(*args: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    env = {"PATH": os.environ.get("PATH", "/usr/bin:/bin"),
           "EZMIGRATE_CACHE_DIR": str(cwd / ".cache")}
    return subprocess.run([sys.executable, "-m", "ezmigrate", *args], capture_output=True,
                          text=True, timeout=300, cwd=cwd, env=env)


@pytest.mark.parametrize("command", [("check", "pick.py"),
                                     ("rewrite", "--dry-run", "--no-verify", "pick.py")])
def test_a_misspelt_key_is_named_with_its_file_and_a_suggestion(tmp_path: Path,
                                                                command: tuple[str, ...]) -> None:
    root = _project(tmp_path / "lab", 'exlude = ["vendor"]\njobs = 1\n')
    run = _ezmigrate(*command, cwd=root)
    assert run.returncode in (0, 1), run.stderr
    expected = ("ezmigrate: warning: pyproject.toml: unknown key 'exlude' in [tool.ezmigrate], "
                "ignored; did you mean 'exclude'?")
    assert run.stderr.splitlines().count(expected) == 1, run.stderr


def test_each_unknown_key_is_named_and_one_like_no_key_has_no_suggestion(
        tmp_path: Path) -> None:
    root = _project(tmp_path / "lab", 'extend_select = ["EZ901"]\nfrobnicate = true\n')
    run = _ezmigrate("check", str(root / "pick.py"), cwd=tmp_path)
    assert run.returncode in (0, 1), run.stderr
    warnings = [line for line in run.stderr.splitlines() if "unknown key" in line]
    assert warnings == [
        "ezmigrate: warning: lab/pyproject.toml: unknown key 'extend_select' in "
        "[tool.ezmigrate], ignored; did you mean 'extend-select'?",
        "ezmigrate: warning: lab/pyproject.toml: unknown key 'frobnicate' in "
        "[tool.ezmigrate], ignored"], run.stderr


def test_known_keys_give_no_warning(tmp_path: Path) -> None:
    root = _project(tmp_path / "lab", 'exclude = ["vendor"]\nextend-select = ["EZ901"]\n'
                                      'timeout = 5\ntarget-version = "py38"\n')
    run = _ezmigrate("check", "pick.py", cwd=root)
    assert run.returncode in (0, 1), run.stderr
    assert "warning" not in run.stderr, run.stderr
