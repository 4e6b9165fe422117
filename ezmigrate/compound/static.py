"""Read compound skills' trees from the syntax tree, when ``expand`` is written literally.

About three ``expand`` bodies in four are literal: ``skill.setProcessor(SerialStar())``
then ``skill(self.skill("Navigate", "", remap={"Target": "Location"}), ...)``. For those
the tree is read here with ``ast``, without importing anything; a body that computes its
tree (a loop, a branch, a helper call, ``specify`` values other than literals and
``self.params["X"].value``) is handed to the tracer (``ezskiros_runtime.compound.trace``),
which runs it in a child process. Both give the same ``CompoundModel``; a property test
holds them to it on generated trees. ``self.setProcessor(...)`` sets the skill instance's
processor, not the tree's (SkiROS2 copied it to the tree's node before ``expand``; the
tracer ignores it too): read past.
"""

from __future__ import annotations

import ast
import builtins
import functools
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ezskiros_runtime.compound.checks import ELSEWHERE, UPSTREAM_PROCESSORS, compound_finding
from ezskiros_runtime.compound.model import (
    COMPUTED,
    CallProblem,
    CompoundModel,
    Node,
    ProcessorNode,
    SkillNode,
)
from ezskiros_runtime.compound.trace import (
    ARGUMENTS,
    PARAMETER_OBJECT,
    call_problem,
    parameter_object_message,
)
from ezskiros_runtime.diagnostics import Finding

from ..codemod.core.ast_names import ast_dotted_name
from ..codemod.core.ast_walk import nodes, walk
from ..lint.ezskiros_static import shape_of

PROCESSORS = UPSTREAM_PROCESSORS | frozenset(ELSEWHERE)


class _Computed(Exception):
    """The body computes (part of) its tree: only running it tells."""


@dataclass(frozen=True)
class NeedsTrace:
    """A compound class whose tree ``ast`` cannot read: trace it (why, for the report).

    ``description`` and ``label`` are read here all the same: in the child, a description
    imported from a package outside the run may be a stand-in with another name.
    """

    implementation: str
    line: int
    reason: str
    description: str | None = None
    label: str = ""
    partial: CompoundModel | None = None
    """What the syntax gives of the tree all the same: the nodes of every statement but
    the ones it cannot read (``CompoundModel.gaps``); ``check`` checks them when it runs
    no code, and when tracing cannot read the tree either."""


def compound_classes(tree: ast.Module) -> list[ast.ClassDef]:
    """Top-level classes that define ``expand``: compound skill implementations."""
    return [node for node in tree.body if isinstance(node, ast.ClassDef)
            and any(isinstance(m, ast.FunctionDef) and m.name == "expand" for m in node.body)]


def read_compounds(tree: ast.Module, path: str) -> list[CompoundModel | NeedsTrace]:
    """Every compound class of a module, read statically or marked for tracing."""
    found: list[CompoundModel | NeedsTrace] = []
    bound = module_names(tree, path)
    for cls in compound_classes(tree):
        expand = [m for m in cls.body if isinstance(m, ast.FunctionDef)
                  and m.name == "expand"][-1]
        description, label = _described(cls)
        try:
            processor, children, gaps = _Reader(expand, bound).read()
        except _Computed as computed:
            found.append(NeedsTrace(cls.name, cls.lineno, str(computed), description, label))
            continue
        model = CompoundModel(cls.name, description, label, processor, children, path,
                              cls.lineno, expand.lineno, "static", gaps)
        found.append(model if not gaps else NeedsTrace(
            cls.name, cls.lineno, gaps[0][1], description, label, model))
    return found


