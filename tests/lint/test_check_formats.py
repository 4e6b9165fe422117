"""``ezmigrate check`` through the real CLI: every output format on ``fixtures/``, the SARIF
fields GitHub code scanning needs, suppression comments, selection (flags and
``[tool.ezmigrate]``), ``--statistics``, ``--exit-zero`` and the exit codes."""

from __future__ import annotations

import json
import re
from pathlib import Path
from urllib.parse import unquote
from xml.etree import ElementTree

import pytest
from check_support import cli, legacy

from ezskiros_runtime.codes import BY_CODE

ROOT = Path(__file__).resolve().parents[2]
TEXT_LINE = re.compile(r"^(?P<path>[^:]+):(?P<line>\d+):(?P<col>\d+): (?P<code>EZ\d{3}) \S")


@pytest.fixture(scope="module")
def runs() -> dict[str, tuple[int, str]]:
    """``check fixtures/`` once per format: (exit code, stdout)."""
    out = {}
    for fmt in ("text", "json", "sarif", "github", "junit"):
        run = cli("fixtures/", "--output-format", fmt, cwd=ROOT)
        assert run.returncode in (0, 1), run.stderr
        out[fmt] = (run.returncode, run.stdout)
    return out


def test_text_is_path_line_col_code_message(runs):
    code, stdout = runs["text"]
    lines = stdout.splitlines()
    assert lines and all(TEXT_LINE.match(line) for line in lines), lines[:5]
    assert code == 1  # fixtures have error-level findings (prefix typo, rejected types)
    assert not any(" EZ901 " in line for line in lines)  # off by default


def test_json_objects_and_same_findings_as_text(runs):
    data = json.loads(runs["json"][1])
    keys = {"path", "line", "column", "end_line", "end_column", "code", "severity",
            "message", "fix"}
    assert data and all(set(d) == keys for d in data)
    # the catalogue's severity, or info where the rule's condition does not hold (a finding
    # is never raised above its rule: docs/rules.md, severity contract)
    assert all(d["severity"] in (BY_CODE[d["code"]].severity, "info") for d in data)
    assert any(d["severity"] == BY_CODE[d["code"]].severity != "info" for d in data)
    text = [TEXT_LINE.match(line) for line in runs["text"][1].splitlines()]
    assert [(m["path"], int(m["line"]), m["code"]) for m in text if m] == [
        (d["path"], d["line"], d["code"]) for d in data]


def test_sarif_has_what_github_code_scanning_requires(runs):
    log = json.loads(runs["sarif"][1])
    assert log["version"] == "2.1.0" and "$schema" in log
    (run,) = log["runs"]
    rules = run["tool"]["driver"]["rules"]
    ids = [r["id"] for r in rules]
    assert len(ids) == len(set(ids)) and all(r["shortDescription"]["text"] for r in rules)
    # the catalogue travels in the log; no URL of a site the project does not publish
    assert all(r["id"] in r["help"]["text"] and "docs/rules.md" in r["help"]["text"]
               for r in rules)
    assert "http" not in json.dumps(run["tool"])
    results = run["results"]
    assert results and {r["ruleId"] for r in results} == set(ids)
    assert run["originalUriBaseIds"]["SRCROOT"]["uri"] == ROOT.as_uri() + "/"
    for result in results:
        assert ids[result["ruleIndex"]] == result["ruleId"]
        (location,) = result["locations"]
        physical = location["physicalLocation"]
        uri = physical["artifactLocation"]["uri"]
        assert uri.startswith("fixtures/") and (ROOT / unquote(uri)).is_file()
        assert physical["artifactLocation"]["uriBaseId"] == "SRCROOT"
        assert physical["region"]["startLine"] >= 1
        assert result["level"] in ("error", "warning", "note")


def test_github_annotations(runs):
    lines = runs["github"][1].splitlines()
    pattern = re.compile(r"^::(error|warning|notice) file=fixtures/[^,]+,line=\d+,col=\d+,"
                         r"endLine=\d+,endColumn=\d+,title=EZ\d{3}::EZ\d{3} .+")
    assert lines and all(pattern.match(line) for line in lines), lines[:3]
    assert len(lines) == len(json.loads(runs["json"][1]))


