"""The verdicts of verification on one migrated file: which skills are proven, which fail.

Both versions of a changed file are loaded in isolated children (``pool``); this module
reads the two outcomes into the file's result: a converted skill whose model differs, or
that does not load, fails with the difference; if anything in a file fails, the file keeps
its old content and its other converted skills are reported as not written. Which classes
to hold back and migrate again is the project's decision (``ezmigrate.project``).
"""

from __future__ import annotations

from dataclasses import dataclass

from ezskiros_runtime.diagnostics import Finding
from ezskiros_runtime.dsl.policy import severity_of

from ..results import FileResult, ReviewFinding, SkillResult
from .compare_files import ClassVerdict, compare_outcomes, load_failure
from .protocol import LoadOutcome


@dataclass(frozen=True)
class Comparison:
    """How strictly two models must agree (``--ignore-order``, ``--ignore-labels``)."""

    ignore_order: bool = False
    ignore_labels: bool = False


def apply_verdicts(result: FileResult, before: LoadOutcome, after: LoadOutcome,
                   comparison: Comparison) -> dict[str, SkillResult]:
    """Mark skills from the two loads; drop the new content unless everything verified.

    Returns the converted classes that did not verify when others in the file did: held
    as they were, the file can be migrated again without them.
    """
    converted = [s for s in result.skills if s.status == "converted"]
    if not before.loaded or not after.loaded:
        side, outcome = ("legacy", before) if not before.loaded else ("migrated", after)
        for skill in converted:
            fail(skill, load_failure(side, outcome))
        capture(result.notes, before, after)
        result.new_source = None
        return {}
    note_stand_ins(result.notes, before, after)
    verdicts = {v.name: v for v in compare_outcomes(
        before, after, ignore_order=comparison.ignore_order,
        ignore_labels=comparison.ignore_labels)}
    by_name = {s.name: s for s in result.skills}
    all_ok = True
    for name, verdict in verdicts.items():
        found = by_name.get(name)
        if verdict.equivalent:
            if found is not None and found.status == "converted":
                found.equivalent = True
            continue
        if verdict.verdict == "unverified" and (found is None or found.status != "converted"):
            continue  # left as it was, and it fails to load as it did before
        all_ok = False
        skill = found if found is not None else SkillResult(name, verdict.line_before or 0,
                                                            "failed")
        if found is None:
            result.skills.append(skill)
        fail(skill, _reason(verdict), verdict)
    for skill in converted:  # converted, yet no class of that name was seen when loading
        if skill.name not in verdicts:
            all_ok = False
            fail(skill, "not verified: the class was not found when loading the file "
                  "(is it defined conditionally?)")
    attach_findings(result.skills, after)
    for skill in converted:
        if skill.status == "converted" and _refuse_rejected(skill, after):
            all_ok = False
    if all_ok:
        return {}
    culprits = {s.name: s for s in converted if s.status != "converted"}
    verified = [s for s in converted if s.status == "converted"]
    for skill in verified:
        skill.status = "skipped"
        skill.reason = "verified, but not written: another class in this file failed"
    result.new_source = None
    return culprits if verified else {}


STATIC_KINDS = frozenset({"unknown-vocabulary", "undeclared-parameter"})
"""Runtime finding kinds the static pass already reports (once per term or key)."""


def fail(skill: SkillResult, reason: str, verdict: ClassVerdict | None = None) -> None:
    skill.status = "failed"
    skill.reason = reason
    skill.equivalent = False if verdict is not None and verdict.verdict == "different" else None
    if verdict is not None and verdict.diff:
        skill.diff = verdict.diff


def _reason(verdict: ClassVerdict) -> str:
    if verdict.verdict == "different":
        first = verdict.diff[0]
        return f"not equivalent after migration ({verdict.message}): {first['where']}: " \
               f"{first['message']}"
    return verdict.message


def rejects(finding: Finding) -> bool:
    """Whether the EzSkiROS runtime refuses to load a skill with this finding.

    The child loads modules under ``collecting()``, which records findings instead of
    raising; the runtime stamps each with ``severity_of(kind)`` in that child, under the
    same policy (and ``EZSKIROS_STRICT``) the robot applies. A finding without a severity
    is judged here by the same policy, never by a list of kinds of our own.
    """
    return (finding.severity or severity_of(finding.kind)) == "error"


def rejections(skill: str, outcome: LoadOutcome, line: str = "line {}") -> list[str]:
    """The error-level findings of ``skill`` in a load, each with its line, once each.

    On the robot these findings make the runtime raise ``SkillTypeError``: the skill does
    not load at all. ``line`` words the line number (whose file it is depends on the caller).
    """
    return list(dict.fromkeys(
        found.message + (f" ({line.format(found.line)})" if found.line else "")
        for found in outcome.findings if found.skill == skill and rejects(found)))


def _refuse_rejected(skill: SkillResult, after: LoadOutcome) -> bool:
    """Skip a skill the EzSkiROS runtime would refuse to load, whatever it means.

    Its lines are those of the migrated version, which is not written: the legacy class it
    stays as is the one that gives the same finding once migrated.
    """
    found = rejections(skill.name, after, "line {} once migrated")
    if not found:
        return False
    skill.status = "skipped"
    skill.equivalent = None
    skill.reason = ("EzSkiROS rejects this skill when it loads: " + "; ".join(found) + ". "
                    "The legacy code has the same problem (SkiROS2 accepted it silently); "
                    "fix the description or the ontology, then migrate")
    return True


def attach_findings(skills: list[SkillResult], after: LoadOutcome,
                     skip: frozenset[str] = STATIC_KINDS) -> None:
    """Runtime check findings (domain/range, datatypes...) of the migrated skills.

    ``skip``: kinds reported elsewhere. ``rewrite``'s static pass already reports
    ``STATIC_KINDS`` once per term; ``verify`` has no static pass and keeps them all.
    """
    by_name = {s.name: s for s in skills}
    for found in after.findings:
        skill = by_name.get(found.skill)
        kind = found.kind.replace("_", "-")
        if skill is None or kind in skip:
            continue
        if not any(f.message == found.message for f in skill.findings):
            skill.findings.append(ReviewFinding(kind, found.line or 0, found.message))


def note_stand_ins(notes: list[str], before: LoadOutcome, after: LoadOutcome) -> None:
    """Say which interpreter loaded the file when it was not ours, and which imports could
    not be resolved and were stood in (on both sides alike, so the comparison still holds;
    a value taken from one would be a stand-in's)."""
    for python in dict.fromkeys(o.python for o in (before, after) if o.python):
        notes.append(f"verified under {python}")
    names = sorted(set(before.stood_in) | set(after.stood_in))
    if names:
        notes.append("stood in (not found when loading; the same permissive stand-in on both "
                     "sides): " + ", ".join(names))


def capture(notes: list[str], before: LoadOutcome, after: LoadOutcome) -> None:
    """What the two versions printed while loading, for the report (the end, when long).

    Called when a version failed to load: its traceback or the module's own complaints are
    often the only explanation. Each side is named, as both are loaded.
    """
    for side, outcome in (("legacy", before), ("migrated", after)):
        for stream, text in (("stdout", outcome.stdout), ("stderr", outcome.stderr)):
            if text.strip():
                notes.append(f"{stream} of the {side} version while loading:\n"
                             + text.strip()[-2000:])
