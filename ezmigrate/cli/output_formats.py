"""The machine formats of ``check``: text, JSON, SARIF 2.1.0, GitHub annotations, JUnit.

Each takes the final list of diagnostics and returns the whole text for stdout, so a CI
step can redirect it to a file (``--output-format sarif > check.sarif``).
"""

from __future__ import annotations

import json
import os
import re
from collections import Counter
from collections.abc import Callable, Sequence
from dataclasses import replace
from pathlib import Path
from urllib.parse import quote
from xml.etree import ElementTree

from ezskiros_runtime.codes import BY_CODE

from .. import __version__
from ..lint.diagnostic import Diagnostic

SARIF_SCHEMA = "https://json.schemastore.org/sarif-2.1.0.json"
_SARIF_LEVEL = {"error": "error", "warning": "warning", "info": "note"}
_GITHUB_LEVEL = {"error": "error", "warning": "warning", "info": "notice"}


_CONTROL = re.compile("[\x00-\x1f\x7f-\x9f\u2028\u2029]")
"""C0 and C1 controls (line breaks, ESC, ...), DEL, and Unicode's line and paragraph
separators: what a terminal or a CI runner may act on instead of showing."""
_ESCAPES = {"\n": "\\n", "\r": "\\r", "\t": "\\t"}
_PLAIN_START = re.compile(r"[\w./~]")


def printable(text: str, path: bool = False) -> str:
    """``text`` with every control character written as an escape (``\\n``, ``\\r``,
    ``\\t``, ``\\x1b``, ``\\x85``), for text output. A file name may hold any of them, and
    printed raw a line break in one starts a line of its own: GitHub's runner reads a line
    starting with ``::`` as a workflow command (``::error file=README.md,...``), a terminal
    acts on ESC. ``path``: ``text`` is a path at the start of a printed line, so a relative
    one not starting with a letter, digit, ``_``, ``.``, ``/`` or ``~`` is written
    ``./NAME`` (the same file) and no line starts with what a file name chose (``-``,
    standard input, stays as it is). The github
    and SARIF formats escape as their readers require instead."""
    escaped = _CONTROL.sub(_control_escape, text)
    if path and escaped and escaped != "-" and not _PLAIN_START.match(escaped):
        return "./" + escaped
    return escaped


def _control_escape(match: re.Match[str]) -> str:
    """One control character as Python writes it in a string literal."""
    character = match.group()
    code = ord(character)
    return _ESCAPES.get(character) or (f"\\x{code:02x}" if code <= 0xFF else f"\\u{code:04x}")


def text(diagnostics: Sequence[Diagnostic]) -> str:
    """``path:line:col: CODE [severity] message``, one per line (what editors and
    terminals parse); path and message through ``printable``, so that each finding is one
    line and none starts with what a file name says."""
    return "".join(f"{_printable_finding(d)}\n" for d in diagnostics)


def _printable_finding(d: Diagnostic) -> Diagnostic:
    """``d`` with what a file or its code chose (path, skill, message) made printable."""
    return replace(d, path=printable(d.path, path=True), skill=printable(d.skill),
                   message=printable(d.message))


def as_json(diagnostics: Sequence[Diagnostic]) -> str:
    """A JSON list of objects with position, code, severity, message and fix hint."""
    return json.dumps([{
        "path": d.path, "line": d.line, "column": d.column, "end_line": d.end_line,
        "end_column": d.end_column, "code": d.code, "severity": d.severity,
        "message": d.text, "fix": d.fix} for d in diagnostics], indent=2) + "\n"


SRCROOT = "SRCROOT"
"""The ``uriBaseId`` of every location: the repository root, named in ``originalUriBaseIds``."""


def _base(diagnostics: Sequence[Diagnostic]) -> Path:
    """The repository root the SARIF locations are relative to: the git top level (else the
    ROS package) of the first file, else the working directory. A CI uploads the log from
    anywhere in the checkout; GitHub resolves locations against the repository root."""
    from ezskiros_runtime.ontology.discovery import enclosing_project

    for d in diagnostics:
        root = enclosing_project(Path(os.path.abspath(d.path)))
        if root is not None:
            return root
    return Path.cwd().resolve()


def _uri(path: str, base: Path) -> tuple[str, bool]:
    """``(percent-encoded URI, relative to base)``: relative to ``base`` when the file is
    inside it (``my%20skill.py``), else an absolute ``file:`` URI."""
    absolute = Path(os.path.realpath(os.path.abspath(path)))
    try:
        return quote(absolute.relative_to(base.resolve()).as_posix()), True
    except ValueError:
        return absolute.as_uri(), False


RULES_DOC = "docs/rules.md"
"""Where the catalogue lives in ezmigrate's repository (generated from ``codes.py``)."""


