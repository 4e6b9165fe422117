"""Helpers for the verification tests: the CLI in a subprocess, fixture trees, edits."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[2]
FIXTURES = ROOT / "fixtures"
LEGACY = FIXTURES / "legacy"
MIGRATED = FIXTURES / "migrated"
ISOLATION = FIXTURES / "isolation"
PAPER_AXIOMS = (
    "--ontology", str(ROOT / "ezskiros_runtime" / "ontology" / "data" / "skiros-core.ttl"),
    "--ontology", str(FIXTURES / "ontology" / "paper_axioms.ttl"))
"""The core plus the EzSkiROS paper's ``hasA`` axiom, for the skills built to break it."""

HEADER = '''from skiros2_common.core.abstract_skill import SkillDescription, ParamOptions
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element
'''

LATE_CONSTANT = HEADER + '''
SPEED = 0.5


class Move(SkillDescription):
    def createDescription(self):
        self.addParam("Target", Element("skiros:Location"), ParamTypes.Required)
        self.addParam("Speed", SPEED, ParamTypes.Optional)


class Stop(SkillDescription):
    def createDescription(self):
        self.addParam("Target", Element("skiros:Location"), ParamTypes.Required)


SPEED = 1.0  # tuned on the robot: SkiROS2 reads this one when it creates the skill
'''
"""A difference static migration cannot see: legacy code reads ``SPEED`` when the skill
is created (1.0), a Python default is evaluated when the class is defined (0.5)."""

FAILS_IN_BOTH = HEADER + '''
CALIBRATION = {}


class Calibrate(SkillDescription):
    def createDescription(self):
        self.addParam("Tool", Element("skiros:Tool"), ParamTypes.Required)
        self._table = CALIBRATION["tool0"]  # filled in on the robot only
'''
"""A convertible skill that cannot be created off the robot, before or after migration:
nothing can be compared, so nothing may be claimed equivalent or written."""


def cli(*args: Any, env: dict[str, str] | None = None, timeout: float = 300,
        cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    """``python -m ezmigrate ARGS`` in a fresh process (stdin closed)."""
    return subprocess.run([sys.executable, "-m", "ezmigrate", *map(str, args)],
                          capture_output=True, text=True, timeout=timeout, check=False,
                          stdin=subprocess.DEVNULL, env={**os.environ, **(env or {})},
                          cwd=cwd or ROOT)


def tree(folder: Path, sources: dict[str, Path | str | bytes]) -> Path:
    """A folder of files: a ``Path`` is copied, text or bytes written."""
    folder.mkdir(parents=True, exist_ok=True)
    for name, source in sources.items():
        target = folder / name
        if isinstance(source, Path):
            shutil.copyfile(source, target)
        elif isinstance(source, bytes):
            target.write_bytes(source)
        else:
            target.write_text(source, encoding="utf-8")
    return folder


def edit(path: Path, old: str, new: str) -> None:
    """Replace exactly one occurrence of ``old`` in ``path``."""
    text = path.read_text(encoding="utf-8")
    assert text.count(old) == 1, (path, old)
    path.write_text(text.replace(old, new), encoding="utf-8")


def read_json(path: Path) -> dict[str, Any]:
    data: dict[str, Any] = json.loads(path.read_text(encoding="utf-8"))
    return data


def skills_of(report: dict[str, Any], file: str) -> dict[str, dict[str, Any]]:
    """The JSON report's skill entries of one file, by class name."""
    return {s["class"]: s for s in report["skills"] if s["file"] == file}


def file_entry(report: dict[str, Any], file: str) -> dict[str, Any]:
    return next(f for f in report.get("files", []) if f["file"] == file)


def snapshot(folder: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in sorted(folder.glob("*.py"))}


def second_python() -> str | None:
    """A real interpreter of Python 3.12 or later other than ours (on PATH, or in pyenv's
    versions folder, whose PATH shims only work when pyenv is told to use them), or None."""
    import shutil

    names = [shutil.which(f"python3.{minor}") for minor in range(20, 11, -1)]
    pyenv = sorted(Path.home().glob(".pyenv/versions/3.1[2-9]*/bin/python3.1[2-9]"),
                   reverse=True)
    for candidate in [*filter(None, names), *map(str, pyenv)]:
        run = subprocess.run([candidate, "-c", "import sys; assert sys.version_info >= (3, 12)"],
                             capture_output=True, check=False, timeout=60)
        if run.returncode == 0:
            return candidate
    return None
