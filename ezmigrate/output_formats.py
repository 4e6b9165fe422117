"""The machine formats of ``check``: text, JSON, SARIF 2.1.0, GitHub annotations, JUnit.

Each takes the final list of diagnostics and returns the whole text for stdout, so a CI
step can redirect it to a file (``--output-format sarif > check.sarif``).
"""

from __future__ import annotations

import json
from collections import Counter
from collections.abc import Callable, Sequence
from pathlib import Path
from xml.etree import ElementTree

from ezskiros_runtime.codes import BY_CODE

from . import __version__
from .lint.diagnostic import Diagnostic

SARIF_SCHEMA = "https://json.schemastore.org/sarif-2.1.0.json"
_SARIF_LEVEL = {"error": "error", "warning": "warning", "info": "note"}
_GITHUB_LEVEL = {"error": "error", "warning": "warning", "info": "notice"}


def text(diagnostics: Sequence[Diagnostic]) -> str:
    """``path:line:col: CODE message``, one per line (what editors and terminals parse)."""
    return "".join(f"{d}\n" for d in diagnostics)


def as_json(diagnostics: Sequence[Diagnostic]) -> str:
    """A JSON list of objects with position, code, severity, message and fix hint."""
    return json.dumps([{
        "path": d.path, "line": d.line, "column": d.column, "end_line": d.end_line,
        "end_column": d.end_column, "code": d.code, "severity": d.severity,
        "message": d.text, "fix": d.fix} for d in diagnostics], indent=2) + "\n"


def _uri(path: str) -> str:
    """A relative path with ``/`` (GitHub resolves it against the checkout), else a URI."""
    candidate = Path(path)
    if candidate.is_absolute():
        try:
            candidate = candidate.relative_to(Path.cwd())
        except ValueError:
            return candidate.as_uri()
    return candidate.as_posix()


def sarif(diagnostics: Sequence[Diagnostic]) -> str:
    """SARIF 2.1.0: one rule per code that occurs, one result per diagnostic."""
    codes = sorted({d.code for d in diagnostics})
    rules = [{
        "id": code, "name": BY_CODE[code].name,
        "shortDescription": {"text": BY_CODE[code].rationale},
        "help": {"text": BY_CODE[code].fix},
        "helpUri": "https://github.com/ezskiros/ezmigrate/blob/main/docs/rules.md",
        "defaultConfiguration": {"level": _SARIF_LEVEL[BY_CODE[code].severity]},
    } for code in codes]
    results = [{
        "ruleId": d.code, "ruleIndex": codes.index(d.code), "level": _SARIF_LEVEL[d.severity],
        "message": {"text": f"{d.text} (fix: {d.fix})"},
        "locations": [{"physicalLocation": {
            "artifactLocation": {"uri": _uri(d.path)},
            "region": {"startLine": d.line, "startColumn": d.column,
                       "endLine": d.end_line or d.line,
                       "endColumn": max(d.end_column, d.column)}}}],
    } for d in diagnostics]
    log = {"version": "2.1.0", "$schema": SARIF_SCHEMA, "runs": [{
        "tool": {"driver": {"name": "ezmigrate", "version": __version__,
                            "informationUri": "https://github.com/ezskiros/ezmigrate",
                            "rules": rules}},
        "results": results}]}
    return json.dumps(log, indent=2) + "\n"


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
    """JUnit XML: a test suite per file, a failing test case per diagnostic."""
    root = ElementTree.Element("testsuites", name="ezmigrate check",
                               tests=str(max(len(diagnostics), 1)),
                               failures=str(len(diagnostics)))
    by_file: dict[str, list[Diagnostic]] = {}
    for d in diagnostics:
        by_file.setdefault(d.path, []).append(d)
    if not by_file:
        suite = ElementTree.SubElement(root, "testsuite", name="ezmigrate", tests="1",
                                       failures="0")
        ElementTree.SubElement(suite, "testcase", name="check", classname="ezmigrate")
    for path, found in by_file.items():
        suite = ElementTree.SubElement(root, "testsuite", name=path, tests=str(len(found)),
                                       failures=str(len(found)))
        for d in found:
            case = ElementTree.SubElement(suite, "testcase", classname=path,
                                          name=f"{d.code} {d.path}:{d.line}:{d.column}")
            failure = ElementTree.SubElement(case, "failure", type=d.code, message=d.text)
            failure.text = f"{d.path}:{d.line}:{d.column}: {d.code} {d.text}\nfix: {d.fix}"
    ElementTree.indent(root)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ElementTree.tostring(
        root, encoding="unicode") + "\n"


def statistics(diagnostics: Sequence[Diagnostic]) -> str:
    """Count per code, most frequent first: ``  12  EZ209  unknown-vocabulary``."""
    counts = Counter(d.code for d in diagnostics)
    width = len(str(max(counts.values(), default=0)))
    return "".join(f"{n:>{width}}  {code}  {BY_CODE[code].name}\n"
                   for code, n in sorted(counts.items(), key=lambda kv: (-kv[1], kv[0])))


FORMATS: dict[str, Callable[[Sequence[Diagnostic]], str]] = {
    "text": text, "json": as_json, "sarif": sarif, "github": github, "junit": junit,
}
