"""The line ``rewrite`` adds to a ``package.xml`` is one catkin accepts, in every format.

Most public SkiROS2 lab packages are format 1 (no ``format`` attribute), where catkin
refuses ``<exec_depend>``: each manifest here, written as labs write them, is read with
catkin's own parser (``catkin_pkg``) before and after, so a dependency in the wrong form,
or a line landing inside a comment, fails the test as it would fail ``catkin build``.
Exactly one line is added, beside the dependencies of its kind, and no other byte moves.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from catkin_pkg.package import InvalidPackage, Package, parse_package_string

from ezmigrate.files.package_xml import (
    OLD_ROSDEP_KEY,
    RUNTIME_PACKAGE,
    ManifestRefused,
    manifest_format,
    runtime_depend,
    with_runtime_depend,
)

ROOT = Path(__file__).resolve().parents[2]
SHIPPED = sorted([*(ROOT / "fixtures").rglob("package.xml"), *(ROOT / "ros").rglob("package.xml")])
"""Every manifest the repository ships: the fixtures' lab packages and the runtime's own."""

HEAD = ["<name>cell_skills</name>", "<version>0.1.0</version>",
        "<description>The lab's cell skills</description>",
        '<maintainer email="lab@example.org">Lab</maintainer>', "<license>BSD</license>"]


def _manifest(attribute: str, body: list[str], newline: str = "\n", indent: str = "  ") -> bytes:
    """A whole manifest as a lab writes one: ``attribute`` on ``<package>``, then ``body``
    (a line starting with a tab keeps it) after the mandatory elements."""
    lines = ['<?xml version="1.0"?>', f"<package{attribute}>"]
    lines += [line if line.startswith("\t") or not line else indent + line
              for line in [*HEAD, "", *body]]
    lines += ["</package>", ""]
    return newline.join(lines).encode()


def _parsed(data: bytes) -> Package:
    """What catkin reads: ``InvalidPackage`` where catkin would refuse the package."""
    return parse_package_string(data.decode())


def _added(old: bytes, new: bytes) -> tuple[int, bytes]:
    """The index and bytes of the one line ``new`` adds to ``old``; nothing else differs."""
    before, after = old.splitlines(keepends=True), new.splitlines(keepends=True)
    pairs = enumerate(zip(before, after[:len(before)], strict=True))
    at = next((i for i, (a, b) in pairs if a != b), len(before))
    assert len(after) == len(before) + 1 and after[:at] + after[at + 1:] == before
    return at, after[at]


def _runtime_dependencies(package: Package) -> list[str]:
    """Where catkin puts the runtime dependency (format 1's ``run_depend`` counts as
    ``exec_depend`` and ``build_export_depend``)."""
    return [d.name for d in package.exec_depends if d.name == RUNTIME_PACKAGE]


FORMAT_1_RUN_BLOCK = ["<buildtool_depend>catkin</buildtool_depend>",
                      "<build_depend>rospy</build_depend>", "<build_depend>skiros2</build_depend>",
                      "<run_depend>rospy</run_depend>", "<run_depend>skiros2</run_depend>",
                      "<test_depend>rostest</test_depend>", "", "<export>", "</export>"]

CASES = {
    # (attribute, body, the line the runtime must follow or None for before </package>)
    "format 1, build then run block": ("", FORMAT_1_RUN_BLOCK,
                                       "<run_depend>skiros2</run_depend>"),
    "format 1, run block first": (
        "", ["<buildtool_depend>catkin</buildtool_depend>", "<run_depend>rospy</run_depend>",
             "<build_depend>rospy</build_depend>", "<build_depend>geometry_msgs</build_depend>"],
        "<run_depend>rospy</run_depend>"),
    "format 1, explicit, no run_depend": (
        ' format="1"', ["<buildtool_depend>catkin</buildtool_depend>",
                        "<build_depend>rospy</build_depend>", "<export/>"],
        "<build_depend>rospy</build_depend>"),
    "format 1, no dependency at all": ("", ["<export/>"], None),
    "format 2, exec then test": (
        ' format="2"', ["<buildtool_depend>catkin</buildtool_depend>",
                        "<exec_depend>skiros2</exec_depend>", "\t<exec_depend>rospy</exec_depend>",
                        "<test_depend>rostest</test_depend>", "<build_depend>rospy</build_depend>"],
        "\t<exec_depend>rospy</exec_depend>"),
    "format 2, depend only": (
        " format='2'", ["<buildtool_depend>catkin</buildtool_depend>", "<depend>rospy</depend>",
                        "<build_depend>message_generation</build_depend>"],
        "<depend>rospy</depend>"),
    "format 3, conditions": (
        ' format="3"', ['<buildtool_depend condition="$ROS_VERSION == 1">catkin</buildtool_depend>',
                        '<exec_depend condition="$ROS_VERSION == 2">rclpy</exec_depend>',
                        "<test_depend>python3-pytest</test_depend>",
                        "<export>", "  <build_type>ament_python</build_type>", "</export>"],
        '<exec_depend condition="$ROS_VERSION == 2">rclpy</exec_depend>'),
    "format 3, only a buildtool": (
        ' format="3"', ["<buildtool_depend>ament_python</buildtool_depend>"],
        "<buildtool_depend>ament_python</buildtool_depend>"),
}


@pytest.mark.parametrize("newline", ["\n", "\r\n"], ids=["LF", "CRLF"])
@pytest.mark.parametrize("indent", ["  ", "\t"], ids=["spaces", "tabs"])
@pytest.mark.parametrize("case", list(CASES), ids=list(CASES))
def test_the_runtime_is_declared_as_the_format_allows_beside_its_kind(case, indent, newline):
    attribute, body, follows = CASES[case]
    old = _manifest(attribute, body, newline, indent)
    version = _parsed(old).package_format
    assert manifest_format(old) == version
    new = with_runtime_depend(old)
    assert new is not None
    at, line = _added(old, new)
    element = "<run_depend>" if version == 1 else "<exec_depend>"
    closing = element.replace("<", "</")
    expected = element + RUNTIME_PACKAGE + closing
    assert runtime_depend(old) == expected
    previous = old.splitlines(keepends=True)[at - 1].decode()
    if follows is None:  # before </package>, indented as the first element
        assert old.splitlines(keepends=True)[at].decode().strip() == "</package>"
        assert line.decode() == indent + expected + newline
    else:
        written = follows if follows.startswith("\t") else indent + follows
        assert previous == written + newline
        own = written[:len(written) - len(written.lstrip())]
        assert line.decode() == own + expected + newline
    assert _runtime_dependencies(_parsed(new)) == [RUNTIME_PACKAGE]  # catkin accepts it
    assert with_runtime_depend(new) is None  # declared once, never twice


def test_catkin_refuses_exec_depend_in_format_1_which_is_why_run_depend_is_written():
    old = _manifest("", FORMAT_1_RUN_BLOCK)
    wrong = old.replace(b"</package>", b"  <exec_depend>ezskiros_runtime</exec_depend>\n"
                                       b"</package>")
    with pytest.raises(InvalidPackage, match="exec_depend"):
        _parsed(wrong)
    assert b"<run_depend>" + RUNTIME_PACKAGE.encode() in (with_runtime_depend(old) or b"")


@pytest.mark.parametrize("declared", [
    f"<run_depend>{RUNTIME_PACKAGE}</run_depend>",
    f"<exec_depend> {RUNTIME_PACKAGE} </exec_depend>",
    f"<depend>{RUNTIME_PACKAGE}</depend>",
    f"<build_export_depend>{RUNTIME_PACKAGE}</build_export_depend>",
    f'<exec_depend condition="$ROS_VERSION == 1">{RUNTIME_PACKAGE}</exec_depend>',
    f"<exec_depend>{OLD_ROSDEP_KEY}</exec_depend>",
    f"<run_depend>{OLD_ROSDEP_KEY}</run_depend>",
])
def test_a_package_that_declares_the_runtime_is_left_alone(declared):
    attribute = ("" if "run_depend" in declared
                 else ' format="3"' if "condition" in declared else ' format="2"')
    old = _manifest(attribute, ["<buildtool_depend>catkin</buildtool_depend>", declared])
    _parsed(old)
    assert with_runtime_depend(old) is None


def test_what_is_commented_out_neither_declares_nor_anchors():
    old = _manifest("", ["<buildtool_depend>catkin</buildtool_depend>",
                         "<run_depend>rospy</run_depend>",
                         f"<!-- <run_depend>{RUNTIME_PACKAGE}</run_depend> -->",
                         "<!--", "<run_depend>python-yaml</run_depend>", "-->"])
    new = with_runtime_depend(old)
    assert new is not None
    at, _ = _added(old, new)
    assert old.splitlines()[at - 1].strip() == b"<run_depend>rospy</run_depend>"
    assert _runtime_dependencies(_parsed(new)) == [RUNTIME_PACKAGE]


def test_the_runtimes_own_manifest_is_left_alone():
    runtime = ROOT / "ros" / "ezskiros_runtime" / "package.xml"
    assert with_runtime_depend(runtime.read_bytes()) is None  # no package needs itself


@pytest.mark.parametrize("data", [b"<not-a-package/>", b"<package>\n  <name>x</name>",
                                  b'<package format="9"><name>x</name></package>'],
                         ids=["other root", "no </package>", "unknown format"])
def test_what_is_no_manifest_is_refused_not_guessed_at(data):
    with pytest.raises(ManifestRefused):
        with_runtime_depend(data)


def _inserted(old: bytes, new: bytes, element: bytes) -> bytes:
    """The one run of bytes, ``element`` with blanks and line breaks around it, that ``new``
    adds to ``old``: every byte of ``old`` is kept, in order."""
    at = new.index(element)
    spans = [(start, end) for start in range(max(0, at - 16), at + 1)
             for end in range(at + len(element), at + len(element) + 4)
             if new[:start] + new[end:] == old and not new[start:end].replace(element, b"").strip()]
    assert spans, (old, new)
    return new[spans[0][0]:spans[0][1]]


def _one_line(attribute: str, body: str) -> bytes:
    """A manifest whose mandatory elements share the line of ``<package>``, ``body`` after
    them (the issue's cases)."""
    head = "".join(HEAD)
    return f'<?xml version="1.0"?>\n<package{attribute}>{head}{body}\n'.encode()


ONE_LINE_CASES = {
    # the manifests: each valid, each came out wrong when edited by lines of text
    "closing tag on the dependency's line": (
        ' format="2"', "\n  <buildtool_depend>catkin</buildtool_depend>\n"
                       "  <exec_depend>rospy</exec_depend></package>"),
    "comment opening on the last dependency's line": (
        ' format="2"', "\n  <buildtool_depend>catkin</buildtool_depend>\n"
                       "  <exec_depend>rospy</exec_depend> <!-- was:\n"
                       "  <exec_depend>python-yaml</exec_depend>\n  -->\n</package>"),
    "the whole manifest on one line": ("", "</package>"),
    "one line with a dependency": ("", "<run_depend>rospy</run_depend></package>"),
    "one line, closing tag on a line of its own": ("", "\n</package>"),
    "CDATA holding what looks like elements": (
        ' format="2"', "\n  <exec_depend>rospy</exec_depend>\n"
                       "  <export><![CDATA[<exec_depend>x</exec_depend></package>]]></export>\n"
                       "</package>"),
}


@pytest.mark.parametrize("case", list(ONE_LINE_CASES), ids=list(ONE_LINE_CASES))
def test_the_line_goes_where_catkin_reads_it_whatever_shares_its_line(case):
    old = _one_line(*ONE_LINE_CASES[case])
    before = _parsed(old)
    new = with_runtime_depend(old)
    assert new is not None
    _inserted(old, new, (runtime_depend(old) or "").encode())  # one element, nothing else
    after = _parsed(new)
    assert _runtime_dependencies(after) == [RUNTIME_PACKAGE]
    assert [d.name for d in after.exec_depends if d.name != RUNTIME_PACKAGE] == [
        d.name for d in before.exec_depends]  # a commented-out dependency stays commented
    assert with_runtime_depend(new) is None


def _evaluated(data: bytes, ros_version: str) -> list[str]:
    """The exec dependencies catkin gives a build for ``ros_version``."""
    package = _parsed(data)
    package.evaluate_conditions({"ROS_VERSION": ros_version, "ROS_PYTHON_VERSION": "3"})
    return [d.name for d in package.exec_depends if d.evaluated_condition]


ROS1 = "<buildtool_depend>catkin</buildtool_depend>"
ROS2 = "<buildtool_depend>ament_python</buildtool_depend>"


@pytest.mark.parametrize(("tool", "condition", "version", "declared"), [
    (ROS1, "$ROS_VERSION == 2", "1", False),
    (ROS1, "$ROS_VERSION == 1", "1", True),
    (ROS2, "$ROS_VERSION == 2", "2", True),
    (ROS2, "$ROS_VERSION == 1", "2", False),
    (ROS1, "$ROS_VERSION != 2", "1", True),
    (ROS1, "$ROS_VERSION == 2 or $ROS_PYTHON_VERSION == 3", "1", True),
    (ROS1, "($ROS_VERSION == 2 or $ROS_VERSION == 3) and $ROS_PYTHON_VERSION == 3", "1", False),
    (ROS1, "$ROS_DISTRO == noetic", "1", False),  # a distribution this run cannot know
], ids=lambda value: str(value))
def test_a_conditional_dependency_counts_for_the_ros_versions_it_admits(
        tool, condition, version, declared):
    old = _manifest(' format="3"', [tool, f'<exec_depend condition="{condition}">'
                                          f"{RUNTIME_PACKAGE}</exec_depend>"])
    assert (RUNTIME_PACKAGE in _evaluated(old, version)) == declared  # what catkin says
    new = with_runtime_depend(old)
    assert (new is None) == declared
    if new is not None:
        _added(old, new)
        assert RUNTIME_PACKAGE in _evaluated(new, version)


def test_a_package_built_for_both_needs_the_runtime_for_both():
    both = ['<buildtool_depend condition="$ROS_VERSION == 1">catkin</buildtool_depend>',
            '<buildtool_depend condition="$ROS_VERSION == 2">ament_python</buildtool_depend>']
    only_2 = _manifest(' format="3"', [*both, '<exec_depend condition="$ROS_VERSION == 2">'
                                              f"{RUNTIME_PACKAGE}</exec_depend>"])
    assert with_runtime_depend(only_2) is not None
    each = only_2.replace(b"</package>", b'  <exec_depend condition="$ROS_VERSION == 1">'
                          + RUNTIME_PACKAGE.encode() + b"</exec_depend>\n</package>")
    assert with_runtime_depend(each) is None


def test_a_line_catkin_would_refuse_is_not_written_and_the_refusal_says_why():
    old = _manifest("", [ROS1, "<run_depend>rospy</run_depend>",
                         f"<test_depend>{RUNTIME_PACKAGE}</test_depend>"])
    _parsed(old)  # valid as it is; a run_depend beside it is "redundant" to catkin
    with pytest.raises(ManifestRefused, match="catkin_pkg would refuse"):
        with_runtime_depend(old)


@pytest.mark.parametrize("path", SHIPPED, ids=lambda p: p.parent.relative_to(ROOT).as_posix())
def test_every_shipped_manifest_parses_before_and_after(path):
    old = path.read_bytes()
    assert _parsed(old).name
    new = with_runtime_depend(old)
    if new is None:  # the runtime's own
        assert _parsed(old).name == RUNTIME_PACKAGE
        return
    _added(old, new)
    assert _runtime_dependencies(_parsed(new)) == [RUNTIME_PACKAGE]


def test_the_shipped_manifests_are_found():
    assert {p.parent.name for p in SHIPPED} >= {"ezskiros_runtime", "lab_skills", "noetic_package"}


LEGACY = '''from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


class Place(SkillDescription):
    def createDescription(self):
        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)
'''


def _rewrite(package: Path, *extra: str) -> subprocess.CompletedProcess[str]:
    env = {k: v for k, v in os.environ.items() if not k.startswith("EZSKIROS_")}
    return subprocess.run([sys.executable, "-m", "ezmigrate", "rewrite", "--no-verify", *extra,
                           "."], cwd=package, capture_output=True, text=True, env=env,
                          timeout=300, check=False)


def test_rewrite_writes_run_depend_into_a_format_1_package_and_says_so(tmp_path):
    package = tmp_path / "cell_skills"
    (package / "src" / "cell_skills").mkdir(parents=True)
    (package / "src" / "cell_skills" / "skills.py").write_text(LEGACY, encoding="utf-8")
    old = _manifest("", FORMAT_1_RUN_BLOCK, "\r\n")
    (package / "package.xml").write_bytes(old)
    kept = tmp_path / "kept"
    shutil.copytree(package, kept)
    run = _rewrite(package)
    assert run.returncode == 0, run.stderr
    assert ("ezmigrate: package.xml: <run_depend>ezskiros_runtime</run_depend> added"
            in run.stderr.splitlines())
    new = (package / "package.xml").read_bytes()
    assert new == with_runtime_depend(old)
    assert _runtime_dependencies(_parsed(new)) == [RUNTIME_PACKAGE]
    off = _rewrite(kept, "--no-package-xml")
    assert off.returncode == 0, off.stderr
    assert (kept / "package.xml").read_bytes() == old
    assert "ezskiros_runtime" in (kept / "src" / "cell_skills" / "skills.py").read_text()


def test_rewrite_names_a_manifest_it_cannot_edit_safely_and_leaves_it_as_it_was(tmp_path):
    package = tmp_path / "cell_skills"
    (package / "src" / "cell_skills").mkdir(parents=True)
    (package / "src" / "cell_skills" / "skills.py").write_text(LEGACY, encoding="utf-8")
    old = _manifest("", [ROS1, "<run_depend>rospy</run_depend>",
                         f"<test_depend>{RUNTIME_PACKAGE}</test_depend>"])
    (package / "package.xml").write_bytes(old)
    run = _rewrite(package)
    assert run.returncode == 1, run.stderr  # a file the run could not process
    said = [line for line in run.stderr.splitlines() if "package.xml" in line]
    assert said and all("left as it was" in line for line in said), run.stderr
    assert str(package / "package.xml") in said[0]
    assert "</run_depend> added" not in run.stderr
    assert (package / "package.xml").read_bytes() == old
    assert "ezskiros_runtime" in (package / "src" / "cell_skills" / "skills.py").read_text()
