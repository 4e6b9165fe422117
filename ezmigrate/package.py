"""Descriptions whose base description lives in another file of the same package.

``class MoveArm(MoveBase)`` with ``from .base import MoveBase`` is a description when
``MoveBase`` is one in ``base.py`` (legacy-skiros2-api.md §2). Files are migrated one at a
time by the pure core, so after the first pass this module matches such imported bases to
the files that define them, asks those files for the bases' operations, and migrates the
deriving files again with them. Chains across several files resolve in a few rounds.
"""

from __future__ import annotations

import os
import re
from collections.abc import Sequence
from pathlib import PurePosixPath
from typing import TYPE_CHECKING

from .core.ir import Operation
from .discover import Candidate
from .migrate import Settings, exported_operations, migrate
from .runner import Migrated, migrate_all

if TYPE_CHECKING:
    from ezskiros_runtime.ontology.index import OntologyIndex

MAX_ROUNDS = 4


def dotted(relative: str) -> str:
    """``pkg/sub/base.py`` -> ``pkg.sub.base`` (``__init__.py`` names its package)."""
    path = PurePosixPath(relative)
    parts = list(path.with_suffix("").parts)
    if parts and parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def target_module(importer: str, source: str) -> str:
    """The dotted module a ``from source import X`` in file ``importer`` refers to."""
    level = len(source) - len(source.lstrip("."))
    if level == 0:
        return source
    package = dotted(importer).split(".")[:-1]
    if PurePosixPath(importer).name == "__init__.py":
        package = dotted(importer).split(".")
    base = package[: len(package) - (level - 1)] if level > 1 else package
    rest = source[level:]
    return ".".join([*base, rest] if rest else base)


def _matches(exporter: str, target: str) -> bool:
    """Absolute imports may name the package from above the scanned root: suffix match."""
    name = dotted(exporter)
    return name == target or name.endswith("." + target) or target.endswith("." + name)


_FROM = re.compile(rb"^[ \t]*from[ \t]+(\.*[\w.]*)[ \t]+import\b", re.MULTILINE)


def imported_from(migrated: Sequence[Migrated]) -> dict[str, frozenset[str]]:
    """Relative path of a description file -> names other files import from it (``*``).

    Every file is read once; a regular expression finds its ``from X import`` lines, and
    only a file whose ``X`` ends in the module name of a description file is parsed (with
    ``ast``) to read the names; the module is then matched like a base's is.
    """
    by_stem: dict[str, list[Migrated]] = {}
    for item in migrated:
        if item.result.skills or item.result.exports:
            by_stem.setdefault(dotted(item.candidate.relative).rsplit(".", 1)[-1], []).append(
                item)
    if not by_stem:
        return {}
    stems = {os.fsencode(stem) for stem in by_stem}
    found: dict[str, set[str]] = {}
    for item in migrated:
        data = item.original
        named = {m.rsplit(b".", 1)[-1] for m in _FROM.findall(data)}
        if not named & stems:
            continue
        for source, names in _from_imports(data):
            target = target_module(item.candidate.relative, source)
            for holder in by_stem.get(target.rsplit(".", 1)[-1], ()):
                if holder is not item and holder.candidate.root == item.candidate.root \
                        and _matches(holder.candidate.relative, target):
                    found.setdefault(holder.candidate.relative, set()).update(names)
    return {relative: frozenset(names) for relative, names in found.items()}


def _from_imports(data: bytes) -> list[tuple[str, list[str]]]:
    """``(module with its leading dots, imported names)`` of every ``from`` import."""
    import ast

    try:
        tree = ast.parse(data)
    except (SyntaxError, ValueError, MemoryError, RecursionError):
        return []
    return [("." * node.level + (node.module or ""), [a.name for a in node.names])
            for node in ast.walk(tree) if isinstance(node, ast.ImportFrom)]


def resolve_cross_file(migrated: Sequence[Migrated], settings: Settings,
                       exported: dict[str, frozenset[str]] | None = None) -> int:
    """Re-migrate files whose classes derive from descriptions of sibling files.

    Returns how many files were migrated again. Only files under the same root are
    matched, and only when exactly one file there defines the imported name.
    """
    redone = 0
    done: set[tuple[int, frozenset[str]]] = set()
    for _ in range(MAX_ROUNDS):
        changed = False
        exporters: dict[tuple[str, str], list[Migrated]] = {}
        for item in migrated:
            for name in item.result.exports:
                exporters.setdefault((str(item.candidate.root), name), []).append(item)
        for item in migrated:
            external: dict[str, list[Operation]] = {}
            sources: list[str] = []
            for base, source in item.result.foreign_bases:
                target = target_module(item.candidate.relative, source)
                found = [e for e in exporters.get((str(item.candidate.root), base), [])
                         if e is not item and _matches(e.candidate.relative, target)]
                if len(found) != 1:
                    continue
                operations = exported_operations(found[0].original, [base], settings)
                if base in operations:
                    external[base] = operations[base]
                    sources.append(found[0].candidate.relative)
            key = (id(item), frozenset(external))
            if not external or key in done:
                continue
            done.add(key)
            item.settings = Settings(settings.index, external, exported=(exported or {}).get(
                item.candidate.relative, frozenset()))
            result = migrate(item.original, item.settings, item.candidate.relative)
            result.depends_on = sorted(set(sources))
            item.result = result
            redone += 1
            changed = True
        if not changed:
            break
    return redone


def migrate_package(candidates: Sequence[Candidate], index: OntologyIndex | None,
                    jobs: int) -> list[Migrated]:
    """Migrate every candidate in parallel, then resolve bases defined in sibling files and
    keep the legacy imports that sibling files import from a migrated one."""
    migrated = migrate_all(candidates, index, jobs)
    exported = imported_from(migrated)
    for item in migrated:
        names = exported.get(item.candidate.relative)
        if names and item.result.changed:
            item.settings = Settings(index, exported=names)
            item.result = migrate(item.original, item.settings, item.candidate.relative)
    if any(m.result.foreign_bases for m in migrated):
        resolve_cross_file(migrated, Settings(index=index), exported)
    return migrated
