"""What a ROS package's ``package.xml`` says, and the runtime declared in it.

A package's manifest gives its name (vendored SkiROS2 packages, launch files), whether it
is ROS 1 or ROS 2 (its buildtool: the robot's Python) and where the packages of a run are;
one reader per fact, here.

Migrated skills import ``ezskiros_runtime`` on the robot, so the package must say it needs
it, or ``rosdep install`` on a fresh robot leaves it out and the skill manager fails to load
the skills. ``rewrite`` adds one ``<exec_depend>`` line to the ``package.xml`` of each ROS
package whose files it migrated, when no dependency on the runtime is declared yet. Nothing
else in the file changes: the new line copies the indentation of the ``*depend`` line it
follows (or of the package's first child element) and the file's own line ending.
``--no-package-xml`` turns this off.
"""

from __future__ import annotations

import os
import re
from collections.abc import Iterable, Iterator
from pathlib import Path
from xml.etree import ElementTree

from ezskiros_runtime.ontology.discovery import NOT_SEARCHED, PACKAGE_XML, package_root

ROSDEP_KEY = "python3-ezskiros-runtime-pip"
"""The rosdep key for the runtime, defined by the lab's rosdep file (README, "On the robot")."""

_DECLARED = re.compile(rb"<(?:exec_|build_export_|)depend>\s*(?:python3-)?ezskiros[-_]runtime"
                       rb"(?:-pip)?\s*</")
_DEPEND_LINE = re.compile(rb"^([ \t]*)<(?:exec_|build_|build_export_|test_|)depend>[^\r\n]*", re.M)
_CLOSE = re.compile(rb"^([ \t]*)</package>", re.M)
_CHILD = re.compile(rb"^([ \t]+)<[A-Za-z]", re.M)
_BUILDTOOL = re.compile(rb"<buildtool_depend>\s*([A-Za-z0-9_]+)\s*</buildtool_depend>")


def with_exec_depend(data: bytes) -> bytes | None:
    """``data`` with the runtime's ``<exec_depend>`` added; None when it is declared already
    or the file has no ``</package>`` to anchor the line (it is left alone)."""
    if _DECLARED.search(data):
        return None
    newline = b"\r\n" if b"\r\n" in data else b"\n"
    depends = list(_DEPEND_LINE.finditer(data))
    if depends:
        anchor, indent = depends[-1].end(), depends[-1].group(1)
        line = newline + indent + b"<exec_depend>" + ROSDEP_KEY.encode() + b"</exec_depend>"
        return data[:anchor] + line + data[anchor:]
    close = _CLOSE.search(data)
    if close is None:
        return None
    child = _CHILD.search(data)
    indent = child.group(1) if child else b"  "
    line = indent + b"<exec_depend>" + ROSDEP_KEY.encode() + b"</exec_depend>" + newline
    return data[:close.start()] + line + data[close.start():]


def package_name(package_xml: Path) -> str | None:
    """The ``<name>`` a ``package.xml`` gives its package, or None (unreadable, no name)."""
    try:
        name = ElementTree.parse(package_xml).findtext("name")
    except (ElementTree.ParseError, OSError):
        return None
    return name.strip() if name and name.strip() else None


def manifests_below(folder: Path) -> Iterator[Path]:
    """Every ``package.xml`` under ``folder``, sorted, not in hidden folders nor in what
    discovery never searches (build, devel and install spaces hold copies of them)."""
    for here, dirs, names in os.walk(folder):
        dirs[:] = sorted(d for d in dirs if not d.startswith(".") and d not in NOT_SEARCHED)
        if PACKAGE_XML in names:
            yield Path(here) / PACKAGE_XML


def packages_of(files: Iterable[Path]) -> list[Path]:
    """The ``package.xml`` of each ROS package holding one of ``files``, in order."""
    found: dict[Path, None] = {}
    for file in files:
        root = package_root(file.resolve())
        if root is not None:
            found[root / PACKAGE_XML] = None
    return list(found)


def package_files(paths: Iterable[Path]) -> list[Path]:
    """The ``package.xml`` of each ROS package the paths are in or, for a folder, hold,
    without repeats, in order."""
    found: dict[Path, None] = {}
    for path in paths:
        found.update(dict.fromkeys(packages_of([path])))
        if path.is_dir():
            found.update(dict.fromkeys(manifests_below(path.resolve())))
    return list(found)


def ros_flavour(package_xml: Path) -> str | None:
    """``ros1`` for a catkin package, ``ros2`` for an ament one, None when it says neither
    (or cannot be read)."""
    try:
        data = package_xml.read_bytes()
    except OSError:
        return None
    tools = {match.group(1).decode() for match in _BUILDTOOL.finditer(data)}
    if "catkin" in tools:
        return "ros1"
    if any(tool.startswith("ament") for tool in tools):
        return "ros2"
    return None
