"""The skill index covers the whole repository, whatever files a run names (issue 21,
patterns 1 and 7): children defined in unstaged siblings, in files Python 3 cannot parse,
or in two packages of one repository are never reported as errors on a guess.

Real files in git repositories made in a temporary folder, the real check core (compound
pass, static reader), no mocks.
"""

from __future__ import annotations

import subprocess
import textwrap
from pathlib import Path

from ezmigrate.checking.pipeline import run_check
from ezmigrate.compound.repository import read_classes, recover_classes
from ezmigrate.files.discover import repository_root
from ezmigrate.lint.diagnostic import Diagnostic
from ezmigrate.verify.pool import PoolConfig

HEADER = """\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element
from skiros2_skill.core.skill import SkillBase
"""


def description(name: str, *keys: str) -> str:
    body = "".join(f'        self.addParam("{k}", Element("skiros:Location"), '
                   "ParamTypes.Required)\n" for k in keys) or "        pass\n"
    return f"\n\nclass {name}(SkillDescription):\n    def createDescription(self):\n{body}"


def compound(child: str, specify: str = "") -> str:
    extra = f", specify={{{specify!r}: 1.0}}" if specify else ""
    return textwrap.dedent(f'''


        class Task(SkillDescription):
            def createDescription(self):
                pass


        class task(SkillBase):
            def createDescription(self):
                self.setDescription(Task(), self.__class__.__name__)

            def expand(self, skill):
                skill(self.skill("{child}", ""{extra}))
        ''')


def write(root: Path, files: dict[str, str]) -> Path:
    for name, text in files.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
    subprocess.run(["git", "init", "-q", str(root)], check=True)
    return root


def ez3(paths: list[Path]) -> list[Diagnostic]:
    outcome = run_check(paths, None, PoolConfig(workers=1))
    return [d for d in outcome.diagnostics if d.code.startswith("EZ3")]


def brief(found: list[Diagnostic]) -> set[tuple[str, int, str, str]]:
    return {(Path(d.path).name, d.line, d.code, d.severity) for d in found}


def test_a_child_in_an_unstaged_sibling_is_known_when_one_file_is_named(tmp_path: Path):
    repo = write(tmp_path / "repo", {
        "pkg/descriptions.py": HEADER + description("Navigate", "Target"),
        "pkg/tasks.py": HEADER + compound("Navigate", "Target"),
    })
    assert ez3([repo / "pkg" / "tasks.py"]) == []
    # near miss: a child defined nowhere in the repository is still an error
    (repo / "pkg" / "tasks.py").write_text(HEADER + compound("Navigat"), encoding="utf-8")
    found = ez3([repo / "pkg" / "tasks.py"])
    assert brief(found) == {("tasks.py", 18, "EZ301", "error")}


def test_one_named_file_gets_exactly_the_findings_of_the_repository_run(tmp_path: Path):
    repo = write(tmp_path / "repo", {
        "a/descriptions.py": HEADER + description("Navigate", "Target"),
        "b/tasks.py": HEADER + compound("Navigate", "Targt"),
        "b/other.py": HEADER + compound("Nowhere").replace("Task", "Other").replace(
            "task", "other"),
    })
    alone = brief(ez3([repo / "b" / "tasks.py"]))
    whole = {f for f in brief(ez3([repo])) if f[0] == "tasks.py"}
    assert alone == whole == {("tasks.py", 18, "EZ307", "error")}


def test_descriptions_of_a_python_2_file_are_recovered_not_reported(tmp_path: Path):
    py2 = description("Scan", "Area") + "        print 'python 2'\n"  # in the class itself
    repo = write(tmp_path / "repo", {"pkg/old.py": HEADER + py2,
                                     "pkg/tasks.py": HEADER + compound("Scan", "Nope")})
    assert ez3([repo / "pkg" / "tasks.py"]) == []  # the type exists; its keys are unknown
    assert ez3([repo]) == []
    # near miss: the same file parsable, the wrong specify key is certain
    (repo / "pkg" / "old.py").write_text(HEADER + description("Scan", "Area"),
                                         encoding="utf-8")
    assert {f[2] for f in brief(ez3([repo / "pkg" / "tasks.py"]))} == {"EZ307"}


def test_an_unreadable_file_makes_an_unknown_child_informational(tmp_path: Path):
    repo = write(tmp_path / "repo", {"pkg/tasks.py": HEADER + compound("Scan")})
    (repo / "pkg" / "broken.py").write_bytes(b"\xff\xfeclass Scan(SkillDescription):\n")
    found = ez3([repo / "pkg" / "tasks.py"])
    assert brief(found) == {("tasks.py", 18, "EZ301", "info")}
    assert "broken.py" in found[0].message and "could not be read" in found[0].message


