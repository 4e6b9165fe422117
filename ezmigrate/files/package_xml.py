"""What a ROS package's ``package.xml`` says, and the runtime declared in it.

A package's manifest says whether it is ROS 1 or ROS 2 (its buildtool: the robot's
Python) and where the packages of a run are; one reader per fact, here. Its name is read by
``ezskiros_runtime.ontology.vendored.package_name``, which the runtime's vendored-copy rule
needs too.

Migrated skills import ``ezskiros_runtime`` on the robot, so the package must say it needs
it, or ``rosdep install`` and the build tools leave it out and the skill manager fails to
load the skills. The runtime is a ROS package of its own, ``ezskiros_runtime`` (the folder
``ros/ezskiros_runtime`` of a checkout of ezmigrate, put in the workspace's ``src/``), so
``rewrite`` adds one dependency on it to the ``package.xml`` of each ROS package whose
files it migrated, unless one is declared (by that name, or by the rosdep key earlier
versions wrote) or the manifest is the runtime's own. The element is the one the format
allows: catkin refuses a format 1 manifest (no ``format`` attribute) holding
``<exec_depend>``, so there it is ``<run_depend>``; formats 2 and 3 get ``<exec_depend>``.

The manifest is read by an XML parser (expat, with the byte offset of every element), never
by patterns over its text, so what a comment or a CDATA section holds declares nothing and
anchors nothing. A dependency with a ``condition`` counts only for the ROS versions its
condition admits (evaluated as catkin does, with ``$ROS_VERSION`` 1 or 2 as the package's
build type says): ``condition="$ROS_VERSION == 2"`` declares nothing for a ROS 1 package.
The line goes after the last dependency of the same kind (``run_depend``; ``exec_depend``
or ``depend``), else after the last ``*depend`` element, else before ``</package>``; it
copies the indentation of the line it follows (or of the package's first child element)
and the file's own line ending. One line is inserted and every other byte is kept; when the
element it follows shares its line with something else (``</package>``, a comment that
opens there), the new element goes right after it on a line of its own. The result is
parsed again (well-formed, and by catkin's own parser when ``catkin_pkg`` is installed)
before anything is written; a manifest with no safe place for the line raises
``ManifestRefused``, and the caller says so and leaves the file as it was.
``--no-package-xml`` turns this off.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from xml.parsers import expat

from ezskiros_runtime.ontology.discovery import NOT_SEARCHED, PACKAGE_XML, package_root
from ezskiros_runtime.ontology.listing import walk

RUNTIME_PACKAGE = "ezskiros_runtime"
"""The runtime's ROS package (``ros/ezskiros_runtime/package.xml``), the dependency that
``rewrite`` declares: built in the lab's workspace, it brings the runtime to the robot."""

OLD_ROSDEP_KEY = "python3-ezskiros-runtime-pip"
"""What earlier versions declared instead: a package naming it is left as it is."""

_DECLARING = frozenset({"run_depend", "exec_depend", "depend", "build_export_depend"})
"""The elements that bring a package to the robot at run time (catkin's exec and export
dependencies)."""
_DEPENDS = frozenset({*_DECLARING, "build_depend", "buildtool_depend",
                      "buildtool_export_depend", "test_depend", "doc_depend"})
_BESIDE = {1: ("run_depend",), 2: ("exec_depend", "depend"), 3: ("exec_depend", "depend")}
"""The dependencies the runtime's line follows first, by format."""
_BUILDTOOL = re.compile(rb"<buildtool_depend>\s*([A-Za-z0-9_]+)\s*</buildtool_depend>")
_ROS_PYTHON_VERSION = "3"
"""``$ROS_PYTHON_VERSION`` for conditions: Noetic and every ROS 2 run Python 3."""


class ManifestRefused(ValueError):
    """No safe place for the runtime's line in this manifest, or the result would not read
    back as the same package with the runtime declared; the message says which, and the
    file is left as it was."""


