"""State and helpers shared by extraction rules while they read one ``createDescription``."""

from __future__ import annotations

import ast
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field

import libcst as cst
import libcst.helpers
from libcst.metadata import PositionProvider

from .ir import CondSpec, ExtractedSkill, Literal, Operation, Unsupported
from .legacy_names import LegacyNames


@dataclass
class ExtractContext:
    """What a rule may consult: the module, its legacy names, locals seen so far.

    ``locals`` maps a local variable to the literal or condition object it holds, so that
    ``c = self.getRelationCond(...)`` followed by ``self.addPreCondition(c)`` is one
    condition, and ``key = "Object"`` can be used as a key. ``parent_operations`` returns the
    IR of a base description in the same module (for ``Parent.createDescription(self)``).
    """

    module: cst.Module
    names: LegacyNames
    positions: Mapping[cst.CSTNode, object]
    skill: ExtractedSkill
    self_name: str = "self"
    class_name: str = ""
    class_names: frozenset[str] = frozenset()
    """Names the class body binds: a signature default would see them, not the module's."""
    base_names: Sequence[str] = ()
    constants: Mapping[str, Literal] = field(default_factory=dict)
    function_names: frozenset[str] = frozenset()
    """Names ``createDescription`` binds anywhere: Python makes them local throughout, so
    such a name never reads the module constant of the same name."""
    locals: dict[str, Literal | CondSpec] = field(default_factory=dict)
    opaque_locals: set[str] = field(default_factory=set)
    parent_operations: Callable[[str], list[Operation]] | None = None

    def line(self, node: cst.CSTNode) -> int:
        """1-based line where ``node`` starts (0 when unknown)."""
        pos = self.positions.get(node)
        return pos.start.line if pos is not None else 0  # type: ignore[attr-defined]

    def code(self, node: cst.CSTNode) -> str:
        """The exact source text of ``node``."""
        return self.module.code_for_node(node)

    def literal(self, node: cst.BaseExpression) -> Literal | None:
        """A literal (``"x"``, ``-1``, ``[0.0, 1.0]``, ``True``) or a local holding one."""
        if isinstance(node, cst.Name) and isinstance(self.locals.get(node.value), Literal):
            found = self.locals[node.value]
            assert isinstance(found, Literal)
            return found
        return literal_of(node, self.module)

    def constant(self, node: cst.BaseExpression) -> Literal | None:
        """The literal a module-level constant named by ``node`` is bound to (``KEY = "X"``,
        bound once), unless ``createDescription`` binds that name itself."""
        if isinstance(node, cst.Name) and node.value not in self.function_names:
            return self.constants.get(node.value)
        return None

    def resolved(self, node: cst.BaseExpression) -> Literal | None:
        """A literal, a local holding one, or a module constant: a value known statically."""
        found = self.literal(node)
        return found if found is not None else self.constant(node)

    def string(self, node: cst.BaseExpression, what: str) -> str:
        """A string known statically, or ``Unsupported`` naming ``what`` it should have been."""
        lit = self.resolved(node)
        if lit is None or not isinstance(lit.value, str):
            raise Unsupported(
                f"{what} is `{self.code(node).strip()}`, not a string literal: the key or name "
                "is computed at run time, so the migrated form cannot be written statically",
                node)
        return lit.value

    def self_method(self, node: cst.BaseExpression) -> str | None:
        """For ``self.addParam(...)``: ``"addParam"``; ``None`` for anything else."""
        if (isinstance(node, cst.Call) and isinstance(node.func, cst.Attribute)
                and isinstance(node.func.value, cst.Name)
                and node.func.value.value == self.self_name):
            return node.func.attr.value
        return None


def literal_of(node: cst.BaseExpression, module: cst.Module) -> Literal | None:
    """The literal value of an expression written with literal syntax only."""
    if not _is_literal_shape(node):
        return None
    code = module.code_for_node(node).strip()
    try:
        value = ast.literal_eval(code)
    except (ValueError, SyntaxError, TypeError, MemoryError, RecursionError):
        return None
    return Literal(value, code)


def module_constants(module: cst.Module) -> dict[str, Literal]:
    """Module-level names bound exactly once, to a literal (``MAX_SPEED = 0.5``)."""
    bound: dict[str, int] = {}
    found: dict[str, Literal] = {}

    class _Bindings(cst.CSTVisitor):
        def visit_AssignTarget(self, node: cst.AssignTarget) -> None:
            for name in _target_names(node.target):
                bound[name] = bound.get(name, 0) + 1

        def visit_AugAssign(self, node: cst.AugAssign) -> None:
            for name in _target_names(node.target):
                bound[name] = bound.get(name, 0) + 2

        def visit_Global(self, node: cst.Global) -> None:
            for item in node.names:
                bound[item.name.value] = bound.get(item.name.value, 0) + 2

    module.visit(_Bindings())
    for stmt in module.body:
        if isinstance(stmt, cst.SimpleStatementLine) and len(stmt.body) == 1:
            small = stmt.body[0]
            if isinstance(small, cst.Assign) and len(small.targets) == 1 \
                    and isinstance(small.targets[0].target, cst.Name):
                name = small.targets[0].target.value
                value = literal_of(small.value, module)
                if value is not None:
                    found[name] = value
    return {name: value for name, value in found.items() if bound.get(name) == 1}