KNOWN_STAR: dict[str, frozenset[str]] = {
    **dict.fromkeys(
        ("skiros2_skill.core.skill", "skiros2_skill.core.processors"),
        PROCESSORS | frozenset({"SkillBase", "SkillCore", "SkillDescription", "SkillWrapper",
                                "ParamTypes", "ParamOptions", "Element", "State", "Params"})),
    # SkiROS2's other modules labs star-import (master's top-level public names): they
    # bind no processor, so a misspelt processor beside them is still undefined
    "skiros2_common.core.primitive": frozenset({
        "Element", "PrimitiveBase", "SkillCore", "State", "datetime", "log"}),
    "skiros2_common.core.abstract_skill": frozenset({
        "Element", "Enum", "Event", "IdGen", "ParamOptions", "SkillCore", "SkillDescription",
        "State", "TimeKeeper", "cond", "copy", "deepcopy", "log", "params"}),
    "skiros2_common.core.params": frozenset({
        "Element", "Enum", "Param", "ParamHandler", "ParamTypes", "Property", "copy",
        "datetime", "deepcopy", "log", "timedelta"}),
    "skiros2_common.core.world_element": frozenset({
        "DiscreteReasoner", "Element", "PluginLoader", "Property", "basestring", "datetime",
        "ispy2unicode", "log", "rospy"}),
    "skiros2_common.core.conditions": frozenset({
        "AbstractConditionRelation", "ConditionBase", "ConditionGenerate",
        "ConditionHasProperty", "ConditionIsSpecified", "ConditionOnType", "ConditionOr",
        "ConditionProperty", "ConditionRelation", "Element", "absolute_import", "deepcopy",
        "operator", "operators", "params"}),
}
"""What ``from M import *`` binds for SkiROS2's modules, as far as a processor's name
goes: for the modules a tree's processors come from, every processor of every branch and
fork (``compound.checks``), so that a misspelt one is still found undefined; for the
others, their public top-level names (none a processor)."""


def star_sources(tree: ast.Module, path: str) -> tuple[str, ...]:
    """The files of the repository that ``module_names`` reads for this module's star
    imports (transitively): what is read of the module depends on their bytes too, so a
    cache keeps the reading by them as well."""
    read: list[str] = []
    module_names(tree, path, read=read)
    return tuple(dict.fromkeys(read))


def module_names(tree: ast.Module, path: str | None = None,
                 seen: frozenset[str] = frozenset(),
                 read: list[str] | None = None) -> frozenset[str] | None:
    """The names a module binds at its top level (imports, classes, functions, assignments,
    also inside top-level ``if``/``try``), and the builtins; None when a star import may
    bind any name. ``path``: the module's file, where a star import of a module of the
    repository beside it (``from primitives import *``, the lab's own) is read for what it
    exports (``read``, when given, collects the files read so)."""
    names: set[str] = set(dir(builtins))
    todo: list[ast.stmt] = list(tree.body)
    while todo:
        node = todo.pop()
        if isinstance(node, ast.ImportFrom) and any(a.name == "*" for a in node.names):
            if not node.level and node.module in KNOWN_STAR:
                names |= KNOWN_STAR[node.module]
                continue
            exported = _star_names(node, path, seen, read)
            if exported is None:
                return None  # any name may come from it
            names |= exported
            continue
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            names.update((a.asname or a.name).split(".")[0] for a in node.names)
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, (ast.If, ast.Try, ast.With, ast.For, ast.While)):
            todo += [c for c in ast.iter_child_nodes(node) if isinstance(c, ast.stmt)]
            if isinstance(node, ast.Try):
                todo += [s for h in node.handlers for s in h.body]
            names |= _stored(node)
        else:
            names |= _stored(node)
    return frozenset(names)


def _star_names(node: ast.ImportFrom, path: str | None, seen: frozenset[str],
                read: list[str] | None = None) -> frozenset[str] | None:
    """The public names ``from M import *`` binds, for a module ``M`` found as a file of the
    repository near ``path`` (beside it, or as a package a few folders up); None when it is
    not found or cannot be read (then any name may come from it)."""
    if path is None or node.module is None:
        return None
    parts = node.module.split(".")
    start = Path(path).parent
    bases = [start.parents[node.level - 2] if node.level > 1 else start] if node.level \
        else [start, *list(start.parents)[:4]]
    for base in bases:
        for candidate in (base.joinpath(*parts).with_suffix(".py"),
                          base.joinpath(*parts, "__init__.py")):
            if candidate.is_file():
                if read is not None:
                    read.append(str(candidate))
                return _exports(str(candidate), seen | {path}, read)
    return None


