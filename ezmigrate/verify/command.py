"""``ezmigrate verify BEFORE AFTER``: prove two versions of files or folders equivalent."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from ..discover import discover
from ..prefilter import may_hold_descriptions
from ..results import FileResult, SkillResult, SkillStatus
from .compare_files import class_sources, compare_outcomes, load_failure
from .pool import PoolConfig, job_for, run_jobs
from .protocol import LoadJob
from .rewrite import rejections


@dataclass(frozen=True)
class VerifyOptions:
    """What ``verify`` compares and how strictly."""

    before: Path
    after: Path
    pool: PoolConfig
    ignore_order: bool = False
    ignore_labels: bool = False
    exclude: tuple[str, ...] = ()


def _pairs(options: VerifyOptions) -> list[tuple[str, Path | None, Path | None]]:
    if options.before.is_file() or options.after.is_file():
        return [(options.after.name, options.before, options.after)]
    old, _ = discover([options.before], options.exclude)
    new, _ = discover([options.after], options.exclude)
    old_map = {c.relative: c.path for c in old}
    new_map = {c.relative: c.path for c in new}
    return [(rel, old_map.get(rel), new_map.get(rel))
            for rel in sorted(set(old_map) | set(new_map))]


def _nothing_to_compare(old: Path | None, new: Path | None) -> bool:
    """Both versions are the same bytes and neither can hold a description of its own.

    Such a pair is the bulk of a monorepo and is never imported. The one class it could
    still hold is a subclass of a description from another file that adds nothing (no
    ``createDescription``, no ``SkillDescription``): its parameters and conditions are its
    base's, which are compared where the base is defined. ``rewrite`` draws the same line
    (``prefilter.py``) when it decides which files hold descriptions.
    """
    if old is None or new is None:
        return False
    try:
        data = old.read_bytes()
        return data == new.read_bytes() and not may_hold_descriptions(data)
    except OSError:
        return False  # the load reports why the file cannot be read


def run_verify(options: VerifyOptions) -> tuple[list[FileResult], bool]:
    """Per-file results, and whether some file could not be loaded at all."""
    pairs = _pairs(options)
    skipped = {index for index, (_, old, new) in enumerate(pairs)
               if _nothing_to_compare(old, new)}
    jobs: list[LoadJob] = []
    slots: list[int] = []
    for index, (_, old, new) in enumerate(pairs):
        for path, root in ((old, options.before), (new, options.after)):
            if index in skipped:
                slots.append(-1)
            elif path is not None:
                slots.append(len(jobs))
                jobs.append(job_for(path, None, root if root.is_dir() else None))
            else:
                slots.append(-1)
    outcomes = run_jobs(jobs, options.pool)
    results: list[FileResult] = []
    unloadable = False
    for index, (relative, old, new) in enumerate(pairs):
        result = FileResult(path=relative)
        results.append(result)
        if index in skipped:
            continue
        if old is None or new is None:
            result.error = "missing after migration" if new is None else "only in the new tree"
            result.skills.append(SkillResult("*", 0, "failed", result.error, equivalent=False))
            continue
        before = outcomes[slots[2 * index]]
        after = outcomes[slots[2 * index + 1]]
        if not before.loaded or not after.loaded:
            unloadable = True
            side, outcome = ("legacy", before) if not before.loaded else ("migrated", after)
            result.error = load_failure(side, outcome)
            result.error_line = outcome.line
            continue
        old_bytes, new_bytes = old.read_bytes(), new.read_bytes()
        old_classes, new_classes = class_sources(old_bytes), class_sources(new_bytes)
        for verdict in compare_outcomes(before, after, ignore_order=options.ignore_order,
                                        ignore_labels=options.ignore_labels):
            status: SkillStatus = ("unchanged" if old_bytes == new_bytes else "converted") \
                if verdict.equivalent else "failed"
            reason = None if verdict.equivalent else verdict.message
            rejected = rejections(verdict.name, after) if verdict.equivalent else []
            if rejected and old_bytes != new_bytes:  # means the same, yet will not load
                status, reason = "failed", ("EzSkiROS rejects the migrated class when it "
                                            "loads: " + "; ".join(rejected))
            if verdict.verdict == "unverified":  # loads in neither version: nothing to compare
                same = old_classes.get(verdict.name) == new_classes.get(verdict.name) is not None
                status = "unchanged" if same else "failed"
                reason = (f"{verdict.message} (its source is unchanged)" if same
                          else f"not verified: {verdict.message}")
            results[-1].skills.append(SkillResult(
                verdict.name, verdict.line_after or verdict.line_before or 0, status, reason,
                equivalent=None if verdict.verdict == "unverified" or rejected
                else verdict.equivalent,
                diff=verdict.diff or None))
    return results, unloadable
