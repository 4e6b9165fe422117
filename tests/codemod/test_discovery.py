"""Which classes are legacy descriptions: every import spelling, aliased bases from sibling
files, children of bases an earlier run migrated, and bases in files not given.

A description a run does not find is neither converted nor reported: the legacy code
stays and nobody is told (README, "What is skipped, with a reason"). Package-level cases
go through the CLI, as a user runs them.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from ezmigrate.codemod.migrate import migrate

HEADER = '''from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element
'''

DESCRIPTIONS = HEADER + '''

class Navigate(SkillDescription):
    def createDescription(self):
        self.addParam("Target", Element("skiros:Location"), ParamTypes.Required)
'''

MIGRATED_DESCRIPTIONS = '''from ezskiros_runtime import SkillDescription
from ezskiros_runtime.ontology import skiros


class Navigate(SkillDescription):
    def description(self, Target: skiros.Location):
        pass
'''
"""``DESCRIPTIONS`` after an earlier run."""

CHILDREN = '''from skiros2_common.core.params import ParamTypes
{import_line}


class NavigateTwice({base}):
    def createDescription(self):
        for key in sorted(("First", "Second")):  # computed at run time: never converted
            self.addParam(key, 0.5, ParamTypes.Optional)


class NavigateSlow({base}):
    def createDescription(self):
        self.addParam("Speed", 0.1, ParamTypes.Optional)


class NavigateAgain({base}):
    def createDescription(self):
        {base}.createDescription(self)
        self.addParam("Speed", 0.1, ParamTypes.Optional)


class NavigateImpl({base}):
    """No createDescription: not evidence of a legacy description."""
'''


def cli(*args: object) -> subprocess.CompletedProcess[str]:
    """``python -m ezmigrate ARGS`` in a fresh process."""
    return subprocess.run([sys.executable, "-m", "ezmigrate", *map(str, args)],
                          capture_output=True, text=True, stdin=subprocess.DEVNULL,
                          timeout=300, check=False)


def package(root: Path, files: dict[str, str]) -> Path:
    """``root/pkg`` holding ``files`` and an empty ``__init__.py``."""
    folder = root / "pkg"
    folder.mkdir()
    (folder / "__init__.py").write_text("", encoding="utf-8")
    for name, text in files.items():
        (folder / name).write_text(text, encoding="utf-8")
    return folder


def imports_cleanly(root: Path, *modules: str) -> subprocess.CompletedProcess[str]:
    """Import ``modules`` and build every description in them, off the robot."""
    code = ("import inspect\nfrom ezskiros_runtime.legacy.stand_ins import legacy_imports\n"
            "with legacy_imports():\n    import importlib\n"
            f"    for name in {list(modules)!r}:\n"
            "        module = importlib.import_module(name)\n"
            "        for cls in vars(module).values():\n"
            "            if inspect.isclass(cls) and hasattr(cls, 'createDescription') \\\n"
            "                    and cls.__module__ == name:\n"
            "                cls()\n")
    return subprocess.run([sys.executable, "-c", code], cwd=root, capture_output=True,
                          text=True, timeout=120, check=False)


@pytest.mark.parametrize("imports", [
    "from skiros2_common.core import params\n"
    "from skiros2_common.core import world_element as we\n",
    "import skiros2_common.core.params as params\n"
    "import skiros2_common.core.world_element as we\n",
])
def test_legacy_submodules_imported_as_modules_resolve(imports: str):
    source = ("from skiros2_common.core.abstract_skill import SkillDescription\n" + imports
              + "\n\nclass Navigate(SkillDescription):\n    def createDescription(self):\n"
              '        self.addParam("Target", we.Element("skiros:Location"), '
              "params.ParamTypes.Required)\n")
    result = migrate(source)
    assert [(s.name, s.status, s.reason) for s in result.skills] == [
        ("Navigate", "converted", None)]
    assert 'Target: Annotated[REQUIRED, ELEMENT("skiros:Location")]' in str(result.new_source)
    assert "skiros2_common" not in str(result.new_source)  # the module imports are unused


def test_a_package_above_the_legacy_submodules_resolves():
    source = ("from skiros2_common.core.abstract_skill import SkillDescription\n"
              "from skiros2_common import core\n\n\n"
              "class Navigate(SkillDescription):\n    def createDescription(self):\n"
              '        self.addParam("Target", core.world_element.Element("skiros:Location"), '
              "core.params.ParamTypes.Required)\n")
    result = migrate(source)
    assert [s.status for s in result.skills] == ["converted"], result.skills


def test_an_aliased_base_from_a_sibling_file_is_found(tmp_path: Path):
    folder = package(tmp_path, {
        "descriptions.py": DESCRIPTIONS,
        "impl.py": HEADER + "from .descriptions import Navigate as Nav2\n\n\n"
                   "class NavigateSlow(Nav2):\n    def createDescription(self):\n"
                   "        Nav2.createDescription(self)\n"
                   '        self.addParam("Speed", 0.1, ParamTypes.Optional)\n'})

    run = cli("rewrite", folder)

    assert run.returncode == 0, run.stderr
    assert "2 skills found, 2 converted" in run.stderr
    impl = (folder / "impl.py").read_text(encoding="utf-8")
    assert "class NavigateSlow(Nav2):" in impl
    assert "Target: skiros.Location" in impl and "Speed: OPTIONAL[float] = 0.1" in impl
    loaded = imports_cleanly(tmp_path, "pkg.descriptions", "pkg.impl")
    assert loaded.returncode == 0, loaded.stderr


def _reasons(stderr: str) -> dict[str, str]:
    """Skill name -> the verdict ``rewrite`` printed for it (``skipped: ...``)."""
    found = {}
    for line in stderr.splitlines():
        parts = line.split(": ", 2)
        if len(parts) == 3 and ".py:" in parts[0]:
            found[parts[1]] = parts[2]
    return found


@pytest.mark.parametrize("layout", ["same file", "sibling file"])
def test_children_of_a_base_an_earlier_run_migrated_are_counted(tmp_path: Path, layout: str):
    if layout == "same file":
        children = CHILDREN.format(import_line="", base="Navigate").replace(
            "from skiros2_common.core.params import ParamTypes\n",
            "from skiros2_common.core.params import ParamTypes\n"
            + MIGRATED_DESCRIPTIONS.split("\n\n\n")[0] + "\n\n\n"
            + MIGRATED_DESCRIPTIONS.split("\n\n\n")[1])
        folder = package(tmp_path, {"skills.py": children})
        modules: tuple[str, ...] = ("pkg.skills",)
    else:
        folder = package(tmp_path, {
            "descriptions.py": MIGRATED_DESCRIPTIONS,
            "skills.py": CHILDREN.format(import_line="from .descriptions import Navigate",
                                         base="Navigate")})
        modules = ("pkg.descriptions", "pkg.skills")

    run = cli("rewrite", folder)

    # the EzSkiROS classes an earlier run wrote count as unchanged, as the report counts them
    # (Navigate, and in the same file NavigateImpl, which derives from it there)
    earlier = 2 if layout == "same file" else 1
    assert (f"{3 + earlier} skills found, 1 converted, 2 skipped, 0 failed, {earlier} "
            "unchanged") in run.stderr, run.stderr
    assert run.returncode == 0  # skipped with reasons: the run did its work
    reasons = _reasons(run.stderr)
    assert reasons["NavigateTwice"].startswith("skipped: a loop"), reasons
    assert "already an EzSkiROS description" in reasons["NavigateAgain"], reasons
    assert "NavigateImpl" not in reasons
    skills = (folder / "skills.py").read_text(encoding="utf-8")
    assert "Speed: OPTIONAL[float] = 0.1" in skills  # NavigateSlow, verified and written
    assert skills.count("def createDescription(self):") == 2
    loaded = imports_cleanly(tmp_path, *modules)
    assert loaded.returncode == 0, loaded.stderr


@pytest.mark.parametrize("import_line", ["from .descriptions import Navigate",
                                         "from pkg.descriptions import Navigate"])
def test_a_base_in_a_sibling_that_was_not_given_is_reported(tmp_path: Path, import_line: str):
    folder = package(tmp_path, {
        "descriptions.py": DESCRIPTIONS,
        "impl.py": CHILDREN.format(import_line=import_line, base="Navigate")})
    before = (folder / "impl.py").read_bytes()

    run = cli("rewrite", folder / "impl.py")

    assert run.returncode == 0, run.stderr
    assert "3 skills found, 0 converted, 3 skipped" in run.stderr, run.stderr
    source = import_line.split()[1]
    reasons = _reasons(run.stderr)
    assert reasons["NavigateSlow"] == (f"skipped: its base Navigate is imported from {source}, "
                                       "which was not given: pass the package folder")
    assert "NavigateImpl" not in reasons  # no createDescription: no evidence
    assert (folder / "impl.py").read_bytes() == before


def test_a_base_from_a_library_is_not_a_missing_sibling(tmp_path: Path):
    """Only a module that exists beside the file is evidence of a sibling not given."""
    folder = package(tmp_path, {
        "impl.py": CHILDREN.format(import_line="from some_library import Navigate",
                                   base="Navigate")})

    run = cli("rewrite", folder / "impl.py")

    assert run.returncode == 0, run.stderr
    assert "0 skills found" in run.stderr
