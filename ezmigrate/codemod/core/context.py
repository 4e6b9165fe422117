"""State and helpers shared by extraction rules while they read one ``createDescription``."""

from __future__ import annotations

import ast
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Protocol

if TYPE_CHECKING:
    import libcst as cst
    from libcst.metadata import CodeRange
else:
    from .lazy_cst import cst

from .ir import CondSpec, ExtractedSkill, Literal, Operation, Unsupported
from .legacy_names import LegacyNames
from .syntax_facts import Span


class StatementLines:
    """Line numbers of the nodes of one block (a class or function body), from ``ast``.

    ``ast`` gives every statement its first and last line at no cost; a node of a
    statement written on one line is on that line. Only a statement spread over lines (a
    call with an argument per line) gets a position pass, of its own and when asked: a pass
    over the whole module would cost as much as parsing it again. The reader says which
    statement it is in (``enter``); rules ask for the lines of nodes inside it.
    ``statements``: the block's statements as ``ast`` counts them (a line ``a; b`` is two).
    """

    def __init__(self, module: cst.Module, block: cst.BaseSuite,
                 statements: Sequence[Span]) -> None:
        self.module = module
        self.spans: dict[int, Span] = {}
        self.current: cst.CSTNode | None = None
        self._positions: dict[int, tuple[Mapping[cst.CSTNode, CodeRange], int]] = {}
        rest = iter(statements)
        children = block.body if isinstance(block, cst.IndentedBlock) else [block]
        for stmt in children:
            smalls = list(stmt.body) if isinstance(stmt, (cst.SimpleStatementLine,
                                                          cst.SimpleStatementSuite)) else []
            group = [next(rest) for _ in range(len(smalls) or 1)]
            for small, span in zip(smalls, group, strict=False):
                self.spans[id(small)] = span
            self.spans[id(stmt)] = (group[0][0], max(last for _, last in group))

    def enter(self, stmt: cst.CSTNode) -> None:
        """The reader is now in ``stmt`` (a statement of the block)."""
        self.current = stmt

    def one_line(self) -> bool:
        """Whether the current statement is written on one line (no comment inside it)."""
        if self.current is None:
            return False
        first, last = self.spans[id(self.current)]
        return first == last

    def line(self, node: cst.CSTNode) -> int:
        """1-based line where ``node`` starts (0 when it is not in the block)."""
        span = self.spans.get(id(node))
        if span is not None:
            return span[0]
        if self.current is None:
            return 0
        first = self.spans[id(self.current)][0]
        if self.one_line():
            return first
        positions, shift = self._positions_of(self.current)
        found = positions.get(node)
        return found.start.line + shift if found is not None else first

    def _positions_of(self, stmt: cst.CSTNode) -> tuple[Mapping[cst.CSTNode, CodeRange], int]:
        assert isinstance(stmt, cst.BaseStatement)  # a suite is on one line: never asked
        if id(stmt) not in self._positions:
            alone = self.module.with_changes(header=(), body=(stmt,), footer=())
            wrapper = cst.MetadataWrapper(alone, unsafe_skip_copy=True)
            positions = wrapper.resolve(cst.metadata.PositionProvider)
            self._positions[id(stmt)] = (
                positions, self.spans[id(stmt)][0] - positions[stmt].start.line)
        return self._positions[id(stmt)]


StatementRule = Callable[["cst.BaseSmallStatement", "ExtractContext"],
                         "Sequence[Operation] | None"]
"""Turns one small statement of ``createDescription`` into IR: ``None`` when the statement
is not its construct, a list of operations (possibly empty) when it handled it, or raises
``Unsupported`` with a reason."""
ConditionRule = Callable[["cst.BaseExpression", "ExtractContext"], "CondSpec | None"]
"""Turns an expression that builds a condition into a ``CondSpec`` (``None``: not its)."""
CompoundRule = Callable[["cst.BaseStatement", "ExtractContext"],
                        "Sequence[Operation] | None"]
"""Turns one compound statement of ``createDescription`` (a loop) into IR: ``None`` when it
is not its construct (the reader then refuses it), the operations it stands for, or raises
``Unsupported`` with a reason."""
ReadPass = Callable[["list[Operation]"], "list[Operation]"]
"""Runs over a whole ``createDescription``'s operations once it is read."""


