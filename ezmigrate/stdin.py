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

from .diffs import unified_diff
from .migrate import Settings, migrate
from .results import FileResult


def rewrite_stdin(index: Any, ontology: tuple[str, ...], *, verify: bool, check: bool,
                  dry_run: bool, timeout: float) -> int:
    """Exit code as for files; stdout gets the (possibly unchanged) source or a diff."""
    data = sys.stdin.buffer.read()
    result = migrate(data, Settings(index=index), "-")
    if result.error:
        print(f"-: {result.error}", file=sys.stderr)
    new = result.new_source if isinstance(result.new_source, bytes) else None
    if new is not None and verify:
        new = _verified(data, result, ontology, timeout)
    if dry_run or check:
        if new is not None and dry_run:
            sys.stdout.write(unified_diff("-", data, new))
        return 1 if new is not None and check else 0 if result.error is None else 1
    sys.stdout.buffer.write(new if new is not None else data)
    skipped = any(s.status in ("skipped", "failed") for s in result.skills)
    return 1 if result.error or skipped or (new is None and result.changed) else 0


def _verified(data: bytes, result: FileResult, ontology: tuple[str, ...],
              timeout: float) -> bytes | None:
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
                                 PoolConfig(workers=2, timeout=timeout, ontology=ontology))
    item = Migrated(Candidate(path, path.parent), data, digest(data), result)
    apply_verdicts(item, before, after, RewriteOptions(paths=[], timeout=timeout))
    if item.result.new_source is None:
        why = next((f"{s.name}: {(s.reason or '').splitlines()[0]}" for s in result.skills
                    if s.status == "failed"), "no description class was loaded")
        print(f"-: not rewritten: the migrated version could not be verified equivalent "
              f"({why})", file=sys.stderr)
        return None
    new = item.result.new_source
    return new if isinstance(new, bytes) else None
