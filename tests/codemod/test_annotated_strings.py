"""Strings in annotations (issue 43, pyflakes F722 and F821): written in ``Annotated[...]``.

pyflakes parses every string literal of an annotation as a forward reference: the verbatim
type ``ELEMENT("scalable:Workstation")`` is F722 (a syntax error), a description
``DESC("compliant|joint_config")`` is F821 twice (``compliant``, ``joint_config``). It does
not parse the items after the first of a subscript named ``Annotated``, so the codemod
writes ``DESC``, ``KEY`` and a verbatim ``ELEMENT`` there. Each output below is also run
through flake8 (pyflakes) and ruff with their default rules, which must find nothing.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

from codemod_case import HEADER, assert_migrates, assert_unchanged, run

DEFAULT_RULES = "E4,E7,E9,F"


def case(body: str) -> str:
    return HEADER + "\n\nclass S(SkillDescription):\n    def createDescription(self):\n" + body


def lint(tmp_path: Path, source: str) -> list[str]:
    """The codes flake8 (its defaults, but E501: line length is no matter here) and ruff
    (its classic defaults) report on ``source``, written to a real file."""
    path = tmp_path / "skill.py"
    path.write_text(source, encoding="utf-8")
    flake8 = subprocess.run([sys.executable, "-m", "flake8", "--isolated", "--extend-ignore",
                             "E501", "--format", "%(code)s", str(path)],
                            capture_output=True, text=True, check=False, timeout=120)
    assert flake8.returncode in (0, 1), flake8.stderr
    ruff = subprocess.run([sys.executable, "-m", "ruff", "check", "--isolated", "--no-cache",
                           "--select", DEFAULT_RULES, "--output-format", "json", "--exit-zero",
                           str(path)], capture_output=True, text=True, check=False, timeout=120)
    assert ruff.returncode == 0, ruff.stderr
    return flake8.stdout.split() + [f["code"] for f in json.loads(ruff.stdout)]


def test_a_verbatim_type_a_description_and_a_key_go_in_annotated(tmp_path: Path) -> None:
    result = assert_migrates(case(
        '        self.addParam("Target", Element("scalable:Workstation"), ParamTypes.Required)\n'
        '        self.addParam("Place", Element(":Location"), ParamTypes.Inferred, [], "where")\n'
        '        self.addParam("Object", Element("skiros:TransformationPose"), ParamTypes.Required, [], "The position of the prompt object")\n'
        '        self.addParam("Controller", "", ParamTypes.Required, [], "compliant|joint_config")\n'
        '        self.addParam("On/Off", True, ParamTypes.Optional)\n'
    ), '''\
from ezskiros_runtime import (
    SkillDescription,
    Annotated,
    INFERRED,
    OPTIONAL,
    REQUIRED,
    ELEMENT,
    KEY,
    DESC,
)
from ezskiros_runtime.ontology import skiros


class S(SkillDescription):
    def description(self,
                    Target: Annotated[REQUIRED, ELEMENT("scalable:Workstation")],
                    Place: Annotated[INFERRED, ELEMENT(":Location"), DESC("where")],
                    Object: Annotated[skiros.TransformationPose, DESC("The position of the prompt object")],
                    Controller: Annotated[str, DESC("compliant|joint_config")] = "",
                    On_Off: Annotated[OPTIONAL[bool], KEY("On/Off")] = True):
        pass
''')
    assert isinstance(result.new_source, str)
    assert lint(tmp_path, result.new_source) == []


def test_options_stay_in_the_kind_form_or_follow_a_verbatim_type(tmp_path: Path) -> None:
    result = assert_migrates(case(
        '        self.addParam("Cam", Element("skiros:Location"), ParamTypes.Required, [ParamOptions.Lock], "camera")\n'
        '        self.addParam("Torch", Element("rparts:WeldingTorch"), ParamTypes.Inferred, [ParamOptions.Lock])\n'
    ), '''\
from ezskiros_runtime import SkillDescription, Annotated, INFERRED, REQUIRED, ELEMENT, DESC, Lock
from ezskiros_runtime.ontology import skiros


class S(SkillDescription):
    def description(self,
                    Cam: Annotated[REQUIRED[skiros.Location, Lock], DESC("camera")],
                    Torch: Annotated[INFERRED, ELEMENT("rparts:WeldingTorch"), Lock]):
        pass
''')
    assert isinstance(result.new_source, str)
    assert lint(tmp_path, result.new_source) == []


def test_forms_without_strings_are_written_as_before() -> None:
    """No-op for the new form: nothing holds a string, so no ``Annotated``."""
    assert_migrates(case(
        '        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)\n'
        '        self.addParam("Cam", Element("skiros:Location"), ParamTypes.Optional, [ParamOptions.Lock])\n'
        '        self.addParam("Any", Element(), ParamTypes.Inferred)\n'
        '        self.addParam("Speed", 0.5, ParamTypes.Optional)\n'
    ), '''\
from ezskiros_runtime import SkillDescription, INFERRED, OPTIONAL, ELEMENT, Lock
from ezskiros_runtime.ontology import skiros


class S(SkillDescription):
    def description(self,
                    Object: skiros.Product,
                    Cam: OPTIONAL[skiros.Location, Lock],
                    Any: INFERRED[ELEMENT()],
                    Speed: OPTIONAL[float] = 0.5):
        pass
''')


def test_a_module_that_binds_annotated_keeps_the_kind_form() -> None:
    """``typing.Annotated`` refuses a kind marker before Python 3.11, and an alias
    (``EzAnnotated``) is no ``Annotated`` to pyflakes: the strings stay in the brackets."""
    result = run("from typing import Annotated\n" + case(
        '        self.addParam("Speed", 0.5, ParamTypes.Optional, [], "m/s")\n'
        '        self.addParam("Target", Element("scalable:Workstation"), ParamTypes.Required)\n'),
        trim=True)
    assert isinstance(result.new_source, str)
    assert 'Speed: OPTIONAL[float, DESC("m/s")] = 0.5' in result.new_source
    assert 'Target: ELEMENT("scalable:Workstation")' in result.new_source
    assert "EzAnnotated" not in result.new_source


def test_descriptions_already_written_in_the_old_spelling_are_left_alone() -> None:
    """Existing EzSkiROS code keeps its spelling: the runtime reads both."""
    assert_unchanged('''\
from ezskiros_runtime import SkillDescription, OPTIONAL, REQUIRED, ELEMENT, KEY, DESC


class S(SkillDescription):
    def description(self,
                    Target: ELEMENT("scalable:Workstation"),
                    On_Off: REQUIRED[bool, KEY("On/Off")] = True,
                    Speed: OPTIONAL[float, DESC("m/s")] = 0.5):
        pass
''')


def test_the_old_spelling_is_what_pyflakes_flags(tmp_path: Path) -> None:
    """The check above can fail: the forms the codemod wrote before are F722 and F821."""
    codes = lint(tmp_path, '''\
from ezskiros_runtime import SkillDescription, REQUIRED, ELEMENT, DESC


class S(SkillDescription):
    def description(self,
                    Target: ELEMENT("scalable:Workstation"),
                    Controller: REQUIRED[str, DESC("compliant|joint_config")] = ""):
        pass
''')
    assert sorted(codes) == ["F722", "F821", "F821"]