@dataclass
class _Element:
    """One child of ``<package>`` (or of its ``<export>``), with its byte span in the file."""

    tag: str
    attributes: dict[str, str]
    start: int
    """The offset of its ``<``."""
    end: int = -1
    """The offset just after its last ``>``."""
    text: str = ""


@dataclass
class _Manifest:
    """What the runtime's line needs of a parsed ``package.xml``."""

    format: int
    children: list[_Element] = field(default_factory=list)
    exports: list[_Element] = field(default_factory=list)
    """The children of ``<export>`` (``build_type``)."""
    close: int = -1
    """The offset of ``</package>``."""

    def named(self, tag: str) -> list[_Element]:
        """The children called ``tag``, in file order."""
        return [child for child in self.children if child.tag == tag]


class _Reader:
    """Expat's events turned into a ``_Manifest``: ``<package>``'s children (and
    ``<export>``'s) with their byte spans and text. Comments, processing instructions and
    CDATA sections are events of their own, so nothing inside them is taken for an element."""

    def __init__(self, data: bytes) -> None:
        self.data = data
        self.manifest: _Manifest | None = None
        self.open: list[_Element | None] = []
        """The elements open now, outermost first (None: one nobody needs)."""
        self.last_start = -1
        """The offset of the latest start tag when nothing came after it yet, else -1."""
        self.parser = expat.ParserCreate()
        self.parser.StartElementHandler = self._start
        self.parser.EndElementHandler = self._end
        self.parser.CharacterDataHandler = self._text
        self.parser.CommentHandler = self._other
        self.parser.ProcessingInstructionHandler = self._other
        self.parser.StartCdataSectionHandler = self._other

    def read(self) -> _Manifest:
        """The manifest, or ``ManifestRefused`` saying why the bytes are none."""
        try:
            self.parser.Parse(self.data, True)
        except expat.ExpatError as error:
            raise ManifestRefused(f"not well-formed XML ({error})") from None
        if self.manifest is None or self.manifest.close < 0:
            raise ManifestRefused("its root element is not <package>")
        return self.manifest

    def _start(self, tag: str, attributes: dict[str, str]) -> None:
        at = self.parser.CurrentByteIndex
        depth = len(self.open)
        element = None
        if depth == 0 and tag == "package":
            self.manifest = _Manifest(_format(attributes.get("format", "1")))
        elif self.manifest is not None and depth == 1:
            element = _Element(tag, attributes, at)
            self.manifest.children.append(element)
        elif self.manifest is not None and depth == 2 and self.open[1] is not None \
                and self.open[1].tag == "export":
            element = _Element(tag, attributes, at)
            self.manifest.exports.append(element)
        self.open.append(element)
        self.last_start = at

    def _end(self, tag: str) -> None:
        at = self.parser.CurrentByteIndex
        element = self.open.pop()
        if not self.open and self.manifest is not None:
            self.manifest.close = at
        elif element is not None:
            element.end = _end_of(self.data, at, self.last_start == element.start)
        self.last_start = -1

    def _text(self, text: str) -> None:
        element = self.open[-1] if self.open else None
        if element is not None:
            element.text += text
        self.last_start = -1

    def _other(self, *_: object) -> None:
        self.last_start = -1


def _end_of(data: bytes, at: int, nothing_inside: bool) -> int:
    """The offset after an element whose end event expat reports at ``at``: there its end
    tag starts (``</name>``), or, for an empty-element tag (``<name/>``: nothing between
    its start and end events, and ``/>`` just before ``at``), it has just ended."""
    if nothing_inside and data[at - 2:at] == b"/>":
        return at
    return data.index(b">", at) + 1


def _format(value: str) -> int:
    """The manifest format catkin reads from the attribute (it reads 1, 2 and 3 only)."""
    try:
        version = int(value)
    except ValueError:
        version = 0
    if version not in (1, 2, 3):
        raise ManifestRefused(f"format {value!r} is none catkin reads")
    return version


