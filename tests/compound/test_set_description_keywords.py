"""``self.setDescription(description=Problem1(), label="solve")`` implements ``Problem1``, as
``self.setDescription(Problem1(), "solve")`` does (issue 43): the arguments are bound as
Python binds them, by position or by keyword, wherever a ``setDescription`` call is read
(the ``ast`` reading of ``compound.static``, the token reading of ``recover_classes``).

Real files in a temporary folder and the real CLI in a child process: the review report
names the description, and ``check`` judges the implementation's ``self.params`` keys
against it (EZ109), which it cannot do for "an unknown description"."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from ezmigrate.compound.repository import recover_classes

HEADER = '''\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.primitive import PrimitiveBase
from skiros2_common.core.world_element import Element
from skiros2_skill.core.skill import SkillBase


class Problem1(SkillDescription):
    def createDescription(self):
        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)

'''

CALLS = {
    "by position": 'Problem1(), "{label}"',
    "by keyword": 'description=Problem1(), label="{label}"',
    "by keyword, label first": 'label="{label}", description=Problem1()',
}


def _module(arguments: str) -> str:
    """A compound skill and a primitive that both implement ``Problem1`` with ``arguments``;
    the primitive reads a key ``Problem1`` does not declare."""
    return HEADER + f'''
class solve(SkillBase):
    def createDescription(self):
        self.setDescription({arguments.format(label="solve")})

    def expand(self, skill):
        skill(self.skill("Wait", "wait"))


class solve_primitive(PrimitiveBase):
    def createDescription(self):
        self.setDescription({arguments.format(label="solve_primitive")})

    def execute(self):
        return self.params["Nope"].value
'''


def _ezmigrate(*args: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "ezmigrate", *args], capture_output=True,
                          text=True, timeout=300, cwd=cwd,
                          env={"PATH": "/usr/bin:/bin", "EZMIGRATE_CACHE_DIR": str(cwd / "c")})


@pytest.mark.parametrize("how", sorted(CALLS))
def test_the_report_names_the_description_however_it_is_passed(tmp_path: Path,
                                                               how: str) -> None:
    (tmp_path / "skills.py").write_text(_module(CALLS[how]), encoding="utf-8")
    run = _ezmigrate("rewrite", "--dry-run", "--no-verify", "skills.py", "--report", "r.md",
                     cwd=tmp_path)
    assert run.returncode in (0, 1), run.stderr
    report = (tmp_path / "r.md").read_text(encoding="utf-8")
    assert "Implements Problem1 as `solve`; tree read statically." in report, report
    assert "an unknown description" not in report


@pytest.mark.parametrize("how", sorted(CALLS))
def test_check_judges_the_keys_of_an_implementation_however_it_is_passed(
        tmp_path: Path, how: str) -> None:
    (tmp_path / "skills.py").write_text(_module(CALLS[how]), encoding="utf-8")
    run = _ezmigrate("check", "skills.py", "--select", "EZ109", cwd=tmp_path)
    assert "EZ109" in run.stdout and "'Nope'" in run.stdout, run.stdout + run.stderr


@pytest.mark.parametrize("how", sorted(CALLS))
def test_a_module_ast_cannot_read_is_recovered_with_the_same_description(how: str) -> None:
    python2 = _module(CALLS[how]) + '\n\ndef legacy():\n    print "x"\n'
    found = recover_classes(python2.encode())
    assert found is not None
    assert ("solve", python2.splitlines().index("class solve(SkillBase):") + 1,
            "Problem1") in found
