"""``load_file`` / ``load_source``: naming, per-class errors, module errors, clean-up."""

from __future__ import annotations

import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from ezskiros_runtime.diagnostics import class_error
from ezskiros_runtime.legacy import ModuleLoadError, load_file, load_source
from ezskiros_runtime.model import Param

HEADER = """\
from skiros2_common.core.abstract_skill import SkillDescription, ParamOptions
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element
"""


def write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(textwrap.dedent(text))
    return path


def test_failing_class_is_an_error_while_its_neighbour_loads(tmp_path: Path) -> None:
    path = write(tmp_path / "skills.py", HEADER + """
class Broken(SkillDescription):
    def createDescription(self):
        self.addParam("A", 0.5, ParamTypes.Optional)
        raise RuntimeError("boom")


class Fine(SkillDescription):
    def createDescription(self):
        self.addParam("A", 0.5, ParamTypes.Optional)


class WithFunction(SkillDescription):
    def createDescription(self):
        from skiros2_common.core.conditions import ConditionFunction
        self.addPreCondition(ConditionFunction("Free", lambda skill: True))
""")
    result = load_file(path)
    assert [(m.name, m.line) for m in result.models] == [("Fine", 11)]
    assert result.models[0].params[0] == Param("A", "Optional", "float",
                                               values=(("float", 0.5),))
    assert result.errors == [
        class_error("Broken", 5, "RuntimeError: boom (line 8)", str(path.absolute())),
        class_error("WithFunction", 16, result.errors[1].message, str(path.absolute()),
                    "not-declarative"),
    ]
    assert "ConditionFunction" in result.errors[1].message
    assert "Free" in result.errors[1].message


def test_module_raising_at_import_names_file_and_line(tmp_path: Path) -> None:
    path = write(tmp_path / "bad.py", HEADER + """
SPEED = 1.0
LIMIT = SPEED / 0
""")
    modules = set(sys.modules)
    with pytest.raises(ModuleLoadError) as info:
        load_file(path)
    error = info.value
    assert (error.path, error.line, error.exc_type) == (str(path), 6, "ZeroDivisionError")
    assert str(error) == (f"{path}:6: cannot import module: ZeroDivisionError: "
                          "float division by zero")
    assert not {n for n in set(sys.modules) - modules if "skiros2" in n or "bad" in n}


def test_python2_file_is_a_module_error_with_its_line(tmp_path: Path) -> None:
    path = write(tmp_path / "old.py", "import rospy\n\nprint 'hello'\n")
    with pytest.raises(ModuleLoadError, match=r"old\.py:3: .*SyntaxError") as info:
        load_file(path)
    assert info.value.line == 3


def test_failing_sibling_points_at_the_import_and_the_sibling(tmp_path: Path) -> None:
    write(tmp_path / "pkg" / "__init__.py", "")
    write(tmp_path / "pkg" / "helpers.py", "x = 1\nraise ValueError('bad helper')\n")
    path = write(tmp_path / "pkg" / "skills.py", HEADER + "from .helpers import x\n")
    with pytest.raises(ModuleLoadError) as info:
        load_file(path)
    assert info.value.line == 4 and info.value.exc_type == "ValueError"
    assert info.value.origin == f"{tmp_path / 'pkg' / 'helpers.py'}:2"
    assert "pkg" not in sys.modules and "pkg.helpers" not in sys.modules


def test_package_files_get_dotted_names_and_root_limits_the_search(tmp_path: Path) -> None:
    write(tmp_path / "outer" / "__init__.py", "")
    write(tmp_path / "outer" / "inner" / "__init__.py", "")
    write(tmp_path / "outer" / "inner" / "consts.py", "DEFAULT = 2.5\n")
    path = write(tmp_path / "outer" / "inner" / "skills.py", HEADER + """
from . import consts
from outer.inner.consts import DEFAULT

MODULE = __name__

class Uses(SkillDescription):
    def createDescription(self):
        self.addParam("Name", MODULE, ParamTypes.Optional)
        self.addParam("Default", consts.DEFAULT + DEFAULT, ParamTypes.Optional)
""")
    (model,) = load_file(path).models
    assert model.params[0].values == (("str", "outer.inner.skills"),)
    assert model.params[1].values == (("float", 5.0),)
    limited = write(tmp_path / "outer" / "inner" / "limited.py", HEADER + """
MODULE = __name__

class Uses(SkillDescription):
    def createDescription(self):
        self.addParam("Name", MODULE, ParamTypes.Optional)
""")
    (model,) = load_file(limited, root=tmp_path / "outer" / "inner").models
    assert model.params[0].values == (("str", "inner.limited"),)
    (model,) = load_file(limited, module_name="custom_name").models
    assert model.params[0].values == (("str", "custom_name"),)
    assert not {"outer", "outer.inner", "inner", "custom_name"} & set(sys.modules)
    assert not list(tmp_path.rglob("__pycache__"))


