"""Shared helpers of the safety tests: run the real CLI in a subprocess, on real files.

Nothing is mocked: every test copies fixtures into a temporary folder, runs
``python -m ezmigrate`` there as a user would, and looks at the bytes on disk.
"""

from __future__ import annotations

import ast
import os
import re
import shutil
import subprocess
import sys
from collections.abc import Callable, Sequence
from pathlib import Path

import libcst as cst

REPO = Path(__file__).resolve().parents[2]
FIXTURES = REPO / "fixtures"
LEGACY = FIXTURES / "legacy"
BROKEN = FIXTURES / "broken"
ISOLATION = FIXTURES / "isolation"
PYTHON_VERSION = f"{sys.version_info.major}.{sys.version_info.minor}"


def cli(*args: str | Path, cwd: Path | None = None, timeout: float = 900,
        env: dict[str, str] | None = None, stdin: int | None = subprocess.DEVNULL,
        preexec_fn: Callable[[], None] | None = None) -> subprocess.CompletedProcess[str]:
    """Run ``python -m ezmigrate ARGS`` to completion; text output, never raises on exit code."""
    return subprocess.run(
        [sys.executable, "-m", "ezmigrate", *map(str, args)], cwd=cwd, env=env, stdin=stdin,
        capture_output=True, text=True, timeout=timeout, check=False, preexec_fn=preexec_fn)


def no_newer_python(folder: Path) -> dict[str, str]:
    """An environment in which no Python but ours can be found (PATH holds only its folder
    and the system's, pyenv's root is empty): a file with newer syntax stays unimportable,
    instead of being verified under the oldest newer Python that reads it."""
    import os

    return {**os.environ, "PYENV_ROOT": str(folder / "no-pyenv"),
            "PATH": os.pathsep.join([str(Path(sys.executable).parent), "/usr/bin", "/bin"])}


def start_cli(*args: str | Path, cwd: Path | None = None,
              env: dict[str, str] | None = None) -> subprocess.Popen[str]:
    """Start ``python -m ezmigrate ARGS`` without waiting (for the signal tests)."""
    return subprocess.Popen([sys.executable, "-m", "ezmigrate", *map(str, args)], cwd=cwd,
                            env=env, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)


_FRAME = re.compile(r'^\s*File ".*", line \d+', re.M)


def assert_no_traceback(*outputs: str) -> None:
    """No Python traceback (header or frame line) in any of ``outputs``."""
    for output in outputs:
        assert "Traceback" not in output, output
        assert not _FRAME.search(output), output


def copy_fixtures(target: Path, sources: Sequence[Path]) -> dict[str, bytes]:
    """Copy files into ``target``; returns name -> original bytes."""
    target.mkdir(parents=True, exist_ok=True)
    originals = {}
    for source in sources:
        shutil.copyfile(source, target / source.name)
        originals[source.name] = source.read_bytes()
    return originals


def snapshot(folder: Path) -> dict[str, bytes]:
    """Every regular file under ``folder`` (relative POSIX path -> bytes), links not followed."""
    found = {}
    for path in sorted(folder.rglob("*")):
        if path.is_file() and not path.is_symlink():
            found[path.relative_to(folder).as_posix()] = path.read_bytes()
    return found


def leftovers(folder: Path) -> list[str]:
    """Temporary files a write could leave behind (there must be none)."""
    return sorted(p.name for p in folder.rglob("*") if p.name.endswith(".ezmigrate")
                  or (p.name.startswith(".") and ".py." in p.name))


def libcst_parses(data: bytes) -> bool:
    try:
        cst.parse_module(data)
    except Exception:
        return False
    return True


def python_parses(data: bytes) -> bool:
    try:
        ast.parse(data)
    except (SyntaxError, ValueError):
        return False
    return True


def expected_migration(data: bytes, name: str = "<test>") -> bytes | None:
    """What ``rewrite --no-verify`` writes for one self-contained file (``None``: nothing)."""
    from ezmigrate.codemod.migrate import Settings, migrate
    from ezskiros_runtime.ontology.load import load_index

    result = migrate(data, Settings(index=load_index(None)), name)
    return result.new_source if isinstance(result.new_source, bytes) else None


def mode_of(path: Path) -> int:
    return os.stat(path).st_mode & 0o7777