def test_junit_xml(runs):
    root = ElementTree.fromstring(runs["junit"][1])
    assert root.tag == "testsuites"
    cases = root.findall("./testsuite/testcase")
    failures = root.findall("./testsuite/testcase/failure")
    found = json.loads(runs["json"][1])
    errors = [d for d in found if d["severity"] == "error"]
    assert len(cases) == len(found) and len(failures) == len(errors) < len(found)
    assert root.get("failures") == str(len(errors))
    assert all(re.fullmatch(r"EZ\d{3}", f.get("type", "")) for f in failures)
    passed = [c for c in cases if c.find("failure") is None]
    assert all(c.findtext("system-out", "").startswith(("warning: ", "info: "))
               for c in passed)


def test_sarif_uris_are_relative_to_the_repository_root_and_encoded(tmp_path: Path):
    repo = tmp_path / "lab repo"
    write(repo / "pkg", UNKNOWN)
    (repo / "pkg" / "skill.py").rename(repo / "pkg" / "my skill.py")
    (repo / ".git").mkdir()  # the marker of a git top level
    run = cli("my skill.py", "--output-format", "sarif", cwd=repo / "pkg")
    log = json.loads(run.stdout)
    (result,) = log["runs"][0]["results"]
    artifact = result["locations"][0]["physicalLocation"]["artifactLocation"]
    assert artifact == {"uri": "pkg/my%20skill.py", "uriBaseId": "SRCROOT"}
    assert log["runs"][0]["originalUriBaseIds"]["SRCROOT"]["uri"] == \
        repo.resolve().as_uri() + "/"


def test_statistics_has_a_json_form_and_no_sarif_one(tmp_path: Path):
    folder = write(tmp_path, UNKNOWN)
    run = cli(".", "--statistics", "--output-format", "json", cwd=folder)
    assert json.loads(run.stdout) == [{"code": "EZ209", "name": "unknown-vocabulary",
                                       "count": 1}]
    refused = cli(".", "--statistics", "--output-format", "sarif", cwd=folder)
    assert refused.returncode == 2 and refused.stdout == ""
    assert "--statistics has no sarif form" in refused.stderr


def write(folder: Path, text: str, pyproject: str | None = None) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "skill.py").write_text(text, encoding="utf-8")
    if pyproject is not None:
        (folder / "pyproject.toml").write_text(pyproject, encoding="utf-8")
    return folder


PREFIX_TYPO = legacy('self.addParam("Param", Element("skiros;:Product"), ParamTypes.Required)')
UNKNOWN = legacy('self.addParam("Fruit", Element("skiros:Banana"), ParamTypes.Required)')


def codes(run) -> list[str]:
    return [m["code"] for line in run.stdout.splitlines() if (m := TEXT_LINE.match(line))]


def test_exit_codes(tmp_path: Path):
    clean = write(tmp_path / "clean", legacy('self.addParam("Speed", 0.5, '
                                             'ParamTypes.Optional)'))
    run = cli(".", cwd=clean)
    assert (run.returncode, run.stdout) == (0, ""), run.stderr
    warned = write(tmp_path / "warned", UNKNOWN)
    assert cli(".", cwd=warned).returncode == 0  # a warning is no error
    bad = write(tmp_path / "bad", PREFIX_TYPO)
    assert cli(".", cwd=bad).returncode == 1
    assert cli(".", "--exit-zero", cwd=bad).returncode == 0
    assert cli(".", "--select", "EZ999", cwd=bad).returncode == 2
    assert cli(".", "--output-format", "xml", cwd=bad).returncode == 2


def test_progress_is_not_written_when_stderr_is_no_terminal(tmp_path: Path):
    run = cli(".", cwd=write(tmp_path, UNKNOWN))
    assert "checking" not in run.stderr
    assert run.stderr.strip().splitlines()[-1].startswith("ezmigrate: 1 file checked")