def _exports(path: str, seen: frozenset[str], read: list[str] | None = None
             ) -> frozenset[str] | None:
    """The names ``from <module at path> import *`` binds (its ``__all__`` when literal)."""
    if path in seen or len(seen) > 8:
        return None
    try:
        tree = module_tree(Path(path).read_bytes())
    except OSError:
        return None
    if tree is None:
        return None
    for statement in tree.body:
        if isinstance(statement, ast.Assign) and any(
                isinstance(t, ast.Name) and t.id == "__all__" for t in statement.targets):
            try:
                return frozenset(str(n) for n in ast.literal_eval(statement.value))
            except (ValueError, TypeError, SyntaxError):
                return None
    names = module_names(tree, path, seen, read)
    return None if names is None else frozenset(
        n for n in names - set(dir(builtins)) if not n.startswith("_"))


@functools.lru_cache(maxsize=32)
def module_tree(data: bytes) -> ast.Module | None:
    """The syntax tree of a star-imported module, or None when ``ast`` cannot read it.
    Kept by content, and only read: the modules a lab star-imports are imported by many of
    its files, and their code digest (``file_facts.code_digest_of``) reads the same tree."""
    try:
        return ast.parse(data)
    except (SyntaxError, ValueError, LookupError, MemoryError, RecursionError):
        return None


def _stored(node: ast.AST) -> set[str]:
    """The names a statement (or an expression) assigns, walrus included."""
    return {n.id for n in nodes(node) if isinstance(n, ast.Name)
            and isinstance(n.ctx, ast.Store)}


def _bound_in(function: ast.FunctionDef) -> frozenset[str]:
    """A function's parameters and the names its body binds (its locals)."""
    args = function.args
    params = {a.arg for a in (*args.posonlyargs, *args.args, *args.kwonlyargs,
                              *(a for a in (args.vararg, args.kwarg) if a is not None))}
    imported = {(a.asname or a.name).split(".")[0] for n in nodes(function)
                if isinstance(n, (ast.Import, ast.ImportFrom)) for a in n.names}
    return frozenset(params | imported | _stored(function))


def class_bases(tree: ast.Module) -> list[tuple[str, str]]:
    """``(class, base)`` for the module's top-level classes, bases by their last name
    (``Navigate`` for ``base.Navigate``): which descriptions are not leaves."""
    found = []
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            for base in node.bases:
                name = ast_dotted_name(base)
                if name is not None:
                    found.append((node.name, name.rpartition(".")[2]))
    return found


def implementations(tree: ast.Module) -> list[tuple[str, str | None]]:
    """``(label, description)`` of every implementation class (primitive or compound) of a
    module: what ``self.skill("Type", "label")`` may name. Both its label and its class
    name: ``SkillInstanciator.assign_instance`` matches the label of a loaded instance, and
    where none has it ``add_instance`` loads the plugin of that name, the class."""
    found: dict[tuple[str, str | None], None] = {}
    for description, label, cls in _implementation_classes(tree):
        found[(label, description)] = None
        found[(cls.name, description)] = None
    return list(found)


def described_classes(tree: ast.Module) -> list[tuple[str, ast.ClassDef]]:
    """``(description, class)`` of every implementation class of a module, for checks that
    read what an implementation does with its description's parameters."""
    return [(description, cls) for description, _, cls in _implementation_classes(tree)]


def _implementation_classes(tree: ast.Module) -> Iterator[tuple[str, str, ast.ClassDef]]:
    """``(description, label, class)`` of each top-level class that calls
    ``setDescription`` in its ``createDescription``."""
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            description, label = _described(node)
            if description is not None:
                yield description, label, node


