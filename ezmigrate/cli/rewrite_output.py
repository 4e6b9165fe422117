"""What ``rewrite`` and ``verify`` print and write: each file's problems and diff, the
manifests declared, the report, the summary line and the exit code.

Apart from the commands (``commands``) so that a ``check``, which prints none of it, does
not import the report writers, the diff and the written-lines mapping.
"""

from __future__ import annotations

import sys
from collections.abc import Sequence
from dataclasses import replace
from pathlib import Path
from typing import Any, NoReturn

import click

from ..files.paths import from_repository, in_report, scrub
from ..files.paths import shown as shown_path
from ..project.exit_codes import EXIT_ERROR
from ..report.diffs import unified_diff
from ..report.reports import MarkdownOptions, Summary, json_report, markdown_report
from ..report.results import FileResult
from ..report.written_lines import as_written, written_diff
from .arguments import RewriteArguments
from .output_formats import printable
from .terminal import echo_diff


def said(message: str, debug: bool) -> str:
    """``_short``, printable (``output_formats.printable``): a path inside the message
    starts no line. ``--debug`` prints a traceback whole, as Python wrote it."""
    return _short(message, debug) if debug else printable(_short(message, debug))


def _short(message: str, debug: bool) -> str:
    """A message for stderr: its first line, unless ``--debug`` asks for all of it."""
    lines = message.splitlines() or [""]
    if debug or len(lines) == 1:
        return message
    return f"{lines[0].rstrip(':')} (rerun with --debug for details)"


def write_report(path: Path, results: list[FileResult], options: MarkdownOptions) -> None:
    """The report of ``results`` to ``path`` (``-``: stdout), Markdown or JSON by its name."""
    markdown = path.suffix.lower() == ".md"
    text = scrub(markdown_report(results, options) if markdown
                 else json_report(results, options=options))  # no path of this machine
    # a file name that is not valid UTF-8 reaches us as lone surrogates (caf\udce9.py), which
    # UTF-8 cannot encode: written as the text \udce9, which in JSON is the escape of that
    # very surrogate (json.load and os.fsencode give back the file's real bytes)
    text = text.encode("utf-8", "backslashreplace").decode("utf-8")
    if str(path) == "-":
        click.echo(text, nl=False)
        return
    try:
        path.write_text(text, encoding="utf-8")
    except OSError as error:
        click.echo(f"ezmigrate: error: cannot write the report {printable(str(path))}: "
                   f"{error.strerror or error}", err=True)
        sys.exit(EXIT_ERROR)


def results_as_written(migrated: Sequence[Any],
                results: Sequence[FileResult] | None = None) -> list[FileResult]:
    """Each file's result (``results``, one per file, else its own) as stderr and the
    report show it: named relative to the working directory (no absolute path in a
    report), lines those of the file written, with the legacy line beside them
    (``written_lines``)."""
    return [as_written(replace(r, path=in_report(m.candidate.path, m.candidate.relative)),
                       m.original)
            for m, r in zip(migrated, results or [m.result for m in migrated], strict=True)]


def show_manifests(outcome: Any, request: Any, color: bool | None) -> list[str]:
    """Say what became of each package.xml the run declares the runtime in (``session``
    decided and wrote them): a diff with --dry-run, ``would rewrite`` with --check, one
    stderr line each; and one line each for the report."""
    from ..files.package_xml import runtime_depend

    lines = []
    for manifest in outcome.manifests:
        shown = shown_path(manifest.path)
        element = runtime_depend(manifest.old)
        if request.dry_run:  # applies from the repository root, as the files' diffs do
            diff = unified_diff(printable(from_repository(manifest.path, shown)),
                                manifest.old, manifest.new)
            echo_diff(diff, color)
        elif request.check:
            click.echo(f"would rewrite {printable(shown)}")
        lines.append(f"`{shown}`: declares the runtime, `{element}`"
                     + ("" if request.writes else " (would)"))
        click.echo(f"ezmigrate: {printable(shown)}: {element} "
                   + ("added" if request.writes else "would be added"), err=True)
    return lines


def print_result(shown: str, relative: str, original: bytes, result: FileResult,
                  args: RewriteArguments) -> None:
    """One file's problems on stderr; its diff (``--dry-run``) or name (``--check``)."""
    if result.error:
        click.echo(f"{printable(shown, path=True)}: {said(result.error, args.debug)}",
                   err=True)
    for skill in result.skills:
        if skill.status in ("skipped", "failed"):
            reason = (skill.reason or "").splitlines()[0] if skill.reason else ""
            click.echo(f"{printable(shown, path=True)}:{skill.line}: {printable(skill.name)}: "
                       f"{skill.status}: {printable(reason)}", err=True)
    if result.changed and args.dry_run:
        assert isinstance(result.new_source, bytes)
        diff = unified_diff(printable(relative), original, result.new_source,
                            written_diff(result))
        echo_diff(diff, args.color)
    elif result.changed and args.check:
        click.echo(f"would rewrite {printable(shown)}")


def finish(args: RewriteArguments, results: list[FileResult], refused: list[str],
            options: MarkdownOptions, reported: list[FileResult] | None = None) -> NoReturn:
    """The report (of ``reported``, the whole tree, when given), the summary line, and the
    exit code every ``rewrite`` ends with."""
    if args.report is not None:
        write_report(args.report, results if reported is None else reported, options)
    from ..project.session import exit_code

    summary = Summary.of(results)
    click.echo(f"ezmigrate: {summary.line(dry=not args.writes)}", err=True)
    sys.exit(exit_code(summary, args.check, args.strict, refused))
