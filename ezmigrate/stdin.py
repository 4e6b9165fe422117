"""``ezmigrate rewrite -``: one file from stdin to stdout, for editors and pre-commit hooks.

Whatever happens, stdout gets a whole file: the migrated source, or the input unchanged
(an editor replacing its buffer with our output must never lose a line). Problems go to
stderr on one line each; user code runs only when verifying, in isolated children.
"""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path
from typing import Any

from .migrate import Settings, migrate
from .results import FileResult


def rewrite_stdin(index: Any, ontology: tuple[str, ...], *, verify: bool,
                  timeout: float, python: str | None = None) -> tuple[bytes, FileResult]:
    """Stdin's bytes and their result; ``new_source`` is set only when it verified (or
    verification is off). The command line prints and exits exactly as for a file."""
    data = sys.stdin.buffer.read()
    result = migrate(data, Settings(index=index), "-")
    if isinstance(result.new_source, bytes) and verify:
        result.new_source = _verified(data, result, ontology, timeout, python)
    return data, result


def _verified(data: bytes, result: FileResult, ontology: tuple[str, ...],
              timeout: float, python: str | None) -> bytes | None:
    """The migrated bytes if they verify, by the same rules as ``rewrite``; else ``None``."""
    from .discover import Candidate
    from .runner import Migrated
    from .session import RewriteOptions
    from .verify.pool import PoolConfig, job_for, run_jobs
    from .verify.rewrite import apply_verdicts
    from .writing import digest

    assert isinstance(result.new_source, bytes)
    with tempfile.TemporaryDirectory(prefix="ezmigrate-stdin-") as folder:
        path = Path(folder) / "stdin_module.py"
        path.write_bytes(data)
        before, after = run_jobs([job_for(path, data), job_for(path, result.new_source)],
                                 PoolConfig(workers=2, timeout=timeout, ontology=ontology,
                                            python=python))
    item = Migrated(Candidate(path, path.parent), data, digest(data), result)
    apply_verdicts(item, before, after, RewriteOptions(paths=[], timeout=timeout))
    new = item.result.new_source
    return new if isinstance(new, bytes) else None