def modified_params(tree: ast.Module) -> list[tuple[str, str, str | None, bool, str]]:
    """``(description, key, element type, on the wrapper, implementation label)`` for each
    literal ``addParam`` in an implementation's ``modifyDescription(self, skill)``.

    SkiROS2's ``SkillWrapper.setInstance`` calls ``instance.modifyDescription(wrapper)``:
    what is added to ``skill`` (the wrapper) is declared like the description's own
    parameters; what is added to ``self`` is not on the wrapper, so a ``specify`` of it is
    dropped."""
    found: list[tuple[str, str, str | None, bool, str]] = []
    for node in tree.body:
        if not isinstance(node, ast.ClassDef):
            continue
        description, label = _described(node)
        for member in node.body:
            if not (isinstance(member, ast.FunctionDef) and member.name == "modifyDescription"
                    and len(member.args.args) == 2 and description is not None):
                continue
            me, wrapper = member.args.args[0].arg, member.args.args[1].arg
            for call in walk(member):
                if not (isinstance(call, ast.Call) and isinstance(call.func, ast.Attribute)
                        and call.func.attr == "addParam" and call.args
                        and isinstance(call.func.value, ast.Name)
                        and call.func.value.id in (me, wrapper)
                        and isinstance(call.args[0], ast.Constant)
                        and isinstance(call.args[0].value, str)):
                    continue
                found.append((description, call.args[0].value, _element_type(call),
                              call.func.value.id == wrapper, label))
    return found


def _element_type(call: ast.Call) -> str | None:
    value = call.args[1] if len(call.args) > 1 else None
    if isinstance(value, ast.Call) and ast_dotted_name(value.func) in ("Element",) \
            and value.args and isinstance(value.args[0], ast.Constant) \
            and isinstance(value.args[0].value, str):
        return value.args[0].value
    return None


IMPLEMENTATION_BASES = frozenset({"SkillBase", "PrimitiveBase", "PrimitiveThreadBase",
                                  "PrimitiveActionClient"})
"""SkiROS2's bases of skill implementations (``skiros2_skill.core.skill``,
``skiros2_common.core.primitive``, ``skiros2_std_skills``): a class deriving from one is
a plugin the skill manager may instantiate (``SkillInstanciator.add_instance``)."""
DESCRIBING_CALLS = frozenset({
    "addParam", "addPreCondition", "addHoldCondition", "addPostCondition",
    "getRelationCond", "getAbstractRelationCond", "getPropCond", "getHasPropCond",
    "getIsSpecifiedCond", "getGenerateCond", "getOnTypeCond", "getParamCond"})
"""``self`` methods a ``createDescription`` may call that never set the description."""


def undescribed(tree: ast.Module) -> list[tuple[str, int, tuple[str, ...]]]:
    """``(class, line, bases)`` of the module's top-level classes that derive from a named
    class and define a ``createDescription`` that never calls ``setDescription``, read in
    full: no ``raise`` (an abstract base), no ``super()``, no call of a helper that might
    call it (a ``self`` method other than SkiROS2's description builders, a function of
    the module, any call given ``self``), no assignment to an attribute. Whether the class
    is an implementation (its bases reach SkiROS2's, ``IMPLEMENTATION_BASES``) and a leaf
    is for the caller, which knows every class of the repository."""
    found = []
    for node in tree.body:
        if not isinstance(node, ast.ClassDef):
            continue
        bases = tuple(name.rpartition(".")[2] for name in map(ast_dotted_name, node.bases)
                      if name is not None)
        creates = [m for m in node.body if isinstance(m, ast.FunctionDef)
                   and m.name == "createDescription"]
        if bases and creates and _never_describes(creates[-1]):
            found.append((node.name, node.lineno, bases))
    return found


