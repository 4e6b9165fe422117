"""Installs the Python package ``ezskiros_runtime`` as the ROS package of the same name.

catkin (ROS 1, ``catkin_python_setup()`` in CMakeLists.txt) and colcon's ament_python (ROS
2) both run this file in this folder. ``ezskiros_runtime`` here is a link to the package at
the repository root, where ``pip install`` from a checkout finds it: one copy of the code,
and only the runtime (not the ``ezmigrate`` command, which needs libcst and Python 3.10).
Name, version, maintainer and licence come from package.xml (``generate_distutils_setup``
checks that catkin and setup.py agree). ROS 2 (``ROS_VERSION=2``) also installs the
package's marker in the ament index and its package.xml, as ament_python packages must; on
ROS 1 ``catkin_package()`` installs package.xml itself. There is no setup.cfg: in an
ament_python package it only places scripts, and the runtime has none. This file runs
under the robot's Python, 3.8 on Noetic.
"""

import os

from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import find_packages, setup

HERE = os.path.dirname(os.path.realpath(__file__))
NAME = "ezskiros_runtime"

ROS2_DATA_FILES = [
    ("share/ament_index/resource_index/packages", ["resource/" + NAME]),
    ("share/" + NAME, ["package.xml"]),
]

setup(**generate_distutils_setup(
    package_xml_path=HERE,
    packages=find_packages(HERE, include=[NAME, NAME + ".*"]),
    package_data={NAME: ["ontology/data/*.ttl", "py.typed"]},
    data_files=ROS2_DATA_FILES if os.environ.get("ROS_VERSION") == "2" else [],
))