def test_a_type_defined_in_two_packages_is_read_from_its_own(tmp_path: Path):
    repo = write(tmp_path / "repo", {
        "arm/descriptions.py": HEADER + description("Scan", "Area"),
        "arm/tasks.py": HEADER + compound("Scan", "Zone"),
        "base/descriptions.py": HEADER + description("Scan", "Zone"),
    })
    assert {f[2] for f in brief(ez3([repo]))} == {"EZ307"}  # arm's Scan has no Zone
    (repo / "arm" / "tasks.py").write_text(HEADER + compound("Scan", "Area"),
                                           encoding="utf-8")
    assert ez3([repo]) == []


def test_a_type_defined_twice_equally_near_is_judged_only_where_both_agree(tmp_path: Path):
    repo = write(tmp_path / "repo", {
        "pkg/one.py": HEADER + description("Scan", "Area"),
        "pkg/two.py": HEADER + description("Scan", "Zone"),
        "pkg/tasks.py": HEADER + compound("Scan", "Zone"),
    })
    assert ez3([repo]) == []  # one of the two declares Zone: not certain
    (repo / "pkg" / "tasks.py").write_text(HEADER + compound("Scan", "Speed"),
                                           encoding="utf-8")
    assert {f[2] for f in brief(ez3([repo]))} == {"EZ307"}  # neither declares Speed


def test_recover_classes_reads_python_2_modules(tmp_path: Path):
    source = (b"class Wave(SkillDescription):\n    def createDescription(self):\n"
              b"        print 'x'\n\nclass wave(SkillBase):\n    def createDescription(self):\n"
              b"        self.setDescription(Wave(), 'wave')\n\nclass Helper(object):\n"
              b"    pass\n")
    assert recover_classes(source) == [("Wave", 1, None), ("wave", 5, "Wave")]


def test_the_scope_of_a_named_file_is_its_git_top_level_else_its_package(tmp_path: Path):
    package = tmp_path / "ws" / "pkg"
    (package / "src").mkdir(parents=True)
    (package / "package.xml").write_text("<package/>", encoding="utf-8")
    (package / "src" / "a.py").write_text("", encoding="utf-8")
    assert repository_root(package / "src" / "a.py") == package.resolve()
    subprocess.run(["git", "init", "-q", str(tmp_path / "ws")], check=True)
    assert repository_root(package / "src" / "a.py") == (tmp_path / "ws").resolve()
    assert repository_root(package) == package


def test_an_implementation_with_its_own_label_is_no_description(tmp_path: Path):
    implementation = HEADER + description("Navigate", "Target") + textwrap.dedent('''


        class drive(SkillBase):
            def createDescription(self):
                self.setDescription(Navigate(), "drive_mobile_base")
        ''')
    repo = write(tmp_path / "repo", {"pkg/drive.py": implementation,
                                     "pkg/tasks.py": HEADER + compound("drive")})
    assert brief(ez3([repo / "pkg" / "tasks.py"])) == {("tasks.py", 18, "EZ301", "error")}
    (repo / "pkg" / "tasks.py").write_text(HEADER + compound("Navigate"), encoding="utf-8")
    assert ez3([repo / "pkg" / "tasks.py"]) == []


def test_a_file_naming_a_description_in_a_comment_is_read_where_the_run_reads(
        tmp_path: Path, monkeypatch):
    """A file that mentions ``SkillDescription`` outside its code is not a description
    file, but the repository scan must still learn whether it parses: an unreadable one
    softens an unknown child. The run's reading learns it (``FileFacts.parsed``,
    ``unparsed``); the scan parses none of the run's files again."""
    from ezmigrate.compound import repository

    scanned: list[str] = []
    real = repository._scan_file
    monkeypatch.setattr(repository, "_scan_file", lambda candidate, *rest, **kw: (
        scanned.append(candidate.relative), real(candidate, *rest, **kw))[1])
    repo = write(tmp_path / "repo", {
        "pkg/tasks.py": HEADER + compound("Scan"),
        "pkg/notes.py": "# not a SkillDescription any more\nVALUE = 1\n",
    })
    assert brief(ez3([repo])) == {("tasks.py", 18, "EZ301", "error")}
    (repo / "pkg" / "notes.py").write_text("# a SkillDescription, once\nx = '''\n",
                                           encoding="utf-8")  # not even tokenize reads it
    found = ez3([repo])
    assert brief(found) == {("tasks.py", 18, "EZ301", "info")}
    assert "notes.py" in found[0].message and "could not be read" in found[0].message
    assert scanned == []