def sarif(diagnostics: Sequence[Diagnostic]) -> str:
    """SARIF 2.1.0: one rule per code that occurs, one result per diagnostic."""
    codes = sorted({d.code for d in diagnostics})
    rules = [{
        "id": code, "name": BY_CODE[code].name,
        "shortDescription": {"text": BY_CODE[code].rationale},
        # the catalogue travels inside the log: no helpUri to a site this project does not
        # publish (a made-up URL in every code-scanning alert is worse than none)
        "help": {"text": f"{BY_CODE[code].fix} ({RULES_DOC}, {code})",
                 "markdown": f"{BY_CODE[code].fix}\n\n{BY_CODE[code].rationale}\n\n"
                             f"`{RULES_DOC}`, {code}"},
        "defaultConfiguration": {"level": _SARIF_LEVEL[BY_CODE[code].severity]},
    } for code in codes]
    base = _base(diagnostics)
    results = [{
        "ruleId": d.code, "ruleIndex": codes.index(d.code), "level": _SARIF_LEVEL[d.severity],
        "message": {"text": f"{d.text} (fix: {d.fix})"},
        "locations": [{"physicalLocation": {
            "artifactLocation": _artifact(d.path, base),
            "region": {"startLine": d.line, "startColumn": d.column,
                       "endLine": d.end_line or d.line,
                       "endColumn": max(d.end_column, d.column)}}}],
    } for d in diagnostics]
    log = {"version": "2.1.0", "$schema": SARIF_SCHEMA, "runs": [{
        "tool": {"driver": {"name": "ezmigrate", "version": __version__,
                            "rules": rules}},
        "originalUriBaseIds": {SRCROOT: {"uri": base.resolve().as_uri() + "/"}},
        "results": results}]}
    return json.dumps(log, indent=2) + "\n"


def _artifact(path: str, base: Path) -> dict[str, str]:
    uri, relative = _uri(path, base)
    return {"uri": uri, "uriBaseId": SRCROOT} if relative else {"uri": uri}


def _escape(value: str, properties: bool) -> str:
    """GitHub workflow-command escaping (``%``, line breaks; ``:`` and ``,`` in properties)."""
    value = value.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")
    return value.replace(":", "%3A").replace(",", "%2C") if properties else value


def github(diagnostics: Sequence[Diagnostic]) -> str:
    """``::error file=..,line=..,col=..,title=CODE::message`` annotations for Actions."""
    return "".join(
        f"::{_GITHUB_LEVEL[d.severity]} file={_escape(d.path, True)},line={d.line},"
        f"col={d.column},endLine={d.end_line or d.line},endColumn={d.end_column},"
        f"title={d.code}::{_escape(f'{d.code} {d.text}', False)}\n" for d in diagnostics)


def junit(diagnostics: Sequence[Diagnostic]) -> str:
    """JUnit XML: a test suite per file, a test case per diagnostic; only error-severity
    findings fail (what fails ``check``'s exit code fails the CI's test report too), the
    others pass with their text as output."""
    errors = sum(1 for d in diagnostics if d.severity == "error")
    root = ElementTree.Element("testsuites", name="ezmigrate check",
                               tests=str(max(len(diagnostics), 1)), failures=str(errors))
    by_file: dict[str, list[Diagnostic]] = {}
    for d in diagnostics:
        by_file.setdefault(d.path, []).append(d)
    if not by_file:
        suite = ElementTree.SubElement(root, "testsuite", name="ezmigrate", tests="1",
                                       failures="0")
        ElementTree.SubElement(suite, "testcase", name="check", classname="ezmigrate")
    for path, found in by_file.items():
        suite = ElementTree.SubElement(
            root, "testsuite", name=path, tests=str(len(found)),
            failures=str(sum(1 for d in found if d.severity == "error")))
        for d in found:
            case = ElementTree.SubElement(suite, "testcase", classname=path,
                                          name=f"{d.code} {d.path}:{d.line}:{d.column}")
            text = f"{d.path}:{d.line}:{d.column}: {d.code} {d.text}\nfix: {d.fix}"
            if d.severity == "error":
                failure = ElementTree.SubElement(case, "failure", type=d.code, message=d.text)
                failure.text = text
            else:
                ElementTree.SubElement(case, "system-out").text = f"{d.severity}: {text}"
    ElementTree.indent(root)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ElementTree.tostring(
        root, encoding="unicode") + "\n"


def statistics(diagnostics: Sequence[Diagnostic]) -> str:
    """Count per code, most frequent first: ``  12  EZ209  unknown-vocabulary``."""
    counts = Counter(d.code for d in diagnostics)
    width = len(str(max(counts.values(), default=0)))
    return "".join(f"{n:>{width}}  {code}  {BY_CODE[code].name}\n"
                   for code, n in sorted(counts.items(), key=lambda kv: (-kv[1], kv[0])))


def statistics_json(diagnostics: Sequence[Diagnostic]) -> str:
    """``--statistics --output-format json``: the counts as a JSON list, most frequent
    first (``[{"code": "EZ209", "name": "unknown-vocabulary", "count": 12}]``)."""
    counts = Counter(d.code for d in diagnostics)
    return json.dumps([{"code": code, "name": BY_CODE[code].name, "count": n}
                       for code, n in sorted(counts.items(), key=lambda kv: (-kv[1], kv[0]))],
                      indent=2) + "\n"


STATISTICS: dict[str, Callable[[Sequence[Diagnostic]], str]] = {
    "text": statistics, "json": statistics_json,
}
"""The formats ``--statistics`` has; with another one it is a usage error."""

FORMATS: dict[str, Callable[[Sequence[Diagnostic]], str]] = {
    "text": text, "json": as_json, "sarif": sarif, "github": github, "junit": junit,
}
