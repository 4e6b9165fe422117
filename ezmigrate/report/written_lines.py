"""Report lines as the written file has them, with the legacy line beside them.

Why: after ``rewrite`` a reviewer opens the written file, and ``check`` on it gives the new
line numbers; a report that gives only the legacy ones points at the wrong lines (imports
and signatures change line counts). A line is mapped only when the mapping is certain:

- a line outside the migrated code is where ``difflib`` finds it unchanged;
- a class is where the new file defines a class of that name;
- an ``addParam`` line inside a replaced block is the signature line of its key
  (``Key: ...``), when exactly one such line is there;
- the n-th condition call of a replaced block is the n-th ``+=`` of a condition list in it,
  when both count the same.

Anything else keeps its legacy line alone (``legacy_line`` is then ``None``).
"""

from __future__ import annotations

import ast
import difflib
import re
from dataclasses import replace

from ezskiros_runtime.diagnostics import Finding

from .diffs import decode, diff_body
from .results import ClassLines, FileResult, WrittenLines, source_digest

_KEY = re.compile(r"""\.addParam\(\s*(?:key\s*=\s*)?(["'])(\w+)\1""")
_CONDITION_CALL = re.compile(r"\.add(?:Pre|Post|Hold)?Condition\(")
_CONDITION_ADD = re.compile(r"\b\w+\.(?:pre|post|hold)_conditions\s*\+=")


def line_map(before: str, after: str) -> dict[int, int]:
    """Legacy line -> written line (1-based), for the lines the mapping is certain of."""
    old = before.splitlines()
    new = after.splitlines()
    mapped: dict[int, int] = {}
    matcher = difflib.SequenceMatcher(None, old, new, autojunk=False)
    for tag, i1, i2, j1, j2 in matcher.get_opcodes():
        if tag == "equal":
            mapped.update({i1 + k + 1: j1 + k + 1 for k in range(i2 - i1)})
        elif tag == "replace":
            mapped.update(_replaced(old, new, range(i1, i2), range(j1, j2)))
    return mapped


def _replaced(old: list[str], new: list[str], olds: range, news: range) -> dict[int, int]:
    """Mapped lines of one replaced block: parameters by key, conditions by order."""
    found: dict[int, int] = {}
    for i in olds:
        match = _KEY.search(old[i])
        if match:
            key = match.group(2)
            hits = [j for j in news if new[j].lstrip().startswith(f"{key}:")]
            if len(hits) == 1:
                found[i + 1] = hits[0] + 1
    calls = [i for i in olds if _CONDITION_CALL.search(old[i])]
    adds = [j for j in news if _CONDITION_ADD.search(new[j])]
    if calls and len(calls) == len(adds):
        found.update({i + 1: j + 1 for i, j in zip(calls, adds, strict=True)})
    return found


def _class_lines(after: str) -> dict[str, int]:
    """Top-level class name -> line of its ``class`` statement in the written file."""
    try:
        return classes_of(ast.parse(after))
    except (SyntaxError, ValueError):
        return {}


def classes_of(tree: ast.Module) -> dict[str, int]:
    """Top-level class name -> line of its ``class`` statement (the last of a name wins):
    of the written file here, or of the parse that checked it (``ClassLines``)."""
    return {node.name: node.lineno for node in tree.body if isinstance(node, ast.ClassDef)}


def with_written_lines(result: FileResult, original: bytes, diff: bool = False
                       ) -> FileResult:
    """``result`` carrying its ``WrittenLines`` (and, with ``diff``, its diff's hunks):
    worked out in the worker that migrated the file, so that the main process
    (``as_written``, ``--dry-run``'s diffs) does not diff and parse every file again one
    after the other."""
    if not result.changed or not isinstance(result.new_source, bytes):
        return result
    written = _written(original, result.new_source, result.new_classes)
    if diff:
        written = replace(written, diff=diff_body(original, result.new_source))
    return replace(result, written=written)


def written_diff(result: FileResult) -> str | None:
    """The hunks made for ``result``'s new source where it was migrated, if any."""
    written = result.written
    if written is None or written.diff is None or not isinstance(result.new_source, bytes) \
            or written.digest != source_digest(result.new_source):
        return None
    return written.diff


def _written(original: bytes, new_source: bytes, known: ClassLines | None) -> WrittenLines:
    """The map of ``new_source``'s lines; its classes are those the migration's check
    parsed (``known``) when they are of this very source."""
    after = decode(new_source)
    digest = source_digest(new_source)
    classes = known.classes if known is not None and known.digest == digest \
        else _class_lines(after)
    return WrittenLines(digest, line_map(decode(original), after), classes)


def as_written(result: FileResult, original: bytes) -> FileResult:
    """``result`` with its skills' and findings' lines those of the file it writes (or, with
    ``--dry-run``, would write), each with ``legacy_line``; unchanged when nothing changes."""
    if not result.changed or not isinstance(result.new_source, bytes):
        return result
    written = result.written
    if written is None or written.digest != source_digest(result.new_source):
        written = _written(original, result.new_source, result.new_classes)
    mapped, classes = written.lines, written.classes
    skills = []
    for skill in result.skills:
        at = classes.get(skill.name, mapped.get(skill.line))
        skills.append(replace(
            skill, line=at if at is not None else skill.line,
            legacy_line=skill.line if at is not None else None,
            findings=[_finding(f, mapped) for f in skill.findings]))
    return replace(result, skills=skills)


def _finding(finding: Finding, mapped: dict[int, int]) -> Finding:
    at = mapped.get(finding.line) if finding.line else None
    if at is None:
        return finding
    return replace(finding, line=at, legacy_line=finding.line)


__all__ = ["as_written", "line_map", "with_written_lines", "written_diff"]
