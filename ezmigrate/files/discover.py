"""Which files a run looks at: ``.py`` files under the given paths, minus exclusions.

Conventions of black and ruff: excludes apply to explicitly named files too (pre-commit
passes file names), ``.gitignore`` is respected inside git checkouts, and symlinks are
followed only while they stay inside the given roots (a loop or an escape ends there).

A vendored copy of SkiROS2's own Python (the framework's packages, its standard skill
libraries, inside a lab's repository) is not the lab's code: migrating or linting it would
rewrite upstream files the lab does not own and bury its findings in theirs. Such a folder
is passed over with one note, unless it (or a path in it) is named on the command line, or
``include_vendored`` is set (``--include-vendored``). What counts as vendored is
``ezskiros_runtime.ontology.vendored``: the same packages in SkiROS2's own repositories are
their maintainers' code and are walked like any other.
"""

from __future__ import annotations

import errno
import fnmatch
import functools
import os
import re
from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path

from ezskiros_runtime.ontology.discovery import enclosing_project
from ezskiros_runtime.ontology.listing import remember
from ezskiros_runtime.ontology.vendored import rule_for, upstream_package

from .git_ignored import IgnoredQuery
from .paths import shown
from .writing import is_temporary_name

ROS_IGNORE_MARKERS = ("CATKIN_IGNORE", "COLCON_IGNORE", "AMENT_IGNORE")
"""Files whose presence keeps a folder out of the ROS build (catkin, colcon, ament): what
the robot never builds is not the lab's skill code either (a test corpus, an old copy)."""

ALWAYS_EXCLUDED = frozenset({".git", ".hg", ".svn", "__pycache__", ".venv", "venv", ".tox",
                             ".mypy_cache", ".ruff_cache", ".pytest_cache", "node_modules",
                             "build", "dist", ".eggs", ".ezmigrate_cache"})


@dataclass(frozen=True)
class Candidate:
    """A file to consider, with the root it was found under (for relative report paths)."""

    path: Path
    root: Path

    @property
    def relative(self) -> str:
        try:
            return self.path.relative_to(self.root).as_posix() or self.path.name
        except ValueError:
            return self.path.as_posix()


def excluded_under(base: Path, patterns: Sequence[str]) -> Callable[[Path], bool]:
    """Whether a path is excluded, matched relative to ``base`` (the project's folder).
    Without patterns nothing is, and no path is resolved to say so."""
    if not patterns:
        return lambda _path: False

    def skip(path: Path) -> bool:
        try:
            relative = path.resolve().relative_to(base.resolve()).as_posix()
        except ValueError:
            return False
        return _excluded(relative, patterns)
    return skip


def _excluded(relative: str, patterns: Sequence[str]) -> bool:
    """A pattern matches the path, any one folder or file name in it, or any leading
    folders of it (``src/legacy`` excludes ``src/legacy/a.py``, as in ruff)."""
    if not patterns:
        return False
    parts = relative.split("/")
    prefixes = ["/".join(parts[:i]) for i in range(1, len(parts) + 1)]
    matches = _any_of(tuple(patterns))
    return any(matches(os.path.normcase(p)) for p in (*prefixes, *parts))


@functools.lru_cache(maxsize=32)
def _any_of(patterns: tuple[str, ...]) -> Callable[[str], object]:
    """``fnmatch.fnmatch`` against any of ``patterns``, as one compiled expression: a run
    asks it of every folder and name of every file."""
    joined = "|".join(f"(?:{fnmatch.translate(os.path.normcase(p))})" for p in patterns)
    return re.compile(joined).match


def _spellings(path: Path, project: Path | None, named: bool) -> set[str]:
    """Relative spellings of ``path`` for excludes to match (with each folder in them).

    Always relative to the project (the folder of the ``pyproject.toml``), as ruff does:
    ``exclude = ["src/legacy"]`` there holds whatever folder the run starts from. A file
    ``named`` on the command line also as given and relative to the working directory:
    pre-commit passes ``src/legacy/a.py``, and ``legacy`` or ``legacy/*`` must exclude it,
    as with black and ruff. Absolute spellings are never used: every folder above the
    project (``/tmp``, ``/home``) would then be matched too.
    """
    names = {path.name}
    starts: list[str | Path] = [project] if project is not None else []
    if named:
        starts.append(os.curdir)
        if not path.is_absolute():
            names.add(path.as_posix().removeprefix("./"))
    for start in starts:
        relative = os.path.relpath(path, start)
        if not relative.startswith(".."):
            names.add(Path(relative).as_posix())
    return names


def _inside(real: str, roots: Iterable[str]) -> bool:
    """Whether the resolved path ``real`` is one of the resolved ``roots`` or below one."""
    return any(real == r or real.startswith(os.path.join(r, "")) for r in roots)


