"""The project's own ontology: every file under the ``owl/`` folders of the repository.

SkiROS2's world model loads the core files, then every ``.owl`` under its ``workspace_dir``
(usually the skill package's own ``owl/`` folder), so nearly every skill repository ships
an ``owl/`` folder with its robot description and project classes (``scalable:Ur5``,
``paintbot:Paint``). Without them, every project class would be "unknown vocabulary".

When nothing is configured, the files used are the bundled core plus every ``.owl``/``.ttl``/
``.rdf`` file under each folder named ``owl`` inside the repository (its git top level, or
the given paths outside git). A vendored copy of the core files (``skiros2/owl/skiros.owl``)
is skipped: the bundled core states the same facts, and loading both would only add
duplicates. So are the ``owl/`` folders of SkiROS2 packages vendored into a lab's
repository (``vendored``): the lab's skill manager does not load them, and its code is not
the lab's either. Build output, virtual environments, hidden folders and the project's excludes
are not searched, and a symbolic link that leads outside the repository is not loaded
(``leads_outside``).
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path

from .listing import walk
from .vendored import NOT_SEARCHED, PACKAGE_XML, git_top, vendored_skip

OWL_FOLDER = "owl"
SUFFIXES = (".owl", ".ttl", ".rdf")
PROJECT_FILES = (PACKAGE_XML, "pyproject.toml")
"""The files that make a folder a project outside git: a ROS package, a Python project."""
CORE_FILE_NAMES = frozenset({"skiros.owl", "skirosextra.owl", "sumo.owl", "cora.owl",
                             "corax.owl", "rparts.owl"})
"""The SkiROS2 core files (``skiros2/owl`` and its IEEE-1872-2015 folder), by lower-cased
name: a copy of one of them in a repository is the core, already bundled."""


@dataclass(frozen=True)
class Discovered:
    """What the search found under ``root``: the project's files and the vendored core."""

    root: Path
    files: tuple[Path, ...]
    vendored: tuple[Path, ...]


def repository_root(paths: Sequence[Path]) -> Path | None:
    """The project of the first path (``enclosing_project``), else the common folder of
    the folders named; None when only files outside any project were named: a file alone
    is checked alone, and nothing around it is searched (a file in a shared folder once
    had that whole folder's ``owl/`` files loaded).

    The command (for the paths it works on) and the runtime (for the first skill module that
    asks for vocabulary, wherever the working directory is: roslaunch starts nodes in
    ``~/.ros``) both search from here, so they load the same files. A robot's installed
    workspace often has no ``.git``, but its packages keep their ``package.xml``."""
    if not paths:
        return None
    enclosing = enclosing_project(Path(paths[0]))
    if enclosing is not None:
        return enclosing
    folders = [p for p in (Path(x).resolve() for x in paths) if p.is_dir()]
    return Path(os.path.commonpath([str(f) for f in folders])) if folders else None


def enclosing_project(path: Path) -> Path | None:
    """The project ``path`` belongs to, the upper bound of every search made for it: the
    git top level at or above ``path``, else the nearest folder with a ``package.xml`` or a
    ``pyproject.toml``; None when ``path`` is in none of them (a home folder, a shared
    folder: then nothing around it is the project's to search)."""
    first = path.resolve()
    folder = first if first.is_dir() else first.parent
    return git_top(folder) or next((candidate for candidate in (folder, *folder.parents)
                                    if any((candidate / name).is_file()
                                           for name in PROJECT_FILES)), None)


def package_root(path: Path) -> Path | None:
    """The nearest folder at or above ``path`` with a ``package.xml``: its ROS package."""
    folder = path if path.is_dir() else path.parent
    return next((candidate for candidate in (folder, *folder.parents)
                 if (candidate / PACKAGE_XML).is_file()), None)


def discover(root: Path, skip: Callable[[Path], bool] | None = None) -> Discovered:
    """Every ontology file under the ``owl/`` folders below ``root``, sorted; ``skip`` says
    which folders and files are excluded (the project's excludes). Copies of the core files
    and the files of vendored SkiROS2 packages (``vendored``) are listed apart."""
    files: list[Path] = []
    vendored: list[Path] = []
    for path, upstream in _owl_files(root, skip or (lambda _path: False)):
        own = not upstream and path.name.lower() not in CORE_FILE_NAMES
        (files if own else vendored).append(path)
    return Discovered(root, tuple(sorted(files)), tuple(sorted(vendored)))


def _owl_files(root: Path, skip: Callable[[Path], bool]) -> Iterable[tuple[Path, bool]]:
    """The ontology files below ``root``, each with whether it lies in a vendored SkiROS2
    package (``vendored.VendoredRule``, with ``root`` as the repository outside git).

    Which folders lie in a vendored package, and which at or below an ``owl/`` folder, is
    carried down from each folder to the ones it holds (a folder's path is made once)."""
    is_vendored = vendored_skip(root)
    upstream: set[str] = set()  # the folders of vendored packages met so far
    owl: set[str] = set()  # the folders at or below an owl/ folder under root
    for folder, dirs, names in walk(root):
        here = Path(folder)
        inside, in_owl = folder in upstream, folder in owl
        kept = []
        for name in sorted(dirs):
            if name.startswith(".") or name in NOT_SEARCHED:
                continue
            below = here / name
            if skip(below):
                continue
            kept.append(name)
            path = os.path.join(folder, name)
            if inside or is_vendored(path):
                upstream.add(path)
            if in_owl or name == OWL_FOLDER:
                owl.add(path)
        dirs[:] = kept
        if not in_owl:
            continue
        for name in names:
            if (name.lower().endswith(SUFFIXES) and not skip(here / name)
                    and not leads_outside(here / name, root)):
                yield here / name, inside


def leads_outside(path: Path, root: Path) -> bool:
    """Whether ``path`` is a symbolic link whose target lies outside ``root``.

    Such a file is skipped, as the command skips every file of the kind ("symlink leads
    outside the given paths, skipped", ``ezmigrate.files.discover``): a repository's
    ``owl/lab.ttl`` must not load whatever file elsewhere on the machine it points to. A
    link that cannot be resolved counts as outside. Symbolic links to folders are never
    entered (``walk``, as ``os.walk``)."""
    if not os.path.islink(path):
        return False
    try:
        target = Path(os.path.realpath(path))
        base = Path(os.path.realpath(root))
    except (OSError, ValueError):
        return True
    return target != base and base not in target.parents
