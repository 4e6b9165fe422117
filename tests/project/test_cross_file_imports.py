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


# -- the import scan: the same words as the pattern over the whole file -------------------

from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from ezmigrate.project.import_scan import _IMPORTS, _WORD, import_words  # noqa: E402

_FRAGMENTS = ["import", "from", " ", "\t", "\n", "\r\n", "(", ")", ",", ".", "..", "#",
              "x", "pkg", "important", "_import", "reimport", "as", "*", '"', "'", ";", "\\"]


def _whole_file(data: bytes) -> set[bytes]:
    named: set[bytes] = set()
    for source, names, plain in _IMPORTS.findall(data):
        named.update(_WORD.findall(source + b" " + names + b" " + plain))
    return named


@settings(max_examples=400, deadline=None)
@given(st.lists(st.sampled_from(_FRAGMENTS), max_size=60))
def test_import_words_finds_what_the_pattern_finds_over_the_whole_file(
        fragments: list[str]) -> None:
    data = "".join(fragments).encode()
    assert import_words(data) == _whole_file(data)


@pytest.mark.parametrize("text", [
    "from .base import (\n    Navigate,\n    important,\n)\nimport os\n",
    "import a; import b\nx = 1  # import c\n",
    "def f():\n    from pkg.sub import m as n\n",
    "s = 'important'\nfrom x import y\r\nimport z\n",
])
def test_import_words_on_real_shapes(text: str) -> None:
    data = text.encode()
    assert import_words(data) == _whole_file(data)
    assert import_words(data)  # each shape imports something