def repository_root(path: Path) -> Path | None:
    """The scope of a named path: a directory itself; for a file, its project (its git
    top level, else its nearest ``package.xml`` or ``pyproject.toml``: ``enclosing_project``,
    as ontology discovery finds it), else None: a file alone is checked alone, and the
    folder around it may be anyone's (a home folder, a shared checkout of several labs)."""
    if path.is_dir():
        return path
    return enclosing_project(path)


def discover(paths: Sequence[Path], exclude: Sequence[str] = (),
             respect_gitignore: bool = True,
             stale: list[Path] | None = None,
             project: Path | None = None,
             include_vendored: bool = False) -> tuple[list[Candidate], list[str]]:
    """All candidate files, sorted and unique, plus messages about what was passed over
    (``start_discovery``, waited for)."""
    return start_discovery(paths, exclude, respect_gitignore, stale, project,
                           include_vendored).result()


def start_discovery(paths: Sequence[Path], exclude: Sequence[str] = (),
                    respect_gitignore: bool = True,
                    stale: list[Path] | None = None,
                    project: Path | None = None,
                    include_vendored: bool = False) -> Discovery:
    """The walk for ``discover``, done, and git asked what it ignores (``IgnoredQuery``):
    a caller with other work does it while git answers (``Discovery.result``).

    ``stale`` (when given) collects temporary files of ours (``.NAME.XXXXXXXX.ezmigrate``)
    found beside the candidates: only a SIGKILLed run leaves them. Discovery only lists
    them; ``session.run_rewrite`` decides whether to remove them (only when it writes).
    ``project``: the folder excludes are also matched relative to (see ``_spellings``).
    ``include_vendored``: walk into vendored SkiROS2 packages too (see the module doc).

    Each file's real path (symlinks resolved) is worked out once, from its folder's real
    path, which is resolved once per folder: a tree of 20,000 files costs one ``stat`` per
    entry, not one per path component of every file.
    """
    notes: list[str] = []
    found: dict[str, Candidate] = {}
    named_files: set[str] = set()  # real paths of files named on the command line
    for given in paths:
        if not given.exists() and not given.is_symlink():
            notes.append(f"{given}: no such file or directory")
            continue
        root = given if given.is_dir() else given.parent
        real_roots = [os.path.realpath(root)]
        if given.is_file():
            if not any(_excluded(name, exclude) for name in _spellings(given, project, named=True)):
                found.setdefault(os.path.realpath(given), Candidate(given, root))
                named_files.add(os.path.realpath(given))
                if stale is not None:
                    stale.extend(_temporaries_of(given))
            continue
        named = given.resolve()  # a path in a vendored package, named: include all of it
        inside = any(upstream_package(f) for f in (named, *named.parents))
        vendored = None if include_vendored or inside else _note_vendored(notes, named)
        for file, real in _walk(given, real_roots, notes, stale, vendored):
            candidate = Candidate(file, root)
            if exclude and any(_excluded(name, exclude) for name in
                               {candidate.relative, *_spellings(file, project, named=False)}):
                continue
            found.setdefault(real, candidate)
    ordered = sorted(found.items(), key=lambda pair: str(pair[1].path))
    asked = IgnoredQuery([real for real, _ in ordered]) if respect_gitignore else None
    return Discovery(ordered, notes, named_files, asked)


class Discovery:
    """A discovery whose walk is done and whose answers from git may be on their way."""

    def __init__(self, ordered: list[tuple[str, Candidate]], notes: list[str],
                 named_files: set[str], asked: IgnoredQuery | None) -> None:
        self._ordered = ordered
        self._notes = notes
        self._named_files = named_files
        self._asked = asked
        self._result: tuple[list[Candidate], list[str]] | None = None

    def result(self) -> tuple[list[Candidate], list[str]]:
        """The candidates, sorted and unique, less what git ignores, and the notes."""
        if self._result is None:
            ordered, notes = self._ordered, self._notes
            if self._asked is not None:
                ignored = self._asked.answer()
                notes = notes + [f"{shown(c.path)}: skipped, git ignores it (.gitignore)"
                                 for real, c in ordered  # named: say so
                                 if real in ignored and real in self._named_files]
                ordered = [(real, c) for real, c in ordered if real not in ignored]
            self._result = [c for _, c in ordered], notes
        return self._result


def library_candidates(paths: Sequence[Path]) -> list[tuple[Candidate, bytes]]:
    """The Python files of ``[tool.ezmigrate] skill-libraries``, read."""
    found, _ = discover([p for p in paths if p.exists()])
    items = []
    for candidate in found:
        try:
            items.append((candidate, candidate.path.read_bytes()))
        except OSError:
            continue
    return items


