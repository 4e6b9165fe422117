"""Unified diffs of a migration, decoded with each file's own encoding."""

from __future__ import annotations

import io
import tokenize


def decode(data: bytes) -> str:
    """Source bytes as text, honouring a BOM or PEP 263 cookie (lossless for display)."""
    try:
        encoding, _ = tokenize.detect_encoding(io.BytesIO(data).readline)
    except SyntaxError:
        encoding = "utf-8"
    return data.decode(encoding, errors="replace")


def unified_diff(path: str, before: bytes, after: bytes, body: str | None = None) -> str:
    """``--- a/path`` / ``+++ b/path`` diff; line endings shown as they are. ``body``: its
    hunks (``diff_body``) when they were made already, where the file was migrated."""
    hunks = diff_body(before, after) if body is None else body
    return f"--- a/{path}\n+++ b/{path}\n{hunks}" if hunks else ""


def diff_body(before: bytes, after: bytes) -> str:
    """The hunks of ``unified_diff``, without the two lines naming the file: what a
    migration's worker can make without knowing how the file will be named."""
    import difflib  # (the terminal's colours import this module for ``colour`` alone)

    old = decode(before).splitlines(keepends=True)
    new = decode(after).splitlines(keepends=True)
    out = []
    for number, line in enumerate(difflib.unified_diff(old, new, fromfile="", tofile="")):
        if number < 2:
            continue  # the "--- " and "+++ " lines
        out.append(line if line.endswith("\n") else line + "\n\\ No newline at end of file\n")
    return "".join(out)


def colour(diff: str) -> str:
    """ANSI colours for a terminal (never used when output is piped)."""
    import click

    styled = []
    for line in diff.splitlines(keepends=True):
        if line.startswith(("+++", "---")):
            styled.append(click.style(line, bold=True))
        elif line.startswith("+"):
            styled.append(click.style(line, fg="green"))
        elif line.startswith("-"):
            styled.append(click.style(line, fg="red"))
        elif line.startswith("@@"):
            styled.append(click.style(line, fg="cyan"))
        else:
            styled.append(line)
    return "".join(styled)
