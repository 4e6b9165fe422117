"""The settings a command runs with: its command line merged with ``[tool.ezmigrate]``.

Every command (``rewrite PATH``, ``rewrite -``, ``verify``, ``check``) builds its settings
with ``Options.resolve``, the one place that says which source wins, so that commands
cannot drift apart (``rewrite -`` once ignored the project's ``timeout``). The precedence:

* a value given on the command line beats the project's ``[tool.ezmigrate]``, which beats
  the default (``jobs``, ``timeout``, ``python``);
* ``exclude`` adds up: the command line's globs and the project's both apply (the project
  keeps its vendored folders out whatever a hook passes);
* ``select``, ``ignore`` and ``extend-select`` follow ruff: a ``--select`` on the command
  line replaces the project's whole selection (its ``ignore`` and ``extend-select`` too);
  without one, the command line's ``--ignore`` and ``--extend-select`` add to the project's;
* ``skill-libraries`` and ``single-valued`` have no command-line option: the project's
  value, or none. They are resolved here once, from the project of the first path (for
  stdin, the file it stands for), and nothing re-reads the configuration later.

The ontology is not here: its precedence (``--ontology``, then ``EZSKIROS_ONTOLOGY``, then
the project, then discovery) is the runtime's, which robots use without this command line
(``ezskiros_runtime.ontology.config``).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import TypeVar

from ..verify.interpreters import resolve
from ..verify.pool_config import PoolConfig, default_jobs
from .config import ConfigError, ProjectConfig

DEFAULT_TIMEOUT = 20.0
"""Seconds a file may take to load when verifying, when nobody says otherwise."""

_T = TypeVar("_T")


@dataclass(frozen=True)
class CommandLine:
    """What the command line said. ``None`` means the option was not given; options that
    add up (``exclude``, ``ignore``, ``extend_select``) are empty when not given."""

    exclude: tuple[str, ...] = ()
    jobs: int | None = None
    timeout: float | None = None
    python: str | None = None
    select: tuple[str, ...] | None = None
    ignore: tuple[str, ...] = ()
    extend_select: tuple[str, ...] = ()


@dataclass(frozen=True)
class Options:
    """The merged settings a command runs with (see the module doc for who wins)."""

    exclude: tuple[str, ...] = ()
    """Globs of paths to skip: the command line's, then the project's."""
    jobs: int = field(default_factory=default_jobs)
    """Parallel workers."""
    timeout: float = DEFAULT_TIMEOUT
    """Seconds per file when a file is loaded (verification, tracing)."""
    python: str | None = None
    """The interpreter files are loaded with, found on disk or PATH; None: ours (and, for
    newer syntax, the newest that compiles the file: see ``verify.interpreters``)."""
    select: tuple[str, ...] | None = None
    """``check``'s selectors as written (validated by ``check``); None: the default rules."""
    select_from: str = "--select"
    """Where ``select`` came from, for the message when one of its selectors is unknown."""
    ignore: tuple[str, ...] = ()
    extend_select: tuple[str, ...] = ()
    skill_libraries: tuple[Path, ...] = ()
    """Folders of skill libraries compound skills may use (absolute)."""
    project: Path | None = None
    """The folder of the ``pyproject.toml`` in use: project excludes are relative to it."""
    target_version: tuple[int, int] | None = None
    """The project's ``target-version``; None: decided from the repository (``target``)."""
    source: str = "[tool.ezmigrate]"
    """The pyproject.toml the settings came from, for messages."""
    single_valued: tuple[str, ...] | None = None
    """The relations EZ401 keeps to one parent or one place; None: the default list."""

    def pool(self, ontology: tuple[str, ...], workers: int | None = None) -> PoolConfig:
        """The sandbox's settings for these options, loading ``ontology`` (resolved files;
        empty: the bundled default) with ``workers`` workers (default: ``jobs``)."""
        return PoolConfig(workers=self.jobs if workers is None else workers,
                          timeout=self.timeout, ontology=ontology, python=self.python,
                          python_given=self.python is not None)

    @classmethod
    def resolve(cls, cli: CommandLine, pyproject: ProjectConfig) -> Options:
        """The settings from the command line and the project, by the module's precedence.

        Raises ``ConfigError`` (a usage error, exit 2) when the chosen interpreter does not
        exist: running with another one instead would verify under the wrong Python."""
        replaced = cli.select is not None  # as ruff: --select replaces the whole selection
        where = str(pyproject.source or "[tool.ezmigrate]")
        jobs = _first(None, cli.jobs, pyproject.jobs)
        return cls(
            exclude=(*cli.exclude, *pyproject.exclude),
            jobs=jobs if jobs is not None else default_jobs(),
            timeout=_first(DEFAULT_TIMEOUT, cli.timeout, pyproject.timeout),
            python=_interpreter(cli.python, pyproject),
            select=cli.select if replaced else pyproject.select,
            select_from="--select" if replaced else where,
            ignore=cli.ignore if replaced else (*pyproject.ignore, *cli.ignore),
            extend_select=(cli.extend_select if replaced
                           else (*pyproject.extend_select, *cli.extend_select)),
            skill_libraries=pyproject.skill_libraries,
            project=pyproject.source.parent if pyproject.source else None,
            target_version=pyproject.target_version, source=where,
            single_valued=pyproject.single_valued,
        )


def _first(default: _T, *values: _T | None) -> _T:
    """The first of ``values`` that was given (not ``None``), else ``default``: the
    precedence of a plain setting, command line first."""
    return next((value for value in values if value is not None), default)


def _interpreter(given: str | None, pyproject: ProjectConfig) -> str | None:
    """``--python`` (else ``[tool.ezmigrate] python``) as a path to run, or None for ours.

    A name that does not run is a usage error naming where it was written, never a silent
    fallback to this interpreter."""
    value = _first(None, given, pyproject.python)
    if value is None:
        return None
    found = resolve(value)  # absolute; never from a relative PATH entry
    if found is None:
        where = "--python" if given is not None else (
            f"{pyproject.source or 'pyproject.toml'}: [tool.ezmigrate] python")
        raise ConfigError(f"{where}: {value}: no such interpreter (a path, or a name on PATH)")
    return found