def _never_describes(method: ast.FunctionDef) -> bool:
    """Whether ``createDescription`` certainly never calls ``setDescription`` (see
    ``undescribed``)."""
    if not method.args.args:
        return False
    me = method.args.args[0].arg
    for node in nodes(method):
        if isinstance(node, (ast.Raise, ast.Global, ast.Nonlocal, ast.Lambda)) or (
                isinstance(node, ast.Attribute) and isinstance(node.ctx, (ast.Store, ast.Del))):
            return False
        if isinstance(node, ast.Name) and node.id in ("super", "setattr", "getattr", "exec",
                                                        "eval", "__class__"):
            return False
        if isinstance(node, ast.Attribute) and node.attr in ("setDescription", "__class__"):
            return False
        if not isinstance(node, ast.Call):
            continue
        if any(isinstance(a, ast.Name) and a.id == me
               for a in (*node.args, *(k.value for k in node.keywords))):
            return False
        func = node.func
        if isinstance(func, ast.Attribute) and isinstance(func.value, ast.Name) \
                and func.value.id == me and func.attr not in DESCRIBING_CALLS:
            return False
        if isinstance(func, ast.Name) and func.id not in _HARMLESS \
                and not func.id.startswith("Condition"):
            return False
        if not isinstance(func, (ast.Name, ast.Attribute)):
            return False
    return True


_HARMLESS = frozenset({"Element", "print", "str", "int", "float", "bool", "list", "dict",
                       "tuple", "set", "len", "range", "repr", "format"})
"""Functions a ``createDescription`` may call that cannot set the description."""


def implementation_classes(tree: ast.Module) -> set[str]:
    """Names of the module's implementation classes (their ``createDescription`` calls
    ``setDescription``): whatever label they register, they are no descriptions."""
    return {cls.name for _, cls in described_classes(tree)}


def _described(cls: ast.ClassDef) -> tuple[str | None, str]:
    """``self.setDescription(Desc(), label)`` in the class's ``createDescription``
    (``self.__class__.__name__`` or anything computed counts as the class's name). Only the
    body's own statements are read: that is where SkiROS2 code calls it, and walking every
    description's body for a call that is not there would cost more than the reading."""
    for member in cls.body:
        if isinstance(member, ast.FunctionDef) and member.name == "createDescription":
            for statement in member.body:
                found = _set_description(statement.value, cls.name) \
                    if isinstance(statement, ast.Expr) else None
                if found is not None:
                    return found
    return None, cls.name


def _set_description(node: ast.expr, name: str) -> tuple[str | None, str] | None:
    """``(description, label)`` of a ``setDescription`` call, None for any other node.

    Its arguments are read as Python binds them to ``setDescription(description,
    label="")``: by position or by keyword (``description=Problem1(), label="x"``), so
    that a class written either way implements the same description. A label that is not
    a literal string (``self.__class__.__name__``) is the class's name."""
    if not (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
            and node.func.attr == "setDescription"):
        return None
    keywords = {k.arg: k.value for k in node.keywords if k.arg is not None}
    first = node.args[0] if node.args else keywords.get("description")
    if first is None:
        return None
    label = node.args[1] if len(node.args) > 1 else keywords.get("label")
    kind = ast_dotted_name(first.func if isinstance(first, ast.Call) else first)
    described = kind and kind.rpartition(".")[2]
    if isinstance(label, ast.Constant) and isinstance(label.value, str):
        return described, label.value
    return described, name


