"""Where an unreadable file lives, and so how bad it is that Python cannot parse it (EZ905).

The skill manager loads its skills with ``PluginLoader.__import_plugins``
(``skiros2_common/tools/plugin_loader.py``): it imports the package of each name in the
launch file's ``libraries_list`` and every module ``pkgutil.walk_packages`` finds in it,
and catches only ``ImportError``. A ``SyntaxError`` in one of those modules is not one: it
stops ``SkillManager.load_skills`` and the skill manager does not start. In the
``__init__.py`` of a sub-package, ``walk_packages`` passes it to ``onerror``, which
ignores it: none of that sub-package's skills is loaded, silently. A file outside any such
package (``scripts/``, a test, a loose module) is not imported by the skill manager, and
Python 2 syntax is no mistake on a robot whose ROS runs Python 2.

A skill library is a Python package (folders holding ``__init__.py``) that the launch file
names in ``libraries_list``, or that sits where a ROS package installs its Python code:
``<package>/src/<library>/`` (catkin's ``catkin_python_setup``) or ``<package>/<library>/``
of an ``ament_python`` package.
"""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path

from ezskiros_runtime.ontology.discovery import package_root

from ..files.package_xml import ros_flavour


def library_of(path: Path, libraries: Iterable[str] = ()) -> tuple[Path, Path] | None:
    """``(library folder, ROS package folder)`` of a module the skill manager imports, or
    None when the file is in no skill library (see the module doc)."""
    folder = path.parent
    if not (folder / "__init__.py").is_file():
        return None
    top = folder
    while (top.parent / "__init__.py").is_file() and top.parent != top:
        top = top.parent
    package = package_root(top)
    if package is None:
        return None
    named = top.name in set(libraries)
    catkin = top.parent.name == "src" and top.parent.parent == package
    ament = top.parent == package and ros_flavour(package / "package.xml") == "ros2"
    return (top, package) if named or catkin or ament else None


def python3_robot(package: Path) -> bool:
    """Whether the ROS package certainly runs on Python 3: a ROS 2 package, or a manifest
    that names Python 3 (``python3-`` dependencies, ``$ROS_PYTHON_VERSION == 3``)."""
    manifest = package / "package.xml"
    if ros_flavour(manifest) == "ros2":
        return True
    try:
        text = manifest.read_text(encoding="utf-8", errors="replace")
    except OSError:
        return False
    return ("python3" in text or "ROS_PYTHON_VERSION == 3" in text) \
        and "ROS_PYTHON_VERSION == 2" not in text  # a manifest for both: maybe Python 2


def unreadable_severity(path: str, message: str, python2: bool,
                        libraries: Iterable[str] = ()) -> tuple[str, str]:
    """``(severity, message)`` of an EZ905 finding for the file at ``path``: an error in a
    module of a skill library the robot's Python cannot import, info elsewhere (the
    message then says why). ``python2``: the error is Python 2 syntax
    (``FileResult.python2``)."""
    file = Path(path).resolve()
    found = library_of(file, libraries)
    if found is None:
        return "info", (f"{message}; info: the file is in no skill library package the skill "
                        "manager imports (PluginLoader.__import_plugins)")
    top, package = found
    if python2 and not python3_robot(package):
        return "info", (f"{message}; info: Python 2 syntax, and nothing says the ROS package "
                        f"{package.name} runs on Python 3 (a Python 2 ROS imports it)")
    if file.name == "__init__.py" and file.parent != top:
        return "error", (f"{message}; in the skill library {top.name}, pkgutil.walk_packages "
                         "(PluginLoader.__import_plugins) ignores the error of this "
                         f"sub-package and the skill manager loads none of the skills of "
                         f"{file.parent.name}")
    return "error", (f"{message}; a module of the skill library {top.name}: "
                     "PluginLoader.__import_plugins imports it and catches only ImportError, "
                     "so the SyntaxError stops SkillManager.load_skills and the skill "
                     "manager does not start")
