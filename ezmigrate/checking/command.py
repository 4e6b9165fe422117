"""The ``check`` command's flow around the pipeline, so that the command line only parses,
calls and prints.

Standard input is checked as the file it stands for (``--stdin-filename``) through a
private copy (``project/stdin.py``); the outcome's findings are selected and suppressed
(``lint/select.py``), shown with paths as the working directory sees them, fixed or shown
as a diff (``fixes``), and turned into the exit code: 0 when no finding at error severity
remains, 1 when one does (or, for ``--diff``, when a fix would change a file).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Literal

from ..files.paths import shown as shown_path
from ..lint.diagnostic import Diagnostic
from ..lint.select import Selection, apply
from ..project.exit_codes import EXIT_ATTENTION, EXIT_OK
from ..report.wording import counted
from .run import CheckOutcome

FixMode = Literal["fix", "diff"]


@dataclass(frozen=True)
class Subject:
    """What a run checks: its paths, the folders its project is found from, the path its
    settings and launch file are found from, and the names its files are shown by."""

    paths: tuple[Path, ...]
    roots: tuple[Path, ...]
    anchor: Path
    shown_as: dict[str, str] = field(default_factory=dict)
    """A private copy of standard input -> the name it stands for."""


def subject(paths: tuple[Path, ...], stdin: bytes | None = None,
            stdin_filename: Path | None = None) -> Subject:
    """The run's subject: ``paths`` (the working directory when none), or, for ``-``, a
    private copy of ``stdin`` checked as ``stdin_filename``."""
    paths = paths or (Path("."),)
    if [str(p) for p in paths] != ["-"]:
        return Subject(paths, paths, paths[0])
    from ..project.stdin import stdin_file, stdin_roots

    copy = stdin_file(stdin_filename, stdin or b"")
    return Subject((copy,), tuple(stdin_roots(stdin_filename)), stdin_filename or Path.cwd(),
                   {str(copy): str(stdin_filename) if stdin_filename else "-"})


@dataclass(frozen=True)
class Conclusion:
    """How a run's outcome becomes its findings and exit code."""

    selection: Selection
    fix: FixMode | None = None
    quiet: bool = False
    """Only errors are shown."""
    exit_zero: bool = False


@dataclass
class Concluded:
    """What the command prints, and its exit code."""

    shown: list[Diagnostic]
    """The findings to print (none are printed for ``--diff``: ``findings`` is False)."""
    findings: bool = True
    messages: list[str] = field(default_factory=list)
    """Lines for stderr, in order: the outcome's notes, refused fixes, what was fixed."""
    diffs: list[str] = field(default_factory=list)
    summary: str | None = None
    exit_code: int = EXIT_OK


def conclude(outcome: CheckOutcome, of: Subject, how: Conclusion) -> Concluded:
    """Select, show, fix and judge the findings of ``outcome``."""
    done = Concluded([], messages=list(outcome.notes))
    seen = {path: of.shown_as.get(path) or shown_path(path)  # as cwd sees it, once a file
            for path in {d.path for d in outcome.diagnostics}}
    found = [replace(d, path=seen.get(d.path) or shown_path(d.path))
             for d in apply(outcome.diagnostics, outcome.sources, how.selection)]
    if how.fix is not None:
        from .fixes import apply_fixes

        writes = how.fix == "fix"
        fixes = apply_fixes(found, of.paths, write=writes)
        done.diffs = fixes.diffs
        done.messages += fixes.refused
        if fixes.fixed or writes:
            done.messages.append(f"{'fixed' if writes else 'would fix'} "
                                 f"{counted(fixes.fixed, 'finding')} in "
                                 f"{counted(fixes.files, 'file')}")
        found = fixes.remaining
        if not writes:
            done.exit_code = EXIT_ATTENTION if fixes.fixed else EXIT_OK
            done.findings = False  # a diff says it all: no findings, no summary
            return done
    errors = sum(1 for d in found if d.severity == "error")
    done.shown = [d for d in found if d.severity == "error"] if how.quiet else found
    if not how.quiet:
        done.summary = (f"{counted(outcome.files, 'file')} checked, "
                        f"{counted(outcome.skills, 'skill')}, {counted(errors, 'error')}, "
                        f"{counted(len(found) - errors, 'other finding')}")
    done.exit_code = EXIT_OK if how.exit_zero or not errors else EXIT_ATTENTION
    return done
