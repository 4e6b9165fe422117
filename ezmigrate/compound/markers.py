"""What the compound pass and the repository scan look for in a file's bytes before (or
instead of) its syntax tree: one place, so that ``checking.early_cutoff`` counts every such
look as part of a file's reading, and imports nothing heavy to do it."""

from __future__ import annotations

import re

READ_WHEN = (b"expand", b"setDescription", b"createDescription")
"""A file is read for compound skills, implementations and description bases if it has any
(``analysis.Trees``)."""
SCAN_WHEN = (*READ_WHEN, b"SkillDescription")
"""A file is scanned for the repository's descriptions if it has any: ``READ_WHEN``, or a
description class with no ``createDescription`` of its own."""
ROS2_IMPORT = re.compile(rb"^\s*(?:import|from)\s+rclpy\b", re.MULTILINE)
ROS1_IMPORT = re.compile(rb"^\s*(?:import|from)\s+rospy\b", re.MULTILINE)
"""A file's own ROS imports, when no ``package.xml`` says its flavour (``ros_package_of``)."""
