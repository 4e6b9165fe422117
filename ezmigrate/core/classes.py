"""Which classes of a module are legacy descriptions, and what they derive from.

A description derives from the legacy ``SkillDescription`` directly or through another
description of the same module or package (legacy-skiros2-api.md §2). Implementation
classes (``PrimitiveBase``, ``SkillBase``) are never descriptions, even though they have a
``createDescription`` of their own.
"""

from __future__ import annotations

from collections.abc import Collection
from dataclasses import dataclass

import libcst as cst

from .legacy_names import LegacyNames, dotted_name


@dataclass
class DescriptionClass:
    """A top-level description class: ``base`` is ``None`` for a direct legacy base."""

    node: cst.ClassDef
    name: str
    base: str | None
    base_arg: cst.Arg
    other_bases: int


def description_classes(module: cst.Module, names: LegacyNames,
                        external: Collection[str] = ()) -> list[DescriptionClass]:
    """Top-level description classes in definition order.

    ``external`` names description classes defined elsewhere in the package that this
    module imports by name (bases that are neither legacy nor local).
    """
    found: dict[str, DescriptionClass] = {}
    for stmt in module.body:
        if not isinstance(stmt, cst.ClassDef):
            continue
        for arg in stmt.bases:
            if arg.keyword is not None:
                continue
            base = dotted_name(arg.value)
            if names.symbol(arg.value) == "SkillDescription":
                found[stmt.name.value] = DescriptionClass(stmt, stmt.name.value, None, arg,
                                                          len(stmt.bases) - 1)
                break
            if base is not None and (base in found or base in external):
                found[stmt.name.value] = DescriptionClass(stmt, stmt.name.value, base, arg,
                                                          len(stmt.bases) - 1)
                break
    return list(found.values())
