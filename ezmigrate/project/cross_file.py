"""Descriptions whose base description lives in another file of the same package.

``class MoveArm(MoveBase)`` with ``from .base import MoveBase`` is a description when
``MoveBase`` is one in ``base.py`` (legacy-skiros2-api.md §2). Files are migrated one at a
time by the pure core, so after the first pass this module matches such imported bases to
the files that define them, asks those files for the bases' operations, and migrates the
deriving files again with them. Chains across several files resolve in a few rounds.
"""

from __future__ import annotations

import functools
import os
from collections.abc import Sequence
from dataclasses import replace
from pathlib import Path, PurePosixPath
from typing import TYPE_CHECKING

from ..codemod.settings import RUNTIME_ROOT, Settings

if TYPE_CHECKING:
    from ..codemod.core.ir import Operation
    from .runner import Migrated

MAX_ROUNDS = 4
RUNTIME_MARKER = RUNTIME_ROOT.encode()


@functools.cache
def dotted(relative: str) -> str:
    """``pkg/sub/base.py`` -> ``pkg.sub.base`` (``__init__.py`` names its package).
    Cached: cross-file matching asks it of the same few thousand paths again and again."""
    path = PurePosixPath(relative)
    parts = list(path.with_suffix("").parts)
    if parts and parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def module_name(path: str) -> str:
    """The last part of the name a file is imported by (``base`` for ``pkg/base.py``,
    ``pkg`` for ``pkg/__init__.py``): the word an import statement must spell to reach it."""
    return dotted(path).rpartition(".")[2]


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




