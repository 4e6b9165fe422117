"""Which ontology files to load: argument, environment, pyproject.toml, or the bundled default.

Precedence, first match wins:
1. explicit paths (the CLI's repeatable `--ontology`), relative to the working directory;
2. `EZSKIROS_ONTOLOGY`, `os.pathsep`-separated, relative to the working directory;
3. `[tool.ezmigrate] ontology = [...]` in the nearest pyproject.toml walking up from
   `start`; paths relative to that file's folder (so the setting means the same from any
   subfolder). The nearest pyproject.toml is the project, even without our table: the
   file is found and read by `ezskiros_runtime.pyproject`, the same reader the other
   `[tool.ezmigrate]` settings (ezmigrate.cli.config) go through;
4. the vocabulary bundled with the package, plus, when the caller names the paths it works
   on (`roots`), every ontology file under the `owl/` folders of their repository
   (`discovery`: what the SkiROS2 world model would load from the skill package).

A configured path that does not exist is an `OntologyConfigError` that says where the path
came from: silently falling back to another ontology would make every check misleading.
For the same reason a pyproject.toml that is found but unusable (not valid TOML,
unreadable, `[tool.ezmigrate]` not a table) is an `OntologyConfigError` too, by the rule of
`ezskiros_runtime.pyproject`, never "nothing configured".
"""

from __future__ import annotations

import os
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ..pyproject import TOOL_TABLE, PyprojectError, find_tool_table
from .errors import OntologyConfigError, OntologyLoadError

if TYPE_CHECKING:
    from .index import OntologyIndex

__all__ = ["ENV_VAR", "TOOL_TABLE", "OntologySource", "SettledSource", "find_tool_config",
           "load_source", "resolve_ontology_paths", "settle_source"]

ENV_VAR = "EZSKIROS_ONTOLOGY"


@dataclass(frozen=True)
class OntologySource:
    """The resolved ontology paths and where they came from (for messages and `--verbose`).

    `origin` is "argument", "environment", "pyproject:<path to pyproject.toml>", "bundled"
    (then `paths` is empty and the bundled vocabulary applies) or "discovered:<repository>"
    (then `paths` is the bundled core followed by the project's files, and `skipped` the
    vendored copies of the core and of SkiROS2 packages that were left out).
    """

    paths: tuple[Path, ...]
    origin: str
    skipped: tuple[Path, ...] = ()
    broken: tuple[tuple[Path, str], ...] = ()
    """Discovered files that could not be read or parsed, with the reason: left out (see
    ``load_source``)."""

    def warnings(self) -> list[str]:
        """One line per broken discovered file, for stderr or the robot's log."""
        return [f"warning: {reason}: skipped (SkiROS2's world model would fail on this "
                f"file if its folder were the workspace_dir)" for _path, reason in self.broken]

    def describe(self) -> str:
        """One line for humans: `ontology from EZSKIROS_ONTOLOGY: a.owl, b.ttl`."""
        where = {
            "argument": "--ontology",
            "environment": ENV_VAR,
            "bundled": "the bundled default",
            "robot": "the SkiROS2 world model's files",
        }.get(self.origin, self.origin.replace("pyproject:", "", 1))
        if self.origin.startswith("discovered:"):
            root = Path(self.origin.partition(":")[2])
            text = (f"ontology: the bundled SkiROS2 core plus the owl/ folders of {root}: "
                    + ", ".join(_shown(p, root) for p in self.paths[1:]))
            if self.skipped:
                text += " (vendored SkiROS2 copies skipped: " + ", ".join(
                    _shown(p, root) for p in self.skipped) + ")"
            if self.broken:
                text += " (unreadable, skipped: " + ", ".join(
                    _shown(p, root) for p, _reason in self.broken) + ")"
            return text
        if not self.paths:
            return f"ontology from {where} (the SkiROS2 core; no owl/ folder found)"
        return f"ontology from {where}: " + ", ".join(str(p) for p in self.paths)


def _shown(path: Path, root: Path) -> str:
    try:
        return str(path.relative_to(root))
    except ValueError:
        return str(path)


