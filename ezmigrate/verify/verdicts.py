"""The verdicts of verification on one migrated file: which skills are proven, which fail.

Both versions of a changed file are loaded in isolated children (``pool``); this module
reads the two outcomes into the file's result: a converted skill whose model differs, or
that does not load, fails with the difference; if anything in a file fails, the file keeps
its old content and its other converted skills are reported as not written. Which classes
to hold back and migrate again is the project's decision (``ezmigrate.project.settle``).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from ezskiros_runtime.diagnostics import Finding
from ezskiros_runtime.dsl.policy import severity_of

from ..report.results import FileResult, SkillResult
from .compare_files import ClassVerdict, compare_outcomes, load_failure
from .protocol import LoadOutcome


@dataclass(frozen=True)
class Comparison:
    """How strictly two models must agree (``--ignore-order``, ``--ignore-labels``)."""

    ignore_order: bool = False
    ignore_labels: bool = False


def apply_verdicts(result: FileResult, before: LoadOutcome, after: LoadOutcome,
                   comparison: Comparison) -> tuple[FileResult, dict[str, SkillResult]]:
    """The file's result once its two loads are judged: skills marked, the new content
    dropped unless everything verified.

    Also returns the converted classes that did not verify when others in the file did:
    held as they were, the file can be migrated again without them.
    """
    skills = {s.name: s for s in result.skills}  # in the file's order; failures join last
    converted = [s.name for s in result.skills if s.status == "converted"]
    notes = list(result.notes)
    if not before.loaded or not after.loaded:
        side, outcome = ("legacy", before) if not before.loaded else ("migrated", after)
        for name in converted:
            skills[name] = failed(skills[name], load_failure(side, outcome))
        capture(notes, before, after)
        return replace(result, skills=list(skills.values()), notes=notes, new_source=None), {}
    note_stand_ins(notes, before, after)
    result = replace(result, python=loaded_with(before, after))
    verdicts = {v.name: v for v in compare_outcomes(
        before, after, ignore_order=comparison.ignore_order,
        ignore_labels=comparison.ignore_labels)}
    all_ok = True
    for name, verdict in verdicts.items():
        found = skills.get(name)
        if verdict.equivalent:
            if found is not None and found.status == "converted":
                skills[name] = replace(found, equivalent=True)
            continue
        if verdict.verdict == "unverified" and (found is None or found.status != "converted"):
            continue  # left as it was, and it fails to load as it did before
        all_ok = False
        skills[name] = failed(found or SkillResult(name, verdict.line_before or 0, "failed"),
                              _reason(verdict), verdict)
    for name in converted:  # converted, yet no class of that name was seen when loading
        if name not in verdicts:
            all_ok = False
            skills[name] = failed(skills[name], "not verified: the class was not found when "
                                  "loading the file (is it defined conditionally?)")
    skills = {s.name: s for s in with_findings(list(skills.values()), after)}
    for name in converted:
        refused = _rejected(skills[name], after) if skills[name].status == "converted" \
            else None
        if refused is not None:
            all_ok = False
            skills[name] = refused
    if all_ok:
        return replace(result, skills=list(skills.values()), notes=notes), {}
    culprits = {n: skills[n] for n in converted if skills[n].status != "converted"}
    verified = [n for n in converted if skills[n].status == "converted"]
    for name in verified:
        skills[name] = replace(skills[name], status="skipped", reason="verified, but not "
                               "written: another class in this file failed")
    return (replace(result, skills=list(skills.values()), notes=notes, new_source=None),
            culprits if verified else {})


STATIC_KINDS = frozenset({"unknown-vocabulary", "undeclared-parameter"})
"""Runtime finding kinds the static pass already reports (once per term or key)."""


def failed(skill: SkillResult, reason: str, verdict: ClassVerdict | None = None) -> SkillResult:
    """``skill`` failed for ``reason`` (with the verdict's difference, when it has one)."""
    return replace(skill, status="failed", reason=reason,
                   equivalent=False if verdict is not None and verdict.verdict == "different"
                   else None,
                   diff=verdict.diff if verdict is not None and verdict.diff else skill.diff)


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


def _rejected(skill: SkillResult, after: LoadOutcome) -> SkillResult | None:
    """``skill`` skipped when the EzSkiROS runtime would refuse to load it, whatever it
    means; ``None`` when it loads.

    Its lines are those of the migrated version, which is not written: the legacy class it
    stays as is the one that gives the same finding once migrated.
    """
    found = rejections(skill.name, after, "line {} once migrated")
    return rejected(skill, found) if found else None


def rejected(skill: SkillResult, found: list[str]) -> SkillResult:
    """``skill`` skipped because the runtime refuses it for the ``found`` findings: worded
    once for the verified run and ``--no-verify``'s static refusal."""
    return replace(skill, status="skipped", equivalent=None, reason=(
        "EzSkiROS rejects this skill when it loads: " + "; ".join(found) + ". The legacy "
        "code has the same problem (SkiROS2 accepted it silently); fix the description or "
        "the ontology, then migrate"))


def with_findings(skills: list[SkillResult], after: LoadOutcome,
                  skip: frozenset[str] = STATIC_KINDS) -> list[SkillResult]:
    """``skills`` with the runtime check findings (domain/range, datatypes...) of the
    migrated skills added.

    ``skip``: kinds reported elsewhere. ``rewrite``'s static pass already reports
    ``STATIC_KINDS`` once per term; ``verify`` has no static pass and keeps them all.
    """
    added: dict[str, list[Finding]] = {}
    names = {s.name for s in skills}
    for found in after.findings:
        if found.skill in names and found.kind not in skip:
            added.setdefault(found.skill, []).append(found)
    out = []
    for skill in skills:
        findings = list(skill.findings)
        for new in added.get(skill.name, ()):
            if not any(f.message == new.message for f in findings):
                findings.append(new)
        out.append(replace(skill, findings=findings) if len(findings) != len(skill.findings)
                   else skill)
    return out


def loaded_with(before: LoadOutcome, after: LoadOutcome) -> str:
    """The interpreter that loaded the file when it was not ours (``FileResult.python``),
    else ""."""
    return next((o.python for o in (before, after) if o.python), "")


def note_stand_ins(notes: list[str], before: LoadOutcome, after: LoadOutcome) -> None:
    """Say which imports could not be resolved and were stood in (on both sides alike, so
    the comparison still holds; a value taken from one would be a stand-in's)."""
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