class _Reader:
    """One literal ``expand`` body; ``bound``: the names the module and ``expand`` bind
    (None: a star import may bind any)."""

    def __init__(self, expand: ast.FunctionDef, bound: frozenset[str] | None = None) -> None:
        args = expand.args.args
        if len(args) != 2:
            raise _Computed("expand does not take (self, skill)")
        self.self_name, self.root = args[0].arg, args[1].arg
        self.body = expand.body
        self.bound = None if bound is None else bound | _bound_in(expand)
        self.problems: list[CallProblem] = []
        self.tolerant = False
        """Reading the nodes of a statement that is not literal (``_loose``): a value
        computed at run time is ``COMPUTED``, a pair with a computed key is left out."""

    def read(self) -> tuple[str, tuple[Node | CallProblem, ...], tuple[tuple[int, str], ...]]:
        """The tree's processor and children, and the statements it could not read (line,
        why): each statement is read on its own, so one that computes its part of the
        tree (a loop, a branch, a world-model query) leaves the others' nodes read."""
        processor = "Sequential"
        children: list[Node | CallProblem] = []
        gaps: list[tuple[int, str]] = []
        for index, stmt in enumerate(self.body):
            if index == 0 and isinstance(stmt, ast.Expr) \
                    and isinstance(stmt.value, ast.Constant):
                continue  # docstring
            if isinstance(stmt, ast.Pass):
                continue
            try:
                processor, children = self._statement(stmt, processor, children)
            except _Computed as computed:
                gaps.append((stmt.lineno, str(computed)))
                children += self._loose(stmt)
        return processor, (*children, *self.problems), tuple(gaps)

    def _loose(self, stmt: ast.stmt) -> list[Node | CallProblem]:
        """The literal ``self.skill(...)`` calls inside a statement the tree cannot be read
        from (a loop, a branch): where they go in the tree is not known, but each node is,
        and its own checks (its type, label, remaps and specifies) hold wherever it goes."""
        found: list[Node | CallProblem] = []
        self.tolerant = True
        try:
            self._walk_loose(stmt, found)
        finally:
            self.tolerant = False
        return found

    def _walk_loose(self, stmt: ast.stmt, found: list[Node | CallProblem]) -> None:
        for call in walk(stmt):
            if not isinstance(call, ast.Call):
                continue
            try:
                if self._is_skill_call(call):
                    found.append(self._skill(call, ()))
                elif isinstance(call.func, ast.Attribute) and call.func.attr == "setProcessor" \
                        and len(call.args) == 1:
                    self._processor(call.args[0])  # for an undefined processor's problem
            except _Computed:
                continue

    def _statement(self, stmt: ast.stmt, processor: str, children: list[Node | CallProblem]
                   ) -> tuple[str, list[Node | CallProblem]]:
        """The processor and children after one statement (``_Computed``: not literal)."""
        call = stmt.value if isinstance(stmt, ast.Expr) else None
        if not isinstance(call, ast.Call) or call.keywords:
            raise _Computed(f"line {stmt.lineno} is {shape_of(stmt)}")
        func = call.func
        if isinstance(func, ast.Attribute) and func.attr == "setProcessor" \
                and self._is_root(func.value) and len(call.args) == 1:
            return self._processor(call.args[0]), children
        if isinstance(func, ast.Attribute) and func.attr == "setProcessor" \
                and self._is_self(func.value) and len(call.args) == 1:
            self._processor(call.args[0])  # the instance's, not the tree's: SkiROS2
            # copied it to the node before ``expand`` (``SkillWrapper.setInstance``)
            return processor, children
        if self._is_root(func):
            return processor, [*children, *(self._node(a) for a in call.args)]
        raise _Computed(f"line {stmt.lineno} is not a literal tree statement")

    def _is_root(self, node: ast.expr) -> bool:
        return isinstance(node, ast.Name) and node.id == self.root

    def _is_self(self, node: ast.expr) -> bool:
        return isinstance(node, ast.Name) and node.id == self.self_name

    def _is_skill_call(self, node: ast.expr) -> bool:
        return isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) \
            and node.func.attr == "skill" and isinstance(node.func.value, ast.Name) \
            and node.func.value.id == self.self_name

    def _node(self, node: ast.expr) -> Node | CallProblem:
        if isinstance(node, ast.Starred):
            raise _Computed(f"line {node.lineno} adds children with *")
        if not isinstance(node, ast.Call):
            raise _Computed(f"line {node.lineno} adds a child computed at run time")
        if self._is_skill_call(node):
            return self._skill(node, ())
        if self._is_skill_call(node.func) and not node.keywords:
            assert isinstance(node.func, ast.Call)
            children = tuple(self._node(a) for a in node.args)
            return self._skill(node.func, children)
        raise _Computed(f"line {node.lineno} adds a child computed at run time")

    def _skill(self, call: ast.Call, children: tuple[Node | CallProblem, ...]
               ) -> Node | CallProblem:
        if any(isinstance(a, ast.Starred) for a in call.args) \
                or any(k.arg is None for k in call.keywords):
            raise _Computed(f"line {call.lineno} passes computed arguments")
        problem = syntax_problem(call)
        if problem is not None:
            return CallProblem(problem, call.lineno)
        bound: dict[str, ast.expr] = dict(zip(ARGUMENTS, call.args, strict=False))
        for keyword in call.keywords:
            if keyword.arg not in ARGUMENTS or keyword.arg in bound:
                raise _Computed(f"line {call.lineno} passes unusual keywords")
            bound[keyword.arg] = keyword.value
        first = bound.get("stype")
        if first is not None and self._is_skill_call(first):
            return CallProblem("self.skill(self.skill(...), ...) passes a node where "
                               "SkiROS2 wants a type name or a processor; call the node "
                               "instead: self.skill(...)(child, ...)", call.lineno)
        remap = tuple((k, COMPUTED if isinstance(v, dict) and COMPUTED in v else str(v))
                      for k, v in self._pairs(bound.get("remap"), call))
        specify = self._pairs(bound.get("specify"), call)
        if isinstance(first, ast.Constant) and isinstance(first.value, str):
            label = self._literal(bound["slabel"], call) if "slabel" in bound else ""
            pre = bound.get("preconditions")
            if pre is not None and not (isinstance(pre, (ast.List, ast.Tuple)) and not pre.elts):
                raise _Computed(f"line {call.lineno} passes preconditions")
            return SkillNode(first.value, label if isinstance(label, str) else repr(label),
                             remap, specify, (), children, call.lineno)
        if isinstance(first, ast.Call) and not first.keywords:
            return ProcessorNode(self._processor(first), children, remap, specify,
                                 call.lineno)
        if isinstance(first, ast.Constant):
            return CallProblem(f"self.skill({first.value!r}) is neither a type name nor a "
                               "processor", call.lineno)
        raise _Computed(f"line {call.lineno} names the child with a computed value")

    def _processor(self, node: ast.expr) -> str:
        if not isinstance(node, ast.Call) or node.keywords:
            raise _Computed(f"line {node.lineno} sets a processor computed at run time")
        name = ast_dotted_name(node.func)
        if name is None or len(node.args) > 1:
            raise _Computed(f"line {node.lineno} sets a processor computed at run time")
        if self.bound is not None and name.split(".")[0] not in self.bound:
            self.problems.append(CallProblem(
                f"processor {name} is defined nowhere in the module (no class, import or "
                "assignment of that name): expand raises NameError when it runs, and the "
                "compound skill fails", node.lineno, "processor-undefined",
                name.rpartition(".")[2]))
        base = name.rpartition(".")[2]
        return f"{base}({self._processor(node.args[0])})" if node.args else base

    def _pairs(self, node: ast.expr | None, call: ast.Call) -> tuple[tuple[str, Any], ...]:
        if node is None or _empty(node):
            return ()  # SkiROS2 iterates them: remap="" or [] is none
        if not isinstance(node, ast.Dict) or any(k is None for k in node.keys):
            if self.tolerant:
                return ()
            raise _Computed(f"line {call.lineno} passes a computed remap or specify")
        pairs = []
        for key, value in zip(node.keys, node.values, strict=True):
            assert key is not None
            try:
                name = self._literal(key, call)
                if not isinstance(name, str):
                    raise _Computed(f"line {call.lineno} has a non-string key")
                pairs.append((name, self._value(value, call)))
            except _Computed:
                if not self.tolerant or not isinstance(key, ast.Constant) \
                        or not isinstance(key.value, str):
                    if self.tolerant:
                        continue  # a computed key: that pair is not known
                    raise
                pairs.append((key.value, {COMPUTED: True}))
        if len({k for k, _ in pairs}) != len(pairs):
            raise _Computed(f"line {call.lineno} repeats a key")  # Python keeps the last
        return tuple(pairs)

    def _value(self, node: ast.expr, call: ast.Call) -> Any:
        """A literal, ``{"param": "X"}`` for ``self.params["X"].value``, or
        ``{"parameter_object": "X"}`` for ``self.params["X"]`` (a mistake checks report)."""
        key = _params_key(node, self.self_name)
        if key is not None:
            return {PARAMETER_OBJECT: key}
        if isinstance(node, ast.Attribute) and node.attr == "value" \
                and isinstance(node.value, ast.Subscript) \
                and isinstance(node.value.value, ast.Attribute) \
                and node.value.value.attr == "params" \
                and isinstance(node.value.value.value, ast.Name) \
                and node.value.value.value.id == self.self_name:
            key = self._literal(node.value.slice, call)
            if isinstance(key, str):
                return {"param": key}
        return self._literal(node, call)

    def _literal(self, node: ast.expr, call: ast.Call) -> Any:
        try:
            value = ast.literal_eval(node)
        except (ValueError, TypeError, SyntaxError, MemoryError, RecursionError):
            raise _Computed(f"line {call.lineno} passes a value computed at run time") \
                from None
        if isinstance(value, (tuple, set, bytes, complex)):
            raise _Computed(f"line {call.lineno} passes a value JSON cannot hold")
        return value


