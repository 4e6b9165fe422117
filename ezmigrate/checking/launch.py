"""SkiROS2 launch files, read statically: what the robot loads when it starts.

A lab starts SkiROS2 with a launch file that sets the world model's ``workspace_dir`` (the
folder of its ontology) and ``init_scene`` (the scene it starts from), and the skill
manager's ``libraries_list`` and ``skill_list`` (the skills it loads). ROS 1 writes them as
``<arg name=... value=...>``/``<param>`` in ``.launch`` XML; ROS 2 as Python
(``.launch.py``), where only literal values can be read without running it. ``check``
resolves vocabulary and child types as the robot would with these values.

Values are kept as written; ``$(find pkg)`` is resolved to the ROS package of that name
in the repository (the folder whose ``package.xml`` names it), ``$(arg x)`` to the
argument's default in the same file. Anything else is left unresolved (``None`` paths),
and checks that depend on it say so rather than guess.
"""

from __future__ import annotations

import ast
import os
import re
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field, replace
from pathlib import Path
from xml.etree import ElementTree

from ezskiros_runtime.ontology.listing import walk
from ezskiros_runtime.ontology.vendored import package_name, vendored_skip

from ..files.discover import ALWAYS_EXCLUDED
from ..lint.scene_search import WorldRun

KEYS = ("workspace_dir", "init_scene", "libraries_list", "skill_list")
SUFFIXES = (".launch", ".launch.xml", ".launch.py")
_FIND = re.compile(r"\$\(find(?:-pkg-share)? ([\w-]+)\)")
_ARG = re.compile(r"\$\((?:arg|var) ([\w-]+)\)")


@dataclass(frozen=True)
class Launch:
    """The SkiROS2 settings of one launch file, as written (``None``: not set there)."""

    path: Path
    values: dict[str, str] = field(default_factory=dict)
    packages: dict[str, Path] = field(default_factory=dict)
    """ROS packages of the repository by name, for ``$(find pkg)``."""

    def folder(self, key: str) -> Path | None:
        """A path setting resolved against the repository, or None when it cannot be."""
        value = self.values.get(key)
        if value is None:
            return None
        found = _FIND.search(value)
        if found is not None:
            package = self.packages.get(found.group(1))
            if package is None:
                return None
            value = value.replace(found.group(0), str(package))
        if "$(" in value:
            return None
        path = Path(value)
        return path if path.is_absolute() else self.path.parent / path

    def listed(self, key: str) -> list[str] | None:
        """``libraries_list``/``skill_list`` as names (``"[a, b]"`` or ``a, b``)."""
        value = self.values.get(key)
        if value is None or "$(" in value:
            return None
        return [item.strip().strip("'\"") for item in value.strip().strip("[]").split(",")
                if item.strip().strip("'\"")]

    def scene(self) -> Path | None:
        """The ``init_scene`` file: as written when absolute or found beside the launch
        file, else in the ``workspace_dir``; None when neither holds it."""
        value = self.values.get("init_scene")
        if value is None or not value.strip() or "$(" in value:  # empty: the robot starts
            return None                                             # with no scene
        workspace = self.folder("workspace_dir")
        for candidate in (Path(value), self.path.parent / value,
                          *([workspace / value] if workspace is not None else [])):
            if candidate.is_file():
                return candidate
        return None

    @property
    def workspace_unresolved(self) -> str | None:
        """The ``workspace_dir`` as written when it names a folder this run cannot read (a
        package outside the repository): vocabulary may be defined there."""
        value = self.values.get("workspace_dir")
        if value is None:
            return None
        folder = self.folder("workspace_dir")
        return value if folder is None or not folder.is_dir() else None


def launch_files(root: Path) -> list[Path]:
    """Launch files under ``root`` that set any SkiROS2 key (hidden and build folders
    skipped)."""
    found = []
    for path in sorted(_walk(root)):
        try:
            text = path.read_text(encoding="utf-8", errors="replace")
        except OSError:
            continue
        if any(key in text for key in KEYS):
            found.append(path)
    return found


def _walk(root: Path) -> Iterator[Path]:
    """The launch files below ``root``, outside hidden and build folders and vendored
    SkiROS2 packages (their launch files start upstream's demos, not the lab's robot)."""
    if root.is_file():
        yield root
        return
    vendored = vendored_skip(root)
    for folder, dirs, names in walk(root):
        dirs[:] = [d for d in dirs if d not in ALWAYS_EXCLUDED and not d.startswith(".")
                   and not vendored(os.path.join(folder, d))]
        for name in names:
            if ".launch" in name and name.endswith(SUFFIXES) and Path(folder, name).is_file():
                yield Path(folder, name)


