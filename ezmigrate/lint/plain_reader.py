"""``check``'s fast path: plainly written legacy descriptions read with ``ast``, not libcst.

``check`` needs what each description declares, not a rewrite, and libcst parses about ten
times slower than ``ast`` (then walks the tree several times for the rewrite). Most real
descriptions are plain: a ``SkillDescription`` subclass whose ``createDescription`` is a
list of ``self.addParam(...)`` and ``self.addPreCondition(self.getRelationCond(...))`` with
literal arguments. This reader builds the codemod's own IR for exactly that form, so the
rest of the way (``emitted_params``, the replay through the legacy backend, the static
facts, the findings of ``add_param``) is the codemod's code, not a copy of it.

Anything else — a local variable, a module constant, an or-condition, inheritance between
descriptions, a base imported from a sibling module, decorators, extra class members, a
value emission could refuse — makes ``read_plain`` give up on the whole file (``None``),
and the file goes through the codemod's reader as ``rewrite`` reads it. The module
``tests/lint/test_plain_reader.py`` proves, on every fixture and on generated
repositories, that whenever this reader accepts a file, ``check`` reports exactly what the
codemod's reader makes it report.
"""

from __future__ import annotations

import ast
import re
from dataclasses import dataclass

from ..codemod.core.ast_names import ast_dotted_name
from ..codemod.core.ast_walk import walk
from ..codemod.core.classes import ast_foreign_bases
from ..codemod.core.context import fork_keyword, not_a_string
from ..codemod.core.declared import static_description
from ..codemod.core.function import emitted_params
from ..codemod.core.ir import (
    AddCondition,
    CondSpec,
    ElementValue,
    ExtractedSkill,
    Literal,
    OpaqueValue,
    ParamOp,
    ParamValue,
    TypeValue,
    Unsupported,
)
from ..codemod.core.legacy_names import LegacyNames
from ..codemod.core.replay import checked_model, replay
from ..codemod.core.syntax_facts import note_binding, note_import
from ..codemod.rules.add_param import (
    ARGUMENTS,
    KINDS,
    OPTIONS,
    TYPE_OBJECTS,
    fork_kind,
    literal_type,
    param_findings,
)
from ..codemod.rules.condition_factories import CLASSES, FACTORIES
from ..codemod.rules.condition_lists import LISTS
from ..report.results import FileResult, SkillResult

_NESTED_LEGACY_IMPORT = re.compile(rb"^[ \t]+(?:from|import)[ \t][^\n]*skiros2", re.MULTILINE)


class _Declined(Exception):
    """Not the plain form: the codemod's reader takes the file."""


class _Kept(Exception):
    """A construct the codemod keeps the skill for (``Unsupported``), met where the codemod
    meets it, worded as it words it: the skill is kept, the file stays plain."""

    def __init__(self, reason: str) -> None:
        super().__init__(reason)
        self.reason = reason


@dataclass(frozen=True)
class Declined:
    """The file is not plain; ``cross_file``: the codemod must see its whole package."""

    cross_file: bool = False


def read_plain(data: bytes, path: str, tree: ast.Module | None = None) -> FileResult | Declined:
    """Every legacy description of a module, when all of them are plain (``tree``: the
    module already parsed by the caller).

    Declined also for a file the codemod must judge itself: one that ``ast`` cannot parse
    (the codemod says why). The caller keeps files using ``ezskiros_runtime`` away.

    A class deriving from a name a user module exports may derive from a description of
    another file: the result names those bases (``foreign_bases``, as the codemod's first
    reading does), for the cross-file pass to resolve with the files around it.
    """
    try:
        tree = tree or ast.parse(data)
    except (SyntaxError, ValueError, UnicodeError, MemoryError, RecursionError):
        return Declined()
    classes = [node for node in tree.body if isinstance(node, ast.ClassDef)]
    foreign = ast_foreign_bases(tree, classes)
    try:
        names = _legacy_names(tree, data)
        constants = _Constants(tree)
        skills = [_skill(node, names, constants, data)
                  for node in _description_classes(classes, names)]
    except (_Declined, Unsupported, SyntaxError, ValueError, UnicodeError, LookupError,
            MemoryError, RecursionError):
        return Declined(cross_file=bool(foreign))
    return FileResult(path=path, skills=skills, foreign_bases=foreign,
                      exports=[s.name for s in skills if s.status == "converted"])


def _legacy_names(tree: ast.Module, data: bytes) -> LegacyNames:
    """The codemod's ``LegacyNames``, filled from ``ast`` imports (nested ones included)."""
    names = LegacyNames()
    for node in walk(tree) if _NESTED_LEGACY_IMPORT.search(data) else iter(tree.body):
        note_import(node, names)
    return names


