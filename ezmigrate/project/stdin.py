"""``ezmigrate rewrite -``: one file from stdin to stdout, for editors and pre-commit hooks.

Whatever happens, stdout gets a whole file: the migrated source, or the input unchanged
(an editor replacing its buffer with our output must never lose a line). Problems go to
stderr on one line each; user code runs only when verifying, in isolated children.

Its settings are those every command resolves (``cli.options.Options.resolve``): the CLI
passes the pool they make and the project's ``target-version``, so the project's
``[tool.ezmigrate]`` (``timeout``, ``python``, ``jobs``) holds here exactly as for ``rewrite
PATH``; ``--ignore-order`` and ``--ignore-labels`` do too. The CLI reads stdin and prints;
nothing here touches the process's streams.
"""

from __future__ import annotations

import atexit
import shutil
import tempfile
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ezskiros_runtime.ontology.discovery import enclosing_project

from ..report.results import FileResult

if TYPE_CHECKING:
    from ..verify.pool import PoolConfig
    from ..verify.verdicts import Comparison

NAME = "stdin_module.py"
"""What the one file of the project is called on disk while it is migrated and loaded."""


def stdin_file(filename: Path | None, data: bytes) -> Path:
    """Stdin's bytes in a private folder (removed when the process ends), named as the file
    it stands for (``check -``: findings are then mapped back to that name)."""
    folder = Path(tempfile.mkdtemp(prefix="ezmigrate-stdin-"))
    atexit.register(shutil.rmtree, folder, True)
    path = folder / (filename.name if filename is not None else NAME)
    path.write_bytes(data)
    return path


def stdin_roots(filename: Path | None) -> list[Path]:
    """Where ontology discovery may look for stdin's project: the folder of
    ``--stdin-filename``; else the working directory, but only inside a git checkout or a
    ROS package. An editor started in a home folder must not have every ``owl/`` folder
    below it loaded (another project's broken file once aborted such a run)."""
    if filename is not None:
        return [filename.parent if filename.parent.is_dir() else Path.cwd()]
    cwd = Path.cwd()
    return [cwd] if enclosing_project(cwd) is not None else []


def rewrite_stdin(data: bytes, index: Any, pool: PoolConfig,
                  target_version: tuple[int, int] | None, verification: Comparison | None,
                  filename: Path | None = None) -> FileResult:
    """The result of stdin's bytes; ``new_source`` is set only when it verified (or
    verification is off: ``verification`` None, else how strictly the two versions must
    agree). The command line prints and exits exactly as for a file.

    Stdin is a project of one file: written to a private folder, it is settled like any
    repository (``project.settle``: migrated, verified, classes that fail held back and
    the rest migrated again), so its verdicts follow the same rules as ``rewrite PATH``.
    Two loads (before and after) never need more than two workers; ``jobs`` can only lower
    that (a project that says ``jobs = 1`` has its reasons, memory most often).
    """
    from ..files.discover import Candidate
    from .settle import Checks, Settling, settle
    from .target import robot_python, target_for

    robot = target_for([filename or Path.cwd()], target_version)
    pool = replace(pool, workers=min(2, pool.workers),
                   python=robot_python(robot, pool.python if pool.python_given else None,
                                       verification is not None))
    checks = None if verification is None else Checks(pool, verification)
    with tempfile.TemporaryDirectory(prefix="ezmigrate-stdin-") as folder:
        path = Path(folder) / NAME
        path.write_bytes(data)
        [item] = settle([Candidate(path, path.parent)], index, 1,
                        Settling(checks, robot.version, refuse_unloadable=True))
    return replace(item.result, path=str(filename) if filename else "-")