def imported_from(migrated: Sequence[Migrated]) -> dict[str, frozenset[str]]:
    """Relative path of a description file -> names other files import from it (``*``).

    The runner took the words of every file's import statements when it read the file
    (``import_scan``); only a file whose imports mention the module name of a description
    file is read again and parsed (with ``ast``) to read the names: ``from .m import X``,
    ``from m import *``, and ``X`` in ``mod.X`` after ``import pkg.m as mod`` or
    ``from pkg import m as mod``. The module is then matched like a base's is.
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
        if not item.imports & stems:
            continue
        data = item.original
        for target, names in _imports_of(item.candidate.relative, data):
            for holder in by_stem.get(target.rsplit(".", 1)[-1], ()):
                if holder is not item and holder.candidate.root == item.candidate.root \
                        and _matches(holder.candidate.relative, target):
                    found.setdefault(holder.candidate.relative, set()).update(names)
    return {relative: frozenset(names) for relative, names in found.items()}


def _imports_of(importer: str, data: bytes) -> list[tuple[str, set[str]]]:
    """``(dotted module, names used from it)`` for the imports of file ``importer``.

    ``from a import b`` counts both ways, as names of ``a`` and as module ``a.b`` (whose
    attributes the file reads): only one of the two is a file of the package.
    """
    import ast

    from ..codemod.core.ast_names import ast_dotted_name

    try:
        tree = ast.parse(data)
    except (SyntaxError, ValueError, MemoryError, RecursionError):
        return []
    used: list[tuple[str, set[str]]] = []
    modules: dict[str, str] = {}  # local spelling -> dotted module it names
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            target = target_module(importer, "." * node.level + (node.module or ""))
            used.append((target, {alias.name for alias in node.names}))
            for alias in node.names:
                modules[alias.asname or alias.name] = \
                    f"{target}.{alias.name}" if target else alias.name
        elif isinstance(node, ast.Import):
            for alias in node.names:
                modules[alias.asname or alias.name] = alias.name
    if not modules:
        return used
    attributes: dict[str, set[str]] = {}
    for node in ast.walk(tree):
        if isinstance(node, ast.Attribute):
            spelled = ast_dotted_name(node.value)
            if spelled in modules:
                attributes.setdefault(modules[spelled], set()).add(node.attr)
    return used + list(attributes.items())


def _split(spelling: str) -> tuple[str, str]:
    """``"Navigate as Nav2"`` (see ``migrate.foreign_bases``) -> ``("Navigate", "Nav2")``."""
    name, _, local = spelling.partition(" as ")
    return name, local or name


def _on_disk(importer: Path, source: str) -> Path | None:
    """The file a ``from source import X`` in ``importer`` names, if it exists beside it.

    Relative imports are resolved from the importer's folder; absolute ones from each of
    its parent folders (the package may start anywhere above it).
    """
    level = len(source) - len(source.lstrip("."))
    parts = source[level:].split(".") if source[level:] else []
    if not parts:
        return None
    starts = [importer.parent.parents[level - 2] if level > 1 else importer.parent] \
        if level else list(importer.parents)[:6]
    for start in starts:
        for path in (start.joinpath(*parts).with_suffix(".py"),
                     start.joinpath(*parts, "__init__.py")):
            if path.is_file():
                return path
    return None


def _ezskiros_classes(item: Migrated) -> set[str]:
    """EzSkiROS description classes of a file; parsed only when a sibling derives from a
    class of it that is no legacy description there (rare: after a partial earlier run)."""
    if RUNTIME_MARKER not in item.original:
        return set()
    import libcst as cst

    from ..codemod.core.classes import ezskiros_classes

    try:
        return ezskiros_classes(cst.parse_module(item.original))
    except (cst.ParserSyntaxError, UnicodeDecodeError, LookupError, SyntaxError,
            RecursionError):
        return set()


def _last(module: str) -> str:
    """``pkg.sub.base`` -> ``base``."""
    return module.rpartition(".")[2]


def _others_at(items: Sequence[Migrated], importer: Migrated, target: str) -> list[Migrated]:
    """The files among ``items``, other than ``importer``, that module ``target`` names."""
    return [e for e in items if e is not importer and _matches(e.candidate.relative, target)]


def resolve_cross_file(migrated: Sequence[Migrated], settings: Settings,
                       exported: dict[str, frozenset[str]] | None = None,
                       settled: Sequence[Migrated] = ()) -> int:
    """Re-migrate files whose classes derive from descriptions of sibling files.

    Returns how many files were migrated again. Only files under the same root are
    matched, and only when exactly one file there defines the imported name. A base the
    sibling defines as an EzSkiROS description (an earlier run migrated it), a base that
    did not convert there, and a base whose file exists but was not given are passed on
    too, so that a deriving class with a ``createDescription`` is reported, not ignored.
    ``settled``: files among ``migrated`` whose readings are final (bases, not migrated
    again).
    """
    fixed = {id(item) for item in settled}
    redone = 0
    done: set[tuple[int, frozenset[str], frozenset[str], frozenset[tuple[str, str]]]] = set()
    ezskiros: dict[str, set[str]] = {}
    for _ in range(MAX_ROUNDS):
        changed = False
        exporters: dict[tuple[str, str], list[Migrated]] = {}
        described: dict[tuple[str, str], list[Migrated]] = {}
        # (root, a module's own name) -> its files: a module matches only files whose last
        # dotted part is its own (see ``_matches``), so a base looks at those alone
        by_module: dict[tuple[str, str], list[Migrated]] = {}
        for item in migrated:
            root = str(item.candidate.root)
            by_module.setdefault((root, _last(dotted(item.candidate.relative))), []).append(item)
            for name in item.result.exports:
                exporters.setdefault((root, name), []).append(item)
            for skill in item.result.skills:
                described.setdefault((root, skill.name), []).append(item)
        for item in migrated:
            if id(item) in fixed:
                continue
            root = str(item.candidate.root)
            external: dict[str, list[Operation]] = {}
            migrated_bases: set[str] = set()
            unresolved: dict[str, str] = {}
            sources: list[str] = []
            for spelling, source in item.result.foreign_bases:
                name, local = _split(spelling)
                target = target_module(item.candidate.relative, source)
                found = _others_at(exporters.get((root, name), []), item, target)
                if len(found) == 1:
                    from ..codemod.migrate import exported_operations  # libcst: only now

                    operations = exported_operations(found[0].original, [name], settings)
                    if name in operations:
                        external[local] = operations[name]
                        sources.append(found[0].candidate.relative)
                    continue
                if found:
                    continue  # several files define it: nothing is certain
                if _others_at(described.get((root, name), []), item, target):
                    unresolved[local] = f"its base class {name} was not converted (in " \
                        f"{source})"
                    continue
                files = _others_at(by_module.get((root, _last(target)), []), item, target)
                if files:
                    for file in files:
                        if file.candidate.relative not in ezskiros:
                            ezskiros[file.candidate.relative] = _ezskiros_classes(file)
                    if any(name in ezskiros[f.candidate.relative] for f in files):
                        migrated_bases.add(local)
                    continue
                if _on_disk(item.candidate.path, source) is not None:
                    unresolved[local] = (f"its base {name} is imported from {source}, which "
                                         "was not given: pass the package folder")
            key = (id(item), frozenset(external), frozenset(migrated_bases),
                   frozenset(unresolved.items()))
            if not (external or migrated_bases or unresolved) or key in done:
                continue
            done.add(key)
            from ..codemod.migrate import migrate  # libcst: only when a file is read again

            item.settings = replace(settings, external=external, exported=(exported or {}).get(
                item.candidate.relative, frozenset()), migrated_bases=frozenset(migrated_bases),
                unresolved_bases=unresolved)
            item.result = replace(migrate(item.original, item.settings,
                                          item.candidate.relative),
                                  depends_on=sorted(set(sources)))
            redone += 1
            changed = True
        if not changed:
            break
    return redone