def _description_classes(classes: list[ast.ClassDef], names: LegacyNames
                         ) -> list[ast.ClassDef]:
    """Top-level classes deriving directly from the legacy ``SkillDescription``; a class
    deriving from another class of the module declines (the codemod inlines its base), and
    so does ``class A(metaclass=M, *bases)``, which Python reads and libcst refuses."""
    found: list[ast.ClassDef] = []
    local: set[str] = set()
    for node in classes:
        if node.keywords and any(isinstance(b, ast.Starred) for b in node.bases):
            raise _Declined
        spelled = [ast_dotted_name(b) for b in node.bases]
        direct = [s for s in spelled if names.symbol_named(s) == "SkillDescription"]
        if any(s in local for s in spelled):
            raise _Declined  # a description through another one
        if not direct:
            continue
        if len(node.bases) != 1 or node.keywords or node.decorator_list:
            raise _Declined
        found.append(node)
        local.add(node.name)
    return found


class _Constants:
    """``core.context.module_constants`` on ``ast``: module-level names bound exactly once
    (counting bindings anywhere in the module), by their own ``NAME = literal`` line.

    Built on first use: most plain descriptions use no constant, and the walk over the
    whole module is then never paid for.
    """

    def __init__(self, tree: ast.Module) -> None:
        self.tree = tree
        self._found: dict[str, Literal] | None = None

    def get(self, name: str) -> Literal | None:
        if self._found is None:
            self._found = self._collect()
        return self._found.get(name)

    def _collect(self) -> dict[str, Literal]:
        bound: dict[str, int] = {}
        for node in walk(self.tree):
            note_binding(node, bound)
        lines = [(n.lineno, n.end_lineno or n.lineno) for n in self.tree.body]
        found: dict[str, Literal] = {}
        for stmt in self.tree.body:
            if isinstance(stmt, ast.Assign) and len(stmt.targets) == 1 \
                    and isinstance(stmt.targets[0], ast.Name) \
                    and bound.get(stmt.targets[0].id) == 1 and not _shares_a_line(stmt, lines):
                value = _literal(stmt.value)
                if value is not None:
                    found[stmt.targets[0].id] = value
        return found


def _shares_a_line(stmt: ast.stmt, lines: list[tuple[int, int]]) -> bool:
    """``A = 1; B = 2``: libcst sees one line of two statements, which is no constant."""
    start, end = stmt.lineno, stmt.end_lineno or stmt.lineno
    return sum(1 for s, e in lines if s <= end and e >= start) > 1


def _skill(node: ast.ClassDef, names: LegacyNames, constants: _Constants,
           data: bytes) -> SkillResult:
    func = _create_description(node)
    if func is None:  # ``migrate._plan``: a description declaring nothing converts as is
        return SkillResult(node.name, node.lineno, "converted",
                           model=replay(node.name, []).to_json())
    skill = ExtractedSkill(node.name, node.lineno)
    reader = _Reader(names, func.args.args[0].arg, skill, constants, node.name, data)
    try:
        for index, stmt in enumerate(func.body):
            if index == 0 and isinstance(stmt, ast.Expr) \
                    and isinstance(stmt.value, ast.Constant) and isinstance(stmt.value.value, str):
                continue  # the docstring
            reader.statement(stmt)
    except _Kept as kept:  # ``migrate._plan``: the skill is kept, with the reason
        return SkillResult(node.name, node.lineno, "skipped", reason=kept.reason)
    params = emitted_params(skill, comments=False)  # a signature's: never written here
    _emittable(skill)
    try:
        model = checked_model(node.name, skill.operations, params)
    except Exception as error:  # reordering, or a rejection: the codemod words it
        raise _Declined from error
    return SkillResult(node.name, node.lineno, "converted", model=model.to_json(),
                       static=static_description(skill),
                       findings=list(skill.findings))


def _create_description(node: ast.ClassDef) -> ast.FunctionDef | None:
    """The class's only member besides a docstring, taking ``self`` alone; None for a class
    with none (a docstring, ``pass``: a description that declares nothing)."""
    body = node.body
    if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant) \
            and isinstance(body[0].value.value, str):
        body = body[1:]
    if all(isinstance(stmt, ast.Pass) for stmt in body):
        return None
    if len(body) != 1 or not isinstance(body[0], ast.FunctionDef):
        raise _Declined
    func = body[0]
    args = func.args
    if (func.name != "createDescription" or func.decorator_list or len(args.args) != 1
            or args.posonlyargs or args.vararg or args.kwonlyargs or args.kwarg
            or not func.body):
        raise _Declined
    return func


