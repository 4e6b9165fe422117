"""EZ905's severity by where the unreadable file lives (issue 42): an error in a module of
a skill library the skill manager imports (``PluginLoader.__import_plugins`` catches only
ImportError, so a SyntaxError stops ``SkillManager.load_skills``), info in ``scripts/``,
outside any package, and for Python 2 syntax where nothing says the robot runs Python 3.
Real files in temporary ROS packages, the real check core."""

from __future__ import annotations

from pathlib import Path

from ezmigrate.checking.pipeline import run_check
from ezmigrate.checking.run import CheckSettings
from ezmigrate.lint.diagnostic import Diagnostic
from ezmigrate.verify.pool import PoolConfig

DESCRIPTION = '''\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes


class Say(SkillDescription):
    def createDescription(self):
        self.addParam("Text", "", ParamTypes.Optional)
'''
TRUNCATED = DESCRIPTION + "\n\nclass Broken(:\n"
PYTHON2 = DESCRIPTION + "\n\ndef shout():\n    print 'hi'\n"
CATKIN = ("<package format=\"2\"><name>lab_skills</name>"
          "<buildtool_depend>catkin</buildtool_depend>{extra}</package>")
AMENT = ("<package format=\"3\"><name>lab_skills</name><export><build_type>ament_python"
         "</build_type></export></package>")


def unreadable(root: Path, relative: str, source: str, manifest: str | None = CATKIN,
               settings: CheckSettings | None = None) -> Diagnostic:
    """The one EZ905 finding of ``source`` written at ``root/relative`` in a ROS package."""
    path = root / relative
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(source, encoding="utf-8")
    folder = path.parent
    while folder != root:  # every folder below the package a Python package
        if folder.name not in ("src", "scripts", "python"):
            (folder / "__init__.py").touch()
        folder = folder.parent
    if manifest is not None:
        (root / "package.xml").write_text(manifest.replace("{extra}", ""), encoding="utf-8")
    found = run_check([root], None, PoolConfig(workers=1), settings).diagnostics
    [hit] = [d for d in found if d.code == "EZ905"]
    return hit


def test_a_module_of_a_catkin_skill_library_is_an_error(tmp_path: Path):
    hit = unreadable(tmp_path / "pkg", "src/lab_skills/say.py", TRUNCATED)
    assert hit.severity == "error" and "PluginLoader.__import_plugins" in hit.message
    assert "lab_skills" in hit.message


def test_a_sub_package_init_is_an_error_naming_walk_packages(tmp_path: Path):
    hit = unreadable(tmp_path / "pkg", "src/lab_skills/arm/__init__.py", TRUNCATED)
    assert hit.severity == "error" and "walk_packages" in hit.message and "arm" in hit.message


def test_an_ament_python_library_is_an_error_even_for_python_2_syntax(tmp_path: Path):
    hit = unreadable(tmp_path / "pkg", "lab_skills/say.py", PYTHON2, AMENT)
    assert hit.severity == "error"


def test_python_2_syntax_where_the_robot_may_run_python_2_is_info(tmp_path: Path):
    hit = unreadable(tmp_path / "pkg", "src/lab_skills/say.py", PYTHON2)
    assert hit.severity == "info" and "Python 2" in hit.message
    three = unreadable(tmp_path / "py3", "src/lab_skills/say.py", PYTHON2, CATKIN.replace(
        "{extra}", "<exec_depend>python3-numpy</exec_depend>"))
    assert three.severity == "error"


def test_scripts_and_loose_files_are_info(tmp_path: Path):
    script = unreadable(tmp_path / "pkg", "scripts/say.py", TRUNCATED)
    assert script.severity == "info" and "no skill library" in script.message
    loose = unreadable(tmp_path / "loose", "say.py", TRUNCATED, manifest=None)
    assert loose.severity == "info"


def test_a_library_the_launch_file_names_is_an_error_outside_src(tmp_path: Path):
    from ezmigrate.checking.launch import Launch

    launch = Launch(tmp_path / "main.launch", {"libraries_list": "[odd_skills]"})
    hit = unreadable(tmp_path / "pkg", "python/odd_skills/say.py", TRUNCATED,
                     settings=CheckSettings(launch=launch))
    assert hit.severity == "error"
    other = unreadable(tmp_path / "pkg2", "python/odd_skills/say.py", TRUNCATED)
    assert other.severity == "info"
