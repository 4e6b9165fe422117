"""Small things a user notices (issue 22, item 12), each through the real command line."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

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