def _emittable(skill: ExtractedSkill) -> None:
    """Decline what the EzSkiROS writer would refuse (``add_param.annotation``,
    ``condition_factories.with_label``/``negated``): that skill is kept, not converted."""
    for op in skill.operations:
        if isinstance(op, ParamOp) and isinstance(op.value, Literal):
            literal_type(op.value, op)  # raises Unsupported
        elif isinstance(op, ParamOp) and isinstance(op.value, OpaqueValue):
            assert op.value.known is not None  # the reader declines unknown ones
            literal_type(op.value.known, op)
        elif isinstance(op, AddCondition):
            spec = op.condition
            if spec.label is None or type(spec.label.value) is not str:
                raise _Declined
            if spec.desired is not None and type(spec.desired.value) is not bool:
                raise _Declined


class _Reader:
    """One ``createDescription`` body, statement by statement, into ``skill.operations``."""

    def __init__(self, names: LegacyNames, self_name: str, skill: ExtractedSkill,
                 constants: _Constants, class_name: str, data: bytes) -> None:
        self.names = names
        self.self_name = self_name
        self.skill = skill
        self.constants = constants
        self.class_name = class_name
        self.data = data

    def resolved(self, node: ast.expr) -> Literal:
        """A literal, or a module constant (``ExtractContext.resolved``); else decline."""
        found = _literal(node)
        if found is None and isinstance(node, ast.Name):
            found = self.constants.get(node.id)
        if found is None:
            raise _Declined
        return found

    def string(self, node: ast.expr) -> str:
        found = self.resolved(node).value
        if not isinstance(found, str):
            raise _Declined
        return found

    def statement(self, stmt: ast.stmt) -> None:
        if isinstance(stmt, ast.Pass):
            return  # declares nothing; the codemod drops it too (``kept_statements``)
        if not isinstance(stmt, ast.Expr):
            raise _Declined
        method = self._self_method(stmt.value)
        assert method is None or isinstance(stmt.value, ast.Call)
        if method == "addParam":
            self._add_param(stmt.value)  # type: ignore[arg-type]
        elif method in LISTS:
            call = stmt.value
            args = _bind(call, ("condition",), 1)  # type: ignore[arg-type]
            self.skill.operations.append(AddCondition(
                LISTS[method], self._condition(args["condition"]), call.lineno))
        else:
            raise _Declined

    def _symbol(self, node: ast.expr) -> str | None:
        """The legacy API symbol an expression names (``LegacyNames.symbol``)."""
        return self.names.symbol_named(ast_dotted_name(node))

    def _self_method(self, node: ast.expr) -> str | None:
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) \
                and isinstance(node.func.value, ast.Name) and node.func.value.id == self.self_name:
            return node.func.attr
        return None

    def _add_param(self, call: ast.Call) -> None:
        args = _bind(call, ARGUMENTS, 3, "addParam")
        key = self._key(args["key"], call)
        options: list[str] = []
        options_text = None
        if "options" in args:
            options, options_text = self._options(args["options"])
        description = self.string(args["description"]) if "description" in args else None
        op = ParamOp(key, self._value(args["value"]), self._kind(args["param_type"]), options,
                     description, call.lineno,
                     options_text=options_text)  # description_code: only emission reads it
        self.skill.operations.append(op)
        param_findings(op, self.skill)

    def _value(self, node: ast.expr) -> ParamValue:
        if isinstance(node, ast.Call) and self._symbol(node.func) == "Element":
            args = _bind(node, ("etype", "label", "eid"), 0)
            if "label" in args or "eid" in args:
                raise _Declined
            return ElementValue(self.string(args["etype"]) if "etype" in args else "Unknown")
        if self._symbol(node) == "Element":
            raise _Declined
        if isinstance(node, ast.Name) and node.id in TYPE_OBJECTS:
            return TypeValue(node.id)
        found = _literal(node)
        if found is not None:
            return found
        if isinstance(node, ast.Name) and node.id not in (self.self_name, self.class_name,
                                                          "createDescription"):
            known = self.constants.get(node.id)
            if known is not None:  # as written, typed by the literal it is bound to
                return OpaqueValue(node.id, known)
        raise _Declined

    def _key(self, node: ast.expr, call: ast.Call) -> str:
        """The key, as ``ExtractContext.string`` reads it; a literal of another type (a
        fork's ``("skill", "key")`` pair) keeps the skill, named as the codemod names it."""
        found = _literal(node)
        if found is None or isinstance(found.value, str):
            return self.string(node)
        code = _own_text(self.data, node, call)
        if code is None:
            raise _Declined
        raise _Kept(not_a_string(f"the key of addParam at line {call.lineno}", code))

    def _kind(self, node: ast.expr) -> str:
        member = self._member(node, "ParamTypes")
        if member in KINDS:
            return member
        if member is not None:  # add_param._kind: the codemod reads the kind last, as here
            raise _Kept(fork_kind(member, node.lineno))
        found = _literal(node) if member is None else None
        if found is not None and type(found.value) is int and 0 <= found.value < len(KINDS):
            return KINDS[found.value]
        raise _Declined

    def _options(self, node: ast.expr) -> tuple[list[str], str | None]:
        found = _literal(node)
        if found is not None and isinstance(found.value, str):
            return [], found.value
        if not isinstance(node, (ast.List, ast.Tuple)):
            raise _Declined
        members = [self._member(e, "ParamOptions") for e in node.elts]
        if not all(m in OPTIONS for m in members):
            raise _Declined
        return [m for m in members if m is not None], None

    def _member(self, node: ast.expr, symbol: str) -> str | None:
        if isinstance(node, ast.Attribute) and self._symbol(node.value) == symbol:
            return node.attr
        return None

    def _condition(self, node: ast.expr) -> CondSpec:
        if not isinstance(node, ast.Call):
            raise _Declined
        factory = self._self_method(node)
        if factory not in FACTORIES:
            factory = CLASSES.get(self._symbol(node.func) or "")
            if factory is None:
                raise _Declined
        kind, names = FACTORIES[factory]
        args = _bind(node, names, len(names))
        vocab = args.get("relation") or args.get("property") or args.get("type")
        return CondSpec(
            kind=kind, label=self.resolved(args["label"]), line=node.lineno,
            vocabulary=None if vocab is None else self.string(vocab),
            subject=self.string(args["subject_key"]),
            object=self.string(args["object_key"]) if "object_key" in args else None,
            operator=self.string(args["operator"]) if "operator" in args else None,
            value=self.resolved(args["value"]) if "value" in args else None,
            desired=(self.resolved(args["desired_state"]) if "desired_state" in args
                     else None))


