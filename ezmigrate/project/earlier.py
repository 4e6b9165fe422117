"""Descriptions an earlier run already migrated, for the report of this one.

Why: after an interrupted run, the rerun found only the legacy descriptions left, and its
report left out every file the first run had written, as if they were not part of the
tree. A report must describe the whole tree's state, so each EzSkiROS description (a class
deriving from ``ezskiros_runtime``'s ``SkillDescription``, directly or through another class
of the file, without a ``createDescription``) is listed as ``unchanged``, with why. Read
with ``ast``, and only for files that name the runtime at all (``whole_tree``). The summary
line on stderr counts the same: one run, one count ("24 skills, 24 unchanged" on a second
run, not "0 skills found" beside a report that lists 24).
"""

from __future__ import annotations

import ast
from collections.abc import Sequence
from dataclasses import replace
from typing import TYPE_CHECKING

from ..codemod.settings import RUNTIME_ROOT
from ..report.results import FileResult, SkillResult

if TYPE_CHECKING:
    from .runner import Migrated

REASON = "already an EzSkiROS description (migrated by an earlier run)"


def with_earlier(result: FileResult, tree: ast.Module | None,
                 source: bytes | str) -> FileResult:
    """``result`` with the file's EzSkiROS descriptions added as ``unchanged`` skills."""
    present = RUNTIME_ROOT.encode() in source if isinstance(source, bytes) \
        else RUNTIME_ROOT in source
    if tree is None or not present or result.error:
        return result
    known = {s.name for s in result.skills}
    found = [SkillResult(name, line, "unchanged", reason=REASON)
             for name, line in _ezskiros_classes(tree) if name not in known]
    if not found:
        return result
    return replace(result, skills=sorted([*result.skills, *found], key=lambda s: s.line))


def _ezskiros_classes(tree: ast.Module) -> list[tuple[str, int]]:
    """``(name, line)`` of the module's top-level EzSkiROS descriptions, in order."""
    roots = _runtime_names(tree)
    ezskiros: set[str] = set()
    found = []
    for node in tree.body:
        if not isinstance(node, ast.ClassDef):
            continue
        if not any(_spelled(base) in roots | ezskiros for base in node.bases):
            continue
        if any(isinstance(m, (ast.FunctionDef, ast.AsyncFunctionDef))
               and m.name == "createDescription" for m in node.body):
            continue  # legacy code on a migrated base: the migration reads it
        ezskiros.add(node.name)
        found.append((node.name, node.lineno))
    return found


def _runtime_names(tree: ast.Module) -> set[str]:
    """Local spellings of the runtime's ``SkillDescription`` (``EzSkillDescription``,
    ``ez.SkillDescription``...)."""
    names = set()
    for node in tree.body:
        if isinstance(node, ast.ImportFrom) and not node.level and node.module \
                and node.module.split(".")[0] == RUNTIME_ROOT:
            names |= {a.asname or a.name for a in node.names if a.name == "SkillDescription"}
        elif isinstance(node, ast.Import):
            names |= {f"{a.asname or a.name}.SkillDescription" for a in node.names
                      if a.name == RUNTIME_ROOT}
    return names


def _spelled(node: ast.expr) -> str:
    """``A`` or ``a.B`` as written ("" for anything else)."""
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        inner = _spelled(node.value)
        return f"{inner}.{node.attr}" if inner else ""
    return ""


def whole_tree(migrated: Sequence[Migrated]) -> list[FileResult]:
    """Each file's result with its earlier-migrated descriptions added; a file that does
    not name the runtime is not parsed."""
    out = []
    for item in migrated:
        tree = None
        if RUNTIME_ROOT.encode() in item.original:
            try:
                tree = ast.parse(item.original)
            except (SyntaxError, ValueError, MemoryError, RecursionError):
                tree = None
        out.append(with_earlier(item.result, tree, item.original))
    return out