class ExtractionRules(Protocol):
    """The part of the rule table (``registry.RuleTable``) that reading consults. Declared
    here, not imported, so that the table may name this context in its rules' signatures
    without the two modules importing each other."""

    @property
    def statement_rules(self) -> tuple[StatementRule, ...]: ...

    @property
    def conditions(self) -> tuple[ConditionRule, ...]: ...

    @property
    def compound_rules(self) -> tuple[CompoundRule, ...]: ...

    @property
    def read_passes(self) -> tuple[ReadPass, ...]: ...


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
    lines: StatementLines
    skill: ExtractedSkill
    rules: ExtractionRules
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
        return self.lines.line(node)

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
            raise Unsupported(not_a_string(what, self.code(node).strip()), node)
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
    if isinstance(node, (cst.SimpleString, cst.Integer, cst.Float, cst.Imaginary, cst.Name)) \
            and not node.lpar:  # its text is its own: no code pass
        code = node.value
        if code in _NAMED:
            return Literal(_NAMED[code], code)
        if _PLAIN_STRING.fullmatch(code):  # no prefix, no escape: the text between quotes
            return Literal(code[1:-1], code)
        number = _number(node)
        if number is not None:
            return Literal(number, code)
    else:
        code = module.code_for_node(node).strip()
    try:
        value = ast.literal_eval(code)
    except (ValueError, SyntaxError, TypeError, MemoryError, RecursionError):
        return None
    return Literal(value, code)


def _number(node: cst.BaseExpression) -> int | float | None:
    """An integer or float literal's value without compiling it (``int``/``float`` read
    Python's literal syntax, underscores and prefixes included); ``None``: let
    ``literal_eval`` decide."""
    try:
        if isinstance(node, cst.Integer):
            return int(node.value, 0)
        if isinstance(node, cst.Float):
            return float(node.value)
    except ValueError:
        pass
    return None


_NAMED = {"True": True, "False": False, "None": None}
_PLAIN_STRING = re.compile(r'"[^"\\\n]*"|\'[^\'\\\n]*\'')
"""A one-line string literal without prefix or backslash: ``literal_eval`` would only
strip its quotes (it compiles each literal, which a file's thousands of keys feel)."""


def module_constants(module: cst.Module, bindings: Mapping[str, int]) -> dict[str, Literal]:
    """Module-level names bound exactly once, to a literal (``MAX_SPEED = 0.5``).

    ``bindings``: how often each name is bound anywhere in the module
    (``SyntaxFacts.bindings``, from one ``ast`` walk instead of a visit of this tree).
    """
    found: dict[str, Literal] = {}
    for stmt in module.body:
        if isinstance(stmt, cst.SimpleStatementLine) and len(stmt.body) == 1:
            small = stmt.body[0]
            if isinstance(small, cst.Assign) and len(small.targets) == 1 \
                    and isinstance(small.targets[0].target, cst.Name) \
                    and bindings.get(small.targets[0].target.value) == 1:
                value = literal_of(small.value, module)
                if value is not None:
                    found[small.targets[0].target.value] = value
    return found


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


def not_a_string(what: str, code: str) -> str:
    """Why a skill is kept whose ``what`` (a key, a name), written ``code``, is no string
    known statically (``lint/plain_reader.py`` words it so too)."""
    return (f"{what} is `{code}`, not a string literal: the key or name is computed at run "
            "time, so the migrated form cannot be written statically")


def fork_keyword(api: str, keyword: str, line: int) -> str:
    """Why a skill is kept whose call passes a keyword upstream SkiROS2 lacks."""
    return f"{api}({keyword}=...) at line {line} is not upstream SkiROS2 API (a fork's extension)"


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
                raise Unsupported(fork_keyword(api, keyword, ctx.line(call)), call)
            bound[keyword] = arg.value
    missing = [n for n in names[:required] if n not in bound]
    if missing:
        raise Unsupported(f"{api} at line {ctx.line(call)} lacks {', '.join(missing)}", call)
    return bound


def positions_of(module: cst.Module) -> tuple[cst.Module, Mapping[cst.CSTNode, object]]:
    """Resolve source positions once per module (the wrapper copies the tree)."""
    wrapper = cst.MetadataWrapper(module, unsafe_skip_copy=True)
    return wrapper.module, wrapper.resolve(cst.metadata.PositionProvider)
