"""``ezmigrate rewrite`` through the real entry point, on real files in temporary folders."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures"
PICK = FIXTURES / "legacy" / "pick_and_place.py"
PICK_MIGRATED = FIXTURES / "migrated" / "pick_and_place.py"
PLAIN = FIXTURES / "legacy" / "nothing_to_do.py"


def ezmigrate(*args: str | Path, stdin: bytes | None = None,
              cwd: Path | None = None) -> subprocess.CompletedProcess[bytes]:
    return subprocess.run([sys.executable, "-m", "ezmigrate", *map(str, args)], input=stdin,
                          capture_output=True, cwd=cwd, check=False, timeout=300)


@pytest.fixture
def repo(tmp_path: Path) -> Path:
    root = tmp_path / "repo"
    (root / "skills").mkdir(parents=True)
    shutil.copy(PICK, root / "skills" / "pick.py")
    shutil.copy(PLAIN, root / "skills" / "plain.py")
    return root


def snapshot(root: Path) -> dict[Path, bytes]:
    return {p: p.read_bytes() for p in root.rglob("*.py")}


def test_dry_run_prints_diffs_writes_nothing_and_summarises_on_stderr(repo: Path):
    before = snapshot(repo)
    proc = ezmigrate("rewrite", "--dry-run", "--no-verify", repo)
    assert proc.returncode == 0
    out = proc.stdout.decode()
    assert out.startswith("--- a/skills/pick.py\n+++ b/skills/pick.py\n")
    assert "+    def description(self," in out and "\x1b[" not in out  # no colour when piped
    assert "plain.py" not in out
    assert snapshot(repo) == before
    assert "2 files scanned, 3 skills found, 3 converted" in proc.stderr.decode()


def test_check_exits_one_when_something_would_change_and_zero_after(repo: Path):
    proc = ezmigrate("rewrite", "--check", "--no-verify", repo)
    assert proc.returncode == 1
    assert proc.stdout.decode().strip() == f"would rewrite {repo / 'skills' / 'pick.py'}"
    assert ezmigrate("rewrite", repo).returncode == 0
    assert (repo / "skills" / "pick.py").read_bytes() == PICK_MIGRATED.read_bytes()
    again = ezmigrate("rewrite", "--check", repo)
    assert again.returncode == 0 and again.stdout == b""


def test_check_and_dry_run_combine(repo: Path):
    proc = ezmigrate("rewrite", "--check", "--dry-run", "--no-verify", repo)
    assert proc.returncode == 1 and b"+++ b/skills/pick.py" in proc.stdout


def test_json_report_schema(repo: Path, tmp_path: Path):
    report = tmp_path / "r.json"
    assert ezmigrate("rewrite", "--dry-run", repo, "--report", report).returncode == 0
    data = json.loads(report.read_text())
    assert data["version"] == 1
    assert data["summary"] == {"files": 2, "skills": 3, "converted": 3, "skipped": 0,
                               "failed": 0}
    first = data["skills"][0]
    assert {"file", "class", "line", "status", "reason", "findings", "equivalent"} <= set(first)
    assert (first["file"], first["class"], first["status"], first["equivalent"]) == \
        ("skills/pick.py", "Pick", "converted", True)


def test_skips_with_a_reason_exit_zero_and_one_only_with_strict(tmp_path: Path):
    """As black: a run that did its work exits 0, though it left skills alone with a reason
    (a pre-commit hook must not fail every commit touching a loop-built description)."""
    shutil.copy(FIXTURES / "legacy" / "not_convertible.py", tmp_path / "nc.py")
    report = tmp_path / "r.md"
    proc = ezmigrate("rewrite", "--dry-run", "--no-verify", tmp_path / "nc.py", "--report", report)
    assert proc.returncode == 0, proc.stderr
    assert "10 skipped" in proc.stderr.decode()
    strict = ezmigrate("rewrite", "--dry-run", "--no-verify", "--strict", tmp_path / "nc.py")
    assert strict.returncode == 1
    assert ezmigrate("rewrite", "--check", tmp_path / "nc.py").returncode == 0  # no change
    text = report.read_text()
    assert text.startswith("# ezmigrate report") and "| files | skills |" in text
    assert "- **FollowWaypoints**" in text and "reason: a loop at line" in text
    assert "NOT verified" in text


def test_excludes_apply_to_explicit_files_and_gitignore_is_respected(repo: Path):
    proc = ezmigrate("rewrite", "--check", "--no-verify", "--exclude", "pick.py",
                     repo / "skills" / "pick.py")
    assert proc.returncode == 0 and "0 files scanned" in proc.stderr.decode()
    subprocess.run(["git", "init", "-q", str(repo)], check=True)
    (repo / ".gitignore").write_text("skills/pick.py\n")
    proc = ezmigrate("rewrite", "--check", "--no-verify", repo)
    assert proc.returncode == 0 and "1 file scanned" in proc.stderr.decode()


def test_output_dir_writes_a_side_by_side_tree(repo: Path, tmp_path: Path):
    before = snapshot(repo)
    out = tmp_path / "out"
    assert ezmigrate("rewrite", repo, "--output-dir", out).returncode == 0
    assert snapshot(repo) == before
    assert (out / "skills" / "pick.py").read_bytes() == PICK_MIGRATED.read_bytes()
    assert (out / "skills" / "plain.py").read_bytes() == PLAIN.read_bytes()
    assert ezmigrate("verify", repo, out).returncode == 0


def test_stdin_to_stdout(tmp_path: Path):
    proc = ezmigrate("rewrite", "-", stdin=PICK.read_bytes(), cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout == PICK_MIGRATED.read_bytes()
    plain = ezmigrate("rewrite", "-", stdin=PLAIN.read_bytes(), cwd=tmp_path)
    assert plain.returncode == 0 and plain.stdout == PLAIN.read_bytes()


def test_usage_errors_exit_two(tmp_path: Path):
    assert ezmigrate("rewrite").returncode == 2
    assert ezmigrate("rewrite", "--jobs", "0", tmp_path).returncode == 2
    assert ezmigrate("rewrite", "--ontology", tmp_path / "missing.ttl", tmp_path).returncode == 2


def test_console_script_and_module_agree(repo: Path):
    script = Path(sys.executable).parent / "ezmigrate"
    a = subprocess.run([str(script), "rewrite", "--dry-run", "--no-verify", str(repo)],
                       capture_output=True, check=False)
    b = ezmigrate("rewrite", "--dry-run", "--no-verify", repo)
    assert (a.returncode, a.stdout) == (b.returncode, b.stdout)


def test_verify_classes_failing_in_both_versions(tmp_path: Path):
    before, after = tmp_path / "before", tmp_path / "after"
    before.mkdir()
    after.mkdir()
    source = FIXTURES / "legacy" / "not_convertible.py"
    shutil.copy(source, before / "nc.py")
    shutil.copy(source, after / "nc.py")
    report = tmp_path / "r.json"
    proc = ezmigrate("verify", before, after, "--report", report)
    assert proc.returncode == 0, proc.stderr  # unchanged classes that load in neither version
    skills = {s["class"]: s for s in json.loads(report.read_text())["skills"]}
    assert skills["EmptyListDefault"]["status"] == "unchanged"
    assert "its source is unchanged" in skills["EmptyListDefault"]["reason"]
    changed = source.read_text().replace('self.addParam("Joints", [], ParamTypes.Optional)',
                                         'self.addParam("Joints", [], ParamTypes.Required)')
    assert changed != source.read_text()
    (after / "nc.py").write_text(changed)
    proc = ezmigrate("verify", before, after, "--report", report)
    assert proc.returncode == 1
    skills = {s["class"]: s for s in json.loads(report.read_text())["skills"]}
    assert skills["EmptyListDefault"]["status"] == "failed"
    assert skills["EmptyListDefault"]["reason"].startswith("not verified")


@pytest.mark.parametrize("pattern", ["skills", "skills/*", "skills/pick.py", "pick.py"])
def test_excludes_see_the_folders_of_explicit_files(repo: Path, pattern: str):
    """pre-commit passes ``skills/pick.py``: a folder pattern must exclude it, as in ruff."""
    proc = ezmigrate("rewrite", "--check", "--no-verify", "--exclude", pattern,
                     Path("skills") / "pick.py", cwd=repo)
    assert proc.returncode == 0 and "0 files scanned" in proc.stderr.decode(), proc.stderr
    kept = ezmigrate("rewrite", "--check", "--no-verify", "--exclude", "other",
                     Path("skills") / "pick.py", cwd=repo)
    assert kept.returncode == 1 and "would rewrite" in kept.stdout.decode()


def test_a_path_that_does_not_exist_is_a_usage_error(repo: Path):
    proc = ezmigrate("rewrite", "--check", repo / "missing.py")
    assert proc.returncode == 2
    assert "missing.py" in proc.stderr.decode() and "does not exist" in proc.stderr.decode()


def test_a_report_name_must_say_its_format(repo: Path, tmp_path: Path):
    wrong = ezmigrate("rewrite", "--check", "--no-verify", "--report", tmp_path / "r.txt", repo)
    assert wrong.returncode == 2 and "*.md for Markdown" in wrong.stderr.decode()
    assert not (tmp_path / "r.txt").exists()
    upper = ezmigrate("rewrite", "--check", "--no-verify", "--report", tmp_path / "R.MD", repo)
    assert upper.returncode == 1
    assert (tmp_path / "R.MD").read_text(encoding="utf-8").startswith("# ezmigrate report")


def test_a_reader_that_stops_early_ends_the_run_quietly(repo: Path):
    """``ezmigrate rewrite --dry-run . | head -1``: no traceback, no "internal error"."""
    proc = subprocess.Popen([sys.executable, "-m", "ezmigrate", "rewrite", "--dry-run",
                             "--no-verify", repo / "skills" / "pick.py"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    assert proc.stdout is not None and proc.stderr is not None
    proc.stdout.close()  # the reader is gone before the first diff line
    stderr = proc.stderr.read().decode()
    assert proc.wait(timeout=300) == 141, stderr
    assert "internal error" not in stderr and "Traceback" not in stderr


@pytest.mark.parametrize("suffix", [".json", ".md"])
def test_a_file_name_that_is_not_utf8_is_migrated_and_reported(tmp_path: Path, suffix: str):
    """Linux file names are bytes: ``caf\\xe9.py`` (latin-1) must not end in an internal error
    after the files were written."""
    folder = tmp_path / "skills"
    folder.mkdir()
    name = os.fsdecode(b"caf\xe9.py")
    shutil.copy(PICK, folder / name)
    report = tmp_path / f"r{suffix}"
    proc = ezmigrate("rewrite", folder, "--report", report)
    assert proc.returncode == 0, proc.stderr
    assert (folder / name).read_bytes() == PICK_MIGRATED.read_bytes()
    assert "caf\\udce9.py" in report.read_text(encoding="utf-8")


@pytest.mark.parametrize(("setting", "complaint"), [
    ("timeout = -1", "timeout must be a positive number of seconds, not -1"),
    ("jobs = 0", "jobs must be a whole number of at least 1, not 0"),
    ('exclude = "legacy"', "exclude must be a list of globs"),
])
def test_a_project_setting_the_tool_cannot_use_is_a_usage_error(repo: Path, setting: str,
                                                                complaint: str):
    (repo / "pyproject.toml").write_text(f"[tool.ezmigrate]\n{setting}\n", encoding="utf-8")
    for command in (("rewrite", "--check", repo), ("verify", repo, repo), ("check", repo)):
        proc = ezmigrate(*command)
        stderr = proc.stderr.decode()
        assert proc.returncode == 2, (command, stderr)
        assert "pyproject.toml: [tool.ezmigrate] " + complaint in stderr, stderr
        assert "internal error" not in stderr and "Traceback" not in stderr


def test_stdin_is_a_one_file_run_with_reasons_summary_and_report(tmp_path: Path):
    """``-`` behaves like a path: skip reasons and the summary on stderr, the report written
    when asked, the same exit codes; stdout still gets a whole file."""
    skipped = (FIXTURES / "legacy" / "not_convertible.py").read_bytes()
    proc = ezmigrate("rewrite", "--no-verify", "-", stdin=skipped, cwd=tmp_path)
    stderr = proc.stderr.decode()
    assert proc.returncode == 0 and proc.stdout == skipped
    assert "-:20: FollowWaypoints: skipped: a loop at line 23" in stderr
    assert "ezmigrate: 1 file scanned, 10 skills found, 0 converted, 10 skipped" in stderr
    dry = ezmigrate("rewrite", "--no-verify", "--dry-run", "-", stdin=skipped, cwd=tmp_path)
    assert dry.returncode == 0 and dry.stdout == b""  # as the same file given by path
    report = tmp_path / "r.json"
    check = ezmigrate("rewrite", "--check", "--report", report, "-", stdin=PICK.read_bytes(),
                      cwd=tmp_path)
    assert check.returncode == 1 and check.stdout.decode() == "would rewrite -\n"
    data = json.loads(report.read_text(encoding="utf-8"))
    assert data["summary"]["converted"] == 3 and data["skills"][0]["file"] == "-"


@pytest.mark.parametrize("pattern", ["skills", "skills/*", "skills/pick.py"])
@pytest.mark.parametrize("inside", [True, False], ids=["from-the-project", "from-outside"])
def test_project_excludes_see_explicit_files_and_folders_from_anywhere(
        repo: Path, pattern: str, inside: bool):
    """``[tool.ezmigrate] exclude`` is relative to its pyproject.toml, as in ruff: it holds
    for files pre-commit names and for folders, whatever folder the run starts from."""
    (repo / "pyproject.toml").write_text(f'[tool.ezmigrate]\nexclude = ["{pattern}"]\n',
                                         encoding="utf-8")
    cwd = repo if inside else repo.parent
    base = Path(".") if inside else Path(repo.name)
    for target in (base / "skills" / "pick.py", base):
        proc = ezmigrate("rewrite", "--check", "--no-verify", target, cwd=cwd)
        assert proc.returncode == 0 and proc.stdout == b"", (target, proc.stderr)
    (repo / "pyproject.toml").write_text('[tool.ezmigrate]\nexclude = ["other"]\n',
                                         encoding="utf-8")
    kept = ezmigrate("rewrite", "--check", "--no-verify", base / "skills" / "pick.py", cwd=cwd)
    assert kept.returncode == 1 and b"would rewrite" in kept.stdout


@pytest.mark.parametrize("pattern", ["src/legacy", "src/legacy/*", "src/*/pick.py"])
def test_excludes_with_several_folders_match_leading_folders(tmp_path: Path, pattern: str):
    """``exclude = ["src/legacy"]`` holds for ``src/legacy/pick.py``, named or walked."""
    (tmp_path / "src" / "legacy").mkdir(parents=True)
    shutil.copy(PICK, tmp_path / "src" / "legacy" / "pick.py")
    (tmp_path / "pyproject.toml").write_text(f'[tool.ezmigrate]\nexclude = ["{pattern}"]\n',
                                             encoding="utf-8")
    for target in (Path("src") / "legacy" / "pick.py", Path(".")):
        proc = ezmigrate("rewrite", "--check", "--no-verify", target, cwd=tmp_path)
        assert proc.returncode == 0 and proc.stdout == b"", (target, proc.stderr)
    (tmp_path / "pyproject.toml").write_text('[tool.ezmigrate]\nexclude = ["src/other"]\n',
                                             encoding="utf-8")
    kept = ezmigrate("rewrite", "--check", "--no-verify", ".", cwd=tmp_path)
    assert kept.returncode == 1 and b"would rewrite" in kept.stdout


def test_output_dir_refuses_a_second_file_with_the_same_relative_path(tmp_path: Path):
    """c1/x.py and c2/x.py would both be out/x.py: the second is refused, named with the
    first, and the run says so (exit 1) instead of reporting two files changed."""
    for folder, source in (("c1", PICK), ("c2", FIXTURES / "legacy" / "conditions.py")):
        (tmp_path / folder).mkdir()
        shutil.copy(source, tmp_path / folder / "x.py")
    out, report = tmp_path / "out", tmp_path / "r.json"
    proc = ezmigrate("rewrite", "--no-verify", "c1/x.py", "c2/x.py", "--output-dir", "out",
                     "--report", report, cwd=tmp_path)
    stderr = proc.stderr.decode()
    assert proc.returncode == 1, stderr
    assert "c2/x.py: its copy out/x.py would overwrite the copy of c1/x.py" in stderr
    assert "1 file changed" in stderr
    assert (out / "x.py").read_bytes() == PICK_MIGRATED.read_bytes()
    assert sorted(p.name for p in out.iterdir()) == ["x.py"]
    skills = json.loads(report.read_text(encoding="utf-8"))["skills"]
    refused = [s for s in skills if s["class"] not in ("Pick", "Place", "PickAndPlace")]
    assert refused and all(s["status"] == "failed" and "would overwrite" in s["reason"]
                           for s in refused), refused
