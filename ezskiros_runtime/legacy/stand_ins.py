"""``legacy_imports()``: serve SkiROS2's module names (and, optionally, stubs) while loading.

SkiROS2 is not installable here (it needs ROS, legacy-skiros2-api.md §1, §8.11), so while the
context is active a ``sys.meta_path`` finder answers ``skiros2_common...`` and
``skiros2_skill...`` with fresh module objects filled from this package. The classes are ours,
not copies: ``skiros2_common.core.abstract_skill.SkillDescription`` *is*
``ezskiros_runtime.legacy.abstract_skill.SkillDescription``, the one base that EzSkiROS classes
also derive from.

With ``permissive=True`` a second finder, placed at the *end* of ``sys.meta_path`` so that real
modules always win, turns every module the normal machinery cannot find into a permissive stub
(see ``stubs.py``). It only does so for imports made by user code: an import coming from the
standard library, from site-packages or from ezmigrate itself gets the usual
``ModuleNotFoundError``, because those probe optional modules with ``try: import x`` and a stub
would make them believe the module exists.

Nothing is active as a side effect of importing this module. Leaving the context removes both
finders and every module they created (also from their parent packages' attributes), and puts
back any ``skiros2_*`` modules that were loaded before.
"""

from __future__ import annotations

import importlib
import os
import site
import sys
import sysconfig
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from functools import lru_cache
from importlib.abc import Loader, MetaPathFinder
from importlib.machinery import ModuleSpec
from pathlib import Path
from types import FrameType, ModuleType
from typing import Any

from . import abstract_skill, conditions, params, primitive, processors, skill, world_element
from .stubs import make_stub_module

__all__ = ["SKIROS2_MODULES", "expected_stand_in", "legacy_imports", "library_roots"]

EXPECTED_ROOTS = frozenset({
    "rospy", "roslib", "rospkg", "rosnode", "rosgraph", "rosparam", "rosbag", "actionlib",
    "tf", "tf2_ros", "tf2_py", "tf2_geometry_msgs", "tf_conversions", "moveit_commander",
    "moveit_msgs", "cv_bridge", "image_geometry", "message_filters", "dynamic_reconfigure",
    "rclpy", "launch", "launch_ros", "ament_index_python", "genpy", "std_srvs",
    "skiros2_msgs", "skiros2_world_model", "skiros2_common", "skiros2_skill",
    "skiros2_std_lib", "skiros2_task", "PyKDL", "kdl_parser_py", "urdf_parser_py"})
"""Top-level modules a skill is expected to import on the robot only: their stand-ins are
no news. Anything else that had to be stood in (a sibling module not given, a relative
import of a file passed alone) is listed in the report."""


def expected_stand_in(name: str) -> bool:
    """Whether the stood-in module ``name`` is ROS or SkiROS2 (not worth a note)."""
    root = name.split(".", 1)[0]
    return root in EXPECTED_ROOTS or root.endswith(("_msgs", "_srvs", "_msg", "_srv"))

_PACKAGE = ()  # a stand-in package: no names of its own, only submodules

SKIROS2_MODULES: dict[str, tuple[ModuleType, ...]] = {
    "skiros2_common": _PACKAGE,
    "skiros2_common.core": _PACKAGE,
    "skiros2_common.core.abstract_skill": (abstract_skill, params, world_element, conditions),
    "skiros2_common.core.params": (params,),
    "skiros2_common.core.world_element": (world_element,),
    "skiros2_common.core.conditions": (conditions,),
    "skiros2_common.core.primitive": (primitive, abstract_skill),
    "skiros2_common.core.primitive_thread": (primitive, abstract_skill),
    "skiros2_skill": _PACKAGE,
    "skiros2_skill.core": _PACKAGE,
    "skiros2_skill.core.skill": (skill,),
    "skiros2_skill.core.processors": (processors,),
}
"""Stand-in module name -> our modules whose ``__all__`` (and PEP 562 ``__getattr__``) it
exports. ``abstract_skill`` also exports what SkiROS2's module imports (params, Element,
conditions) because legacy files pick those up from there too."""

_SKIROS2_ROOTS = ("skiros2_common", "skiros2_skill")


class _Tracker:
    """The modules one ``legacy_imports`` context created (for the clean-up on exit), and
    the names the permissive finder stood in for (what the report lists)."""

    def __init__(self) -> None:
        self.created: dict[str, ModuleType] = {}
        self.stood_in: list[str] = []


