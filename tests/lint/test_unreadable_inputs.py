"""One bad file does not abort a run, and a fix hint never points at a suggestion that is
not there (issue 21, patterns 6 and 9). Real CLI on real files in temporary folders."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path

from check_support import cli, legacy

UNKNOWN = legacy('self.addParam("Fruit", Element("skiros:Banana"), ParamTypes.Required)')
CLOSE = legacy('self.addParam("Fruit", Element("skiros:Prodcut"), ParamTypes.Required)')
PY2 = legacy('self.addParam("Spot", Element("skiros:Location"), ParamTypes.Required)'
             ).replace("class Skill(", "class Old(") + '\n\ndef legacy():\n    print "python 2"\n'


def _repo(tmp_path: Path, files: dict[str, str]) -> Path:
    for name, text in files.items():
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text(text, encoding="utf-8")
    subprocess.run(["git", "init", "-q", str(tmp_path)], check=True)
    return tmp_path


def _json(run: subprocess.CompletedProcess[str]) -> list[dict[str, object]]:
    return json.loads(run.stdout)


def test_an_unparsable_or_empty_discovered_file_is_info_and_skipped(tmp_path: Path):
    repo = _repo(tmp_path, {"pkg/old.py": PY2, "pkg/skill.py": UNKNOWN, "owl/empty.owl": ""})
    run = cli(".", "--output-format", "json", cwd=repo)
    assert run.returncode == 0, run.stderr
    found = {(Path(str(d["path"])).name, d["code"], d["severity"]) for d in _json(run)}
    assert found == {("old.py", "EZ905", "info"), ("skill.py", "EZ209", "warning")}
    assert "empty.owl" in run.stderr and "skipped" in run.stderr
    # near miss: the same repository with the file fixed reports only the real finding
    (repo / "pkg" / "old.py").write_text(PY2.replace('print "python 2"', 'print("3")'))
    found = {d["code"] for d in _json(cli(".", "--output-format", "json", cwd=repo))}
    assert found == {"EZ209"}


def test_a_fix_names_a_suggestion_only_when_there_is_one(tmp_path: Path):
    bare = _json(cli(".", "--output-format", "json", cwd=_repo(tmp_path / "a",
                                                                {"skill.py": UNKNOWN})))
    assert [d["code"] for d in bare] == ["EZ209"]
    assert "suggestion" not in str(bare[0]["fix"]) and str(bare[0]["fix"]).startswith(
        "Fix the name, or load")
    close = _json(cli(".", "--output-format", "json", cwd=_repo(tmp_path / "b",
                                                                 {"skill.py": CLOSE})))
    assert [d["code"] for d in close] == ["EZ209"]
    assert "skiros:Product" in str(close[0]["fix"])


COMPOUND = legacy('self.addParam("Spot", Element("skiros:Location"), ParamTypes.Required)'
                  ).replace("class Skill(", "class Survey(") + '''

from skiros2_skill.core.skill import SkillBase


class survey(SkillBase):
    def createDescription(self):
        self.setDescription(Survey(), self.__class__.__name__)

    def expand(self, skill):
        skill(self.skill("{child}", ""))
'''


def test_an_unknown_child_is_never_offered_the_compounds_own_type(tmp_path: Path):
    own = _json(cli(".", "--output-format", "json", "--select", "EZ3",
                    cwd=_repo(tmp_path / "a", {"t.py": COMPOUND.format(child="Survy")})))
    assert [d["code"] for d in own] == ["EZ301"]
    assert "Survey" not in str(own[0]["fix"]) and "suggestion" not in str(own[0]["fix"])
    other = _json(cli(".", "--output-format", "json", "--select", "EZ3",
                      cwd=_repo(tmp_path / "b", {"t.py": COMPOUND.format(child="Wiat")})))
    assert [(d["code"], d["fix"]) for d in other] == [("EZ301", "Did you mean 'Wait'?")]