def test_package_init_file_loads_as_the_package(tmp_path: Path) -> None:
    write(tmp_path / "top" / "__init__.py", "")
    write(tmp_path / "top" / "sub" / "consts.py", "DEFAULT = 'c'\n")
    path = write(tmp_path / "top" / "sub" / "__init__.py", HEADER + """
from .consts import DEFAULT

class InInit(SkillDescription):
    def createDescription(self):
        self.addParam("Name", __name__, ParamTypes.Optional)
        self.addParam("Default", DEFAULT, ParamTypes.Optional)
""")
    (model,) = load_file(path).models
    assert [p.values for p in model.params[:2]] == [(("str", "top.sub"),), (("str", "c"),)]
    assert not {"top", "top.sub", "top.sub.consts"} & set(sys.modules)


def test_plain_file_is_a_module_of_a_unique_made_up_package_with_its_folder_on_path(
        tmp_path: Path) -> None:
    """The made-up package gives relative imports a parent (test_unresolved_imports.py)."""
    write(tmp_path / "helpers_top.py", "VALUE = 'from sibling'\n")
    path = write(tmp_path / "skills.py", HEADER + """
import helpers_top

class Uses(SkillDescription):
    def createDescription(self):
        self.addParam("Name", __name__, ParamTypes.Optional)
        self.addParam("Sibling", helpers_top.VALUE, ParamTypes.Optional)
""")
    first, second = load_file(path).models[0], load_file(path).models[0]
    names = [first.params[0].values[0][1], second.params[0].values[0][1]]
    assert names[0] != names[1] and all(
        n.startswith("_ezmigrate_standalone_") and n.endswith(".skills") for n in names)
    assert first.params[1].values == (("str", "from sibling"),)
    assert "helpers_top" not in sys.modules and str(tmp_path) not in sys.path


def test_load_source_compiles_text_without_writing(tmp_path: Path) -> None:
    filename = tmp_path / "virtual.py"
    result = load_source(HEADER + textwrap.dedent("""
        class Virtual(SkillDescription):
            def createDescription(self):
                self.addParam("X", Element("skiros:Product"), ParamTypes.Required)
        """), filename)
    assert [(m.name, m.source, m.line) for m in result.models] == [
        ("Virtual", str(filename), 5)]
    assert list(tmp_path.iterdir()) == []


def test_only_classes_defined_in_the_module_and_each_once(tmp_path: Path) -> None:
    write(tmp_path / "defs.py", HEADER + """
class Imported(SkillDescription):
    pass
""")
    path = write(tmp_path / "skills.py", HEADER + """
from defs import Imported

class Local(SkillDescription):
    pass

Alias = Local

class Checked(SkillDescription):
    def createDescription(self):
        self.findings = ["unknown vocabulary"]
""")
    result = load_file(path)
    assert [m.name for m in result.models] == ["Local", "Checked"]
    assert result.findings == ["unknown vocabulary"]


def test_legacy_backend_import_stays_cheap() -> None:
    code = ("import sys, ezskiros_runtime.legacy\n"
            "heavy = [m for m in sys.modules if m.startswith(('rdflib', 'ezskiros_runtime.dsl',"
            " 'libcst', 'ezmigrate'))]\n"
            "assert not heavy, heavy\n"
            "assert 'skiros2_common' not in sys.modules\n"
            "assert not [f for f in sys.meta_path if 'ezskiros' in type(f).__module__]\n")
    subprocess.run([sys.executable, "-c", code], check=True, timeout=60)
    for source in (Path(__file__).parents[3] / "ezskiros_runtime" / "legacy").glob("*.py"):
        text = source.read_text()
        assert "import rdflib" not in text and ".dsl" not in text, source
