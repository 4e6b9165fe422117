"""``[tool.ezmigrate]`` in the nearest ``pyproject.toml``: defaults a project keeps in its repo.

Keys: ``exclude`` (list of globs), ``jobs`` (int), ``timeout`` (seconds), ``python`` (the
interpreter that loads files when verifying, relative to the project when it is a path),
``select``, ``ignore`` and ``extend-select`` (finding codes for ``check``),
``skill-libraries`` (folders of skill libraries a compound skill may use, relative to the
project), ``single-valued`` (the relations EZ401 keeps to one parent or one place), and
``ontology`` (read by ``ezskiros_runtime.ontology.config``). Any other key is a warning on
stderr with the key it most resembles (``exlude``: did you mean ``exclude``?). Command-line
options win over these (``ezmigrate.cli.options`` merges them).

The file is found and read by ``ezskiros_runtime.pyproject``, the one reader the runtime's
ontology setting uses too, so both always take the same file and fail on it alike: no
``pyproject.toml`` means no configuration, while one that is found but unusable (not valid
TOML, unreadable, ``[tool.ezmigrate]`` not a table) is a ``ConfigError``, never silently
"no configuration". This module only checks the values of the keys it owns.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

from ezskiros_runtime.pyproject import PyprojectError, find_pyproject, find_tool_table

from ..files.paths import shown

__all__ = ["KEYS", "ConfigError", "ProjectConfig", "find_pyproject", "load_project_config"]

KEYS = ("exclude", "extend-select", "ignore", "jobs", "ontology", "python", "select",
        "single-valued", "skill-libraries", "target-version", "timeout")
"""Every key ``[tool.ezmigrate]`` may hold (``ontology`` is the runtime's): any other is a
typo the run would otherwise pass over in silence (``exlude`` would exclude nothing)."""


@dataclass(frozen=True)
class ProjectConfig:
    """The project's configured defaults, and where they were read from."""

    exclude: tuple[str, ...] = ()
    jobs: int | None = None
    timeout: float | None = None
    python: str | None = None
    single_valued: tuple[str, ...] | None = None
    """``single-valued = ["skiros:spatiallyRelated", "skiros:at"]``; None: that default."""
    source: Path | None = None
    select: tuple[str, ...] | None = None
    ignore: tuple[str, ...] = ()
    extend_select: tuple[str, ...] = ()
    skill_libraries: tuple[Path, ...] = ()
    target_version: tuple[int, int] | None = None
    """``target-version = "py38"``: the Python migrated code must run on (``target``)."""
    warnings: tuple[str, ...] = ()
    """One line per key of the table that is none of ``KEYS``, for stderr."""


def load_project_config(start: Path) -> ProjectConfig:
    """The project's ``[tool.ezmigrate]`` for a run from ``start``, its values checked.

    No ``pyproject.toml`` at or above ``start`` means no configuration; an unusable one, or
    a value the tool cannot use, is a ``ConfigError`` naming the file."""
    try:
        found = find_tool_table(start)
    except PyprojectError as error:
        raise ConfigError(str(error)) from error
    if found is None:
        return ProjectConfig()
    path, section = found
    return replace(_project_config(path, section),
                   single_valued=_single_valued(section, path),
                   warnings=unknown_keys(path, section))


def unknown_keys(path: Path, section: dict[str, Any]) -> tuple[str, ...]:
    """A warning naming ``path`` for each key of ``section`` that is not one of ``KEYS``,
    with the known key it most resembles, as ruff says of its own table. A warning, not an
    error: a newer ezmigrate's key in a shared ``pyproject.toml`` must not stop an older one."""
    unknown = sorted(k for k in section if k not in KEYS)
    if not unknown:
        return ()
    import difflib  # (for a key that is not ours only)

    found = []
    for key in unknown:
        close = difflib.get_close_matches(key.replace("_", "-").lower(), KEYS, n=1)
        hint = f"; did you mean '{close[0]}'?" if close else ""
        found.append(f"warning: {shown(path)}: unknown key '{key}' in [tool.ezmigrate], "
                     f"ignored{hint}")
    return tuple(found)


def _single_valued(section: dict[str, Any], path: Path) -> tuple[str, ...] | None:
    """The relations the world model keeps single-valued (``prefix:name`` each)."""
    value = section.get("single-valued")
    if value is None:
        return None
    if not (isinstance(value, list) and all(isinstance(v, str) and ":" in v and v.strip()
                                            for v in value)):
        raise ConfigError(f"{path}: [tool.ezmigrate] single-valued must be a list of "
                          f"relations written prefix:name (\"skiros:at\"), not {value!r}")
    return tuple(v.strip() for v in value)


def _project_config(path: Path, section: dict[str, Any]) -> ProjectConfig:
    """The checked values of ``section`` (``[tool.ezmigrate]`` of ``path``)."""
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
    target = section.get("target-version")
    target_version = None
    if target is not None:
        from ..project.target import parse_target  # (rewrite's: not imported for every run)

        target_version = parse_target(target)
    if target is not None and target_version is None:
        raise ConfigError(f"{path}: [tool.ezmigrate] target-version must be a Python version "
                          f"as ruff spells it, py38 or newer (\"py38\"), not {target!r}")
    return ProjectConfig(exclude=tuple(exclude), jobs=jobs, target_version=target_version,
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
    """A setting the tool cannot use (an unusable ``pyproject.toml``, a ``[tool.ezmigrate]``
    value, an interpreter that does not exist): a usage error (exit 2), not a guess."""
