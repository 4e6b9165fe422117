"""``ezmigrate rewrite -``: one file from stdin to stdout, for editors and pre-commit hooks.

Whatever happens, stdout gets a whole file: the migrated source, or the input unchanged
(an editor replacing its buffer with our output must never lose a line). Problems go to
stderr on one line each; user code runs only when verifying, in isolated children.

Its settings are the ``Options`` every command resolves (``options.Options.resolve``), so
the project's ``[tool.ezmigrate]`` (``timeout``, ``python``, ``jobs``) holds here exactly
as for ``rewrite PATH``; ``--ignore-order`` and ``--ignore-labels`` do too.
"""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .migrate import Settings, migrate
from .results import FileResult

if TYPE_CHECKING:
    from .options import Options
    from .session import RewriteOptions


def rewrite_stdin(index: Any, ontology: tuple[str, ...], options: Options, *, verify: bool,
                  ignore_order: bool = False,
                  ignore_labels: bool = False) -> tuple[bytes, FileResult]:
    """Stdin's bytes and their result; ``new_source`` is set only when it verified (or
    verification is off). The command line prints and exits exactly as for a file."""
    data = sys.stdin.buffer.read()
    result = migrate(data, Settings(index=index), "-")
    if isinstance(result.new_source, bytes) and verify:
        result.new_source = _verified(data, result, _request(options, ontology, ignore_order,
                                                             ignore_labels))
    return data, result


def _request(options: Options, ontology: tuple[str, ...], ignore_order: bool,
             ignore_labels: bool) -> RewriteOptions:
    """What ``rewrite PATH`` would be asked for this one file: same settings, same checks.

    Two loads (before and after) never need more than two workers; ``jobs`` can only lower
    that (a project that says ``jobs = 1`` has its reasons, memory most often)."""
    from .session import RewriteOptions

    return RewriteOptions(paths=[], jobs=min(2, options.jobs), timeout=options.timeout,
                          python=options.python, ontology=ontology,
                          ignore_order=ignore_order, ignore_labels=ignore_labels)


def _verified(data: bytes, result: FileResult, request: RewriteOptions) -> bytes | None:
    """The migrated bytes if they verify, by the same rules as ``rewrite``; else ``None``."""
    from .discover import Candidate
    from .runner import Migrated
    from .verify.pool import PoolConfig, job_for, run_jobs
    from .verify.rewrite import apply_verdicts
    from .writing import digest

    assert isinstance(result.new_source, bytes)
    with tempfile.TemporaryDirectory(prefix="ezmigrate-stdin-") as folder:
        path = Path(folder) / "stdin_module.py"
        path.write_bytes(data)
        before, after = run_jobs([job_for(path, data), job_for(path, result.new_source)],
                                 PoolConfig(workers=request.jobs, timeout=request.timeout,
                                            ontology=request.ontology, python=request.python))
    item = Migrated(Candidate(path, path.parent), data, digest(data), result)
    apply_verdicts(item, before, after, request)
    new = item.result.new_source
    return new if isinstance(new, bytes) else None
