"""``ezmigrate rewrite -``: one file from stdin to stdout, for editors and pre-commit hooks.

Whatever happens, stdout gets a whole file: the migrated source, or the input unchanged
(an editor replacing its buffer with our output must never lose a line). Problems go to
stderr on one line each; user code runs only when verifying, in isolated children.
"""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .diffs import unified_diff
from .migrate import Settings, migrate

if TYPE_CHECKING:
    from .verify.compare_files import ClassVerdict
    from .verify.protocol import LoadOutcome


def rewrite_stdin(index: Any, ontology: tuple[str, ...], *, verify: bool, check: bool,
                  dry_run: bool, timeout: float) -> int:
    """Exit code as for files; stdout gets the (possibly unchanged) source or a diff."""
    data = sys.stdin.buffer.read()
    result = migrate(data, Settings(index=index), "-")
    if result.error:
        print(f"-: {result.error}", file=sys.stderr)
    new = result.new_source if isinstance(result.new_source, bytes) else None
    if new is not None and verify:
        from .verify.compare_files import compare_outcomes
        from .verify.pool import PoolConfig, job_for, run_jobs

        with tempfile.TemporaryDirectory(prefix="ezmigrate-stdin-") as folder:
            path = Path(folder) / "stdin_module.py"
            path.write_bytes(data)
            before, after = run_jobs([job_for(path, data), job_for(path, new)],
                                     PoolConfig(workers=2, timeout=timeout, ontology=ontology))
        verdicts = compare_outcomes(before, after) if before.loaded and after.loaded else []
        if not verdicts or not all(v.equivalent for v in verdicts):
            why = _why_unverified(before, after, verdicts)
            print(f"-: not rewritten: the migrated version could not be verified equivalent "
                  f"({why})", file=sys.stderr)
            new = None
    if dry_run or check:
        if new is not None and dry_run:
            sys.stdout.write(unified_diff("-", data, new))
        return 1 if new is not None and check else 0 if result.error is None else 1
    sys.stdout.buffer.write(new if new is not None else data)
    skipped = any(s.status in ("skipped", "failed") for s in result.skills)
    return 1 if result.error or skipped or (new is None and result.changed) else 0


def _why_unverified(before: LoadOutcome, after: LoadOutcome,
                    verdicts: list[ClassVerdict]) -> str:
    """One line: which version did not load, or which class differs."""
    for side, outcome in (("the legacy version", before), ("the migrated version", after)):
        if not outcome.loaded:
            first = (outcome.message.splitlines() or [outcome.status])[0]
            return f"{side} could not be loaded: {first}"
    for verdict in verdicts:
        if not verdict.equivalent:
            return f"{verdict.name}: {verdict.message}"
    return "no description class was loaded"
