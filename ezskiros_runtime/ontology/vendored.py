"""Which SkiROS2 packages in a repository are vendored copies, not the code of its owner.

Labs put SkiROS2 itself, or its standard skill library, in their workspace repository next
to their own packages (``src/skiros2/`` in a demo workspace). Those copies are upstream's
code: migrating or linting them would rewrite files the lab does not own, loading their
``owl/`` folders would add vocabulary the lab's robot never loads, and their launch files
are not the lab's. But the same packages in SkiROS2's own repositories (the framework, its
standard library, the test and template libraries, and forks of any of them) are the
maintainers' code, to be migrated and checked like any other.

So a package is *vendored* only when it is one of SkiROS2's (by its folder name or the name
its ``package.xml`` gives) and the repository holding it also holds code that is not
SkiROS2's: another ROS package, or a Python file outside every SkiROS2 package. The
repository is the git top level; without git, the folder the run was given. One rule, here,
for the command's file discovery, its launch-file search and the ontology discovery the
command and the runtime share.
"""

from __future__ import annotations

import contextlib
import os
from pathlib import Path
from typing import Callable, Iterator
from xml.etree import ElementTree

from .listing import shared_listings

PACKAGE_XML = "package.xml"

UPSTREAM_PACKAGES = frozenset({
    "skiros2", "skiros2_common", "skiros2_skill", "skiros2_world_model", "skiros2_task",
    "skiros2_gui", "skiros2_msgs", "skiros2_resource", "skiros2_std_skills",
    "skiros2_std_reasoners", "skiros2_std_lib", "skiros2_test_lib", "skiros2_template_lib"})
"""SkiROS2's own ROS packages (framework and standard libraries), and the folders that
group them in its repositories (``skiros2/``, ``skiros2_std_lib/``)."""

NOT_SEARCHED = frozenset({"node_modules", "build", "devel", "install", "log", "dist",
                          "site-packages", "__pycache__", "venv"})
"""Folders no search enters: build, devel and install spaces hold copies of packages."""


def package_name(package_xml: Path) -> str | None:
    """The ``<name>`` a ``package.xml`` gives its package, or None (unreadable, no name)."""
    try:
        name = ElementTree.parse(str(package_xml)).findtext("name")
    except (ElementTree.ParseError, OSError):
        return None
    return name.strip() if name and name.strip() else None


def git_top(folder: Path) -> Path | None:
    """The nearest folder at or above ``folder`` holding ``.git`` (a folder, or the file of
    a worktree or submodule), or None."""
    return next((candidate for candidate in (folder, *folder.parents)
                 if (candidate / ".git").exists()), None)


def upstream_package(folder: str | os.PathLike[str]) -> str | None:
    """The SkiROS2 package ``folder`` is (by its name, or the name its ``package.xml``
    gives), or None. The walks ask it of every folder they meet, by the path they have (a
    string, mostly): a ``Path`` is made only for a manifest to parse."""
    path = os.fspath(folder)
    name = os.path.basename(os.path.normpath(path))
    if name in UPSTREAM_PACKAGES:
        return name
    manifest = os.path.join(path, PACKAGE_XML)
    given = package_name(Path(manifest)) if os.path.isfile(manifest) else None
    return given if given in UPSTREAM_PACKAGES else None


def holds_only_skiros2(root: Path) -> bool:
    """Whether every package and Python file below ``root`` is SkiROS2's own, with at least
    one SkiROS2 package: ``root`` is then SkiROS2's repository (or a fork), not a lab's.

    The walk stops at the first package or Python file that is not SkiROS2's, and never
    enters a SkiROS2 package, so a lab repository costs a few folders."""
    found = False
    for folder, dirs, names in os.walk(root):
        here = Path(folder)
        if upstream_package(here) is not None:
            found = True
            dirs[:] = []
            continue
        if PACKAGE_XML in names or any(name.endswith(".py") for name in names):
            return False
        dirs[:] = sorted(d for d in dirs if not d.startswith(".") and d not in NOT_SEARCHED)
    return found


def repository_of(folder: Path, fallback: Path) -> Path:
    """The repository ``folder`` belongs to: its git top level, else ``fallback`` (the
    folder the run was given)."""
    return git_top(folder) or fallback


class VendoredRule:
    """Answers "is this folder a vendored SkiROS2 package?" for the folders of one walk,
    deciding each repository once (a walk meets many packages of the same one) and each
    folder once (the walks of one command share a rule: ``shared_rules``)."""

    def __init__(self, fallback: Path) -> None:
        self._fallback = fallback.resolve()
        self._own: dict[Path, bool] = {}
        self._answers: dict[str, str | None] = {}

    def package(self, folder: str | os.PathLike[str]) -> str | None:
        """The SkiROS2 package ``folder`` is a vendored copy of, or None (not SkiROS2's,
        or SkiROS2's in SkiROS2's own repository)."""
        key = os.path.abspath(folder)  # the walks name a folder relatively or absolutely
        if key not in self._answers:
            self._answers[key] = self._package(folder)
        return self._answers[key]

    def _package(self, folder: str | os.PathLike[str]) -> str | None:
        package = upstream_package(folder)
        if package is None:
            return None
        repository = repository_of(Path(folder).resolve(), self._fallback)
        if repository not in self._own:
            self._own[repository] = holds_only_skiros2(repository)
        return None if self._own[repository] else package


_shared: dict[Path, VendoredRule] | None = None


@contextlib.contextmanager
def shared_rules() -> Iterator[None]:
    """Within it, the walks under the same folder share one ``VendoredRule``, and every
    folder is listed once (``listing.shared_listings``): a command that searches one
    repository for its ontology, launch files, scenes and Python files asks about each
    folder once, not four times. Outside it (a robot's runtime, a test that changes a
    repository between two walks) every walk decides afresh."""
    global _shared
    outer, _shared = _shared, {}
    try:
        with shared_listings():
            yield
    finally:
        _shared = outer


def rule_for(fallback: Path) -> VendoredRule:
    """The rule of a walk under ``fallback``: the shared one within ``shared_rules``."""
    if _shared is None:
        return VendoredRule(fallback)
    key = fallback.resolve()
    if key not in _shared:
        _shared[key] = VendoredRule(fallback)
    return _shared[key]


def vendored_skip(fallback: Path) -> Callable[[str | os.PathLike[str]], bool]:
    """A folder predicate for walks that only need the yes or no of ``VendoredRule``."""
    rule = rule_for(fallback)
    return lambda folder: rule.package(folder) is not None
