"""The click options more than one command takes, each defined once: the same flag must
mean and say the same in ``rewrite``, ``verify``, ``check``, ``server`` and ``scene``."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import click

ONTOLOGY = click.option("--ontology", multiple=True,
                        type=click.Path(path_type=Path, exists=True),
                        help="Ontology file or folder (repeatable).")
JOBS = click.option("--jobs", "-j", type=click.IntRange(min=1), help="Parallel workers.")
TIMEOUT = click.option("--timeout", type=click.FloatRange(min=0.1),
                       help="Seconds per file when loading code (default 20).")
PYTHON = click.option("--python", "python", metavar="PATH",
                      help="Load files with this interpreter when verifying (default: this "
                           "one, and for syntax newer than it the oldest newer python3.X "
                           "that compiles it, from PATH's absolute entries outside the "
                           "checked paths, else from pyenv's versions).")
EXCLUDE = click.option("--exclude", multiple=True, metavar="GLOB",
                       help="Skip matching paths.")
INCLUDE_VENDORED = click.option(
    "--include-vendored", is_flag=True,
    help="Also go into vendored copies of SkiROS2's own packages (skiros2_common, "
         "skiros2_std_skills, ...), which are skipped with a note by default.")
STDIN_FILENAME = click.option(
    "--stdin-filename", type=click.Path(path_type=Path, dir_okay=False),
    help="With PATH '-': the file stdin stands for (as ruff's flag): its project's "
         "configuration, ontology and robot apply, and the output names it.")
IGNORE_ORDER = click.option("--ignore-order", is_flag=True,
                            help="Verification ignores declaration order.")
IGNORE_LABELS = click.option("--ignore-labels", is_flag=True,
                             help="Verification ignores condition labels.")
DEBUG = click.option("--debug", is_flag=True, help="Show tracebacks of internal errors.")


def report_option(check_path: Callable[[Path | None], Path | None]) -> Any:
    """``--report``, its name checked by ``check_path`` (Markdown or JSON)."""
    return click.option("--report", type=click.Path(path_type=Path, dir_okay=False,
                                                    allow_dash=True),
                        callback=lambda _ctx, _param, value: check_path(value),
                        help="Write a report: Markdown for .md, JSON for .json (- for JSON "
                             "on stdout).")
