"""What a command's command line said: one frozen dataclass per command, one field per
option, named as click names the option's parameter.

Why: click hands a command every option as a parameter of its own (23 for ``check``). Each
command takes them as ``**given`` and builds its dataclass here at once, so that neither
the command nor the helpers that print for it take more than a handful of parameters
(issue 40) and a flag travels with the command line it came from, never on its own. The
options themselves are declared once, by the decorators in ``commands`` and
``shared_options``; tests/cli/test_arguments.py holds the fields here to exactly those.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import Path

from .options import CommandLine


@dataclass(frozen=True)
class Arguments:
    """The options of every command that loads files (``shared_options``)."""

    ontology: tuple[Path, ...]
    exclude: tuple[str, ...]
    jobs: int | None
    timeout: float | None
    python: str | None
    debug: bool

    def command_line(self) -> CommandLine:
        """The part the project's ``[tool.ezmigrate]`` is merged with (``Options.resolve``)."""
        return CommandLine(exclude=self.exclude, jobs=self.jobs, timeout=self.timeout,
                           python=self.python)


@dataclass(frozen=True)
class RewriteArguments(Arguments):
    """``ezmigrate rewrite``'s command line."""

    paths: tuple[Path, ...]
    dry_run: bool
    check: bool
    report: Path | None
    include_vendored: bool
    output_dir: Path | None
    verify: bool
    ignore_order: bool
    ignore_labels: bool
    color: bool | None
    stdin_filename: Path | None
    strict: bool
    package_xml: bool

    @property
    def reads_stdin(self) -> bool:
        """``rewrite -``: one file from stdin to stdout (``project.stdin``)."""
        return _is_stdin(self.paths)

    @property
    def writes(self) -> bool:
        """Neither ``--dry-run`` nor ``--check``: the run writes what settled."""
        return not (self.dry_run or self.check)


@dataclass(frozen=True)
class VerifyArguments(Arguments):
    """``ezmigrate verify``'s command line."""

    before: Path
    after: Path
    report: Path | None
    ignore_order: bool
    ignore_labels: bool


@dataclass(frozen=True)
class CheckArguments(Arguments):
    """``ezmigrate check``'s command line."""

    paths: tuple[Path, ...]
    stdin_filename: Path | None
    select: tuple[str, ...]
    ignore: tuple[str, ...]
    extend_select: tuple[str, ...]
    output_format: str
    statistics: bool
    fix: bool
    show_diff: bool
    exit_zero: bool
    include_vendored: bool
    trace: bool
    no_cache: bool
    cache_folder: Path | None
    quiet: bool
    scene: Path | None
    launch_file: Path | None

    def command_line(self) -> CommandLine:
        """As every command's, with the selection: a ``--select`` not given is None (the
        project's selection, else the default rules), never an empty one."""
        return replace(super().command_line(), select=self.select or None,
                       ignore=self.ignore, extend_select=self.extend_select)

    @property
    def reads_stdin(self) -> bool:
        """``check -``: stdin checked as the file it stands for (``checking.command``)."""
        return _is_stdin(self.paths)


def _is_stdin(paths: tuple[Path, ...]) -> bool:
    return [str(p) for p in paths] == ["-"]
