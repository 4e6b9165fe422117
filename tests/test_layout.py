"""Imports flow one way: commands → project → codemod, and project → sandbox.

Read from the source with ``ast`` (every import, module level or inside a function), so a
shortcut taken in a hurry fails here instead of tangling the layers.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "ezmigrate"

COMMANDS = {"cli", "session", "stdin", "check", "__main__"}
PROJECT = {"project", "runner", "cross_file"}
SANDBOX_PREFIX = "verify."
CODEMOD = {"migrate"}
CODEMOD_PREFIXES = ("core.", "rules.")


def _layer(module: str) -> str | None:
    if module in COMMANDS:
        return "commands"
    if module in PROJECT:
        return "project"
    if module.startswith(SANDBOX_PREFIX) or module == "verify":
        return "sandbox"
    if module in CODEMOD or module.startswith(CODEMOD_PREFIXES) or module in ("core", "rules"):
        return "codemod"
    return None


FORBIDDEN = {
    "codemod": {"commands", "project", "sandbox"},
    "sandbox": {"commands", "project"},
    "project": {"commands"},
}


def _module_of(path: Path) -> str:
    parts = path.relative_to(PACKAGE).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _imports(path: Path, module: str) -> list[tuple[int, str]]:
    package = module.split(".")[:-1] if path.name != "__init__.py" else module.split(".")
    found = []
    for node in ast.walk(ast.parse(path.read_bytes())):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = package[: len(package) - (node.level - 1)] if node.level > 1 else package
                target = ".".join([*base, node.module] if node.module else base)
            elif (node.module or "").startswith("ezmigrate."):
                target = (node.module or "").removeprefix("ezmigrate.")
            else:
                continue
            targets = [target] + [f"{target}.{a.name}".lstrip(".") for a in node.names]
            found += [(node.lineno, t) for t in targets]
        elif isinstance(node, ast.Import):
            found += [(node.lineno, a.name.removeprefix("ezmigrate."))
                      for a in node.names if a.name.startswith("ezmigrate.")]
    return found


FILES = sorted(p for p in PACKAGE.rglob("*.py") if "__pycache__" not in p.parts)


def test_every_layer_has_modules() -> None:
    layers = {_layer(_module_of(p)) for p in FILES}
    assert {"commands", "project", "sandbox", "codemod"} <= layers


@pytest.mark.parametrize("path", FILES, ids=lambda p: str(p.relative_to(PACKAGE)))
def test_imports_flow_one_way(path: Path) -> None:
    module = _module_of(path)
    layer = _layer(module)
    if layer not in FORBIDDEN:
        return
    for line, target in _imports(path, module):
        assert _layer(target) not in FORBIDDEN[layer], (
            f"{path.relative_to(PACKAGE)}:{line}: the {layer} imports {target} "
            f"({_layer(target)})")