def resolve_ontology_paths(
    explicit: Sequence[str | os.PathLike[str]] | None = None,
    *,
    environ: Mapping[str, str] | None = None,
    start: Path | None = None,
    roots: Sequence[Path] | None = None,
    skip: Callable[[Path], bool] | None = None,
) -> OntologySource:
    """Decide which ontology files to load, following the precedence in the module doc.

    `roots`: the paths a command works on; without them nothing is discovered (a robot's
    runtime has its own rule, see `robot`); `skip` tells the paths the project excludes."""
    cwd = Path.cwd()
    if isinstance(explicit, (str, os.PathLike)):
        explicit = [explicit]
    if explicit:
        paths = [_absolute(Path(p), cwd) for p in explicit]
        return OntologySource(_existing(paths, "the --ontology argument"), "argument")

    env = os.environ if environ is None else environ
    raw = env.get(ENV_VAR, "")
    entries = [entry for entry in raw.split(os.pathsep) if entry.strip()]
    if entries:
        paths = [_absolute(Path(entry.strip()), cwd) for entry in entries]
        return OntologySource(
            _existing(paths, f"the {ENV_VAR} environment variable"), "environment"
        )

    found = find_tool_config(start if start is not None else cwd)
    if found is not None:
        pyproject, table = found
        configured = table.get("ontology")
        if configured is not None:
            paths = [_absolute(p, pyproject.parent) for p in _path_list(configured, pyproject)]
            if paths:
                where = f"[tool.{TOOL_TABLE}] ontology in {pyproject}"
                return OntologySource(_existing(paths, where), f"pyproject:{pyproject}")
    if roots:
        from .bundled import bundled_ontology_path
        from .discovery import discover, repository_root

        root = repository_root(roots)
        if root is not None:
            discovered = discover(root, skip)
            if discovered.files:
                return OntologySource((bundled_ontology_path(), *discovered.files),
                                      f"discovered:{root}", discovered.vendored)
    return OntologySource((), "bundled")


def load_source(source: OntologySource) -> tuple[OntologyIndex, OntologySource]:
    """The index of ``source``, and the source as loaded (``settle_source``, loaded)."""
    settled = settle_source(source)
    return settled.index(), settled.source


@dataclass
class SettledSource:
    """An ontology source whose files are known to load (those that do not left out), with
    the fingerprint of their index: what a run the outcome cache may answer needs, before
    it knows whether it needs the index itself (``index``)."""

    source: OntologySource
    fingerprint: str
    loaded: OntologyIndex | None = None

    def index(self) -> OntologyIndex:
        """The index, loaded once (from the cache, as a rule)."""
        if self.loaded is None:
            from .load import load_index

            self.loaded = load_index(list(self.source.paths) or None)
        return self.loaded


def settle_source(source: OntologySource) -> SettledSource:
    """Which of ``source``'s files load, and the fingerprint of their index; the index is
    decoded only when it is asked for (``SettledSource.index``).

    A file that discovery found (an ``owl/`` folder nobody named) and that cannot be read
    or parsed, such as an empty ``lth.owl`` committed by mistake, is left out: the source
    returned lists it in ``broken`` and its ``warnings()`` say so, and everything else
    runs. A file someone named (``--ontology``, ``EZSKIROS_ONTOLOGY``, pyproject) is the
    user's choice: its error is raised (``OntologyLoadError``), as is any error of the core.
    """
    from .load import probe_index

    paths: list[Path] = list(source.paths)
    broken: list[tuple[Path, str]] = []
    discovered = source.origin.startswith("discovered:")
    while True:
        try:
            fingerprint, built = probe_index(paths or None)
        except OntologyLoadError as error:
            bad = _named_by(error, paths[1:]) if discovered else None
            if bad is None:
                raise
            paths.remove(bad)
            broken.append((bad, str(error)))
            continue
        return SettledSource(replace(source, paths=tuple(paths), broken=tuple(broken)),
                             fingerprint, built)


def _named_by(error: OntologyLoadError, paths: Sequence[Path]) -> Path | None:
    """Which of ``paths`` the load error is about, or None."""
    if error.path is None:
        return None
    culprit = Path(error.path).resolve()
    return next((path for path in paths if path.resolve() == culprit), None)


def find_tool_config(start: Path) -> tuple[Path, dict[str, Any]] | None:
    """The nearest pyproject.toml at or above `start`, and its [tool.ezmigrate] table.

    The table is empty when the file has none; None when there is no pyproject.toml at all.
    The one reader (`ezskiros_runtime.pyproject`) does the work; an unusable file is an
    `OntologyConfigError` here, the error every caller of this module already handles.
    """
    try:
        return find_tool_table(start)
    except PyprojectError as error:
        raise OntologyConfigError(str(error)) from error


def _path_list(value: object, pyproject: Path) -> list[Path]:
    """`ontology` may be one path or a list of paths (strings)."""
    if isinstance(value, str):
        return [Path(value)]
    if isinstance(value, list) and all(isinstance(item, str) for item in value):
        return [Path(item) for item in value]
    raise OntologyConfigError(
        f"{pyproject}: [tool.{TOOL_TABLE}] ontology must be a path or a list of paths, "
        f"got {value!r}"
    )


def _absolute(path: Path, base: Path) -> Path:
    path = path.expanduser()
    return path if path.is_absolute() else base / path


def _existing(paths: list[Path], where: str) -> tuple[Path, ...]:
    missing = [p for p in paths if not p.exists()]
    if missing:
        names = ", ".join(str(p) for p in missing)
        raise OntologyConfigError(f"ontology path not found: {names} (from {where})")
    return tuple(paths)
