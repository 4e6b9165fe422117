"""``[tool.ezmigrate]`` in the nearest ``pyproject.toml``: defaults a project keeps in its repo.

Keys: ``exclude`` (list of globs), ``jobs`` (int), ``timeout`` (seconds), ``python`` (the
interpreter that loads files when verifying, relative to the project when it is a path),
``select``, ``ignore`` and ``extend-select`` (finding codes for ``check``),
``skill-libraries`` (folders of skill libraries a compound skill may use, relative to the
project), and ``ontology`` (read by ``ezskiros_runtime.ontology.config``). Command-line
options win over these.
"""

from __future__ import annotations

import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib


@dataclass(frozen=True)
class ProjectConfig:
    """The project's configured defaults, and where they were read from."""

    exclude: tuple[str, ...] = ()
    jobs: int | None = None
    timeout: float | None = None
    python: str | None = None
    source: Path | None = None
    select: tuple[str, ...] | None = None
    ignore: tuple[str, ...] = ()
    extend_select: tuple[str, ...] = ()
    skill_libraries: tuple[Path, ...] = ()


def find_pyproject(start: Path) -> Path | None:
    """The nearest ``pyproject.toml`` at or above ``start``."""
    folder = start.resolve()
    if folder.is_file():
        folder = folder.parent
    for candidate in (folder, *folder.parents):
        if (candidate / "pyproject.toml").is_file():
            return candidate / "pyproject.toml"
    return None


def load_project_config(start: Path) -> ProjectConfig:
    """Read ``[tool.ezmigrate]``; a missing or unreadable file means no configuration."""
    path = find_pyproject(start)
    if path is None:
        return ProjectConfig()
    try:
        table: dict[str, Any] = tomllib.loads(path.read_text(encoding="utf-8"))
    except (OSError, tomllib.TOMLDecodeError, UnicodeDecodeError):
        return ProjectConfig()
    section = table.get("tool", {}).get("ezmigrate", {})
    if not isinstance(section, dict):
        return ProjectConfig()
    exclude = section.get("exclude", [])
    if not (isinstance(exclude, list) and all(isinstance(e, str) for e in exclude)):
        raise ConfigError(f"{path}: [tool.ezmigrate] exclude must be a list of globs, "
                          f"not {exclude!r}")
    jobs, timeout = section.get("jobs"), section.get("timeout")
    if jobs is not None and (isinstance(jobs, bool) or not isinstance(jobs, int) or jobs < 1):
        raise ConfigError(f"{path}: [tool.ezmigrate] jobs must be a whole number of at least "
                          f"1, not {jobs!r}")
    if timeout is not None and (isinstance(timeout, bool)
                                or not isinstance(timeout, (int, float)) or timeout <= 0):
        raise ConfigError(f"{path}: [tool.ezmigrate] timeout must be a positive number of "
                          f"seconds, not {timeout!r}")
    python = section.get("python")
    if python is not None and not (isinstance(python, str) and python):
        raise ConfigError(f"{path}: [tool.ezmigrate] python must be an interpreter's name or "
                          f"path, not {python!r}")
    if python is not None and ("/" in python or "\\" in python):
        python = str(path.parent / python)  # a path means the same from any subfolder
    codes = {key: _codes(section, key, path) for key in ("select", "ignore", "extend-select")}
    libraries = section.get("skill-libraries", [])
    if not (isinstance(libraries, list) and all(isinstance(e, str) for e in libraries)):
        raise ConfigError(f"{path}: [tool.ezmigrate] skill-libraries must be a list of "
                          f"folders, not {libraries!r}")
    return ProjectConfig(exclude=tuple(exclude), jobs=jobs,
                         skill_libraries=tuple(path.parent / e for e in libraries),
                         timeout=float(timeout) if timeout is not None else None,
                         python=python, source=path,
                         select=codes["select"], ignore=codes["ignore"] or (),
                         extend_select=codes["extend-select"] or ())


def _codes(section: dict[str, Any], key: str, path: Path) -> tuple[str, ...] | None:
    """``check``'s finding selectors (``select = ["EZ2", "EZ901"]``), validated later."""
    value = section.get(key)
    if value is None:
        return None
    if not (isinstance(value, list) and all(isinstance(v, str) for v in value)):
        raise ConfigError(f"{path}: [tool.ezmigrate] {key} must be a list of finding codes "
                          f"or prefixes, not {value!r}")
    return tuple(value)


class ConfigError(ValueError):
    """A ``[tool.ezmigrate]`` value the tool cannot use: a usage error (exit 2), not a guess."""
