"""``ezmigrate verify BEFORE AFTER``: prove two versions of files or folders equivalent."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from ..files.discover import discover
from ..files.prefilter import may_hold_descriptions
from ..report.results import FileResult, SkillResult, SkillStatus
from .compare_files import class_sources, compare_outcomes, load_failure
from .pool import BATCH, PoolConfig, job_for, run_batched
from .protocol import LoadJob, LoadOutcome
from .verdicts import capture, loaded_with, note_stand_ins, rejections, with_findings


@dataclass(frozen=True)
class VerifyOptions:
    """What ``verify`` compares and how strictly."""

    before: Path
    after: Path
    pool: PoolConfig
    ignore_order: bool = False
    ignore_labels: bool = False
    exclude: tuple[str, ...] = ()


class PathsMismatch(ValueError):
    """BEFORE and AFTER cannot be paired: a file against a folder without that file."""


def _sides(options: VerifyOptions) -> tuple[Path, Path]:
    """The two paths to compare. A file against a folder means the file of that name in
    the folder (``verify old/skill.py new/``), as ``diff`` and ``cp`` read it."""
    before, after = options.before, options.after
    if before.is_dir() == after.is_dir():
        return before, after
    file, folder = (after, before) if before.is_dir() else (before, after)
    inside = folder / file.name
    if not inside.is_file():
        raise PathsMismatch(f"cannot compare the file {file} with the folder {folder}: "
                            f"{inside} does not exist (give two files or two folders)")
    return (inside, after) if before.is_dir() else (before, inside)


def _pairs(before: Path, after: Path,
           exclude: tuple[str, ...]) -> list[tuple[str, Path | None, Path | None]]:
    if not before.is_dir():
        return [(after.name, before, after)]
    old, _ = discover([before], exclude)
    new, _ = discover([after], exclude)
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


def _read(path: Path) -> bytes | None:
    """The file's bytes, or None when it cannot be read (its load already said why)."""
    try:
        return path.read_bytes()
    except OSError:
        return None


def run_verify(options: VerifyOptions) -> tuple[list[FileResult], bool]:
    """Per-file results, and whether some file could not be loaded at all.

    Raises ``PathsMismatch`` when a file is given against a folder that lacks it.
    """
    before_path, after_path = _sides(options)
    roots = (before_path, after_path) if before_path.is_dir() else (None, None)
    pairs = _pairs(before_path, after_path, options.exclude)
    skipped = {index for index, (_, old, new) in enumerate(pairs)
               if _nothing_to_compare(old, new)}
    jobs: list[LoadJob] = []
    slots: list[int] = []
    for index, (_, old, new) in enumerate(pairs):
        for path, root in ((old, roots[0]), (new, roots[1])):
            if index in skipped or path is None:
                slots.append(-1)
            else:
                slots.append(len(jobs))
                jobs.append(job_for(path, None, root))
    outcomes = run_batched(jobs, options.pool, BATCH, alone=lambda outcome: not outcome.loaded)
    results: list[FileResult] = []
    unloadable = False
    for index, (relative, old, new) in enumerate(pairs):
        if index in skipped:
            results.append(FileResult(relative))
        elif old is None or new is None:
            error = "missing after migration" if new is None else "only in the new tree"
            results.append(FileResult(relative, error=error, skills=[
                SkillResult("*", 0, "failed", error, equivalent=False)]))
        else:
            result, failed = _pair(relative, _read(old), _read(new),
                                   outcomes[slots[2 * index]], outcomes[slots[2 * index + 1]],
                                   options)
            results.append(result)
            unloadable = unloadable or failed
    return results, unloadable


def _pair(relative: str, old_bytes: bytes | None, new_bytes: bytes | None,
          before: LoadOutcome, after: LoadOutcome,
          options: VerifyOptions) -> tuple[FileResult, bool]:
    """The result of one file present in both trees, and whether a version of it could
    not be loaded (or read again) at all."""
    notes: list[str] = []
    if not before.loaded or not after.loaded:
        capture(notes, before, after)
        if old_bytes is not None and old_bytes == new_bytes:  # not migrated: a note
            note = "unchanged, not loadable: " + load_failure("unchanged", before)
            return FileResult(relative, notes=[note, *notes]), False
        side, outcome = ("legacy", before) if not before.loaded else ("migrated", after)
        return FileResult(relative, error=load_failure(side, outcome),
                          error_line=outcome.line, notes=notes), True
    if old_bytes is None or new_bytes is None:  # vanished since it was loaded
        return FileResult(relative, error="could not be read again after loading: nothing "
                          "was compared"), True
    note_stand_ins(notes, before, after)
    skills = _compare(old_bytes, new_bytes, before, after, options)
    return FileResult(relative, skills=with_findings(skills, after, skip=frozenset()),
                      notes=notes, python=loaded_with(before, after)), False


def _compare(old_bytes: bytes, new_bytes: bytes, before: LoadOutcome, after: LoadOutcome,
             options: VerifyOptions) -> list[SkillResult]:
    """One result per class of a file that loaded in both versions.

    A class equivalent to its legacy original that the EzSkiROS runtime would refuse to
    load (an error-level finding) fails: the legacy one loaded in SkiROS2, the migrated one
    will not load on the robot. When the runtime refuses both versions the same way (the
    same EzSkiROS file on both sides), nothing was broken by migrating: a finding only.
    """
    sources: list[tuple[dict[str, str], dict[str, str]]] = []  # read when first needed
    skills = []
    for verdict in compare_outcomes(before, after, ignore_order=options.ignore_order,
                                    ignore_labels=options.ignore_labels):
        status: SkillStatus = ("unchanged" if old_bytes == new_bytes else "converted") \
            if verdict.equivalent else "failed"
        reason = None if verdict.equivalent else verdict.message
        rejected = rejections(verdict.name, after) \
            if verdict.equivalent and not rejections(verdict.name, before) else []
        if rejected:  # means the same, yet will not load
            status, reason = "failed", ("EzSkiROS rejects the migrated class when it "
                                        "loads: " + "; ".join(rejected))
        if verdict.verdict == "unverified":  # loads in neither version: nothing to compare
            if not sources:  # rare: parse the two versions only now
                sources.append((class_sources(old_bytes), class_sources(new_bytes)))
            old_classes, new_classes = sources[0]
            same = old_classes.get(verdict.name) == new_classes.get(verdict.name) is not None
            status = "unchanged" if same else "failed"
            reason = (f"{verdict.message} (its source is unchanged)" if same
                      else f"not verified: {verdict.message}")
        skills.append(SkillResult(
            verdict.name, verdict.line_after or verdict.line_before or 0, status, reason,
            equivalent=None if verdict.verdict == "unverified" or rejected
            else verdict.equivalent,
            diff=verdict.diff or None))
    return skills
