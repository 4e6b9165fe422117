"""What a ROS package's ``package.xml`` says, and the runtime declared in it.

A package's manifest says whether it is ROS 1 or ROS 2 (its buildtool: the robot's
Python) and where the packages of a run are; one reader per fact, here. Its name is read by
``ezskiros_runtime.ontology.vendored.package_name``, which the runtime's vendored-copy rule
needs too.

Migrated skills import ``ezskiros_runtime`` on the robot, so the package must say it needs
it, or ``rosdep install`` and the build tools leave it out and the skill manager fails to
load the skills. The runtime is a ROS package of its own, ``ezskiros_runtime`` (the folder
``ros/ezskiros_runtime`` of a checkout of ezmigrate, put in the workspace's ``src/``), so
``rewrite`` adds one dependency on it to the ``package.xml`` of each ROS package whose
files it migrated, unless one is declared (by that name, or by the rosdep key earlier
versions wrote) or the manifest is the runtime's own. The element is the one the format
allows: catkin refuses a format 1 manifest (no ``format`` attribute) holding
``<exec_depend>``, so there it is ``<run_depend>``; formats 2 and 3 get ``<exec_depend>``.
The line goes after the last dependency of the same kind (``run_depend``; ``exec_depend``
or ``depend``), else after the last ``*depend`` line, else before ``</package>``; what is
commented out is no anchor. Nothing else in the file changes: the line copies the
indentation of the line it follows (or of the package's first child element) and the
file's own line ending. ``--no-package-xml`` turns this off.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Iterator
from pathlib import Path

from ezskiros_runtime.ontology.discovery import NOT_SEARCHED, PACKAGE_XML, package_root
from ezskiros_runtime.ontology.listing import walk

RUNTIME_PACKAGE = "ezskiros_runtime"
"""The runtime's ROS package (``ros/ezskiros_runtime/package.xml``), the dependency that
``rewrite`` declares: built in the lab's workspace, it brings the runtime to the robot."""

OLD_ROSDEP_KEY = "python3-ezskiros-runtime-pip"
"""What earlier versions declared instead: a package naming it is left as it is."""

_COMMENT = re.compile(rb"<!--.*?-->", re.S)
_PACKAGE = re.compile(rb"<package\b([^>]*)>")
_FORMAT = re.compile(rb"""\bformat\s*=\s*["']\s*(\d+)\s*["']""")
_DECLARED = re.compile(rb"<(?:run_|exec_|build_export_|)depend\b[^>]*>\s*(?:"
                       + re.escape(RUNTIME_PACKAGE.encode()) + rb"|"
                       + re.escape(OLD_ROSDEP_KEY.encode()) + rb")\s*</")
_ITSELF = re.compile(rb"<name>\s*" + re.escape(RUNTIME_PACKAGE.encode()) + rb"\s*</name>")
_DEPEND_LINE = re.compile(rb"^([ \t]*)<((?:build_export_|buildtool_export_|buildtool_|build_|"
                          rb"exec_|run_|test_|doc_|)depend)\b[^>]*>[^\r\n]*", re.M)
_CLOSE = re.compile(rb"^([ \t]*)</package>", re.M)
_CHILD = re.compile(rb"^([ \t]+)<[A-Za-z]", re.M)
_BUILDTOOL = re.compile(rb"<buildtool_depend>\s*([A-Za-z0-9_]+)\s*</buildtool_depend>")


def manifest_format(data: bytes) -> int | None:
    """The format of a ``package.xml`` (1 when its ``<package>`` names none, as catkin
    reads it), or None when it has no ``<package>`` element."""
    return _format_of(_without_comments(data))


def runtime_depend(data: bytes) -> str | None:
    """The element declaring the runtime that the manifest's format allows, or None when
    ``data`` is no manifest."""
    version = manifest_format(data)
    return None if version is None else _element(version).decode()


def with_runtime_depend(data: bytes) -> bytes | None:
    """``data`` with the runtime's dependency added; None when it is declared already, the
    manifest is the runtime's own, or the file has no ``<package>`` and ``</package>`` to
    anchor the line (it is left alone)."""
    text = _without_comments(data)
    version = _format_of(text)
    if version is None or _DECLARED.search(text) or _ITSELF.search(text):
        return None
    element = _element(version)
    newline = b"\r\n" if b"\r\n" in data else b"\n"
    depends = list(_DEPEND_LINE.finditer(text))
    kinds = (b"run_depend",) if version == 1 else (b"exec_depend", b"depend")
    beside = [match for match in depends if match.group(2) in kinds] or depends
    if beside:
        anchor, indent = beside[-1].end(), beside[-1].group(1)
        return data[:anchor] + newline + indent + element + data[anchor:]
    close = _CLOSE.search(text)
    if close is None:
        return None
    child = _CHILD.search(text)
    indent = child.group(1) if child else b"  "
    return data[:close.start()] + indent + element + newline + data[close.start():]


def _format_of(text: bytes) -> int | None:
    package = _PACKAGE.search(text)
    if package is None:
        return None
    found = _FORMAT.search(package.group(1))
    return int(found.group(1)) if found else 1


def _element(version: int) -> bytes:
    """Format 1 has no ``exec_depend`` (catkin refuses the manifest); 2 and 3 no
    ``run_depend``."""
    tag = b"run_depend" if version == 1 else b"exec_depend"
    return b"<" + tag + b">" + RUNTIME_PACKAGE.encode() + b"</" + tag + b">"


def _without_comments(data: bytes) -> bytes:
    """``data`` with each XML comment blanked (its line breaks kept): what is commented out
    declares nothing and anchors nothing, and every offset still points into ``data``."""
    return _COMMENT.sub(lambda match: re.sub(rb"[^\r\n]", b" ", match.group()), data)


def manifests_below(folder: Path) -> Iterator[Path]:
    """Every ``package.xml`` under ``folder``, sorted, not in hidden folders nor in what
    discovery never searches (build, devel and install spaces hold copies of them)."""
    for here, dirs, names in walk(folder):
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