def _empty(node: ast.expr) -> bool:
    """``""``, ``[]``, ``()``, ``{}``, ``set()``: iterables SkiROS2 reads as no remap."""
    if isinstance(node, ast.Constant):
        return node.value in ("", b"")
    if isinstance(node, (ast.List, ast.Tuple, ast.Set)):
        return not node.elts
    if isinstance(node, ast.Dict):
        return not node.keys
    return isinstance(node, ast.Call) and isinstance(node.func, ast.Name) \
        and node.func.id in ("set", "dict", "list", "tuple") and not node.args \
        and not node.keywords


def _params_key(node: ast.expr, self_name: str) -> str | None:
    """``X`` for ``self.params["X"]`` (the parameter object, not its value)."""
    if isinstance(node, ast.Subscript) and isinstance(node.value, ast.Attribute) \
            and node.value.attr == "params" and isinstance(node.value.value, ast.Name) \
            and node.value.value.id == self_name:
        key = node.slice
        if isinstance(key, ast.Constant) and isinstance(key.value, str):
            return key.value
        return ast.unparse(key)
    return None


def syntax_problem(call: ast.Call) -> str | None:
    """What makes this ``self.skill(...)`` call raise whatever ``expand`` computes: the
    tracer's ``call_problem``, read from the syntax (keywords, argument count, a literal
    string as remap or specify)."""
    keywords = {k.arg: k.value for k in call.keywords if k.arg is not None}
    bound: dict[str, Any] = {}
    for name, value in [*zip(ARGUMENTS, call.args, strict=False), *keywords.items()]:
        if isinstance(value, ast.Constant):
            bound[name] = value.value
    return call_problem(keywords, bound, len(call.args))


