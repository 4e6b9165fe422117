"""Reports of a run: the one-line summary, JSON for machines, Markdown for code review."""

from __future__ import annotations

import json
import os
import sys
from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from ezskiros_runtime.diagnostics import Finding

from .results import FileResult, SkillResult
from .wording import counted

SCHEMA_VERSION = 1


@dataclass
class Summary:
    """Counts over a run (the JSON report's ``summary`` and the closing stderr line)."""

    files: int = 0
    skills: int = 0
    converted: int = 0
    skipped: int = 0
    failed: int = 0
    unchanged: int = 0
    changed_files: int = 0
    file_errors: int = 0

    @classmethod
    def of(cls, results: Sequence[FileResult]) -> Summary:
        s = cls(files=len(results))
        for r in results:
            s.skills += len(r.skills)
            s.converted += r.count("converted")
            s.skipped += r.count("skipped")
            s.failed += r.count("failed")
            s.unchanged += r.count("unchanged")
            s.changed_files += r.changed
            s.file_errors += r.error is not None
        return s

    def line(self, *, dry: bool) -> str:
        change = "would change" if dry else "changed"
        text = (f"{counted(self.files, 'file')} scanned, {counted(self.skills, 'skill')} "
                f"found, {self.converted} converted, {self.skipped} skipped, {self.failed} "
                f"failed, {self.unchanged} unchanged; {counted(self.changed_files, 'file')} "
                f"{change}")
        if self.file_errors:
            text += f"; {counted(self.file_errors, 'file')} could not be processed"
        return text

    def needs_attention(self, strict: bool = False) -> bool:
        """Whether ``rewrite`` exits 1, as black does: a failed verification or a file that
        could not be processed. A skill skipped with a reason is the run doing its work
        (the reason is printed and reported), so it counts only with ``--strict``."""
        return bool(self.failed or self.file_errors or (strict and self.skipped))


def newer_python_lines(results: Sequence[FileResult], run_python: str | None,
                       run_version: str) -> list[str]:
    """One line per interpreter other than the run's (``run_python``; None: ours) that
    verified some files: those whose syntax the run's Python cannot read, loaded under the
    oldest Python that can (``pool._retry_newer_syntax``); ``run_version`` names the run's
    Python (``3.11.7``). For the summary and the report:
    what was proven there is what that Python loads, not the robot's."""
    run_path = os.path.abspath(run_python or sys.executable)
    by_python: dict[str, list[str]] = {}
    for file in results:  # ``python``: its absolute path (``describe``)
        if file.python and file.python != run_path:
            by_python.setdefault(file.python, []).append(file.path)
    return [f"{counted(len(files), 'file')} need{'s' if len(files) == 1 else ''} a newer "
            f"Python than {run_version}: verified under {name}, the oldest found that "
            f"reads {'it' if len(files) == 1 else 'them'} ({', '.join(files)})"
            for name, files in sorted(by_python.items())]


@dataclass
class MarkdownOptions:
    """How equivalence was judged, as both reports say it (Markdown in words, JSON as
    ``"options"``); ``notes`` are Markdown only."""

    verified: bool = True
    ignore_order: bool = False
    ignore_labels: bool = False
    notes: list[str] = field(default_factory=list)
    ontology: str = ""
    """Which ontology files were used and why (``OntologySource.describe``)."""
    compounds: list[str] = field(default_factory=list)
    """The "Compound skills" section (``compound.diagram.markdown_section``), Markdown only."""
    scenes: list[str] = field(default_factory=list)
    """The "Scenes" section (``scene_diagram.markdown_section``), Markdown only."""
    verifier: str = ""
    """Which Python verified and which rdflib read the ontology (``target.verified_with``)."""


def _finding_json(found: Finding) -> dict[str, Any]:
    """A finding as the report's schema has it: what, where (0: the skill as a whole, also
    for a runtime finding without a line) and the legacy line beside the written one."""
    return {"kind": found.kind, "line": found.line or 0, "message": found.message,
            "legacy_line": found.legacy_line, "code": found.code}


def _undefined_prefix(found: Finding) -> str | None:
    """The prefix no loaded ontology defines that a finding of unknown vocabulary is about
    (its subject: ``review_finding``), else None: one cause, which the report says once."""
    return (found.subject or None) if found.kind == "unknown-vocabulary" else None


def _skill_json(file: FileResult, skill: SkillResult) -> dict[str, Any]:
    data: dict[str, Any] = {
        "file": file.path, "class": skill.name, "line": skill.line,
        "legacy_line": skill.legacy_line, "status": skill.status,
        "code": skill.code, "reason": skill.reason,
        "findings": [_finding_json(f) for f in skill.findings],
        "equivalent": skill.equivalent,
    }
    if skill.diff:
        data["diff"] = skill.diff
    return data


