"""Small things a user notices (issue 22, item 12), each through the real command line."""

from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures"


def ezmigrate(cwd: Path, *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "ezmigrate", *args], cwd=cwd,
                          capture_output=True, text=True, stdin=subprocess.DEVNULL,
                          timeout=300, check=False)


def test_a_gitignored_file_named_explicitly_is_skipped_with_a_word(tmp_path: Path):
    subprocess.run(["git", "init", "-q", str(tmp_path)], check=True)
    (tmp_path / "pkg").mkdir()
    legacy = (FIXTURES / "legacy" / "pick_and_place.py").read_bytes()
    (tmp_path / "pkg" / "generated.py").write_bytes(legacy)
    (tmp_path / ".gitignore").write_text("pkg/generated.py\n", encoding="utf-8")
    for command in (("rewrite", "--no-verify"), ("check",)):
        run = ezmigrate(tmp_path, *command, "pkg/generated.py")
        assert run.returncode == 0, run.stderr
        assert "ezmigrate: pkg/generated.py: skipped, git ignores it (.gitignore)\n" \
            in run.stderr, command
    assert (tmp_path / "pkg" / "generated.py").read_bytes() == legacy


TAGGED = '''

class fetch_tagged(SkillBase):
    """Labels its children after the instance, as real code does to tell runs apart."""

    def createDescription(self):
        self.setDescription(FetchPart(), "fetch_tagged_%d" % id(self))

    def expand(self, skill):
        skill.setProcessor(SerialStar())
        skill(
            self.skill("Navigate", "navigate_%x" % id(self), remap={"Target": "Shelf"}),
            self.skill("Pick", "pick_%s" % hex(id(skill)), remap={"Container": "Shelf"}),
        )
'''


def test_the_report_is_the_same_on_every_run_when_expand_uses_id(tmp_path: Path):
    repo = tmp_path / "repo"
    shutil.copytree(FIXTURES / "compound_repo", repo)
    with (repo / "lab_tasks" / "src" / "lab_tasks" / "tasks.py").open("a") as tasks:
        tasks.write(TAGGED)
    reports = []
    for run in (1, 2):
        done = ezmigrate(tmp_path, "rewrite", "--dry-run", "repo", "--report", f"r{run}.md")
        assert done.returncode == 0, done.stderr
        reports.append((tmp_path / f"r{run}.md").read_text(encoding="utf-8"))
    assert reports[0] == reports[1]
    assert "navigate_1</i>" in reports[0] and "pick_0x2</i>" in reports[0]


def test_after_an_interrupted_run_the_reruns_report_covers_the_whole_tree(tmp_path: Path):
    """The first run is stopped (SIGINT) once it wrote one file; the rerun's report lists
    that file's descriptions too, as migrated by an earlier run."""
    tree = tmp_path / "tree"
    tree.mkdir()
    for name in ("pick_and_place.py", "descriptions.py"):
        shutil.copy(FIXTURES / "legacy" / name, tree / name)
    hold = tmp_path / "hold"
    hold.mkdir()
    env = {**os.environ, "EZMIGRATE_HOLD_DIR": str(hold), "EZMIGRATE_HOLD_AT": "written:1"}
    first = subprocess.Popen([sys.executable, "-m", "ezmigrate", "rewrite", "--no-verify",
                              "tree"], cwd=tmp_path, env=env, stdin=subprocess.DEVNULL,
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        while not (hold / "written:1.reached").exists():  # the run holds there until "go"
            assert first.poll() is None, first.communicate()[1]
            time.sleep(0.005)
        first.send_signal(signal.SIGINT)
        (hold / "written:1.go").touch()
        _, stderr = first.communicate(timeout=300)
    finally:
        (hold / "written:1.go").touch()
        if first.poll() is None:
            first.kill()
            first.wait()
    assert first.returncode == 128 + signal.SIGINT, stderr
    second = ezmigrate(tmp_path, "rewrite", "--no-verify", "--report", "r.json", "tree")
    assert second.returncode == 0, second.stderr
    skills = json.loads((tmp_path / "r.json").read_text(encoding="utf-8"))["skills"]
    by_file: dict[str, set[str]] = {}
    for skill in skills:
        by_file.setdefault(skill["file"], set()).add(skill["status"])
    assert by_file == {"tree/descriptions.py": {"unchanged"},  # written by the first run
                       "tree/pick_and_place.py": {"converted"}}, by_file
    earlier = [s for s in skills if s["status"] == "unchanged"]
    assert all(s["reason"] == "already an EzSkiROS description (migrated by an earlier run)"
               for s in earlier)
    # one run, one count: stderr's summary counts what the report lists
    converted = sum(s["status"] == "converted" for s in skills)
    assert (f"{len(skills)} skills found, {converted} converted, 0 skipped, 0 failed, "
            f"{len(earlier)} unchanged") in second.stderr, second.stderr


def test_check_with_no_path_checks_the_working_directory(tmp_path: Path):
    """As ruff: ``ezmigrate check`` is ``ezmigrate check .``."""
    shutil.copy(FIXTURES / "legacy" / "param_values.py", tmp_path / "skills.py")
    bare = ezmigrate(tmp_path, "check", "--output-format", "json")
    dotted = ezmigrate(tmp_path, "check", "--output-format", "json", ".")
    assert bare.returncode == dotted.returncode == 1, bare.stderr
    assert json.loads(bare.stdout) == json.loads(dotted.stdout) != []


def test_text_findings_say_their_severity_and_quiet_keeps_the_errors(tmp_path: Path):
    shutil.copy(FIXTURES / "compound_repo" / "lab_tasks" / "src" / "lab_tasks" / "mistakes.py",
                tmp_path / "mistakes.py")
    shutil.copy(FIXTURES / "legacy" / "param_values.py", tmp_path / "skills.py")
    data = json.loads(ezmigrate(tmp_path, "check", "--output-format", "json").stdout)
    lines = ezmigrate(tmp_path, "check").stdout.splitlines()
    shown = [line.split(" ", 3)[2] for line in lines]
    assert shown == [f"[{d['severity']}]" for d in data]
    assert {"[error]", "[warning]"} <= set(shown)
    quiet = ezmigrate(tmp_path, "check", "-q").stdout.splitlines()
    assert quiet == [line for line in lines if " [error] " in line] != []


@pytest.mark.parametrize("flag", ["-V", "--version"])
def test_the_version_flags(tmp_path: Path, flag: str):
    run = ezmigrate(tmp_path, flag)
    assert run.returncode == 0 and run.stdout.startswith("ezmigrate, version "), run.stderr