def expand_findings(tree: ast.Module) -> dict[str, list[Finding]]:
    """``{class: [finding]}``: mistakes in every ``self.skill(...)`` call of a
    compound class's ``expand``, read from the syntax alone, so that they are reported even
    when the tree can be neither read nor traced (a branch on the world model). Readable
    trees report the same mistakes from their model."""
    found: dict[str, list[Finding]] = {}
    for cls in compound_classes(tree):
        expand = [m for m in cls.body if isinstance(m, ast.FunctionDef)
                  and m.name == "expand"][-1]
        if not expand.args.args:
            continue
        me = expand.args.args[0].arg
        for node in walk(expand):
            if not (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
                    and node.func.attr == "skill" and isinstance(node.func.value, ast.Name)
                    and node.func.value.id == me):
                continue
            problem = syntax_problem(node)
            if problem is not None:
                found.setdefault(cls.name, []).append(compound_finding(
                    "compound-call-shape", node.lineno, problem, cls.name))
            for key in _specified_objects(node, me):
                found.setdefault(cls.name, []).append(compound_finding(
                    "specify-parameter-object", node.lineno, parameter_object_message(key),
                    cls.name))
    return found


def _specified_objects(call: ast.Call, me: str) -> list[str]:
    """Keys of ``self.params[...]`` given as ``specify`` values without ``.value``."""
    given = [k.value for k in call.keywords if k.arg == "specify"] + call.args[3:4]
    found = []
    for value in given:
        if isinstance(value, ast.Dict):
            found += [k for k in (_params_key(v, me) for v in value.values) if k is not None]
    return found

