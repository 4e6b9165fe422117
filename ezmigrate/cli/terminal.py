"""Colour on a terminal, and only there: the one rule every command's output follows.

Why one rule: ``rewrite --dry-run`` coloured its diffs on a terminal whatever
``NO_COLOR`` said, and ``check`` never coloured at all. The rule, as ruff and the
no-color.org convention have it: a ``--color``/``--no-color`` the command was given wins;
else ``NO_COLOR`` set to anything but the empty string means none; else colour exactly
when the stream is a terminal, so a pipe, a file and CI logs get plain text.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Sequence
from typing import TextIO

import click

from ..lint.diagnostic import Diagnostic
from ..report.diffs import colour
from .output_formats import text

SEVERITY_COLOURS = {"error": "red", "warning": "yellow", "info": "cyan"}
"""The colour of a finding's code and severity in ``check``'s text output: what fails the
run stands out from what only advises."""


def wants_colour(stream: TextIO, given: bool | None = None) -> bool:
    """Whether output to ``stream`` is coloured: ``given`` (``--color``/``--no-color``),
    else not under a non-empty ``NO_COLOR``, else when ``stream`` is a terminal."""
    if given is not None:
        return given
    if os.environ.get("NO_COLOR"):
        return False
    try:
        return bool(stream.isatty())
    except (AttributeError, OSError, ValueError):  # no isatty, or a closed stream
        return False


def echo_diff(diff: str, given: bool | None = None) -> None:
    """A unified diff on stdout, coloured by ``wants_colour``. ``color`` is passed to click
    either way, so that ``--color`` colours a pipe too (click strips ANSI from a
    stream that is not a terminal unless told)."""
    use = wants_colour(sys.stdout, given)
    click.echo(colour(diff) if use else diff, nl=False, color=use)


def coloured_text(diagnostics: Sequence[Diagnostic]) -> str:
    """``check``'s text format (``output_formats.text``) with each finding's place bold and
    its code and severity in the colour of that severity. The plain format's lines are
    coloured, not written again, so that both stay the same text but for the escapes."""
    lines = text(diagnostics).split("\n")[:-1]  # one per finding, each ended by "\n"
    return "".join(_coloured_line(line, d) + "\n"
                   for line, d in zip(lines, diagnostics, strict=True))


def _coloured_line(line: str, d: Diagnostic) -> str:
    """One line of ``text`` with ``path:line:col:`` bold and ``CODE [severity]`` coloured
    (the first place they follow each other: the path comes first)."""
    head = f"{d.code} [{d.severity}]"
    at = line.find(f":{d.line}:{d.column}: {head}")
    if at < 0:  # not the shape the colours are laid on: leave it plain
        return line
    where = line[:at] + f":{d.line}:{d.column}:"
    fg = SEVERITY_COLOURS.get(d.severity)
    return (f"{click.style(where, bold=True)} {click.style(head, fg=fg, bold=True)}"
            f"{line[len(where) + 1 + len(head):]}")
