"""The process-wide ontology: resolved once from configuration, replaceable explicitly.

Namespaces (`skiros.Product`) and the early checks need one ontology without every call
site passing it around, and loading it must happen once per process, not once per skill
file. `active_index()` resolves the configuration (working directory, environment) on first
use; the CLI and tests call `use_ontology()` to pin a specific one.

On a robot the working directory is arbitrary (roslaunch starts nodes in ``~/.ros``), so when
neither an argument, the environment nor a pyproject.toml above the working directory names
an ontology, the pyproject.toml above the first file that asked for vocabulary (see
`note_source_file`) is searched; then, with the SkiROS2 backend active, the files the world
model server loads (`robot`); then what ``ezmigrate`` itself would use for that file: the
bundled core plus the ``owl/`` folders of its repository or ROS package (the one resolution
function, ``config.resolve_ontology_paths``, serves both, so a lab's plain-Python unit tests
import migrated skills with the vocabulary ``rewrite`` verified them with). A discovered
file that does not parse is skipped with one logged warning (``config.load_source``).
"""

from __future__ import annotations

import logging
import os
import threading
from collections.abc import Sequence
from pathlib import Path

from .config import OntologySource, load_source, resolve_ontology_paths
from .index import OntologyIndex
from .load import load_index
from .robot import (
    PackageLocator,
    ParameterSource,
    locate_package,
    read_parameter,
    robot_ontology_files,
)

_lock = threading.RLock()
_active: OntologyIndex | None = None
_source: OntologySource | None = None
_hint: list[Path] = []
"""The first source file that asked for vocabulary (at most one entry)."""
log = logging.getLogger("ezskiros_runtime")


def note_source_file(path: str | os.PathLike[str] | None) -> None:
    """Remember the file of the first skill module that asks for the ontology.

    Called with the module of a description class when it is defined and with the module
    importing a prefix (``from ezskiros_runtime.ontology import skiros``, which usually
    comes first). Only the first real file counts (``<stdin>`` and the like do not).
    """
    if _hint or path is None:
        return
    file = Path(path)
    if file.is_absolute() and file.is_file():
        _hint.append(file)


def active_index() -> OntologyIndex:
    """The ontology of this process, loading it from the configuration on first use."""
    global _active
    index = _active
    if index is not None:
        return index
    with _lock:
        if _active is None:
            _active = _load_configured()
        return _active


def active_source() -> OntologySource | None:
    """Where the active index came from (None before the first load or for a given index)."""
    return _source


def use_ontology(
    paths_or_index: Sequence[str | os.PathLike[str]] | OntologyIndex | None,
) -> OntologyIndex:
    """Replace the active index and return it.

    An `OntologyIndex` is used as is; paths are loaded (through the cache); None resolves
    the configuration again, e.g. after the working directory or environment changed.
    """
    global _active, _source
    with _lock:
        if paths_or_index is None:
            _active = _load_configured()
        elif isinstance(paths_or_index, OntologyIndex):
            _active = paths_or_index
            _source = None
        else:
            if isinstance(paths_or_index, (str, os.PathLike)):
                paths_or_index = [paths_or_index]
            source = resolve_ontology_paths(paths_or_index)
            _active = load_index(list(source.paths) or None)
            _source = source
        return _active


def _on_skiros2() -> bool:
    """Whether skills run on real SkiROS2 here (the backend's own decision)."""
    from ..dsl.backend import select_backend

    try:
        return select_backend().name == "skiros2"
    except ImportError:
        return False


def robot_source(locator: PackageLocator = locate_package,
                 parameters: ParameterSource = read_parameter) -> OntologySource:
    """The world model's files as an ontology source (the bundled core when not found)."""
    files = robot_ontology_files(locator, parameters)
    return OntologySource(files, "robot") if files else OntologySource((), "bundled")


def _load_configured() -> OntologyIndex:
    global _source
    source = resolve_ontology_paths()
    if source.origin == "bundled" and _hint:  # nothing configured from the working directory
        source = resolve_ontology_paths(start=_hint[0])
    if source.origin == "bundled" and _on_skiros2():
        source = robot_source()
    if source.origin == "bundled" and _hint:  # as ezmigrate resolves it for this file
        source = resolve_ontology_paths(start=_hint[0], roots=[_hint[0]])
    index, source = load_source(source)
    for warning in source.warnings():
        log.warning("ezskiros_runtime: %s", warning)
    _source = source
    return index
