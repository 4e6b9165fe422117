"""The house by role: every module in a room, imports running one way, no import circles.

Read from the source with ``ast``: every import counts, at module level, inside a function
or under ``TYPE_CHECKING``, so neither a lazy import nor a type-only one can hide a circle
or a shortcut taken in a hurry. The rooms' own ``__init__`` docstrings say what each may
import; the table below is checked against them, so the two cannot drift apart.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterator
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("ezmigrate", "ezskiros_runtime")

MAY_IMPORT: dict[str, frozenset[str]] = {
    "files": frozenset(),
    "report": frozenset(),
    "codemod": frozenset({"report"}),
    "verify": frozenset({"files", "report"}),
    "lint": frozenset({"files", "report", "codemod", "verify"}),
    "compound": frozenset({"files", "report", "codemod", "verify", "lint"}),
    "project": frozenset({"files", "report", "codemod", "verify", "lint", "compound"}),
    "cache": frozenset({"files", "report", "verify", "lint", "project"}),
    "checking": frozenset({"files", "report", "codemod", "verify", "lint", "compound",
                           "project", "cache"}),
    "server": frozenset({"files", "report", "codemod", "verify", "lint", "compound",
                         "project", "cache", "checking"}),
    "cli": frozenset({"files", "report", "codemod", "verify", "lint", "compound", "project",
                      "cache", "checking", "server"}),
}
"""Which rooms of ``ezmigrate`` a room may import (besides itself, the runtime and the
package's ``__version__``): commands → server → checking → cache → project → compound → lint →
codemod and verify → report and files."""

TOP_LEVEL = {"ezmigrate", "ezmigrate.__main__"}
"""The only modules outside a room: the version, and the entry point that gates Python."""

TEST_SUITES = {"runtime", "safety", "perf", "strategies"}
"""Test folders that are not an ``ezmigrate`` room: the runtime's tests, and the suites
that drive the whole command (signals and hostile input, speed behaviour, generators)."""


def _modules() -> dict[str, Path]:
    found = {}
    for package in PACKAGES:
        for path in sorted((ROOT / package).rglob("*.py")):
            if "__pycache__" in path.parts:
                continue
            parts = path.relative_to(ROOT).with_suffix("").parts
            found[".".join(parts[:-1] if parts[-1] == "__init__" else parts)] = path
    return found


MODULES = _modules()


def _targets(module: str, path: Path) -> Iterator[tuple[int, str]]:
    """Every module of ours that ``module`` imports, with the line of the import."""
    package = module.split(".") if path.name == "__init__.py" else module.split(".")[:-1]
    for node in ast.walk(ast.parse(path.read_bytes())):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = package[: len(package) - node.level + 1]
                target = ".".join([*base, node.module] if node.module else base)
            else:
                target = node.module or ""
            for alias in node.names:
                submodule = f"{target}.{alias.name}"
                if submodule in MODULES:
                    yield node.lineno, submodule
                elif target in MODULES:
                    yield node.lineno, target
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name in MODULES:
                    yield node.lineno, alias.name


IMPORTS = {module: sorted(set(_targets(module, path))) for module, path in MODULES.items()}


def _room(module: str) -> str | None:
    parts = module.split(".")
    if parts[0] != "ezmigrate" or module in TOP_LEVEL:
        return None
    return parts[1]


def _relative(module: str) -> str:
    return str(MODULES[module].relative_to(ROOT))


def test_every_module_is_in_a_room() -> None:
    loose = [m for m in MODULES if m.startswith("ezmigrate") and m not in TOP_LEVEL
             and _room(m) not in MAY_IMPORT]
    assert not loose, f"modules outside the rooms {sorted(MAY_IMPORT)}: {loose}"


@pytest.mark.parametrize("room", sorted(MAY_IMPORT))
def test_room_docstring_says_what_it_holds_and_may_import(room: str) -> None:
    init = ROOT / "ezmigrate" / room / "__init__.py"
    doc = ast.get_docstring(ast.parse(init.read_bytes())) or ""
    holds = {p.stem for p in init.parent.iterdir()
             if (p.suffix == ".py" and p.stem != "__init__") or (p / "__init__.py").exists()}
    unnamed = sorted(name for name in holds if f"`{name}`" not in doc)
    assert not unnamed, f"{_relative(f'ezmigrate.{room}')}: the docstring never names {unnamed}"
    said = re.search(r"May\s+import\s+([^.]*)\.", doc)
    assert said, f"{_relative(f'ezmigrate.{room}')}: no 'May import ...' sentence"
    named = set(re.findall(r"`(\w+)`", said.group(1))) & set(MAY_IMPORT)
    assert named == MAY_IMPORT[room], (
        f"ezmigrate/{room}/__init__.py says it may import {sorted(named)}; "
        f"tests/test_layout.py allows {sorted(MAY_IMPORT[room])}")


@pytest.mark.parametrize("module", sorted(m for m in MODULES if m.startswith("ezmigrate")))
def test_imports_run_one_way(module: str) -> None:
    room = _room(module)
    for line, target in IMPORTS[module]:
        if not target.startswith("ezmigrate") or target == "ezmigrate":
            continue
        if module == "ezmigrate.__main__":
            assert _room(target) == "cli", f"{_relative(module)}:{line}: imports {target}"
            continue
        assert room is not None, f"{_relative(module)}:{line}: imports {target}"
        other = _room(target)
        assert other == room or other in MAY_IMPORT[room], (
            f"{_relative(module)}:{line}: the {room} room imports {target} ({other}), "
            f"which it may not (it may import {sorted(MAY_IMPORT[room])})")


def test_the_runtime_never_imports_ezmigrate() -> None:
    wrong = []
    for module, path in MODULES.items():
        if module.startswith("ezskiros_runtime"):
            for node in ast.walk(ast.parse(path.read_bytes())):
                names = ([node.module or ""] if isinstance(node, ast.ImportFrom) and not node.level
                         else [a.name for a in node.names] if isinstance(node, ast.Import)
                         else [])
                wrong += [f"{_relative(module)}:{node.lineno}: imports {name}"
                          for name in names if name.split(".")[0] == "ezmigrate"]
    assert not wrong, "\n".join(wrong)


def _circles() -> list[list[str]]:
    """Strongly connected components of more than one module (Tarjan, iteratively)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []
    for start in MODULES:
        if start in index:
            continue
        work = [(start, iter(target for _, target in IMPORTS[start]))]
        index[start] = low[start] = len(index)
        stack.append(start)
        on_stack.add(start)
        while work:
            node, edges = work[-1]
            for target in edges:
                if target not in index:
                    index[target] = low[target] = len(index)
                    stack.append(target)
                    on_stack.add(target)
                    work.append((target, iter(t for _, t in IMPORTS[target])))
                    break
                if target in on_stack:
                    low[node] = min(low[node], index[target])
            else:
                work.pop()
                if work:
                    low[work[-1][0]] = min(low[work[-1][0]], low[node])
                if low[node] == index[node]:
                    component = []
                    while True:
                        member = stack.pop()
                        on_stack.discard(member)
                        component.append(member)
                        if member == node:
                            break
                    if len(component) > 1:
                        found.append(sorted(component))
    return found


def test_no_import_circles() -> None:
    circles = _circles()
    assert not circles, "modules that import one another (directly or around a circle): " + (
        "; ".join(" ↔ ".join(c) for c in circles))


def test_the_circle_finder_finds_circles() -> None:
    saved = dict(IMPORTS)
    try:
        IMPORTS["ezmigrate.files.paths"] = [(1, "ezmigrate.files.discover")]
        assert ["ezmigrate.files.discover", "ezmigrate.files.paths"] in _circles()
    finally:
        IMPORTS.clear()
        IMPORTS.update(saved)


def test_tests_mirror_the_rooms() -> None:
    folders = {p.name for p in (ROOT / "tests").iterdir()
               if p.is_dir() and p.name != "__pycache__"}
    assert folders - set(MAY_IMPORT) <= TEST_SUITES, sorted(folders - set(MAY_IMPORT)
                                                             - TEST_SUITES)
    runtime = {p.name for p in (ROOT / "tests" / "runtime").iterdir() if p.is_dir()}
    packages = {p.name for p in (ROOT / "ezskiros_runtime").iterdir()
                if (p / "__init__.py").exists()}
    assert runtime - {"__pycache__"} <= packages, sorted(runtime - packages)
