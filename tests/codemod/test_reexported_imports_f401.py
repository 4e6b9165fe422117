"""Legacy imports kept for other modules, and F401 (issue 43).

A legacy import whose last use the migration removed goes, unless other modules of the
package import that name from this one (``Settings.exported``: ``from .prims import
ParamTypes``, or ``from prims import *``): removing it would break them. Kept for them, it is
unused here, pyflakes' F401; it says so with ``# noqa: F401``, the usual mark of a re-export,
so flake8 and ruff count no more F401 than before. Imports unused before stay byte for byte.
"""

from __future__ import annotations

import json
import subprocess
import sys
from collections import Counter
from pathlib import Path

from codemod_case import settings

from ezmigrate.codemod.migrate import Settings, migrate

SOURCE = '''\
from skiros2_skill.core.skill import SkillDescription, ParamOptions
from skiros2_common.core.params import ParamTypes  # SkiROS2
from skiros2_common.core.world_element import (
    Element,
)
from skiros2_common.core.primitive import PrimitiveBase  # noqa: F401 - for the plugin


class Listen(SkillDescription):
    def createDescription(self):
        self.addParam("Robot", Element("cora:Robot"), ParamTypes.Required)
'''


def migrated(exported: frozenset[str]) -> str:
    base = settings()
    result = migrate(SOURCE, Settings(index=base.index, exported=exported), "prims.py")
    assert isinstance(result.new_source, str), [s.reason for s in result.skills]
    assert migrate(result.new_source, Settings(index=base.index, exported=exported),
                   "prims.py").new_source is None  # idempotent
    return result.new_source


def counts(tmp_path: Path, name: str, source: str) -> Counter[str]:
    """F401 and the rest of pyflakes, as flake8 and ruff (classic defaults) count them."""
    path = tmp_path / name
    path.write_text(source, encoding="utf-8")
    flake8 = subprocess.run([sys.executable, "-m", "flake8", "--isolated", "--select", "F",
                             "--format", "%(code)s", str(path)],
                            capture_output=True, text=True, check=False, timeout=120)
    ruff = subprocess.run([sys.executable, "-m", "ruff", "check", "--isolated", "--no-cache",
                           "--select", "E4,E7,E9,F", "--output-format", "json", "--exit-zero",
                           str(path)], capture_output=True, text=True, check=False, timeout=120)
    assert flake8.returncode in (0, 1) and ruff.returncode == 0, flake8.stderr + ruff.stderr
    return Counter([f"flake8 {c}" for c in flake8.stdout.split()]
                   + [f"ruff {f['code']}" for f in json.loads(ruff.stdout)])


def test_a_star_imported_module_marks_what_it_keeps_for_others(tmp_path: Path) -> None:
    after = migrated(frozenset({"*"}))
    assert after == '''\
from skiros2_skill.core.skill import SkillDescription, ParamOptions  # noqa: F401
from ezskiros_runtime import SkillDescription as EzSkillDescription
from ezskiros_runtime.ontology import cora
from skiros2_common.core.params import ParamTypes  # SkiROS2  # noqa: F401
from skiros2_common.core.world_element import (  # noqa: F401
    Element,
)
from skiros2_common.core.primitive import PrimitiveBase  # noqa: F401 - for the plugin


class Listen(EzSkillDescription):
    def description(self,
                    Robot: cora.Robot):
        pass
'''
    old, new = counts(tmp_path, "before.py", SOURCE), counts(tmp_path, "after.py", after)
    assert {code: (old[code], new[code]) for code in new if new[code] > old[code]} == {}


def test_a_name_another_module_imports_is_marked_and_the_rest_goes(tmp_path: Path) -> None:
    after = migrated(frozenset({"ParamTypes"}))
    assert "from skiros2_common.core.params import ParamTypes  # SkiROS2  # noqa: F401\n" \
        in after
    assert "Element" not in after  # nobody imports it from here: it went with its last use
    old, new = counts(tmp_path, "before.py", SOURCE), counts(tmp_path, "after.py", after)
    assert {code: (old[code], new[code]) for code in new if new[code] > old[code]} == {}


def test_without_importers_nothing_is_marked() -> None:
    """No-op for the mark: the names that lost their last use go, and the import that was
    unused before (``ParamOptions``, ``PrimitiveBase``) stays as it was."""
    after = migrated(frozenset())
    assert after.splitlines()[:4] == [
        "from skiros2_skill.core.skill import ParamOptions",
        "from ezskiros_runtime import SkillDescription",
        "from ezskiros_runtime.ontology import cora",
        "from skiros2_common.core.primitive import PrimitiveBase  # noqa: F401 - for the plugin",
    ]
    assert "noqa: F401\n" not in after


def test_the_check_can_fail(tmp_path: Path) -> None:
    """Without the mark, the kept names are F401 for both tools."""
    after = migrated(frozenset({"*"})).replace("  # noqa: F401\n", "\n")
    new = counts(tmp_path, "after.py", after)
    old = counts(tmp_path, "before.py", SOURCE)
    assert new["flake8 F401"] > old["flake8 F401"] and new["ruff F401"] > old["ruff F401"]
