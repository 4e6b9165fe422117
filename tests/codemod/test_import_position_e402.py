"""Where the new imports go, and E402 (issue 43).

The new imports follow the last star import after the first legacy one, which could
rebind them (a lab's helper re-exporting the legacy ``SkillDescription``). When that star
import itself comes after module code, as in ``sys.path.append(...)`` then ``from
primitives import *`` (pycodestyle's E402 for every import there, the original's included),
nowhere after it is the top of the module: the new import says so with ``# noqa: E402``,
and flake8 counts no more E402 than before. Anywhere else, nothing is added.
"""

from __future__ import annotations

import subprocess
import sys
import textwrap
from pathlib import Path

import libcst as cst
import pytest
from codemod_case import assert_migrates, run

from ezmigrate.codemod.core.imports import past_import_zone

SYS_PATH = '''\
from skiros2_common.core.primitive import *
from skiros2_skill.core.skill import *
from skiros2_common.core.params import ParamTypes

import sys, os
sys.path.append('/home/lab/catkin_ws/src/skills/src/skills')
from primitives import *

class Compound(SkillDescription):
    def createDescription(self):
        self.addParam("Speed", 0.5, ParamTypes.Optional, [], "m/s")

class compound(SkillBase):
    pass
'''


def flake8_codes(path: Path) -> list[str]:
    proc = subprocess.run([sys.executable, "-m", "flake8", "--isolated", "--select", "E402,F",
                           "--format", "%(code)s", str(path)],
                          capture_output=True, text=True, check=False, timeout=120)
    assert proc.returncode in (0, 1), proc.stderr
    return sorted(proc.stdout.split())


def test_after_a_star_import_past_module_code_the_import_says_noqa(tmp_path: Path) -> None:
    result = assert_migrates(SYS_PATH, '''\
from skiros2_common.core.primitive import *
from skiros2_skill.core.skill import *

import sys, os
sys.path.append('/home/lab/catkin_ws/src/skills/src/skills')
from primitives import *
from ezskiros_runtime import SkillDescription, Annotated, OPTIONAL, DESC  # noqa: E402

class Compound(SkillDescription):
    def description(self,
                    Speed: Annotated[OPTIONAL[float], DESC("m/s")] = 0.5):
        pass

class compound(SkillBase):
    pass
''')
    before, after = tmp_path / "before.py", tmp_path / "after.py"
    before.write_text(SYS_PATH, encoding="utf-8")
    assert isinstance(result.new_source, str)
    after.write_text(result.new_source, encoding="utf-8")
    old, new = flake8_codes(before), flake8_codes(after)
    assert old.count("E402") == new.count("E402") == 1  # the star import's own
    assert {code: new.count(code) for code in new if new.count(code) > old.count(code)} == {}


def test_a_long_import_carries_the_noqa_on_its_first_line(tmp_path: Path) -> None:
    source = SYS_PATH.replace(
        '        self.addParam("Speed", 0.5, ParamTypes.Optional, [], "m/s")\n',
        '        self.addParam("Speed", 0.5, ParamTypes.Optional, [], "m/s")\n'
        '        self.addParam("Cam", Element("scalable:Cam"), ParamTypes.Inferred, '
        '[ParamOptions.Lock, ParamOptions.Consume], "camera")\n'
        '        self.addParam("On/Off", True, ParamTypes.Required)\n', 1)
    result = run(source)
    assert isinstance(result.new_source, str), [s.reason for s in result.skills]
    assert "from ezskiros_runtime import (  # noqa: E402\n    SkillDescription,\n" \
        in result.new_source
    path = tmp_path / "after.py"
    path.write_text(result.new_source, encoding="utf-8")
    assert flake8_codes(path).count("E402") == 1


def test_an_import_in_the_zone_gets_no_noqa() -> None:
    """No-op: a docstring, ``__all__``, a ``try`` of imports and a star import of the
    lab's module before any code: no E402, no comment."""
    assert_migrates('''\
"""Skills."""
from __future__ import annotations
__all__ = ["S"]
try:
    import rospy
except ImportError:
    rospy = None
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from helpers import *


class S(SkillDescription):
    def createDescription(self):
        self.addParam("Speed", 0.5, ParamTypes.Optional, [], "m/s")
''', '''\
"""Skills."""
from __future__ import annotations
__all__ = ["S"]
try:
    import rospy
except ImportError:
    rospy = None
from helpers import *
from ezskiros_runtime import SkillDescription, Annotated, OPTIONAL, DESC


class S(SkillDescription):
    def description(self,
                    Speed: Annotated[OPTIONAL[float], DESC("m/s")] = 0.5):
        pass
''')


@pytest.mark.parametrize(("prefix", "past"), [
    ("", False),
    ('"""doc"""\n', False),
    ('"""doc"""\n"""second string"""\n', True),
    ("__version__ = '1'\n__all__: list = []\n", False),
    ("if True:\n    import os\nelse:\n    pass\n", False),
    ("with open('x'):\n    pass\n", False),
    ("import os\n", False),
    ("x = 1\n", True),
    ("sys.path.append('x')\n", True),
    ("def f():\n    pass\n", True),
    ("class C:\n    pass\n", True),
    ("for i in []:\n    pass\n", True),
])
def test_the_import_zone_is_read_as_pycodestyle_reads_it(tmp_path: Path, prefix: str,
                                                         past: bool) -> None:
    """``past_import_zone`` against pycodestyle itself on the same file."""
    assert past_import_zone(cst.parse_module(prefix).body) is past
    path = tmp_path / "zone.py"
    path.write_text(prefix + "import json\n", encoding="utf-8")
    assert ("E402" in flake8_codes(path)) is past


def test_the_noqa_is_not_added_twice() -> None:
    """Idempotent: the migrated file, migrated again, is unchanged (``assert_migrates``
    checks that too); its ``# noqa: E402`` line is the runtime's import, no legacy one."""
    result = run(SYS_PATH)
    assert isinstance(result.new_source, str)
    assert textwrap.dedent(result.new_source).count("# noqa: E402") == 1
