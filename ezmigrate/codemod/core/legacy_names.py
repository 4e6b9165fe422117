"""Which local names of a module mean which part of the legacy SkiROS2 API.

Legacy files import the API in many styles (legacy-skiros2-api.md §1): plain, aliased, as a
module (``import skiros2_common.core.params as params``) or re-exported from
``skiros2_skill.core.skill``. Every rule asks this one resolver instead of matching names.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import libcst as cst
else:
    from .lazy_cst import cst

LEGACY_EXPORTS: dict[str, frozenset[str]] = {
    "skiros2_common.core.abstract_skill": frozenset({"SkillDescription", "ParamOptions"}),
    "skiros2_skill.core.skill": frozenset(
        {"SkillDescription", "ParamOptions", "SkillBase", "ParamTypes", "Element"}),
    "skiros2_common.core.params": frozenset({"ParamTypes", "Param", "ParamHandler"}),
    "skiros2_common.core.world_element": frozenset({"Element"}),
    "skiros2_common.core.conditions": frozenset({
        "ConditionRelation", "AbstractConditionRelation", "ConditionProperty",
        "ConditionHasProperty", "ConditionIsSpecified", "ConditionGenerate", "ConditionOnType",
        "ConditionOr", "ConditionFunction"}),
    "skiros2_common.core.primitive": frozenset({"PrimitiveBase"}),
}
LEGACY_ROOTS = ("skiros2_common", "skiros2_skill")


def dotted_name(node: cst.BaseExpression) -> str | None:
    """``a.b.c`` as text for a Name/Attribute chain, else ``None``."""
    if isinstance(node, cst.Name):
        return node.value
    if isinstance(node, cst.Attribute):
        base = dotted_name(node.value)
        return None if base is None else f"{base}.{node.attr.value}"
    return None


def is_legacy_module(module: str) -> bool:
    """True for ``skiros2_common...`` / ``skiros2_skill...`` modules."""
    return module.split(".")[0] in LEGACY_ROOTS


def _holds_exports(module: str) -> bool:
    """Whether ``module`` is a legacy module with API symbols, or a package above one
    (``skiros2_common.core``, whose ``params`` submodule holds ``ParamTypes``)."""
    return any(known == module or known.startswith(module + ".") for known in LEGACY_EXPORTS)


class LegacyNames:
    """Resolves expressions like ``PT.Required`` to ``("ParamTypes", "Required")``.

    Built once per module from its top-level imports (and imports anywhere, since legacy
    files sometimes import inside ``try`` blocks).
    """

    def __init__(self) -> None:
        self.symbols: dict[str, str] = {}
        self.modules: dict[str, str] = {}

    def add_from_import(self, module: str, aliases: Iterable[tuple[str, str]] | None) -> None:
        """Record ``from module import name as alias`` (``aliases`` None means ``*``)."""
        if not is_legacy_module(module):
            return
        exported = LEGACY_EXPORTS.get(module, frozenset())
        if aliases is None:
            for name in exported:
                self.symbols[name] = name
            return
        for name, alias in aliases:
            if name in exported:
                self.symbols[alias] = name
            elif _holds_exports(f"{module}.{name}"):
                # ``from skiros2_common.core import params`` binds a module, not a symbol:
                # ``params.ParamTypes.Required`` then resolves like any module import.
                self.modules[alias] = f"{module}.{name}"

    def add_import(self, module: str, alias: str | None) -> None:
        """Record ``import module [as alias]``."""
        if not is_legacy_module(module):
            return
        if alias is not None:
            self.modules[alias] = module
        else:
            root = module.split(".")[0]
            self.modules[root] = root

    def symbol(self, node: cst.BaseExpression) -> str | None:
        """The legacy API symbol (``"ParamTypes"``, ``"Element"``) an expression names."""
        return self.symbol_named(dotted_name(node))

    def symbol_named(self, name: str | None) -> str | None:
        """``symbol`` for a name already spelt out (``"PT"``, ``"params.ParamTypes"``)."""
        if name is None:
            return None
        if name in self.symbols:
            return self.symbols[name]
        head, _, attr = name.rpartition(".")
        if head:
            module = self._module(head)
            if module is not None and attr in LEGACY_EXPORTS.get(module, ()):
                return attr
        return None

    def member(self, node: cst.BaseExpression, symbol: str) -> str | None:
        """For ``PT.Required`` with ``symbol="ParamTypes"``: ``"Required"``."""
        if isinstance(node, cst.Attribute) and self.symbol(node.value) == symbol:
            return node.attr.value
        return None

    def _module(self, dotted: str) -> str | None:
        head, *rest = dotted.split(".")
        base = self.modules.get(head)
        if base is None:
            return None
        return ".".join([base, *rest])

    def local_names_for(self, symbol: str) -> set[str]:
        """Every local name bound directly to ``symbol``."""
        return {alias for alias, sym in self.symbols.items() if sym == symbol}
