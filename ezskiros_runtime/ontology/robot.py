"""On the robot, the robot's ontology: what the SkiROS2 world model server loads.

The world model loads every ``.owl`` file under the installed ``skiros2`` package's ``owl/``
folder (the core), then every ``.owl`` file under its ``workspace_dir`` parameter (usually
the skill package's own ``owl/`` folder with the robot description and project classes).
When the SkiROS2 backend is active and nothing is configured, the runtime checks skills
against exactly those files, so a launch-time check sees the classes the robot has.

Both look-ups are seams (``PackageLocator``, ``ParameterSource``) so that tests give a
stand-in package layout and parameter server; the defaults ask ROS (``rospkg`` on ROS 1,
``ament_index_python`` on ROS 2, ``rospy.get_param``) and fail soft: when the package or
the parameter cannot be read, the bundled core is used and one log line says so.
"""

from __future__ import annotations

import logging
from pathlib import Path
from typing import Callable, Optional

PACKAGE = "skiros2"
WORKSPACE_PARAMETERS = ("/wm/workspace_dir", "workspace_dir")
"""Where the world model server's ``workspace_dir`` is looked for (its private parameter
under the usual node name ``wm``, then a global one)."""

PackageLocator = Callable[[str], Optional[Path]]
ParameterSource = Callable[[str], Optional[str]]

log = logging.getLogger("ezskiros_runtime")


def locate_package(name: str) -> Path | None:
    """The installed ROS package's folder, or None (no ROS, or no such package)."""
    try:
        import rospkg

        return Path(rospkg.RosPack().get_path(name))
    except Exception:  # not ROS 1, or not found: try ROS 2
        pass
    try:
        from ament_index_python.packages import (
            get_package_share_directory,
        )

        return Path(get_package_share_directory(name))
    except Exception:
        return None


def read_parameter(name: str) -> str | None:
    """A parameter of the ROS parameter server, or None when it cannot be read."""
    try:
        import rospy

        value = rospy.get_param(name, None)
    except Exception:
        return None
    return value if isinstance(value, str) and value else None


def robot_ontology_files(locator: PackageLocator = locate_package,
                         parameters: ParameterSource = read_parameter) -> tuple[Path, ...]:
    """The ``.owl`` files the world model would load, core first; empty when the ``skiros2``
    package cannot be found (then the bundled core is the best guess, see ``active``)."""
    package = locator(PACKAGE)
    if package is None or not (package / "owl").is_dir():
        log.warning("ezskiros_runtime: the %s package's owl/ folder was not found: checking "
                    "skills against the bundled SkiROS2 core", PACKAGE)
        return ()
    files = sorted((package / "owl").rglob("*.owl"))
    workspace = next((value for name in WORKSPACE_PARAMETERS
                      if (value := parameters(name)) is not None), None)
    if workspace is None or not Path(workspace).expanduser().is_dir():
        log.warning("ezskiros_runtime: the world model's workspace_dir could not be read: "
                    "checking skills against the %s core files only", PACKAGE)
    else:
        files += sorted(Path(workspace).expanduser().rglob("*.owl"))
    return tuple(dict.fromkeys(files))