def bound_names(func: cst.FunctionDef) -> frozenset[str]:
    """Every name ``func``'s body binds (assignments, walrus, loops, imports, ``as``)."""
    found: set[str] = set()

    class _Bindings(cst.CSTVisitor):
        def visit_AssignTarget(self, node: cst.AssignTarget) -> None:
            found.update(_target_names(node.target))

        def visit_AugAssign(self, node: cst.AugAssign) -> None:
            found.update(_target_names(node.target))

        def visit_AnnAssign(self, node: cst.AnnAssign) -> None:
            found.update(_target_names(node.target))

        def visit_NamedExpr(self, node: cst.NamedExpr) -> None:
            found.update(_target_names(node.target))

        def visit_For(self, node: cst.For) -> None:
            found.update(_target_names(node.target))

        def visit_AsName(self, node: cst.AsName) -> None:
            found.update(_target_names(node.name))

        def visit_ImportAlias(self, node: cst.ImportAlias) -> None:
            if node.asname is None:
                found.add(cst.helpers.get_full_name_for_node_or_raise(node.name).split(".")[0])

    func.body.visit(_Bindings())
    return frozenset(found)


def _target_names(node: cst.BaseExpression) -> list[str]:
    if isinstance(node, cst.Name):
        return [node.value]
    if isinstance(node, (cst.Tuple, cst.List)):
        return [n for e in node.elements for n in _target_names(e.value)]
    return []


def _is_literal_shape(node: cst.BaseExpression) -> bool:
    """Cheap syntactic pre-check so that ``literal_eval`` only sees literal syntax."""
    if isinstance(node, (cst.SimpleString, cst.ConcatenatedString, cst.Integer, cst.Float,
                         cst.Imaginary)):
        return True
    if isinstance(node, cst.Name):
        return node.value in ("True", "False", "None")
    if isinstance(node, cst.UnaryOperation):
        return isinstance(node.operator, (cst.Minus, cst.Plus)) and _is_literal_shape(
            node.expression)
    if isinstance(node, (cst.List, cst.Tuple, cst.Set)):
        return all(isinstance(e, cst.Element) and _is_literal_shape(e.value)
                   for e in node.elements)
    if isinstance(node, cst.Dict):
        return all(isinstance(e, cst.DictElement) and _is_literal_shape(e.key)
                   and _is_literal_shape(e.value) for e in node.elements)
    return False


def bind_arguments(call: cst.Call, names: Sequence[str], required: int, api: str,
                   ctx: ExtractContext) -> dict[str, cst.BaseExpression]:
    """Match a call's arguments to the legacy signature ``names``.

    Keywords the upstream API does not have (a fork's ``remap=``) and ``*args`` make the
    skill unsupported with a reason; so do missing required arguments.
    """
    bound: dict[str, cst.BaseExpression] = {}
    for index, arg in enumerate(call.args):
        if arg.star:
            raise Unsupported(f"{api} called with `{arg.star}` arguments at line "
                              f"{ctx.line(call)}: the arguments are not known statically", call)
        if arg.keyword is None:
            if index >= len(names):
                raise Unsupported(f"{api} called with {len(call.args)} arguments at line "
                                  f"{ctx.line(call)}; upstream SkiROS2 takes {len(names)}", call)
            bound[names[index]] = arg.value
        else:
            keyword = arg.keyword.value
            if keyword not in names:
                raise Unsupported(f"{api}({keyword}=...) at line {ctx.line(call)} is not "
                                  "upstream SkiROS2 API (a fork's extension)", call)
            bound[keyword] = arg.value
    missing = [n for n in names[:required] if n not in bound]
    if missing:
        raise Unsupported(f"{api} at line {ctx.line(call)} lacks {', '.join(missing)}", call)
    return bound


def positions_of(module: cst.Module) -> tuple[cst.Module, Mapping[cst.CSTNode, object]]:
    """Resolve source positions once per module (the wrapper copies the tree)."""
    wrapper = cst.MetadataWrapper(module, unsafe_skip_copy=True)
    return wrapper.module, wrapper.resolve(PositionProvider)
