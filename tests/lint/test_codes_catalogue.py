"""The catalogue of finding codes: every kind the project emits has exactly one code, codes
are unique and well-formed, and docs/rules.md is the generated table, byte for byte."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from ezmigrate.cli import rules_doc
from ezmigrate.lint.diagnostic import check_finding
from ezmigrate.report.results import review_finding
from ezskiros_runtime.codes import (
    BY_CODE,
    CODE_PATTERN,
    GROUPS,
    RULES,
    code_for,
    known_kind,
    valid_selector,
)
from ezskiros_runtime.diagnostics import SEVERITIES, Finding
from ezskiros_runtime.dsl.policy import DEFAULT_SEVERITY

ROOT = Path(__file__).resolve().parents[2]
EMITTERS = {"add", "finding", "Finding", "_failure", "emit", "compound_finding",
            "review_finding", "check_finding"}
"""Calls whose first string argument is a finding kind: the runtime's ``ctx.add``, the
codemod's ``skill.finding``, ``Finding`` itself, the lint's ``emit``, the review report's
and ``check``'s own findings."""


def emitted_kinds() -> set[str]:
    """Every literal kind passed to a finding constructor anywhere in the two packages."""
    kinds: set[str] = set()
    for package in ("ezskiros_runtime", "ezmigrate"):
        for path in (ROOT / package).rglob("*.py"):
            for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
                if not isinstance(node, ast.Call) or not node.args:
                    continue
                func = node.func
                name = func.attr if isinstance(func, ast.Attribute) else getattr(func, "id", "")
                if name == "add" and not (isinstance(func, ast.Attribute)
                                          and getattr(func.value, "id", "") in ("ctx", "self")):
                    continue  # set.add, not CheckContext.add or the compound checker's
                first = node.args[0]
                if name in EMITTERS and isinstance(first, ast.Constant) \
                        and isinstance(first.value, str):
                    kinds.add(first.value)
                elif name == "add" and isinstance(first, ast.JoinedStr):  # f"{kind}-unproven"
                    kinds |= {"domain-unproven", "range-unproven"}
    return kinds


def test_codes_are_unique_well_formed_and_grouped():
    codes = [r.code for r in RULES]
    assert len(codes) == len(set(codes))
    assert all(CODE_PATTERN.match(c) for c in codes), codes
    assert all(r.code[:3] in GROUPS for r in RULES)
    assert [r.code for r in RULES if r.code.startswith("EZ3")], "compound skills have codes"
    names = [r.name for r in RULES]
    assert len(names) == len(set(names))
    assert all(r.severity in SEVERITIES and r.rationale and r.fix for r in RULES)


def test_every_kind_maps_to_exactly_one_code():
    all_kinds = [k for r in RULES for k in r.kinds]
    assert len(all_kinds) == len(set(all_kinds)), "a kind listed under two codes"
    emitted = emitted_kinds() | set(DEFAULT_SEVERITY) | {"skipped", "failed"}
    assert len(emitted) > 20  # the scan found the emitters at all
    missing = sorted(k for k in emitted if not known_kind(k))
    assert missing == []


def test_runtime_and_catalogue_agree_on_severity():
    for kind, severity in DEFAULT_SEVERITY.items():
        assert BY_CODE[code_for(kind)].severity == severity, kind


def test_findings_carry_their_code():
    finding = Finding("range-unproven", "warning", "m", None, 3, "Pick")
    assert finding.code == "EZ204" and finding.to_json()["code"] == "EZ204"
    assert review_finding("description-in-options", "Pick", 4, "m").code == "EZ101"
    assert review_finding("undeclared-key", "Pick", 4, "m").code == \
        code_for("undeclared-parameter")
    assert check_finding("unloadable", 0, "m").severity == "error"
    assert check_finding("unloadable", 0, "m", lowered=True).severity == "info"


def test_not_migrated_is_off_by_default():
    assert not BY_CODE["EZ901"].enabled
    assert [r.code for r in RULES if not r.enabled] == ["EZ901"]


@pytest.mark.parametrize(("selector", "valid"), [
    ("EZ", True), ("EZ2", True), ("EZ3", True), ("EZ201", True), ("ALL", True),
    ("EZ299", False), ("E501", False), ("ez201", False), ("EZ2011", False)])
def test_selectors(selector: str, valid: bool):
    assert valid_selector(selector) is valid


def test_committed_rules_doc_is_the_generated_one():
    assert rules_doc.DOC.read_text(encoding="utf-8") == rules_doc.render(), (
        "run `python -m ezmigrate.cli.rules_doc` and commit docs/rules.md")
    for rule in RULES:
        assert f"| {rule.code} | {rule.name} |" in rules_doc.render()


@pytest.mark.parametrize(("argv", "status"), [(["--help"], 0), (["-x"], 2), (["a", "b"], 2)])
def test_rules_doc_refuses_options_instead_of_writing_a_file_named_after_them(
        argv: list[str], status: int, tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
        capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.chdir(tmp_path)
    assert rules_doc.main(argv) == status
    assert "usage: python -m ezmigrate.cli.rules_doc" in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == []


def test_rules_doc_writes_to_the_path_given_or_prints_with_a_dash(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    target = tmp_path / "rules.md"
    assert rules_doc.main([str(target)]) == 0
    assert target.read_text(encoding="utf-8") == rules_doc.render()
    assert rules_doc.main(["-"]) == 0
    assert capsys.readouterr().out == rules_doc.render()


def test_the_readme_tables_say_the_catalogues_severities():
    """A row of a README table that names finding kinds (`` `domain`, `range` | error``) says
    the severity the catalogue gives each of them: the README is derived, not a fifth home."""
    import re

    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    rows = re.findall(r"^\| ((?:`[a-z_-]+`(?:, )?)+) \| (error|warning|info) \|", readme,
                      flags=re.MULTILINE)
    assert len(rows) >= 5, "the early-checks table was found"
    for kinds, severity in rows:
        for kind in re.findall(r"`([a-z_-]+)`", kinds):
            assert BY_CODE[code_for(kind)].severity == severity, kind


def test_a_kind_no_rule_lists_is_refused_not_filed_elsewhere():
    from ezskiros_runtime.codes import UnknownKind, rule_for
    from ezskiros_runtime.dsl.policy import set_severity, severity_of

    with pytest.raises(UnknownKind):
        rule_for("no-such-kind")
    with pytest.raises(UnknownKind):
        severity_of("no_such_kind")
    with pytest.raises(UnknownKind):
        set_severity("no_such_kind", "error")


def test_every_error_names_what_skiros2_does():
    """The severity contract (docs/rules.md): an error means SkiROS2 fails or misbehaves,
    and says where."""
    for rule in RULES:
        if rule.severity == "error":
            assert rule.skiros2, f"{rule.code} is an error and names no SkiROS2 behaviour"