def test_select_ignore_extend_select(tmp_path: Path):
    folder = write(tmp_path, PREFIX_TYPO.replace(
        'ParamTypes.Required)', 'ParamTypes.Required)\n        self.addParam("Fruit", '
        'Element("skiros:Banana"), ParamTypes.Required)'))
    assert codes(cli(".", cwd=folder)) == ["EZ212", "EZ209"]
    assert codes(cli(".", "--select", "EZ2", "--ignore", "EZ212", cwd=folder)) == ["EZ209"]
    assert codes(cli(".", "--ignore", "EZ2", "--extend-select", "EZ212", cwd=folder)) == [
        "EZ212"]
    assert codes(cli(".", "--select", "EZ9", cwd=folder)) == ["EZ901"]
    assert codes(cli(".", "--extend-select", "EZ901", "--ignore", "EZ209",
                     cwd=folder)) == ["EZ901", "EZ212"]
    assert codes(cli(".", "--select", "EZ212,EZ209", cwd=folder)) == ["EZ212", "EZ209"]


def test_selection_from_pyproject_and_flags_win(tmp_path: Path):
    folder = write(tmp_path, PREFIX_TYPO, '[tool.ezmigrate]\nignore = ["EZ212"]\n'
                                          'extend-select = ["EZ901"]\n')
    run = cli(".", cwd=folder)
    assert codes(run) == ["EZ901"] and run.returncode == 1  # EZ901 is an error
    # as ruff: --select on the command line replaces the configured selection
    assert codes(cli(".", "--select", "EZ2", cwd=folder)) == ["EZ212"]
    assert codes(cli(".", "--ignore", "EZ901", cwd=folder)) == []
    broken = write(tmp_path / "broken", UNKNOWN, '[tool.ezmigrate]\nselect = "EZ2"\n')
    assert cli(".", cwd=broken).returncode == 2


def test_suppression_comments_and_unused_ones(tmp_path: Path):
    source = PREFIX_TYPO.replace("ParamTypes.Required)",
                                 "ParamTypes.Required)  # ezskiros: ignore[EZ212]")
    source += ("\n\nclass Other(SkillDescription):\n    def createDescription(self):\n"
               '        self.addParam("Fruit", Element("skiros:Banana"), '
               "ParamTypes.Required)  # ezskiros: ignore[EZ209,EZ101]\n"
               '        self.addParam("Speed", 0.5, ParamTypes.Optional)  '
               "# ezskiros: ignore[EZ209]\n")
    folder = write(tmp_path, source)
    run = cli(".", cwd=folder)
    found = [(m["code"], int(m["line"])) for line in run.stdout.splitlines()
             if (m := TEXT_LINE.match(line))]
    fruit = next(i for i, t in enumerate(source.splitlines(), 1) if '"Fruit"' in t)
    assert found == [("EZ100", fruit), ("EZ100", fruit + 1)], run.stdout
    assert "no EZ101 finding" in run.stdout and run.returncode == 0
    quiet = cli(".", "--ignore", "EZ100", cwd=folder)
    assert quiet.stdout == ""
    assert "EZ100" not in cli(".", "--select", "EZ2", cwd=folder).stdout


def test_noqa_comments_of_our_codes_suppress_as_ruff_and_flake8_write_them(tmp_path: Path):
    """``# noqa: EZ212`` (after another linter's ``# noqa: E501`` too) silences that code
    on its line; a bare ``# noqa`` or one naming only other tools' codes silences nothing of
    ours, and an EZ code that finds nothing there is reported unused (EZ100)."""
    typo_line = next(t for t in PREFIX_TYPO.splitlines() if "ParamTypes.Required)" in t)
    for comment, left in (("  # noqa: EZ212", []), ("  # noqa: E501  # noqa: EZ212", []),
                          ("  # noqa", ["EZ212"]), ("  # noqa: E501", ["EZ212"]),
                          ("  # noqa: EZ212, EZ209", ["EZ100"])):
        folder = write(tmp_path / str(abs(hash(comment))), PREFIX_TYPO.replace(
            typo_line, typo_line + comment))
        run = cli(".", cwd=folder)
        found = [m["code"] for line in run.stdout.splitlines() if (m := TEXT_LINE.match(line))]
        assert found == left, (comment, run.stdout)


def test_statistics(tmp_path: Path):
    folder = write(tmp_path, UNKNOWN + UNKNOWN.split("\n\n\n", 1)[1].replace(
        "class Skill", "class Skill2"))
    run = cli(".", "--statistics", "--extend-select", "EZ901", cwd=folder)
    assert run.stdout.splitlines() == ["2  EZ209  unknown-vocabulary",
                                       "2  EZ901  not-migrated"], run.stdout