def ros_packages(root: Path) -> dict[str, Path]:
    """``{name: folder}`` of the ``package.xml`` files under ``root``."""
    from ..files.package_xml import manifests_below  # (a run the cache answers needs none)

    found: dict[str, Path] = {}
    for manifest in manifests_below(root):
        name = package_name(manifest)
        if name:
            found.setdefault(name, manifest.parent)
    return found


def read_launch(path: Path, packages: dict[str, Path] | None = None) -> Launch:
    """The SkiROS2 settings of a launch file (XML or Python); none when it cannot be read."""
    try:
        data = path.read_bytes()
    except OSError:
        return Launch(path, {}, packages or {})
    values = _python(data) if path.name.endswith(".py") else _xml(data)
    return Launch(path, values, packages or {})


def _xml(data: bytes) -> dict[str, str]:
    """``<arg name="k" value|default="v"/>`` and ``<param name="k" value="v"/>``, with
    ``$(arg x)`` replaced by the file's own defaults of ``x``."""
    try:
        root = ElementTree.fromstring(data)
    except ElementTree.ParseError:
        return {}
    defaults: dict[str, str] = {}
    values: dict[str, str] = {}
    for node in root.iter():
        if node.tag not in ("arg", "param"):
            continue
        name = node.get("name", "")
        value = node.get("value", node.get("default"))
        if value is None:
            continue
        if node.get("default") is not None and node.get("value") is None:
            defaults.setdefault(name, value)
        if name.rpartition("/")[2] in KEYS:
            values.setdefault(name.rpartition("/")[2], value)
    return {key: _ARG.sub(lambda m: defaults.get(m.group(1), m.group(0)), value)
            for key, value in values.items()}


def _python(data: bytes) -> dict[str, str]:
    """Literal values of the keys in a ``.launch.py``: ``{"skill_list": "[a, b]"}`` in a
    dict, ``("skill_list", "[a, b]")`` pairs, and ``DeclareLaunchArgument("skill_list",
    default_value="...")``."""
    try:
        tree = ast.parse(data)
    except (SyntaxError, ValueError):
        return {}
    values: dict[str, str] = {}
    for node in ast.walk(tree):
        for key, value in _pairs(node):
            if key in KEYS and value is not None:
                values.setdefault(key, value)
    return values


def _pairs(node: ast.AST) -> Iterable[tuple[str | None, str | None]]:
    if isinstance(node, ast.Dict):
        yield from ((_string(k), _string(v)) for k, v in zip(node.keys, node.values, strict=True))
    elif isinstance(node, ast.Tuple) and len(node.elts) == 2:
        yield _string(node.elts[0]), _string(node.elts[1])
    elif isinstance(node, ast.Call) and node.args:
        for keyword in node.keywords:
            if keyword.arg in ("default_value", "value"):
                yield _string(node.args[0]), _string(keyword.value)


def _string(node: ast.AST | None) -> str | None:
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value
    if isinstance(node, (ast.List, ast.Tuple)) and all(
            isinstance(e, ast.Constant) and isinstance(e.value, str) for e in node.elts):
        return "[" + ", ".join(str(e.value) for e in node.elts  # type: ignore[attr-defined]
                               ) + "]"
    return None


def project_launch(root: Path, chosen: Path | None = None) -> tuple[Launch | None, str | None]:
    """The launch file a run uses, and a note when it had to choose: ``chosen``
    (``--launch``), else the only one under ``root`` that sets a SkiROS2 key; with several
    and none chosen, none is used and the note says so."""
    if chosen is not None:
        return read_launch(chosen, _packages(root)), None
    files = launch_files(root)
    if len(files) == 1:
        return read_launch(files[0], _packages(root)), None
    if files:
        names = ", ".join(str(f.relative_to(root)) for f in files)
        return None, (f"{len(files)} SkiROS2 launch files ({names}): pick the one the robot "
                      "starts with --launch FILE to check against it")
    return None, None


def _packages(root: Path) -> dict[str, Path]:
    """The ROS packages of the repository at ``root`` (``ros_packages``), for the launch
    file a run uses: searched only once there is one (a workspace of several launch files,
    or none, uses none)."""
    return ros_packages(root.resolve()) if root.is_dir() else {}


def with_init_scene(world: WorldRun, launch: Launch | None) -> WorldRun:
    """``world`` with the launch file's ``init_scene`` among its scenes (once): the scene
    the robot starts from is checked like the repository's own."""
    scene = launch.scene() if launch is not None else None
    if scene is None or any(s.resolve() == scene.resolve() for s in world.scenes):
        return world
    return replace(world, scenes=(*world.scenes, scene))
