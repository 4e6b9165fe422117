"""Which classes of a module are legacy descriptions, and what they derive from.

A description derives from the legacy ``SkillDescription`` directly or through another
description of the same module or package (legacy-skiros2-api.md §2). Implementation
classes (``PrimitiveBase``, ``SkillBase``) are never descriptions, even though they have a
``createDescription`` of their own.

A class that defines ``createDescription`` and derives from an EzSkiROS description (one an
earlier run migrated, here or in a sibling file) is a legacy description too: overriding
``createDescription`` turns the EzSkiROS machinery off for it (ezskiros_runtime/dsl/skill.py),
so its string-based body is what SkiROS2 runs. Without this, a child skipped by a partial
run would vanish from later runs and from ``check`` once its base was converted.
"""

from __future__ import annotations

import ast
from collections.abc import Collection, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import libcst as cst
else:
    from .lazy_cst import cst

from ..settings import RUNTIME_ROOT
from .ast_names import ast_dotted_name
from .legacy_names import LegacyNames, dotted_name, is_legacy_module
from .reader import class_bindings


@dataclass
class DescriptionClass:
    """A top-level description class: ``base`` is ``None`` for a direct legacy base.

    ``migrated_base``: ``base`` is already an EzSkiROS description (nothing to inline from
    it). ``kept``: why the class must stay as it is whatever its body holds.
    """

    node: cst.ClassDef
    name: str
    base: str | None
    base_arg: cst.Arg
    other_bases: int
    migrated_base: bool = False
    kept: str | None = None


def description_classes(module: cst.Module, names: LegacyNames,
                        external: Collection[str] = (), migrated: Collection[str] = (),
                        unresolved: Mapping[str, str] | None = None) -> list[DescriptionClass]:
    """Top-level description classes in definition order.

    ``external`` names description classes defined elsewhere in the package that this
    module imports by name (bases that are neither legacy nor local). ``migrated`` names
    imported EzSkiROS descriptions; ``unresolved`` maps imported bases whose file is not
    part of the run to the reason a class deriving from them is kept. Only classes that
    define ``createDescription`` count as descriptions through those two: an EzSkiROS
    child, or any class deriving from an unknown base, is not evidence of one.

    Two top-level classes of one name are two descriptions, each converted in the same
    run (the second still shadows the first when the module loads): keyed by name, the
    first would wait for a second run.
    """
    return _classify(module, names, external, migrated, unresolved or {})[0]


def ezskiros_classes(module: cst.Module) -> set[str]:
    """Top-level EzSkiROS description classes: deriving from ``ezskiros_runtime``'s
    ``SkillDescription``, directly or through another, without a ``createDescription``."""
    from .cst_facts import legacy_names_of  # libcst's visitor: the reader needs none

    return _classify(module, legacy_names_of(module), (), (), {})[1]


def _classify(module: cst.Module, names: LegacyNames, external: Collection[str],
              migrated: Collection[str], unresolved: Mapping[str, str]) -> tuple[
                  list[DescriptionClass], set[str]]:
    """Legacy description classes and names of EzSkiROS ones (see ``description_classes``)."""
    found: list[DescriptionClass] = []
    named: set[str] = set()  # a second class of one name is a description of its own too
    ezskiros = set(migrated)
    runtime_bases = _runtime_base_names(module)
    for stmt in module.body:
        if not isinstance(stmt, cst.ClassDef):
            continue
        for arg in positional_bases(stmt):
            base = dotted_name(arg.value)
            described: DescriptionClass | None = None
            if names.symbol(arg.value) == "SkillDescription":
                described = DescriptionClass(stmt, stmt.name.value, None, arg,
                                             len(stmt.bases) - 1)
            elif base is not None and (base in named or base in external):
                described = DescriptionClass(stmt, stmt.name.value, base, arg,
                                             len(stmt.bases) - 1)
            elif base is not None and (base in ezskiros or base in runtime_bases
                                       or base in unresolved):
                legacy = any(n == "createDescription" for n, _ in class_bindings(stmt))
                if legacy and base not in runtime_bases:
                    described = DescriptionClass(stmt, stmt.name.value, base, arg,
                                                 len(stmt.bases) - 1,
                                                 migrated_base=base not in unresolved,
                                                 kept=unresolved.get(base))
                elif not legacy and base not in unresolved:
                    ezskiros.add(stmt.name.value)  # an EzSkiROS description
            else:
                continue
            if described is not None:
                found.append(described)
                named.add(described.name)
            break
    return found, ezskiros - set(migrated)


