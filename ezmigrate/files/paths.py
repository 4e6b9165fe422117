"""How every command prints a path: one base for stderr, reports and ``check``.

Why: ruff and black print paths relative to the working directory when the file is inside
it (what a user can paste into their editor or shell), and a unified diff names files
relative to the repository root (``a/pkg/x.py``) so that ``git apply`` from the root takes
it. A report lands in a pull request, so it must never carry a path of the machine that
made it: a file outside the working directory is named relative to its repository, else
relative to the PATH it was found under.
"""

from __future__ import annotations

import os
import re
from functools import lru_cache
from pathlib import Path

from ezskiros_runtime.ontology.discovery import git_top


def shown(path: Path | str) -> str:
    """``path`` as the user sees it: relative to the working directory when inside it,
    else as given (a ``-`` stays ``-``)."""
    text = str(path)
    if text == "-":
        return text
    absolute = os.path.abspath(text)
    cwd = os.getcwd()
    if absolute == cwd or absolute.startswith(cwd.rstrip(os.sep) + os.sep):
        return Path(os.path.relpath(absolute, cwd)).as_posix()
    return text


def in_report(path: Path | str, fallback: str | None = None) -> str:
    """``path`` for a report: ``shown``, unless that is absolute (then ``from_repository``):
    no report names a folder of the machine that wrote it."""
    text = shown(path)
    if not os.path.isabs(text):
        return text
    return from_repository(text, fallback)


def from_repository(path: Path | str, fallback: str | None = None) -> str:
    """``path`` relative to the root of the git repository holding it (the names of a
    diff's ``a/``/``b/`` headers), else relative to the working directory when inside it,
    else ``fallback`` (the path relative to the PATH argument it was found under), else its
    name."""
    absolute = Path(os.path.abspath(path))
    root = git_root(absolute.parent)
    if root is not None:
        return absolute.relative_to(root).as_posix()
    text = shown(absolute)
    if not os.path.isabs(text):
        return text
    return fallback if fallback is not None and not os.path.isabs(fallback) else absolute.name


@lru_cache(maxsize=256)
def git_root(folder: Path) -> Path | None:
    """``discovery.git_top``, remembered: a report asks it of the same folders often."""
    return git_top(folder)


_ABSOLUTE = re.compile(r"(?<![\w.~/-])/[^\s\"'`,;:()\[\]<>|*]+")
"""An absolute POSIX path inside a text (not ``m/s``, not the ``/s`` of ``1 /s``)."""


def scrub(text: str, report: bool = True) -> str:
    """``text`` with every absolute path that names a file or folder of this machine (an
    ontology file, the interpreter, a traceback's file) relative to the working directory
    when inside it, else to the home folder (``~/.pyenv/...``), else as ``in_report``
    writes it: what a report says must not depend on where it was made. ``report=False``
    (stderr): only the first rule, as ruff and black print paths."""
    home = os.path.expanduser("~").rstrip(os.sep) + os.sep

    def relative(match: re.Match[str]) -> str:
        found = match.group(0).rstrip(".")
        if not os.path.exists(found):
            return match.group(0)
        named = shown(found)
        if not report:  # stderr: as ruff prints a path, absolute outside the directory
            pass
        elif os.path.isabs(named) and found.startswith(home) and home != os.sep:
            named = "~/" + found[len(home):]  # an interpreter in ~/.pyenv: still findable
        elif os.path.isabs(named):
            named = in_report(found)
        return named + match.group(0)[len(found):]
    return _ABSOLUTE.sub(relative, text)