def _read(data: bytes) -> _Manifest:
    """``data`` read as a manifest; ``ManifestRefused`` when it is none."""
    return _Reader(data).read()


_CONDITION_TOKEN = re.compile(r"""\s*(?:(?P<op>==|!=|>=|<=|>|<)|(?P<paren>[()])|\$(?P<var>\w+)
                                  |"(?P<dq>[^"]*)"|'(?P<sq>[^']*)'|(?P<word>[\w-]+))""",
                              re.X | re.A)
_COMPARE = {"==": str.__eq__, "!=": str.__ne__, ">=": str.__ge__, "<=": str.__le__,
            ">": str.__gt__, "<": str.__lt__}


class _Unreadable(ValueError):
    """A ``condition`` attribute catkin could not parse either."""


def _condition_tokens(condition: str, context: dict[str, str]) -> list[tuple[str, str]]:
    """``(kind, value)`` pairs; a variable is its value already (unset: empty, as catkin)."""
    tokens = []
    at, end = 0, len(condition.rstrip())
    while at < end:
        match = _CONDITION_TOKEN.match(condition, at)
        if match is None:
            raise _Unreadable(condition)
        kind = match.lastgroup or ""
        value = match.group(kind)
        if kind == "var":
            kind, value = "term", context.get(value, "")
        elif kind in ("dq", "sq", "word"):
            kind = value if kind == "word" and value in ("and", "or") else "term"
        tokens.append((kind, value))
        at = match.end()
    return tokens


class _Condition:
    """A recursive-descent reading of REP 149's conditions, as catkin evaluates them:
    comparisons of strings, ``and`` binding tighter than ``or``, parentheses."""

    def __init__(self, tokens: list[tuple[str, str]]) -> None:
        self.tokens = tokens
        self.at = 0

    def value(self) -> bool:
        """The whole condition's truth; ``_Unreadable`` for what catkin would not parse."""
        result = self._any()
        if self.at != len(self.tokens):
            raise _Unreadable("trailing tokens")
        return result

    def _take(self, kind: str) -> str:
        if self.at >= len(self.tokens) or self.tokens[self.at][0] != kind:
            raise _Unreadable(f"expected {kind}")
        self.at += 1
        return self.tokens[self.at - 1][1]

    def _next_is(self, kind: str) -> bool:
        return self.at < len(self.tokens) and self.tokens[self.at][0] == kind

    def _any(self) -> bool:
        result = self._all()
        while self._next_is("or"):
            self.at += 1
            result = self._all() or result
        return result

    def _all(self) -> bool:
        result = self._one()
        while self._next_is("and"):
            self.at += 1
            result = self._one() and result
        return result

    def _one(self) -> bool:
        if self._next_is("paren") and self.tokens[self.at][1] == "(":
            self.at += 1
            result = self._any()
            if self._take("paren") != ")":
                raise _Unreadable("expected )")
            return result
        left = self._take("term")
        compare = _COMPARE[self._take("op")]
        return compare(left, self._take("term"))


def _admits(element: _Element, ros_version: int) -> bool:
    """Whether ``element`` applies to a build for ``ros_version``: no ``condition``, or
    one that holds there. A condition catkin could not parse applies nowhere."""
    condition = element.attributes.get("condition")
    if condition is None:
        return True
    context = {"ROS_VERSION": str(ros_version), "ROS_PYTHON_VERSION": _ROS_PYTHON_VERSION}
    try:
        return _Condition(_condition_tokens(condition, context)).value()
    except _Unreadable:
        return False


def _version_of_tool(name: str) -> int | None:
    """1 for catkin, 2 for ament's build types and buildtools, None for others."""
    name = name.strip()
    return 1 if name == "catkin" else 2 if name.startswith("ament") else None


def _ros_versions(manifest: _Manifest) -> set[int]:
    """The ROS versions the package is built for: by its ``<export><build_type>``, else
    by its ``<buildtool_depend>``s (each only where its condition admits it), else both."""
    for elements in ([e for e in manifest.exports if e.tag == "build_type"],
                     manifest.named("buildtool_depend")):
        versions = {version for element in elements
                    if (version := _version_of_tool(element.text)) is not None
                    and _admits(element, version)}
        if versions:
            return versions
    return {1, 2}


