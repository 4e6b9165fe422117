"""Which robot the migrated code is for: its ROS distribution, and so its Python.

Migrated skills run inside SkiROS2's skill manager, under the robot's Python: ROS 1 Noetic
is Python 3.8 (most labs), ROS 2 Humble 3.10, Jazzy 3.12. The codemod must write only what
that Python runs (``list[float]`` raises ``TypeError`` under 3.8), and verification should
load the code under it. ``[tool.ezmigrate] target-version = "py38"`` (ruff's spelling)
says so explicitly; otherwise the repository does: a ROS package's ``package.xml`` names
its build tool, ``catkin`` for ROS 1 and ``ament_*`` for ROS 2. A run over packages of both
kinds writes for the oldest Python among them, which the others run as well.
"""

from __future__ import annotations

import os
import re
import sys
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

from ..codemod.settings import DEFAULT_TARGET
from ..files.package_xml import package_files, ros_flavour
from ..verify.interpreters import find_python, rdflib_version, version_of

SPELLING = re.compile(r"py3(\d{1,2})\Z")
OLDEST = (3, 8)
PYTHON_OF = {"ros1": (3, 8), "ros2": (3, 10)}
"""The oldest Python of each ROS generation's supported distributions (Noetic; Humble)."""
DISTRIBUTION = {"ros1": "ROS 1 (Noetic)", "ros2": "ROS 2 (Humble or newer)"}


@dataclass(frozen=True)
class Target:
    """The Python the migrated code must run on, and why (for the summary and report)."""

    version: tuple[int, int]
    why: str
    flavour: str | None = None
    """``ros1``/``ros2`` when a ``package.xml`` said so; None otherwise."""

    @property
    def name(self) -> str:
        """``py38``: ruff's spelling."""
        return f"py{self.version[0]}{self.version[1]}"

    @property
    def python(self) -> str:
        """``3.8``: the interpreter version to look for."""
        return f"{self.version[0]}.{self.version[1]}"


def parse_target(value: object) -> tuple[int, int] | None:
    """``(3, 8)`` for ``"py38"``; None for anything else (the caller says where it was)."""
    match = SPELLING.match(value) if isinstance(value, str) else None
    if match is None:
        return None
    version = (3, int(match.group(1)))
    return version if version >= OLDEST else None


def target_for(paths: Iterable[Path], configured: tuple[int, int] | None,
               where: str = "[tool.ezmigrate] target-version") -> Target:
    """The target of a run over ``paths``: the configured one, else the oldest Python among
    the ROS packages found, else the default."""
    if configured is not None:
        return Target(configured, f"{where} = \"py{configured[0]}{configured[1]}\"")
    kinds = [(flavour, xml) for xml in package_files(paths)
             if (flavour := ros_flavour(xml)) is not None]
    if not kinds:
        return Target(DEFAULT_TARGET, "no ROS package.xml found: the default")
    flavour, xml = min(kinds, key=lambda kind: PYTHON_OF[kind[0]])
    version = PYTHON_OF[flavour]
    return Target(version, f"{shown(xml)} is a {DISTRIBUTION[flavour]} "
                           f"package: Python {version[0]}.{version[1]}", flavour)


def shown(path: Path) -> str:
    """``path`` as the run's other lines name it: relative to the working directory."""
    relative = os.path.relpath(path)
    return relative if not relative.startswith("..") else str(path)


def robot_python(target: Target, configured: str | None, verify: bool) -> str | None:
    """The interpreter to verify with: the configured one; else, for a ROS 1 repository,
    a ``python3.8`` found on PATH or in pyenv's versions folder (the robot's Python, so
    that what verified is what the robot will load); else None (this one)."""
    if configured is not None or not verify or target.flavour != "ros1":
        return configured
    return find_python(target.python)


def verified_with(python: str | None, target: Target) -> str:
    """One line for the summary and the report header: which Python verified (and which
    rdflib read the ontology), and, when it is not the robot's, which one the robot runs."""
    found = version_of(python)
    used = python or sys.executable  # absolute: a report scrubs it as it scrubs every path
    line = f"verified under Python {found} ({used}), ontology read with rdflib {rdflib_version()}"
    major_minor = tuple(int(part) for part in found.split(".")[:2] if part.isdigit())
    if target.flavour is None or major_minor == target.version:
        return line
    looked = target.flavour == "ros1"  # ``robot_python`` looked for it
    return (f"{line}; the robot runs Python {target.python} ({target.why})"
            + (f": no python{target.python} was found on PATH's absolute entries or in "
               "pyenv's versions folder; install one, or pass --python to verify under it"
               if looked else f": pass --python naming a python{target.python} to verify "
               "under it"))
