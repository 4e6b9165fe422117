"""Reports of a verifying ``rewrite``: JSON for machines (schema version 1 plus
``equivalent`` and ``diff``), Markdown for code review (summary table, then per file and
skill the verdict, both sides of a difference in legacy notation, skip reasons, and the
findings in a section of their own)."""

from __future__ import annotations

import json
from typing import Any

import pytest
from verify_support import LATE_CONSTANT, LEGACY, PAPER_AXIOMS, cli, tree

from ezskiros_runtime.codes import code_for

SKILL_KEYS = {"file", "class", "line", "legacy_line", "status", "code", "reason", "findings",
              "equivalent"}
LEGACY_SIDE = "addParam('Speed', 1.0, ParamTypes.Optional)"
MIGRATED_SIDE = "addParam('Speed', 0.5, ParamTypes.Optional)"


@pytest.fixture(scope="module")
def reports(tmp_path_factory):
    """Four dry runs over one folder: JSON and Markdown, with and without verification."""
    tmp = tmp_path_factory.mktemp("reports")
    folder = tree(tmp / "skills", {
        "late_constant.py": LATE_CONSTANT, "descriptions.py": LEGACY / "descriptions.py",
        "not_convertible.py": LEGACY / "not_convertible.py",
        "ontology_violations.py": LEGACY / "ontology_violations.py"})
    out = {}
    for name, extra in (("verified", ()), ("unverified", ("--no-verify",))):
        for suffix in ("json", "md"):
            report = tmp / f"{name}.{suffix}"
            run = cli("rewrite", folder, "--dry-run", *extra, "--report", report,
                      *PAPER_AXIOMS)
            # a failed verification needs attention; skips with a reason alone do not
            assert run.returncode == (1 if name == "verified" else 0), run.stderr
            out[f"{name}.{suffix}"] = report.read_text(encoding="utf-8")
    return out


def test_json_report_follows_the_schema(reports):
    data = read_json_text(reports["verified.json"])
    assert data["version"] == 1
    counts = {"files": 4, "skills": 20, "converted": 9, "skipped": 10, "failed": 1}
    assert {k: data["summary"][k] for k in counts} == counts
    for skill in data["skills"]:
        expected = SKILL_KEYS | ({"diff"} if skill["equivalent"] is False else set())
        assert set(skill) == expected, skill
        assert isinstance(skill["line"], int) and skill["line"] > 0
        assert skill["code"] == {"skipped": "EZ902", "failed": "EZ903"}.get(skill["status"])
        for finding in skill["findings"]:
            assert set(finding) == {"kind", "line", "legacy_line", "message", "code"}, finding
            assert finding["code"] == code_for(finding["kind"]), finding


def test_json_report_says_what_was_proven(reports):
    verified = {(s["file"], s["class"]): s for s in read_json_text(reports["verified.json"])
                ["skills"]}
    move = verified[("late_constant.py", "Move")]
    assert (move["status"], move["equivalent"]) == ("failed", False)
    assert move["diff"] == [{"where": "params", "message": "parameter #2 differs",
                             "before": LEGACY_SIDE, "after": MIGRATED_SIDE}]
    converted = [s for s in verified.values() if s["status"] == "converted"]
    assert len(converted) == 9 and all(s["equivalent"] is True for s in converted)
    stop = verified[("late_constant.py", "Stop")]  # written, with Move held as it was
    assert (stop["status"], stop["equivalent"]) == ("converted", True)
    skipped = [s for s in verified.values() if s["status"] == "skipped"]
    assert len(skipped) == 10 and all(s["equivalent"] is None and s["reason"] for s in skipped)
    attach = verified[("ontology_violations.py", "AttachCamera")]
    assert any(f["kind"] == "range-unproven" and "cora:robotPart" in f["message"]
               for f in attach["findings"])
    unverified = read_json_text(reports["unverified.json"])["skills"]
    assert [s["equivalent"] for s in unverified if s["status"] == "converted"] == [None] * 10
    assert not any("diff" in s for s in unverified)


def test_markdown_report_for_code_review(reports):
    text = reports["verified.md"]
    lines = text.splitlines()
    assert lines[0] == "# ezmigrate report"
    assert lines[2] == "Equivalence: verified by loading both versions."
    table = lines.index("| files | skills | converted | skipped | failed | unchanged |")
    assert lines[table + 2] == "| 4 | 20 | 9 | 10 | 1 | 0 |"
    late = _section(text, "## `late_constant.py`")
    # lines of the written file (imports changed above), the legacy line beside them
    assert "- **Move** (line 10, legacy line 8): failed (EZ903)" in late
    assert f"    - legacy: `{LEGACY_SIDE}`" in late
    assert f"    - migrated: `{MIGRATED_SIDE}`" in late
    assert "- **Stop** (line 16, legacy line 14): converted, equivalent" in late
    skipped = _section(text, "## `not_convertible.py`")
    assert "- **FollowWaypoints** (line 20): skipped (EZ902)\n  - reason: a loop at line 23" \
        in skipped
    assert "- **Navigate** (line 19, legacy line 11): converted, equivalent" in text


def test_markdown_lists_findings_apart_from_equivalence(reports):
    text = reports["verified.md"]
    heading = "## Findings (kept as they were; not equivalence problems)"
    findings = _section(text, heading)
    assert "`ontology_violations.py` PlaceOnPose (line 31) **EZ204** range-unproven: skiros:hasA " \
        "expects object of class skiros:TransformationPose" in findings
    assert text.index(heading) > text.index("## `ontology_violations.py`")
    violations = _section(text, "## `ontology_violations.py`")
    assert "**EZ20" not in violations
    assert violations.count("converted, equivalent") == 2


def test_markdown_says_when_nothing_was_verified(reports):
    text = reports["unverified.md"]
    assert text.splitlines()[2] == "Equivalence: NOT verified."
    assert "- **Move** (line 8): converted (not verified)" in text
    assert "converted, equivalent" not in text


def read_json_text(text: str) -> dict[str, Any]:
    data: dict[str, Any] = json.loads(text)
    return data


def _section(text: str, heading: str) -> str:
    start = text.index(heading + "\n")
    end = text.find("\n## ", start + 1)
    return text[start:end if end != -1 else len(text)]



def test_the_review_report_says_an_undefined_prefix_once_and_guesses_no_other_prefix():
    """Issue 43: one cause, one line, as in ``check``; a "did you mean" is a typo away in
    the term's own prefix (or the same name under another prefix), never a guess."""
    from ezmigrate.report.findings import _close
    from ezmigrate.report.reports import MarkdownOptions, markdown_report
    from ezmigrate.report.results import FileResult, SkillResult, review_finding
    from ezskiros_runtime.diagnostics import Finding

    assert _close("scalable:Ur5EndEffector", ["rparts:EndEffector"]) == []
    assert _close("skiros:Lcoation", ["skiros:Location", "cora:Location"]) == [
        "skiros:Location"]
    assert _close("skirso:Location", ["skiros:Location"]) == ["skiros:Location"]

    def finding(skill: str, line: int) -> Finding:
        return review_finding("unknown-vocabulary", skill, line, "class 'acme:Gripper' is not "
                              "in the loaded ontology", "acme")

    results = [FileResult(f"f{n}.py", skills=[SkillResult(
        f"S{n}", 1, "converted", findings=[finding(f"S{n}", 3), finding(f"S{n}", 4)])])
        for n in range(3)]
    text = markdown_report(results, MarkdownOptions())
    lines = [line for line in text.splitlines() if "acme:Gripper" in line]
    assert len(lines) == 1 and "(6 uses of prefix 'acme' in the migration" in lines[0]