def _declares_runtime(manifest: _Manifest) -> bool:
    """Whether every ROS version the package builds for gets the runtime (or the old
    rosdep key) from a dependency whose condition admits that version."""
    names = (RUNTIME_PACKAGE, OLD_ROSDEP_KEY)
    found = [child for child in manifest.children
             if child.tag in _DECLARING and child.text.strip() in names]
    return all(any(_admits(child, version) for child in found)
               for version in _ros_versions(manifest))


def _is_runtime(manifest: _Manifest) -> bool:
    """Whether the manifest is the runtime's own (no package needs itself)."""
    return any(child.text.strip() == RUNTIME_PACKAGE for child in manifest.named("name"))


def manifest_format(data: bytes) -> int | None:
    """The format of a ``package.xml`` (1 when its ``<package>`` names none, as catkin
    reads it), or None when it is no manifest."""
    try:
        return _read(data).format
    except ManifestRefused:
        return None


def runtime_depend(data: bytes) -> str | None:
    """The element declaring the runtime that the manifest's format allows, or None when
    ``data`` is no manifest."""
    version = manifest_format(data)
    return None if version is None else _element(version).decode()


def with_runtime_depend(data: bytes) -> bytes | None:
    """``data`` with the runtime's dependency added, checked by parsing it again; None when
    it is declared already (for every ROS version the package builds for) or the manifest
    is the runtime's own. ``ManifestRefused`` when the file is no manifest, or has no
    place where the line reads back as the runtime's dependency: it is to be left alone."""
    manifest = _read(data)
    if _is_runtime(manifest) or _declares_runtime(manifest):
        return None
    at, line = _insertion(data, manifest)
    new = data[:at] + line + data[at:]
    _check(data, new)
    return new


def _insertion(data: bytes, manifest: _Manifest) -> tuple[int, bytes]:
    """Where the runtime's element goes and the bytes inserted there: a line of its own
    after the anchor's line (or before the line of ``</package>``) when that line holds
    nothing else, otherwise right after the anchor (or before ``</package>``) with a line
    break of its own, so that no other byte moves out of where it was."""
    element = _element(manifest.format)
    newline = b"\r\n" if b"\r\n" in data else b"\n"
    anchor = _anchor(manifest)
    if anchor is None:
        indent = _child_indent(data, manifest)
        start = _line_start(data, manifest.close)
        if not data[start:manifest.close].strip():
            return start, indent + element + newline
        return manifest.close, newline + indent + element + newline
    own = _own_indent(data, anchor.start)
    indent = own if own is not None else _child_indent(data, manifest)
    line_end = data.find(b"\n", anchor.end)
    if line_end >= 0 and not data[anchor.end:line_end].strip():
        return line_end + 1, indent + element + newline
    return anchor.end, newline + indent + element


def _anchor(manifest: _Manifest) -> _Element | None:
    """The dependency the runtime's line follows: the last of its kind, else the last
    ``*depend`` element, else None (the line goes before ``</package>``)."""
    depends = [child for child in manifest.children if child.tag in _DEPENDS]
    beside = [child for child in depends if child.tag in _BESIDE[manifest.format]]
    chosen = beside or depends
    return chosen[-1] if chosen else None


def _line_start(data: bytes, at: int) -> int:
    return data.rfind(b"\n", 0, at) + 1


def _own_indent(data: bytes, at: int) -> bytes | None:
    """The blanks before offset ``at`` on its line, or None when other text precedes it."""
    prefix = data[_line_start(data, at):at]
    return prefix if not prefix.strip(b" \t") else None


def _child_indent(data: bytes, manifest: _Manifest) -> bytes:
    """The indentation of the package's first child that starts a line (two spaces when
    none does, as in a manifest written on one line)."""
    for child in manifest.children:
        indent = _own_indent(data, child.start)
        if indent is not None:
            return indent
    return b"  "


