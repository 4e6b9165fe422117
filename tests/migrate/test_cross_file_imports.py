"""Legacy names other modules import from a migrated one stay importable.

``impl.py`` doing ``from .descriptions import Navigate, Element`` must keep working after
``descriptions.py`` is migrated: migration removes a legacy import only when no module of
the package imports that name from the file (a star import keeps them all) or reads it as
an attribute of the file imported as a module (``import pkg.descriptions as m``, ``m.X``).
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

DESCRIPTIONS = '''from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


class Navigate(SkillDescription):
    def createDescription(self):
        self.addParam("Target", Element("skiros:Location"), ParamTypes.Required)
'''


def _cli(*args: object) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "ezmigrate", *map(str, args)],
                          capture_output=True, text=True, stdin=subprocess.DEVNULL,
                          timeout=300, check=False)


@pytest.mark.parametrize(("importer", "kept", "dropped"), [
    ("from .descriptions import Navigate, Element\n", "Element", "ParamTypes"),
    ("from pkg.descriptions import ParamTypes as PT\n", "ParamTypes", "Element"),
    ("from .descriptions import *\n", "ParamTypes, Element", None),
    # the module itself imported, its legacy names read as attributes
    ("import pkg.descriptions as m\nTARGET = m.Element\n", "Element", "ParamTypes"),
    ("from pkg import descriptions as d\nKIND = d.ParamTypes\n", "ParamTypes", "Element"),
    ("from . import descriptions\nKIND = descriptions.ParamTypes\n", "ParamTypes", "Element"),
])
def test_names_imported_by_siblings_stay_importable(tmp_path: Path, importer: str,
                                                    kept: str, dropped: str | None):
    package = tmp_path / "pkg"
    package.mkdir()
    (package / "__init__.py").write_text("", encoding="utf-8")
    (package / "descriptions.py").write_text(DESCRIPTIONS, encoding="utf-8")
    (package / "impl.py").write_text(importer, encoding="utf-8")

    run = _cli("rewrite", package)

    assert run.returncode == 0, run.stderr
    migrated = (package / "descriptions.py").read_text(encoding="utf-8")
    assert "def description(self," in migrated  # it was migrated
    for name in kept.split(", "):
        assert f"import {name}" in migrated, (name, migrated)
    if dropped is not None:  # what nobody imports is still pruned
        assert f"import {dropped}" not in migrated, migrated
    loads = subprocess.run(
        [sys.executable, "-c", "from ezskiros_runtime.legacy.stand_ins import legacy_imports\n"
         "with legacy_imports():\n    import pkg.impl, pkg.descriptions\n"
         "    pkg.descriptions.Navigate()\n"],
        cwd=tmp_path, capture_output=True, text=True, timeout=120, check=False)
    assert loads.returncode == 0, loads.stderr