def inert_classes(tree: ast.Module, names: LegacyNames,
                  known: Collection[str]) -> set[int]:
    """``id``s of the top-level classes ``_classify`` leaves out whatever their bodies hold.

    ``_classify`` reads a class body only for a base in its third branch, and takes a
    class only through a base in one of its three: the legacy ``SkillDescription``, a
    description of the module or of ``external``, or an EzSkiROS description of the
    module, of ``migrated``, of ``unresolved`` or of ``ezskiros_runtime``. A class none of
    whose positional bases is the first, nor a class of the module, nor a name in
    ``known`` (the settings' ``external``, ``migrated`` and ``unresolved``), nor a name an
    ``ezskiros_runtime`` import binds, is certainly no description, and its body is never
    read: ``core/holes.py`` stands in for it. Implementation classes (``PrimitiveBase``,
    ``SkillBase``) and plain helpers are such classes.
    """
    classes = [node for node in tree.body if isinstance(node, ast.ClassDef)]
    taken = {node.name for node in classes} | set(known) | _runtime_bound(tree)
    found = set()
    for node in classes:
        spelled = [ast_dotted_name(base) for base in ast_positional_bases(node)]
        if all(names.symbol_named(name) != "SkillDescription" and (
                name is None or (name not in taken and name.split(".")[0] not in taken))
               for name in spelled):
            found.add(id(node))
    return found


def positional_bases(stmt: cst.ClassDef) -> list[cst.Arg]:
    """The arguments of a class statement that can make it a description: neither a
    keyword (``metaclass=``) nor starred. ``class X(*Base)`` unpacks ``Base``, which a
    class never allows (Python raises when the module loads), so it is no description;
    ``ast_positional_bases`` says the same, so that the stand-in reading and libcst
    classify every class alike."""
    return [arg for arg in stmt.bases if arg.keyword is None and not arg.star]


def ast_positional_bases(node: ast.ClassDef) -> list[ast.expr]:
    """``positional_bases`` as ``ast`` reads the class (keywords are apart already)."""
    return [base for base in node.bases if not isinstance(base, ast.Starred)]


def ast_foreign_bases(tree: ast.Module, classes: list[ast.ClassDef]) -> list[tuple[str, str]]:
    """``migrate.foreign_bases`` read from ``ast``: ``(base, module)`` for each class base
    (starred ones too, as libcst lists them) named by a top-level ``from`` import of a
    user module, spelt ``"Name as Alias"`` when imported under another name."""
    imported: dict[str, tuple[str, str]] = {}
    for node in tree.body:
        if not isinstance(node, ast.ImportFrom) or node.names[0].name == "*":
            continue
        source = "." * node.level + (node.module or "")
        if node.level or not is_legacy_module(source):
            for alias in node.names:
                if alias.asname is not None and alias.asname != alias.name:
                    imported[alias.asname] = (f"{alias.name} as {alias.asname}", source)
                else:
                    imported[alias.name] = (alias.name, source)
    found = []
    for node in classes:
        for base in node.bases:
            named = base.value if isinstance(base, ast.Starred) else base
            if isinstance(named, ast.Name) and named.id in imported:
                found.append(imported[named.id])
    return found


def _runtime_bound(tree: ast.Module) -> set[str]:
    """Local names the top-level imports from ``ezskiros_runtime`` bind (a superset of
    ``_runtime_base_names``'s roots)."""
    bound: set[str] = set()
    for node in tree.body:
        if isinstance(node, ast.ImportFrom) and not node.level \
                and (node.module or "").split(".")[0] == RUNTIME_ROOT:
            bound.update(alias.asname or alias.name for alias in node.names)
        elif isinstance(node, ast.Import):
            bound.update((alias.asname or alias.name).split(".")[0] for alias in node.names
                         if alias.name.split(".")[0] == RUNTIME_ROOT)
    return bound


def _runtime_base_names(module: cst.Module) -> set[str]:
    """Local spellings of ``ezskiros_runtime``'s ``SkillDescription`` in the module
    (``SkillDescription``, ``EzSkillDescription`` as migration aliases it, or
    ``ez.SkillDescription``): the roots of EzSkiROS descriptions."""
    found: set[str] = set()
    for stmt in module.body:
        for small in stmt.body if isinstance(stmt, cst.SimpleStatementLine) else ():
            if isinstance(small, cst.ImportFrom) and small.module is not None \
                    and not small.relative and not isinstance(small.names, cst.ImportStar) \
                    and (dotted_name(small.module) or "").split(".")[0] == RUNTIME_ROOT:
                for alias in small.names:
                    if dotted_name(alias.name) == "SkillDescription":
                        local = alias.asname.name if alias.asname is not None else alias.name
                        found.add(dotted_name(local) or "SkillDescription")
            elif isinstance(small, cst.Import):
                for alias in small.names:
                    module_name = dotted_name(alias.name) or ""
                    if module_name == RUNTIME_ROOT:
                        local = alias.asname.name if alias.asname is not None else alias.name
                        found.add(f"{dotted_name(local)}.SkillDescription")
    return found