def _bind(call: ast.Call, names: tuple[str, ...], required: int,
          api: str | None = None) -> dict[str, ast.expr]:
    """``core.context.bind_arguments`` for the plain form: anything unusual declines. With
    ``api``, a keyword upstream SkiROS2 does not have (a fork's ``remap=``) keeps the skill,
    as the codemod does: it reads the arguments in order, and stops at the first such one."""
    bound: dict[str, ast.expr] = {}
    if len(call.args) > len(names):
        raise _Declined
    for name, arg in zip(names, call.args, strict=False):
        if isinstance(arg, ast.Starred):
            raise _Declined
        bound[name] = arg
    twice = False
    for keyword in call.keywords:
        if keyword.arg is None:
            raise _Declined
        if keyword.arg not in names:
            if api is None:
                raise _Declined
            raise _Kept(fork_keyword(api, keyword.arg, call.lineno))
        twice = twice or keyword.arg in bound
        bound[keyword.arg] = keyword.value
    if twice:
        raise _Declined
    if any(n not in bound for n in names[:required]):
        raise _Declined
    return bound


def _own_text(data: bytes, node: ast.expr, call: ast.Call) -> str | None:
    """The text libcst gives ``node`` (``ExtractContext.code``), when it is one line and
    the first argument of ``call`` with no parentheses of its own: ``ast`` leaves those
    out of a node's span, libcst keeps them. None otherwise (the codemod says it)."""
    if not call.args or call.args[0] is not node or node.lineno != node.end_lineno \
            or call.func.end_lineno != node.lineno or node.end_col_offset is None \
            or call.func.end_col_offset is None:
        return None
    line = data.splitlines()[node.lineno - 1]
    if line[call.func.end_col_offset:node.col_offset].strip() != b"(":
        return None
    try:
        return line[node.col_offset:node.end_col_offset].decode("utf-8")
    except UnicodeDecodeError:
        return None


def _literal_shape(node: ast.expr) -> bool:
    """``core.context._is_literal_shape`` on ``ast`` nodes (``...`` is not a literal)."""
    if isinstance(node, ast.Constant):
        return node.value is not Ellipsis
    if isinstance(node, ast.UnaryOp):
        return isinstance(node.op, (ast.USub, ast.UAdd)) and _literal_shape(node.operand)
    if isinstance(node, (ast.List, ast.Tuple, ast.Set)):
        return all(not isinstance(e, ast.Starred) and _literal_shape(e) for e in node.elts)
    if isinstance(node, ast.Dict):
        return all(k is not None and _literal_shape(k) and _literal_shape(v)
                   for k, v in zip(node.keys, node.values, strict=True))
    return False


def _literal(node: ast.expr) -> Literal | None:
    if not _literal_shape(node):
        return None
    try:
        value = ast.literal_eval(node)
    except (ValueError, SyntaxError, TypeError, MemoryError, RecursionError):
        return None
    return Literal(value, repr(value))  # not the source's spelling: never written
