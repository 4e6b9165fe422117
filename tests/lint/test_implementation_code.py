"""The early checks inside implementation code (issue 30): ``self.params["Key"]`` against
the implemented description (EZ109) and ``Element("p:Class")`` literals one edit away from
a known class (EZ214). Each has its trigger and its near miss, in a real repository checked
by the real CLI."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path

import pytest
from check_support import cli

MODULE = """\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element
from skiros2_skill.core.primitive import PrimitiveBase


class Inspect(SkillDescription):
    def createDescription(self):
        self.addParam("Target", Element("skiros:Location"), ParamTypes.Required)


class inspect(PrimitiveBase):
    def createDescription(self):
        self.setDescription(Inspect(), self.__class__.__name__)

    def modifyDescription(self, skill):
        skill.addParam("Camera", Element("skiros:DepthCamera"), ParamTypes.Optional)

    def execute(self):
        target = self.params["{key}"].value
        robot = self.params["Robot"].value
        camera = self.params["Camera"].value
        box = self._wmi.resolve_element(Element("{cls}"))
        return self.success(str((target, robot, camera, box)))
"""


def _found(tmp_path: Path, key: str, cls: str) -> list[tuple[str, int, str]]:
    (tmp_path / "pkg").mkdir(parents=True)
    (tmp_path / "pkg" / "inspect.py").write_text(MODULE.format(key=key, cls=cls),
                                                 encoding="utf-8")
    subprocess.run(["git", "init", "-q", str(tmp_path)], check=True)
    run = cli(".", "--output-format", "json", "--select", "EZ109,EZ214", cwd=tmp_path)
    assert run.returncode in (0, 1), run.stderr
    return [(str(d["code"]), int(d["line"]), str(d["severity"])) for d in json.loads(run.stdout)]


@pytest.mark.parametrize(("key", "cls", "expected"), [
    ("Traget", "skiros:Location", [("EZ109", 20, "error")]),
    ("Target", "skiros:LargeBoxx", [("EZ214", 23, "warning")]),
    ("Target", "skiros:LargeBox", []),  # near misses: declared key, known class
    ("Target", "lab:Widget", []),  # far from every known class: the lab's own, unseen
])
def test_implementation_code_is_checked_against_what_the_repository_declares(
        tmp_path: Path, key: str, cls: str, expected: list[tuple[str, int, str]]) -> None:
    assert _found(tmp_path, key, cls) == expected


def test_the_message_names_the_key_and_the_fix_the_class(tmp_path: Path) -> None:
    (tmp_path / "a").mkdir()
    (tmp_path / "a" / "inspect.py").write_text(MODULE.format(key="target",
                                                             cls="skiros:LargeBoxx"),
                                               encoding="utf-8")
    subprocess.run(["git", "init", "-q", str(tmp_path)], check=True)
    data = json.loads(cli(".", "--output-format", "json", "--select", "EZ109,EZ214",
                          cwd=tmp_path).stdout)
    by_code = {d["code"]: d for d in data}
    assert "self.params['target']" in by_code["EZ109"]["message"]
    assert by_code["EZ109"]["fix"] == "self.params['Target']"
    assert "did you mean skiros:LargeBox?" in by_code["EZ214"]["message"]


READS = """\
from skiros2_skill.core.primitive import PrimitiveBase


class calibrate(PrimitiveBase):
    def createDescription(self):
        self.setDescription(Inspect(), self.__class__.__name__)

    def execute(self):
        camera = self.params["Target"].value
        camera.setProperty("lab:FocalX", 1.0)
        fx = camera.getProperty("lab:FocalX").value
        a = camera.getProperty("lab:Mean").value
        b = camera.getProperty("lab:Mean").value if camera.hasProperty("lab:Mean") else 0
        return self.success(str((fx, a, b)))
"""


def test_a_property_nothing_sets_is_one_info_finding_per_project(tmp_path: Path) -> None:
    """Set in the code (lab:FocalX): nothing; read three times and set nowhere (lab:Mean):
    one info finding that counts the reads (issue 30)."""
    (tmp_path / "pkg").mkdir()
    (tmp_path / "pkg" / "inspect.py").write_text(
        MODULE.format(key="Target", cls="skiros:Location")
        + READS.split("\n", 2)[2], encoding="utf-8")
    subprocess.run(["git", "init", "-q", str(tmp_path)], check=True)
    data = json.loads(cli(".", "--output-format", "json", "--select", "EZ215",
                          cwd=tmp_path).stdout)
    assert [(d["code"], d["severity"]) for d in data] == [("EZ215", "info")]
    assert data[0]["message"].startswith("calibrate: lab:Mean: nothing in the repository")
    assert "(3 reads of lab:Mean in the project, reported once)" in data[0]["message"]


def test_an_implementation_reads_the_nearest_description_of_its_name(tmp_path: Path) -> None:
    """Two packages of one checkout define ``Inspect`` with different keys (two labs'
    ``ChangeStiffness`` side by side, met on the public repositories): each implementation
    is judged against its own package's description, whichever the index read last."""
    for package, key in (("a_pkg", "Target"), ("b_pkg", "Goal")):
        (tmp_path / package).mkdir()
        (tmp_path / package / "package.xml").write_text(f"<package><name>{package}</name>"
                                                         "</package>", encoding="utf-8")
        (tmp_path / package / "inspect.py").write_text(
            MODULE.format(key=key, cls="skiros:Location").replace(
                'self.addParam("Target"', f'self.addParam("{key}"'), encoding="utf-8")
    subprocess.run(["git", "init", "-q", str(tmp_path)], check=True)
    run = cli(".", "--output-format", "json", "--select", "EZ109", cwd=tmp_path)
    assert run.returncode == 0, run.stdout + run.stderr
    assert json.loads(run.stdout) == []
    # the trigger: a key neither package's description declares
    (tmp_path / "b_pkg" / "inspect.py").write_text(
        MODULE.format(key="Target", cls="skiros:Location").replace(
            'self.addParam("Target"', 'self.addParam("Goal"'), encoding="utf-8")
    found = json.loads(cli(".", "--output-format", "json", "--select", "EZ109",
                           cwd=tmp_path).stdout)
    assert [(d["code"], d["path"].split("/")[-2]) for d in found] == [("EZ109", "b_pkg")]


SETTERS = '''\
import lab


@lab.register(lambda element: element.setProperty("lab:FromDecorator", 1))
def helper(element):
    return element


def setter(element):
    element.setProperty(
        "lab:Spread", 2)
    return element.getPropCond("c", "lab:Cond", "Object", "=", 1, True)


def unrelated(element):
    return element.getProperty("lab:Read")
'''


@pytest.mark.parametrize("newline", ["\n", "\r\n", "\r"])
def test_the_properties_a_module_sets_are_found_wherever_they_are_written(
        newline: str) -> None:
    """Only the statements whose lines name a setter are walked for the properties set: one
    whose setter sits in a decorator, above its ``def``, or on a continuation line, counts
    too, whatever the file's line endings."""
    import ast

    from ezmigrate.checking.implementation_code import module_facts

    data = SETTERS.replace("\n", newline).encode()
    facts = module_facts(ast.parse(data), data)
    assert facts.sets == {"lab:FromDecorator", "lab:Spread", "lab:Cond"}