def _temporaries_of(file: Path) -> list[Path]:
    """Our temporary files for ``file`` (``.NAME.XXXXXXXX.ezmigrate`` beside it)."""
    try:
        with os.scandir(file.parent) as listing:
            return sorted(Path(e.path) for e in listing
                          if e.name.startswith(f".{file.name}.") and is_temporary_name(e.name))
    except OSError:
        return []


def _note_vendored(notes: list[str], given: Path) -> Callable[[str], bool]:
    """Whether to pass over a folder below the ``given`` path: a vendored SkiROS2 package
    (``VendoredRule``, with ``given`` as the repository outside git), said once in
    ``notes``."""
    rule = rule_for(given)

    def skip(folder: str) -> bool:
        package = rule.package(folder)
        if package is not None:
            notes.append(f"{Path(folder)}: a vendored copy of SkiROS2's {package}, not the lab's "
                         "code: skipped (name it, or pass --include-vendored, to include it)")
        return package is not None
    return skip


def _catkin_toplevel(folder: Path, name: str) -> bool:
    """Whether ``folder/name`` is where ``catkin_init_workspace`` puts its symlink to
    ``/opt/ros/<distro>/share/catkin/cmake/toplevel.cmake``: ``CMakeLists.txt`` at the top
    of a workspace's ``src/``. Every catkin workspace has it and it is catkin's, never the
    lab's code, so a note about it would be noise on every run."""
    return name == "CMakeLists.txt" and folder.name == "src"


def _walk(top: Path, roots: list[str], notes: list[str],
          stale: list[Path] | None = None,
          vendored: Callable[[str], bool] | None = None) -> Iterator[tuple[Path, str]]:
    """``.py`` files under ``top`` with their real paths (depth first, names sorted), and
    our temporary files into ``stale`` when it is given; folders ``vendored`` says are
    SkiROS2's own are not entered.

    A folder is listed when its parent's walk meets it, not when it is entered: its ROS
    ignore markers are then read from its own listing (no system call per marker), and the
    listing waits on the stack for its turn. Paths are strings until a file is yielded
    (``pathlib`` costs more than the system calls on a tree of small folders)."""
    seen: set[str] = set()
    first = str(top)
    stack = [(first, os.path.realpath(top), _listed(first))]  # folder, real path, listing
    while stack:
        folder, real, listed = stack.pop()
        if real in seen:
            notes.append(f"{Path(folder)}: symlink loop, not followed again")
            continue
        seen.add(real)
        if isinstance(listed, OSError):
            notes.append(f"{Path(folder)}: cannot list ({listed.strerror})")
            continue
        remember(folder, listed)  # the searches after this one list it no more
        for entry in sorted(listed, key=_name):
            name = entry.name
            if name in ALWAYS_EXCLUDED:
                continue
            if stale is not None and is_temporary_name(name):
                if not entry.is_symlink() and entry.is_file(follow_symlinks=False):
                    stale.append(Path(entry.path))
                continue
            link = entry.is_symlink()
            target = os.path.realpath(entry.path) if link else ""
            if link and not _inside(target, roots):
                if not _catkin_toplevel(Path(folder), name):
                    notes.append(f"{Path(entry.path)}: symlink leads outside the given "
                                 "paths, skipped")
                continue
            try:
                is_dir = entry.is_dir()
                is_file = not is_dir and name.endswith(".py") and entry.is_file()
            except OSError as error:  # a file symlink loop: ELOOP
                reason = "symlink loop" if error.errno == errno.ELOOP else error.strerror
                notes.append(f"{Path(entry.path)}: {reason}, skipped")
                continue
            if not (is_file or is_dir):
                continue
            target = target or os.path.join(real, name)
            if is_file:
                yield Path(entry.path), target
                continue
            child = _listed(entry.path)
            marker = _ros_ignored(entry.path, child)
            if marker is not None:
                notes.append(f"{Path(entry.path)}: skipped, its {marker} keeps it out of the "
                             "ROS build")
            elif not (vendored is not None and vendored(entry.path)):
                stack.append((entry.path, target, child))


def _name(entry: os.DirEntry[str]) -> str:
    return entry.name


def _listed(folder: str) -> list[os.DirEntry[str]] | OSError:
    """The entries of ``folder``, or why it cannot be listed."""
    try:
        with os.scandir(folder) as listing:
            return list(listing)
    except OSError as error:
        return error


def _ros_ignored(folder: str, listed: list[os.DirEntry[str]] | OSError) -> str | None:
    """The ROS ignore marker in ``folder`` (``CATKIN_IGNORE``...), or None: read from its
    listing, or asked of the system when it cannot be listed."""
    if isinstance(listed, OSError):
        return next((m for m in ROS_IGNORE_MARKERS
                     if os.path.lexists(os.path.join(folder, m))), None)
    names = {entry.name for entry in listed}
    return next((m for m in ROS_IGNORE_MARKERS if m in names), None)