def json_report(results: Sequence[FileResult], extra: dict[str, Any] | None = None,
                options: MarkdownOptions | None = None) -> str:
    """The JSON report (schema version 1 of the rewrite issue, plus ``equivalent``/``diff``).

    ``options`` says how equivalence was judged (``"options"``): a verdict reached with
    ``--ignore-order`` or ``--ignore-labels`` proves less, and a reader must be able to tell.
    """
    summary = Summary.of(results)
    data: dict[str, Any] = {
        "version": SCHEMA_VERSION,
        **({"options": {"verified": options.verified, "ignore_order": options.ignore_order,
                        "ignore_labels": options.ignore_labels}} if options else {}),
        **({"ontology": options.ontology} if options and options.ontology else {}),
        **({"verified_with": options.verifier} if options and options.verifier else {}),
        "summary": {"files": summary.files, "skills": summary.skills,
                    "converted": summary.converted, "skipped": summary.skipped,
                    "failed": summary.failed},
        "skills": [_skill_json(f, s) for f in results for s in f.skills],
        "files": [{"file": f.path, "changed": f.changed, "error": f.error,
                   "code": f.error_code,
                   "error_line": f.error_line, "notes": f.notes,
                   **({"python": f.python} if f.python else {})}
                  for f in results if f.error or f.notes or f.changed or f.python],
        **(extra or {}),
    }
    return json.dumps(data, indent=2, ensure_ascii=False) + "\n"


def relaxed(ignore_order: bool, ignore_labels: bool) -> str:
    """What equivalence was judged without (``ignoring labels``), or ``""``: worded once for
    the Markdown report and ``verify``'s summary line."""
    relax = [w for w, on in (("parameter/condition order", ignore_order),
                             ("labels", ignore_labels)) if on]
    return f"ignoring {' and '.join(relax)}" if relax else ""


def _verdict(skill: SkillResult) -> str:
    if skill.status == "converted":
        return "converted, equivalent" if skill.equivalent else (
            "converted (not verified)" if skill.equivalent is None else "converted")
    return f"{skill.status} ({skill.code})" if skill.code else skill.status


def _where(line: int, legacy: int | None) -> str:
    """``line 12`` in the written file, with ``legacy line 10`` beside it when they differ."""
    return f"line {line}" + (f", legacy line {legacy}" if legacy not in (None, line) else "")


def markdown_report(results: Sequence[FileResult], options: MarkdownOptions) -> str:
    """A review report: summary table, then each file and skill with its verdict."""
    s = Summary.of(results)
    out = ["# ezmigrate report", ""]
    how = "verified by loading both versions" if options.verified else "NOT verified"
    relax = relaxed(options.ignore_order, options.ignore_labels)
    out.append(f"Equivalence: {how}" + (f"; {relax}" if relax else "") + ".")
    if options.ontology:  # "ontology from X: files" or "ontology: the core plus ..."
        out += ["", options.ontology[0].upper() + options.ontology[1:] + "."]
    if options.verifier:  # "verified under Python 3.8.18 (...), ontology read with ..."
        out += ["", options.verifier[0].upper() + options.verifier[1:] + "."]
    out += ["", "| files | skills | converted | skipped | failed | unchanged |",
            "|---:|---:|---:|---:|---:|---:|",
            f"| {s.files} | {s.skills} | {s.converted} | {s.skipped} | {s.failed} | "
            f"{s.unchanged} |", ""]
    out += [f"- {note}" for note in options.notes]
    findings: list[str] = []
    said: set[str] = set()
    prefix_uses = Counter(prefix for file in results for skill in file.skills
                          for prefix in map(_undefined_prefix, skill.findings)
                          if prefix is not None)
    for file in results:
        if not file.skills and not file.error and not file.notes:
            continue
        out += [f"## `{file.path}`", ""]
        if file.error:
            out += [f"**Could not be processed ({file.error_code}):** {file.error}", ""]
        for note in file.notes:
            head, _, body = note.partition("\n")
            out += [f"- {head}"] + (["", "```text", body, "```", ""] if body else [])
        for skill in file.skills:
            out.append(f"- **{skill.name}** ({_where(skill.line, skill.legacy_line)}): "
                       f"{_verdict(skill)}")
            if skill.reason:
                out.append(f"  - reason: {skill.reason}")
            for d in skill.diff or ():
                out.append(f"  - {d['where']}: {d['message']}")
                if d.get("before") is not None:
                    out.append(f"    - legacy: `{d['before']}`")
                if d.get("after") is not None:
                    out.append(f"    - migrated: `{d['after']}`")
            for f in skill.findings:
                prefix = _undefined_prefix(f)
                if prefix is not None and prefix in said:
                    continue  # one cause, one line: its uses are counted there
                where = _where(f.line, f.legacy_line) if f.line else "skill"
                uses = prefix_uses.get(prefix or "", 0)
                once = (f" ({uses} uses of prefix {prefix!r} in the migration, reported "
                        "once, here)" if prefix is not None and uses > 1 else "")
                if prefix is not None:
                    said.add(prefix)
                findings.append(f"- `{file.path}` {skill.name} ({where}) **{f.code}** "
                                f"{f.kind}: {f.message}{once}")
        out.append("")
    if findings:
        out += ["## Findings (kept as they were; not equivalence problems)", "", *findings, ""]
    out += options.compounds
    out += options.scenes
    return "\n".join(out).rstrip() + "\n"
