"""The project's ``pyproject.toml`` and its ``[tool.ezmigrate]`` table: the one reader of both.

The runtime (``ontology``, see ``ontology.config``) and the ``ezmigrate`` command (every
other key, validated in ``ezmigrate.cli.config``) both read their settings through
``find_tool_table``, so they can never disagree on which file is the project's, nor on
what makes that file unusable.

Which file: the nearest ``pyproject.toml`` at or above the starting path, whether or not
it has our table. That file is the project (as ruff and black decide); one further up
belongs to some other project. The start is resolved first (symlinks, ``..``): a module
reached through a symlinked install (``colcon build --symlink-install``) or as ``../x``
belongs to the project of the folders that really hold it, not of the folders its
spelling passes through.

Error rule, the same for every key and every caller: no ``pyproject.toml`` at all means no
configuration; a ``pyproject.toml`` that is found but cannot be used (unreadable, not UTF-8,
not valid TOML, or whose ``tool`` or ``tool.ezmigrate`` is not a table) raises
``PyprojectError`` naming the file. It is never taken as "no configuration": a silent
fallback would run with defaults the project did not choose, its ``exclude`` forgotten (so
files it keeps out get rewritten) or another ontology checked against.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path
from typing import Any

TOOL_TABLE = "ezmigrate"
"""Our table in ``pyproject.toml``: ``[tool.ezmigrate]``."""


class PyprojectError(ValueError):
    """A ``pyproject.toml`` was found but cannot be used; the message names the file.

    Callers turn it into their own error type (``OntologyConfigError`` in the runtime,
    ``ConfigError`` in the command line), so that each reports it by its own rules."""


def find_pyproject(start: str | os.PathLike[str]) -> Path | None:
    """The nearest ``pyproject.toml`` at or above ``start`` (a file or a folder, resolved)."""
    here = Path(start).expanduser().resolve()
    folder = here if here.is_dir() else here.parent
    for candidate_dir in (folder, *folder.parents):
        candidate = candidate_dir / "pyproject.toml"
        if candidate.is_file():
            return candidate
    return None


def find_tool_table(start: str | os.PathLike[str]) -> tuple[Path, dict[str, Any]] | None:
    """The nearest ``pyproject.toml`` (see ``find_pyproject``) and its ``[tool.ezmigrate]``.

    The table is empty when the file has none; ``None`` when there is no file at all.
    Raises ``PyprojectError`` by the module's error rule."""
    path = find_pyproject(start)
    if path is None:
        return None
    return path, tool_table(path)


def tool_table(path: Path) -> dict[str, Any]:
    """``[tool.ezmigrate]`` of the ``pyproject.toml`` at ``path`` (empty when absent)."""
    tool = read_toml(path).get("tool", {})
    if not isinstance(tool, dict):
        raise PyprojectError(f"{path}: [tool] must be a table, not {tool!r}")
    table = tool.get(TOOL_TABLE, {})
    if not isinstance(table, dict):
        raise PyprojectError(f"{path}: [tool.{TOOL_TABLE}] must be a table, not {table!r}")
    return table


def read_toml(path: Path) -> dict[str, Any]:
    """The whole document; ``PyprojectError`` when it cannot be read or parsed."""
    if sys.version_info >= (3, 11):
        import tomllib
    else:  # pragma: no cover - exercised on Python 3.10 only
        import tomli as tomllib
    try:
        with path.open("rb") as stream:
            return tomllib.load(stream)
    except OSError as error:
        raise PyprojectError(f"{path}: cannot read: {error.strerror or error}") from error
    except UnicodeDecodeError as error:
        raise PyprojectError(f"{path}: invalid TOML: not UTF-8 ({error.reason} at byte "
                             f"{error.start})") from error
    except tomllib.TOMLDecodeError as error:
        raise PyprojectError(f"{path}: invalid TOML: {error}") from error