def _check(old: bytes, new: bytes) -> None:
    """``ManifestRefused`` unless ``new`` reads back, with an XML parser and with catkin's
    (where installed), as a manifest declaring the runtime."""
    try:
        manifest = _read(new)
    except ManifestRefused as error:
        raise ManifestRefused(f"no safe place for the line: the result would be {error}") \
            from None
    if not _declares_runtime(manifest):
        raise ManifestRefused("no safe place for the line: the result would not declare it")
    refusal = _catkin_refusal(old, new)
    if refusal is not None:
        raise ManifestRefused(f"no safe place for the line: {refusal}")


def _catkin_refusal(old: bytes, new: bytes) -> str | None:
    """Why catkin's own parser would not read ``new`` as the package with the runtime as an
    exec dependency, though it reads ``old``; None when it would, when it refuses ``old``
    already (nothing to keep), or when ``catkin_pkg`` is not installed (a developer
    dependency: the XML check above stands alone then)."""
    try:
        from catkin_pkg.package import parse_package_string
    except ImportError:
        return None
    try:
        parse_package_string(old.decode("utf-8"), warnings=[])
    except Exception:  # catkin raises InvalidPackage, ValueError, AssertionError
        return None
    try:
        package = parse_package_string(new.decode("utf-8"), warnings=[])
    except Exception as error:  # as above: any refusal is one
        return f"catkin_pkg would refuse the result ({' '.join(str(error).split())})"
    if RUNTIME_PACKAGE not in {dependency.name for dependency in package.exec_depends}:
        return "catkin_pkg would not read the runtime's dependency in the result"
    return None


def _element(version: int) -> bytes:
    """Format 1 has no ``exec_depend`` (catkin refuses the manifest); 2 and 3 no
    ``run_depend``."""
    tag = b"run_depend" if version == 1 else b"exec_depend"
    return b"<" + tag + b">" + RUNTIME_PACKAGE.encode() + b"</" + tag + b">"


def manifests_below(folder: Path) -> Iterator[Path]:
    """Every ``package.xml`` under ``folder``, sorted, not in hidden folders nor in what
    discovery never searches (build, devel and install spaces hold copies of them)."""
    for here, dirs, names in walk(folder):
        dirs[:] = sorted(d for d in dirs if not d.startswith(".") and d not in NOT_SEARCHED)
        if PACKAGE_XML in names:
            yield Path(here) / PACKAGE_XML


def packages_of(files: Iterable[Path]) -> list[Path]:
    """The ``package.xml`` of each ROS package holding one of ``files``, in order."""
    found: dict[Path, None] = {}
    for file in files:
        root = package_root(file.resolve())
        if root is not None:
            found[root / PACKAGE_XML] = None
    return list(found)


def package_files(paths: Iterable[Path]) -> list[Path]:
    """The ``package.xml`` of each ROS package the paths are in or, for a folder, hold,
    without repeats, in order."""
    found: dict[Path, None] = {}
    for path in paths:
        found.update(dict.fromkeys(packages_of([path])))
        if path.is_dir():
            found.update(dict.fromkeys(manifests_below(path.resolve())))
    return list(found)


def ros_flavour(package_xml: Path) -> str | None:
    """``ros1`` for a package built for ROS 1 (catkin), ``ros2`` for one built for ROS 2
    only (ament: its ``<export><build_type>``, as an ament_python package says it, else its
    ``<buildtool_depend>``, each where its condition admits it), None when it says neither
    (or cannot be read). A package built for both targets the older robot."""
    try:
        manifest = _read(package_xml.read_bytes())
    except (OSError, ValueError):
        return None
    said = [e for e in manifest.exports if e.tag == "build_type"] \
        + manifest.named("buildtool_depend")
    if not any(_version_of_tool(e.text) is not None for e in said):
        return None
    return "ros1" if 1 in _ros_versions(manifest) else "ros2"
