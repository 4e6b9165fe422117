"""``check --fix`` and ``check --diff``: the findings whose fix is safe and explicit, applied.

Why a fix must be explicit: ``check`` runs in CI and pre-commit, where a change nobody asked
for is a surprise; ruff's convention is that ``--fix`` changes only what a rule's fix says,
and ``--diff`` shows exactly that without writing. A fix is an edit of a few characters at a
position the syntax tree gives, made on the file's own text (its encoding, line endings and
everything else untouched), and it is written atomically (``writing.atomic_write``) only when
the file has not changed since ``check`` read it, so a file is never half-fixed.

Fixes so far:

- EZ101 (``description-in-options``): a string literal passed 4th to ``addParam`` lands in
  the options slot, where SkiROS2 drops it. The fix passes it as ``description=...``, which is
  what its author meant. Only when the call passes no description already and has no
  ``*args``/``**kwargs`` (otherwise where the text belongs is not explicit).
"""

from __future__ import annotations

import ast
import io
import re
import tokenize
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path

from ..files.paths import from_repository, shown
from ..files.writing import WriteRefused, atomic_write, digest
from ..lint.diagnostic import Diagnostic
from ..report.diffs import unified_diff

FIXABLE = frozenset({"EZ101"})
"""Codes ``--fix`` knows how to fix."""

_LINES = re.compile(r"[^\r\n]*(?:\r\n|\r|\n)|[^\r\n]+\Z")
"""Lines as Python counts them (a form feed or ``\\x1c`` does not end one)."""


@dataclass(frozen=True)
class Edit:
    """Replace ``length`` characters at (1-based ``line``, character ``column``) by ``text``."""

    line: int
    column: int
    length: int
    text: str


@dataclass
class FileFix:
    """The fixes of one file: its bytes before and after, and the findings they resolve."""

    path: str
    before: bytes
    after: bytes
    fixed: list[Diagnostic] = field(default_factory=list)


def plan_fixes(found: Sequence[Diagnostic]) -> list[FileFix]:
    """The fix of every file with a fixable finding in ``found`` (already selected and not
    suppressed); a finding whose fix is not explicit in the code is left for the user."""
    by_path: dict[str, list[Diagnostic]] = {}
    for d in found:
        if d.code in FIXABLE:
            by_path.setdefault(d.path, []).append(d)
    fixes = []
    for path, diagnostics in sorted(by_path.items()):
        try:
            data = Path(path).read_bytes()
        except OSError:
            continue
        fix = _fix_file(path, data, diagnostics)
        if fix is not None:
            fixes.append(fix)
    return fixes


def fixed_text(text: str, found: Sequence[Diagnostic]) -> str | None:
    """``text`` (an editor's buffer) with the fixable findings of ``found`` fixed; None
    when none is."""
    fix = _fix_file("", text.encode("utf-8"), [d for d in found if d.code in FIXABLE])
    return None if fix is None else fix.after.decode("utf-8")


def _fix_file(path: str, data: bytes, diagnostics: list[Diagnostic]) -> FileFix | None:
    try:
        encoding, _ = tokenize.detect_encoding(io.BytesIO(data).readline)
        text = data.decode(encoding)
        tree = ast.parse(data)
    except (SyntaxError, ValueError, UnicodeError, LookupError, MemoryError, RecursionError):
        return None
    lines = _LINES.findall(text)
    calls = [node for node in ast.walk(tree)
             if isinstance(node, ast.Call) and _is_add_param(node)]
    edits: dict[tuple[int, int], Edit] = {}
    fixed = []
    for d in diagnostics:
        for call in calls:
            if call.lineno <= d.line <= (call.end_lineno or call.lineno):
                edit = _description_edit(call, lines)
                if edit is not None:
                    edits[(edit.line, edit.column)] = edit
                    fixed.append(d)
                break
    if not edits:
        return None
    new = _applied(lines, edits.values())
    return FileFix(path, data, new.encode(encoding), fixed)


def _is_add_param(node: ast.Call) -> bool:
    return isinstance(node.func, ast.Attribute) and node.func.attr == "addParam"


def _description_edit(call: ast.Call, lines: list[str]) -> Edit | None:
    """``"text"`` in the options slot -> ``description="text"``, when that is explicit."""
    if any(isinstance(a, ast.Starred) for a in call.args) or len(call.args) > 4 \
            or any(k.arg in (None, "description") for k in call.keywords):
        return None
    if len(call.args) == 4:
        arg = call.args[3]
        if not _is_string(arg):
            return None
        return Edit(arg.lineno, _column(lines, arg.lineno, arg.col_offset), 0, "description=")
    options = next((k for k in call.keywords if k.arg == "options"), None)
    if options is None or not _is_string(options.value):
        return None
    return Edit(options.lineno, _column(lines, options.lineno, options.col_offset),
                len("options"), "description")


def _is_string(node: ast.expr) -> bool:
    return isinstance(node, ast.Constant) and isinstance(node.value, str)


def _column(lines: list[str], line: int, offset: int) -> int:
    """The character column of ``ast``'s UTF-8 byte ``offset`` on a 1-based line."""
    return len(lines[line - 1].encode("utf-8")[:offset].decode("utf-8", "replace"))


def _applied(lines: list[str], edits: Iterable[Edit]) -> str:
    """``lines`` with ``edits`` made, right to left on a line so columns stay valid."""
    out = list(lines)
    for edit in sorted(edits, key=lambda e: (e.line, e.column), reverse=True):
        text = out[edit.line - 1]
        out[edit.line - 1] = text[:edit.column] + edit.text + text[edit.column + edit.length:]
    return "".join(out)


@dataclass
class FixOutcome:
    """What ``--fix`` or ``--diff`` did: the findings still standing, how many were (or
    would be) fixed in how many files, each file's diff (``--diff``) and why a file was
    left whole (``--fix``). The command line prints it; nothing here prints."""

    remaining: list[Diagnostic]
    fixed: int = 0
    files: int = 0
    diffs: list[str] = field(default_factory=list)
    refused: list[str] = field(default_factory=list)


def apply_fixes(found: Sequence[Diagnostic], roots: Sequence[Path], *,
                write: bool) -> FixOutcome:
    """``--fix`` (``write``) or ``--diff``: make or show the fixes of ``found``.

    ``--diff`` gives each file's diff (headers relative to the repository root, so ``git
    apply`` takes it) and writes nothing. ``--fix`` writes each file atomically, or leaves it
    whole and says why.
    """
    resolved: set[int] = set()
    outcome = FixOutcome([])
    for fix in plan_fixes(found):
        if write:
            try:
                atomic_write(Path(fix.path), fix.after, digest(fix.before), roots=list(roots))
            except (WriteRefused, OSError) as error:
                outcome.refused.append(f"{shown(fix.path)}: not fixed ({error})")
                continue
        else:
            outcome.diffs.append(unified_diff(from_repository(fix.path), fix.before,
                                              fix.after))
        resolved.update(id(d) for d in fix.fixed)
        outcome.fixed += len(fix.fixed)
        outcome.files += 1
    outcome.remaining = [d for d in found if id(d) not in resolved]
    return outcome