# A module ``ast`` cannot parse (Python 2) is read class by class (``read_classes``): a
# description class that parses on its own, with the module's imports, has its keys known;
# one holding Python 2 syntax itself stays a type whose keys are unknown.
IMPLEMENTATION = textwrap.dedent('''


    class scan(SkillBase):
        def createDescription(self):
            self.setDescription(Scan(), self.__class__.__name__)

        def execute(self):
            try:
                pass
            except Exception, e:
                print "failed", e
            return self.success("")
    ''')


def remapping(child: str, key: str) -> str:
    return textwrap.dedent(f'''


        class Task(SkillDescription):
            def createDescription(self):
                self.addParam("Place", Element("skiros:Location"), ParamTypes.Required)


        class task(SkillBase):
            def createDescription(self):
                self.setDescription(Task(), self.__class__.__name__)

            def expand(self, skill):
                skill(self.skill("{child}", "", remap={{"{key}": "Place"}}))
        ''')


def test_a_python_2_module_whose_description_parses_alone_has_its_keys_known(
        tmp_path: Path):
    py2 = HEADER + description("Scan", "Area") + IMPLEMENTATION
    repo = write(tmp_path / "repo", {"pkg/old.py": py2,
                                     "pkg/tasks.py": HEADER + remapping("Scan", "Aera")})
    found = brief(ez3([repo / "pkg" / "tasks.py"]))
    assert {(f[0], f[2]) for f in found} == {("tasks.py", "EZ304")}
    assert {(f[0], f[2]) for f in brief(ez3([repo]))} == {("tasks.py", "EZ304")}
    (repo / "pkg" / "tasks.py").write_text(HEADER + remapping("Scan", "Area"),
                                           encoding="utf-8")
    assert ez3([repo / "pkg" / "tasks.py"]) == []
    assert ez3([repo]) == []
    (repo / "pkg" / "tasks.py").write_text(HEADER + compound("Scan", "Nope"),
                                           encoding="utf-8")
    assert {f[2] for f in brief(ez3([repo]))} == {"EZ307"}


def test_a_python_2_description_class_stays_unknown(tmp_path: Path):
    """Near miss: the Python 2 syntax in the description class itself."""
    py2 = (HEADER + description("Scan", "Area") + "        print 'python 2'\n"
           + IMPLEMENTATION)
    repo = write(tmp_path / "repo", {"pkg/old.py": py2,
                                     "pkg/tasks.py": HEADER + remapping("Scan", "Aera")})
    assert ez3([repo / "pkg" / "tasks.py"]) == []
    assert ez3([repo]) == []


def test_read_classes_reads_only_what_parses_on_its_own():
    source = (HEADER + "X = 'Area'\n" + description("Scan", "Area")
              + description("Wave") + "        print 'x'\n"
              + "\n\n@decorated\nclass Marked(SkillDescription):\n"
              "    def createDescription(self):\n        self.addParam('A', 1, "
              "ParamTypes.Optional)\n"
              + "\n\nclass Named(SkillDescription):\n    def createDescription(self):\n"
              "        self.addParam(X, 1, ParamTypes.Optional)\n"
              + "\n\nclass Derived(Scan):\n    pass\n"
              + IMPLEMENTATION).encode()
    models = read_classes(source, "old.py")
    assert list(models) == [("Scan", 8)]  # not Wave (print), Marked, Named, Derived
    assert {p["key"] for p in models[("Scan", 8)]["params"]} >= {"Area"}


def test_read_classes_keeps_lines_and_encoding():
    source = ("# -*- coding: latin-1 -*-\r\nfrom skiros2_common.core.abstract_skill import "
              "SkillDescription\r\nfrom skiros2_common.core.params import ParamTypes\r\n"
              "\r\nprint 'caf\xe9'\r\n\r\nclass Scan(SkillDescription):\r\n"
              "    def createDescription(self):\r\n"
              "        self.addParam('Caf\xe9', 1, ParamTypes.Optional)\r\n").encode("latin-1")
    models = read_classes(source, "old.py")
    assert list(models) == [("Scan", 7)]
    assert {p["key"] for p in models[("Scan", 7)]["params"]} >= {"Caf\xe9"}
    assert read_classes(b"\xff\xfeclass Scan(SkillDescription):\n", "x.py") == {}
    assert read_classes(source[:-30], "old.py") == {}  # the tokens stop in the class