class _StandInFinder(MetaPathFinder, Loader):
    """Serves the names of ``SKIROS2_MODULES`` from our modules."""

    def __init__(self, tracker: _Tracker) -> None:
        self._tracker = tracker

    def find_spec(self, fullname: str, path: Sequence[str] | None = None,
                  target: ModuleType | None = None) -> ModuleSpec | None:
        sources = SKIROS2_MODULES.get(fullname)
        if sources is None:
            return None
        return ModuleSpec(fullname, self, is_package=sources is _PACKAGE)

    def create_module(self, spec: ModuleSpec) -> ModuleType | None:
        return None  # the default module object

    def exec_module(self, module: ModuleType) -> None:
        exported: list[str] = []
        for source in SKIROS2_MODULES[module.__name__]:
            for name in source.__all__:
                module.__dict__[name] = getattr(source, name)
                exported.append(name)
            if "__getattr__" in source.__dict__:
                module.__dict__["__getattr__"] = source.__dict__["__getattr__"]
        module.__dict__["__all__"] = list(dict.fromkeys(exported))
        self._tracker.created[module.__name__] = module


@lru_cache(maxsize=1)
def library_roots() -> tuple[str, ...]:
    """Folders whose code must never receive stubs (see the module docstring)."""
    roots = set()
    paths = sysconfig.get_paths()
    for key in ("stdlib", "platstdlib", "purelib", "platlib"):
        if paths.get(key):
            roots.add(paths[key])
    roots.update(site.getsitepackages() if hasattr(site, "getsitepackages") else ())
    if site.ENABLE_USER_SITE and site.getusersitepackages():
        roots.add(site.getusersitepackages())
    here = Path(__file__).resolve().parent  # ezskiros_runtime/legacy
    roots.add(str(here.parent))  # ezskiros_runtime
    roots.add(str(here.parent.parent / "ezmigrate"))
    return tuple(os.path.join(os.path.realpath(r), "") for r in roots)


_IMPORT_MACHINERY = (
    os.path.join(os.path.dirname(os.path.realpath(importlib.__file__)), ""),
    os.path.realpath(__file__),
)


def _importing_file() -> str | None:
    """The file whose code triggered the current import (import machinery frames skipped)."""
    frame: FrameType | None = sys._getframe(1)
    while frame is not None:
        filename = frame.f_code.co_filename
        if not filename.startswith("<frozen importlib"):
            real = os.path.realpath(filename) if not filename.startswith("<") else filename
            if not (real.startswith(_IMPORT_MACHINERY[0]) or real == _IMPORT_MACHINERY[1]):
                return real
        frame = frame.f_back
    return None


class _PermissiveFinder(MetaPathFinder, Loader):
    """Last resort: a stub module for anything user code imports that does not exist."""

    def __init__(self, tracker: _Tracker) -> None:
        self._tracker = tracker
        self._library_roots = library_roots()

    def find_spec(self, fullname: str, path: Sequence[str] | None = None,
                  target: ModuleType | None = None) -> ModuleSpec | None:
        importer = _importing_file()
        if importer is not None and importer.startswith(self._library_roots):
            return None
        return ModuleSpec(fullname, self, is_package=True)

    def create_module(self, spec: ModuleSpec) -> ModuleType | None:
        return None

    def exec_module(self, module: ModuleType) -> None:
        make_stub_module(module)
        self._tracker.created[module.__name__] = module
        self._tracker.stood_in.append(module.__name__)


def _is_skiros2_name(name: str) -> bool:
    return name.split(".", 1)[0] in _SKIROS2_ROOTS


@contextmanager
def legacy_imports(*, permissive: bool = False) -> Iterator[list[str]]:
    """Make SkiROS2's module names importable for the duration (and stub missing modules if
    ``permissive``); see the module docstring for the exact guarantees.

    Yields the list of module names stubbed so far (filled while the context runs)."""
    tracker = _Tracker()
    stand_in = _StandInFinder(tracker)
    stub_finder = _PermissiveFinder(tracker) if permissive else None
    stashed = {n: m for n, m in sys.modules.items() if _is_skiros2_name(n)}
    for name in stashed:
        del sys.modules[name]
    sys.meta_path.insert(0, stand_in)
    if stub_finder is not None:
        sys.meta_path.append(stub_finder)
    try:
        yield tracker.stood_in
    finally:
        for finder in (stand_in, stub_finder):
            if finder is not None and finder in sys.meta_path:
                sys.meta_path.remove(finder)
        _forget(tracker.created)
        for name in [n for n in sys.modules if _is_skiros2_name(n)]:
            del sys.modules[name]  # also what user code put there under SkiROS2's names
        sys.modules.update(stashed)


def _forget(created: dict[str, Any]) -> None:
    """Remove the created modules from ``sys.modules`` and from their parents' attributes."""
    for name, module in created.items():
        if sys.modules.get(name) is module:
            del sys.modules[name]
        parent_name, _, child = name.rpartition(".")
        parent = sys.modules.get(parent_name) if parent_name else None
        if parent is not None and parent.__dict__.get(child) is module:
            delattr(parent, child)
