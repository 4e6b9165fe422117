"""An EzSkiROS file read without running it: the runtime's tracing, on the syntax tree.

``check`` is the gate a lab runs on strangers' pull requests, so it never imports the code
it judges (pylint's and ruff's rule). Legacy descriptions are read from their syntax; this
module does the same for EzSkiROS ones (docs/dsl.md). The signature of ``description`` and
the body's ``self.pre_conditions += ...`` statements are evaluated by a small interpreter
that knows literals, the names the module imports from ``ezskiros_runtime`` and the
parameters of the description, and nothing else. Every value it handles is a literal it
built or an object of the runtime (a ``Symbol``, a ``Cond``, an OWL class, a kind marker),
so every operator and method it applies is the runtime's own code: the same
``Symbol.__getattr__`` resolves ``A.contain`` against the ontology, the same ``run_checks``
gives the findings, and the same lowering through the legacy backend gives the model that
loading the module would give.

What the interpreter does not know (a helper function, a loop, a name imported from the
lab's own modules) is not guessed: the description is reported as not read, naming the
shape, and ``check --trace`` loads the module as before.
"""

from __future__ import annotations

import ast
import importlib
import operator
import types
import typing
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from typing import Any

from ezskiros_runtime.diagnostics import DescriptionError, Finding, class_error
from ezskiros_runtime.legacy.errors import ModuleLoadError

from ..codemod.core.ast_walk import walk
from ..verify.protocol import LoadOutcome

RUNTIME = "ezskiros_runtime"
ONTOLOGY = "ezskiros_runtime.ontology"
_COLLECTORS = {"pre_conditions": "pre", "hold_conditions": "hold", "post_conditions": "post"}
_BUILTIN_TYPES: dict[str, Any] = {t.__name__: t for t in
                                  (float, int, str, bool, dict, list, tuple, bytes)}
_LITERAL_TYPES = (int, float, complex, str, bytes, bool, type(None))
_TYPING = (typing.List, typing.Dict)  # noqa: UP006 - the objects, not annotations
"""``typing``'s aliases, which annotations of the robot's Python 3.8 subscript."""
_COMPARISONS: dict[type, Callable[[Any, Any], Any]] = {
    ast.Eq: operator.eq, ast.NotEq: operator.ne, ast.Lt: operator.lt, ast.LtE: operator.le,
    ast.Gt: operator.gt, ast.GtE: operator.ge}
"""The comparisons the DSL's property conditions are written with (``F.Open == False``)."""
_MAX_LITERAL = 10_000
"""Longest string or collection the interpreter builds (``"x" * 10**9`` is refused)."""


class Unreadable(Exception):
    """A construct the static reading does not evaluate; ``shape`` says which."""

    def __init__(self, node: ast.AST, shape: str) -> None:
        super().__init__(shape)
        self.line = getattr(node, "lineno", 0)
        self.shape = shape


class _Opaque:
    """A name the module binds to something not read (a lab module's import, a function):
    using it makes the description unreadable, naming where it came from."""

    def __init__(self, name: str, origin: str) -> None:
        self.name = name
        self.origin = origin


class RaisedAt(Exception):
    """What the runtime raised while a statement of ``description`` was evaluated, with
    that statement's line (the loader names the line of the user's frame)."""

    def __init__(self, exc: BaseException, line: int) -> None:
        super().__init__(str(exc))
        self.exc = exc
        self.line = line


class _Self:
    """``self`` inside ``description``: its collectors and ``self.param``."""


@dataclass
class _Class:
    """A class of the module, as the interpreter knows it."""

    node: ast.ClassDef
    bases: list[Any]


@dataclass
class StaticLoad:
    """What loading the module would have given, read from its syntax: the loader's
    ``status`` (``ok``, or ``import-error`` when the module itself would fail), models as
    ``SkillModel.to_json()`` dicts, class errors and findings; ``unread`` the classes that
    are or may be descriptions and could not be read, with the shape that stopped it."""

    status: str = "ok"
    message: str = ""
    line: int | None = None
    models: list[dict[str, Any]] = field(default_factory=list)
    errors: list[Finding] = field(default_factory=list)
    findings: list[Finding] = field(default_factory=list)
    unread: list[tuple[str, int, str]] = field(default_factory=list)
    maybe: list[tuple[str, int]] = field(default_factory=list)
    """Classes whose base comes from another module: descriptions perhaps, whose keys are
    not known (the skill index takes them as types it does not judge)."""

    def outcome(self) -> LoadOutcome:
        """As the loader's outcome, which every pass after the loading reads."""
        shaped = {name for name, _, _ in self.unread}
        return LoadOutcome(
            "ok" if self.status == "ok" else "import-error", self.message, self.line,
            models=self.models, errors=self.errors, findings=self.findings,
            unread=[*self.unread, *((n, line, "") for n, line in self.maybe
                                    if n not in shaped)])


def read_ezskiros_statically(tree: ast.Module, path: str) -> StaticLoad:
    """The descriptions of an EzSkiROS module (``tree``, the file ``path``), checked by the
    runtime's early checks against the active ontology, without running the module."""
    module = _Module(path, tree)
    try:
        module.bind()
    except _ImportFailure as failure:
        return StaticLoad("import-error", failure.message, failure.line)
    result = StaticLoad()
    for name, klass in module.classes.items():
        module.read_class(name, klass, result)
    return result


class _ImportFailure(Exception):
    """The module itself would fail to import (an unknown prefix, an annotation naming an
    unknown class without ``from __future__ import annotations``)."""

    def __init__(self, path: str, line: int, exc: BaseException) -> None:
        error = ModuleLoadError(path, line, type(exc).__name__, str(exc) or repr(exc))
        super().__init__(str(error))
        self.message = str(error)
        self.line = line


class _Module:
    """One module's top-level names, as far as the syntax settles them."""

    def __init__(self, path: str, tree: ast.Module) -> None:
        self.path = path
        self.tree = tree
        self.names: dict[str, Any] = dict(_BUILTIN_TYPES)
        self.names.update({"True": True, "False": False, "None": None})
        self.classes: dict[str, _Class] = {}
        self.lazy_annotations = False

    # -- the module's names --------------------------------------------------------------

    def bind(self) -> None:
        """Bind every top-level name in order; a statement that is not read binds its names
        to ``_Opaque``. Raises ``_ImportFailure`` where importing the module would fail."""
        for node in self.tree.body:
            if isinstance(node, ast.ImportFrom):
                self._import_from(node)
            elif isinstance(node, ast.Import):
                for alias in node.names:
                    self._import(node, alias)
            elif isinstance(node, ast.ClassDef):
                self._class(node)
            elif isinstance(node, (ast.Assign, ast.AnnAssign)) and node.value is not None:
                self._assign(node)
            else:
                for name in _bound_names(node):
                    self.names[name] = _Opaque(name, f"line {node.lineno}")

    def _import_from(self, node: ast.ImportFrom) -> None:
        module = node.module or ""
        if node.level == 0 and module == "__future__":
            self.lazy_annotations |= any(a.name == "annotations" for a in node.names)
            return
        trusted = node.level == 0 and (module == RUNTIME or module.startswith(RUNTIME + ".")
                                       or module == "typing")
        for alias in node.names:
            bound = alias.asname or alias.name
            if alias.name == "*" or not trusted:
                if alias.name != "*":
                    self.names[bound] = _Opaque(bound, f"{'.' * node.level}{module}")
                continue
            try:
                imported = importlib.import_module(module)
                self.names[bound] = getattr(imported, alias.name)
            except Exception as exc:  # an unknown prefix: importing the module fails
                raise _ImportFailure(self.path, node.lineno, _as_import_error(exc)) from exc

    def _import(self, node: ast.Import, alias: ast.alias) -> None:
        name = alias.name
        if name == RUNTIME or name.startswith(RUNTIME + ".") or name == "typing":
            try:
                imported = importlib.import_module(name)
            except Exception as exc:
                raise _ImportFailure(self.path, node.lineno, exc) from exc
            if alias.asname:
                self.names[alias.asname] = imported
            else:
                self.names[name.split(".")[0]] = importlib.import_module(name.split(".")[0])
            return
        bound = alias.asname or name.split(".")[0]
        self.names[bound] = _Opaque(bound, name)

    def _assign(self, node: ast.Assign | ast.AnnAssign) -> None:
        targets = node.targets if isinstance(node, ast.Assign) else [node.target]
        try:
            value = _Evaluator(self.names).value(node.value) \
                if node.value is not None else None
        except Exception:  # Unreadable included: a name not read
            value = _Opaque("", f"line {node.lineno}")
        for target in targets:
            if isinstance(target, ast.Name):
                self.names[target.id] = value if not isinstance(value, _Opaque) \
                    else _Opaque(target.id, f"line {node.lineno}")
            else:
                for name in _target_names(target):
                    self.names[name] = _Opaque(name, f"line {node.lineno}")

    def _class(self, node: ast.ClassDef) -> None:
        bases: list[Any] = []
        for base in node.bases:
            local = self.names.get(base.id) if isinstance(base, ast.Name) else None
            if isinstance(local, _Class):
                bases.append(local)
                continue
            try:
                bases.append(_Evaluator(self.names).value(base))
            except Exception:  # Unreadable included: a name not read
                bases.append(_Opaque(ast.unparse(base), f"line {node.lineno}"))
        klass = _Class(node, bases)
        self.names[node.name] = klass
        self.classes[node.name] = klass
        if not self.lazy_annotations and self._is_description(klass):
            description = _own_description(node)
            if description is not None:  # annotations are evaluated when ``def`` runs
                for arg in _parameters(description):
                    if arg.annotation is not None and not isinstance(arg.annotation,
                                                                     ast.Constant):
                        self._annotation_at_import(arg.annotation)

    def _annotation_at_import(self, annotation: ast.expr) -> None:
        """Evaluate an annotation as ``def`` does at import: a runtime error there (an
        unknown class of a known prefix) fails the whole module, as it would loading it."""
        try:
            _Evaluator(self.names).value(annotation)
        except Unreadable:
            return  # decided later, when the class is read
        except Exception as exc:
            raise _ImportFailure(self.path, annotation.lineno, exc) from exc

    # -- the classes -------------------------------------------------------------------

    def _is_description(self, klass: _Class) -> bool | None:
        """True for an EzSkiROS description class, False for any other class, None when a
        base is not known (a class of another module)."""
        from ezskiros_runtime.dsl.skill import SkillDescription

        unknown = False
        for base in klass.bases:
            if base is SkillDescription:
                return True
            if isinstance(base, _Class):
                found = self._is_description(base)
                if found:
                    return True
                unknown |= found is None
            elif isinstance(base, _Opaque):
                unknown = True
        return None if unknown else False

    def _description_of(self, klass: _Class) -> ast.FunctionDef | _Opaque | None:
        """The ``description`` the class defines or inherits (``find_description``): a
        local class's, or ``_Opaque`` when it may come from a base of another module."""
        own = _own_description(klass.node)
        if own is not None:
            return own
        for base in klass.bases:
            if isinstance(base, _Class):
                found = self._description_of(base)
                if found is not None:
                    return found
            elif isinstance(base, _Opaque):
                return base
        return None

    def read_class(self, name: str, klass: _Class, result: StaticLoad) -> None:
        """Add what loading would give of one class: its model and findings, its class
        error, or why it was not read."""
        described = self._is_description(klass)
        line = klass.node.lineno
        if described is False:
            return
        description = self._description_of(klass)
        if described is None or isinstance(description, _Opaque):
            result.maybe.append((name, line))
            if described or _own_description(klass.node) is not None:
                base = next((b for b in klass.bases if isinstance(b, _Opaque)), None)
                origin = f"{base.name} from {base.origin}" if base is not None else "a base"
                result.unread.append((name, line, f"its base {origin} is another module's"))
            return
        if _overrides_create(klass.node):  # legacy code: the static pass reads it
            result.maybe.append((name, line))
            return
        try:
            traced = self._trace(name, description) if description is not None \
                else _Traced.empty(name, self.path, line)
            result.findings += traced.findings
            result.models.append(traced.model(line, self.path))
        except Unreadable as why:
            result.unread.append((name, why.line or line, why.shape))
        except (RecursionError, MemoryError):
            result.unread.append((name, line, "an expression nested too deeply to read"))
        except RaisedAt as raised:
            result.errors.append(_class_error(name, line, raised.exc, raised.line, self.path))
        except Exception as exc:  # what instantiating the class raises: a class error
            result.errors.append(_class_error(name, line, exc, None, self.path))

    def _owner(self, func: ast.FunctionDef) -> str:
        """The name of the class that defines ``func`` (a base's, when inherited)."""
        return next(name for name, klass in self.classes.items() if func in klass.node.body)

    def _trace(self, name: str, func: ast.FunctionDef) -> _Traced:
        """Steps (1), (2) and (5) of the lowering order on the syntax of ``func``."""
        from ezskiros_runtime.dsl.check_context import Trace
        from ezskiros_runtime.dsl.checking import run_checks
        from ezskiros_runtime.dsl.parameters import NO_DEFAULT, spec_of, star_parameters
        from ezskiros_runtime.dsl.symbols import Symbol

        evaluator = _Evaluator(self.names)
        specs = []
        lines: dict[str, int] = {}
        arguments = func.args
        if arguments.vararg is not None or arguments.kwarg is not None:
            raise star_parameters(f"{self._owner(func)}.{func.name}")
        for arg, default, keyword_only in _with_defaults(arguments)[1:]:
            annotation = None if arg.annotation is None else \
                evaluator.annotation(arg.annotation)
            value = NO_DEFAULT if default is None else evaluator.value(default)
            specs.append(spec_of(arg.arg, annotation, value, keyword_only))
            lines[arg.arg] = arg.lineno
        symbols = {spec.name: Symbol(spec.key) for spec in specs}
        body = _Body(self.path, {**self.names, **symbols}, func)
        recorded = body.run()
        trace = Trace(name, None, tuple(specs), tuple(recorded),
                      locations={n: (self.path, line) for n, line in lines.items()},
                      defined_at=(self.path, func.lineno))
        return _Traced(trace, run_checks(trace))


@dataclass
class _Traced:
    """A description read: its ``Trace`` and what the early checks found in it."""

    trace: Any
    findings: list[Finding]

    @classmethod
    def empty(cls, name: str, path: str, line: int) -> _Traced:
        """A class without ``description``: it declares nothing (docs/dsl.md)."""
        from ezskiros_runtime.dsl.check_context import Trace

        return cls(Trace(name, None, (), (), defined_at=(path, line)), [])

    def model(self, line: int, path: str) -> dict[str, Any]:
        """The model SkiROS2's own calls would build (``lower_all`` on the legacy backend),
        or the exception instantiating the class would raise."""
        from ezskiros_runtime.dsl.backend import legacy_backend
        from ezskiros_runtime.dsl.lowering import lower_checked
        from ezskiros_runtime.legacy.extract import model_of

        backend = legacy_backend()
        trace, findings = self.trace, self.findings

        def create(instance: Any) -> None:
            lower_checked(instance, trace.specs, trace.recorded, findings, backend)

        klass = type(trace.skill, (backend.SkillDescription,), {"createDescription": create})
        return dict(model_of(klass()).with_location(path, line).to_json())


class _Body:
    """The statements of ``description``: assignments to locals and ``+=`` to collectors."""

    def __init__(self, path: str, names: dict[str, Any], func: ast.FunctionDef) -> None:
        self.path = path
        self.func = func
        self.self_name = func.args.args[0].arg if func.args.args else "self"
        self.names = {**names, self.self_name: _Self()}
        self.recorded: list[Any] = []

    def run(self) -> list[Any]:
        body = self.func.body
        if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant) \
                and isinstance(body[0].value.value, str):
            body = body[1:]
        for statement in body:
            try:
                self._statement(statement)
            except Unreadable:
                raise
            except Exception as exc:  # raised by the runtime, as tracing would raise it
                raise RaisedAt(exc, statement.lineno) from exc
        return self.recorded

    def _statement(self, node: ast.stmt) -> None:
        evaluator = _Evaluator(self.names)
        if isinstance(node, ast.Pass):
            return
        if isinstance(node, ast.AugAssign) and isinstance(node.op, ast.Add) \
                and isinstance(node.target, ast.Attribute) \
                and isinstance(node.target.value, ast.Name) \
                and node.target.value.id == self.self_name \
                and node.target.attr in _COLLECTORS:
            self._record(_COLLECTORS[node.target.attr], evaluator.value(node.value), node)
            return
        if _harmless(node, self.self_name):
            return
        if isinstance(node, (ast.Assign, ast.AnnAssign)) and node.value is not None:
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            if all(isinstance(t, ast.Name) for t in targets):
                value = evaluator.value(node.value)
                for target in targets:
                    self.names[target.id] = value  # type: ignore[attr-defined]
                return
        raise Unreadable(node, f"the statement at line {node.lineno} of description is "
                               f"{shape_of(node)}")

    def _record(self, which: str, item: Any, node: ast.AugAssign) -> None:
        from ezskiros_runtime.dsl.collectors import record

        record(self.recorded, which, item, self.path, node.lineno)


class _Evaluator:
    """Expressions over literals and the runtime's objects; anything else is ``Unreadable``."""

    def __init__(self, names: dict[str, Any]) -> None:
        self.names = names

    def annotation(self, node: ast.expr) -> Any:
        """An annotation: a string one is parsed and evaluated as an expression, in the
        module's names (docs/dsl.md), as ``evaluate_signature`` does."""
        if isinstance(node, ast.Constant) and isinstance(node.value, str):
            parsed = ast.parse(node.value.strip(), mode="eval").body
            _relocate(parsed, node)
            node = parsed
        return self.value(node)

    def value(self, node: ast.expr) -> Any:
        method: Callable[[Any], Any] | None = getattr(self, f"_{type(node).__name__}", None)
        if method is None:
            raise Unreadable(node, shape_of(node))
        found = method(node)
        if isinstance(found, _Opaque):
            raise Unreadable(node, f"{found.name or 'a value'} is not read statically "
                                   f"(it comes from {found.origin})")
        return found

    def _Constant(self, node: ast.Constant) -> Any:
        return node.value

    def _Name(self, node: ast.Name) -> Any:
        if node.id not in self.names:
            raise Unreadable(node, f"the name {node.id} is defined nowhere the reading sees")
        found = self.names[node.id]
        if isinstance(found, _Class):
            raise Unreadable(node, f"the class {node.id} is used as a value")
        return found

    def _Attribute(self, node: ast.Attribute) -> Any:
        owner = self.value(node.value)
        if isinstance(owner, _Self):
            if node.attr == "param":
                return _bound_param
            raise Unreadable(node, f"self.{node.attr} is read in description")
        _trusted(owner, node)
        if node.attr.startswith("__"):
            raise Unreadable(node, f"the attribute {node.attr}")
        return getattr(owner, node.attr)

    def _Subscript(self, node: ast.Subscript) -> Any:
        owner = self.value(node.value)
        _trusted(owner, node)
        return owner[self.value(node.slice)]

    def _Call(self, node: ast.Call) -> Any:
        func = self.value(node.func)
        if func is not _bound_param and not _dsl_callable(func):
            name = getattr(func, "__name__", type(func).__name__)
            raise Unreadable(node, f"a call of {name}, which is no form of the DSL")
        args = []
        for arg in node.args:
            if isinstance(arg, ast.Starred):
                raise Unreadable(arg, "a starred argument")
            args.append(self.value(arg))
        kwargs = {}
        for keyword in node.keywords:
            if keyword.arg is None:
                raise Unreadable(keyword.value, "a ** argument")
            kwargs[keyword.arg] = self.value(keyword.value)
        return func(*args, **kwargs)

    def _UnaryOp(self, node: ast.UnaryOp) -> Any:
        operand = self.value(node.operand)
        if isinstance(node.op, ast.Invert):
            _trusted(operand, node)
            return ~operand
        if isinstance(node.op, (ast.USub, ast.UAdd)) and isinstance(operand, (int, float)):
            return -operand if isinstance(node.op, ast.USub) else +operand
        raise Unreadable(node, shape_of(node))

    def _BinOp(self, node: ast.BinOp) -> Any:
        left, right = self.value(node.left), self.value(node.right)
        if isinstance(node.op, ast.BitOr):
            _trusted(left, node)
            return left | right
        if isinstance(node.op, (ast.Add, ast.Sub)) and all(
                isinstance(v, (int, float)) and not isinstance(v, bool) for v in (left, right)):
            return left + right if isinstance(node.op, ast.Add) else left - right
        if isinstance(node.op, ast.Add) and isinstance(left, str) and isinstance(right, str) \
                and len(left) + len(right) <= _MAX_LITERAL:
            return left + right
        raise Unreadable(node, shape_of(node))

    def _Compare(self, node: ast.Compare) -> Any:
        if len(node.ops) != 1:
            raise Unreadable(node, "a chained comparison")
        left, right = self.value(node.left), self.value(node.comparators[0])
        _trusted(left, node)
        compare = _COMPARISONS.get(type(node.ops[0]))
        if compare is None:
            raise Unreadable(node, shape_of(node))
        return compare(left, right)

    def _List(self, node: ast.List) -> list[Any]:
        return [self.value(e) for e in self._sized(node.elts, node)]

    def _Tuple(self, node: ast.Tuple) -> tuple[Any, ...]:
        return tuple(self.value(e) for e in self._sized(node.elts, node))

    def _Set(self, node: ast.Set) -> set[Any]:
        return {self.value(e) for e in self._sized(node.elts, node)}

    def _Dict(self, node: ast.Dict) -> dict[Any, Any]:
        if any(k is None for k in node.keys):
            raise Unreadable(node, "a ** in a dict")
        return {self.value(k): self.value(v)
                for k, v in zip(self._sized(node.keys, node), node.values, strict=True)}

    def _JoinedStr(self, node: ast.JoinedStr) -> str:
        parts = []
        for part in node.values:
            if isinstance(part, ast.Constant):
                parts.append(str(part.value))
            elif isinstance(part, ast.FormattedValue) and part.format_spec is None \
                    and part.conversion == -1:
                value = self.value(part.value)
                if not isinstance(value, _LITERAL_TYPES):
                    raise Unreadable(part, "an f-string of a value that is no literal")
                parts.append(str(value))
            else:
                raise Unreadable(part, "an f-string with a format")
        return "".join(parts)

    @staticmethod
    def _sized(items: list[Any], node: ast.AST) -> list[Any]:
        if len(items) > _MAX_LITERAL:
            raise Unreadable(node, "a literal too long to read")
        return items


_NO_MODEL_EFFECT = frozenset({"setAvailableForPlanning"})
"""Methods of SkiROS2's ``SkillDescription`` a description may call that change neither its
parameters nor its conditions (``skill.py``)."""


def _harmless(node: ast.stmt, self_name: str) -> bool:
    """A statement of ``description`` that leaves the model as it is: an attribute of the
    instance set (``self._topic = ...``; not a collector), or a call of a method in
    ``_NO_MODEL_EFFECT``."""
    def on_self(target: ast.expr) -> bool:
        return isinstance(target, ast.Attribute) and isinstance(target.value, ast.Name) \
            and target.value.id == self_name and target.attr not in _COLLECTORS
    if isinstance(node, ast.Assign):
        return all(on_self(t) for t in node.targets)
    if isinstance(node, ast.AnnAssign):
        return on_self(node.target)
    if isinstance(node, ast.Expr) and isinstance(node.value, ast.Call):
        func = node.value.func
        return on_self(func) and isinstance(func, ast.Attribute) \
            and func.attr in _NO_MODEL_EFFECT
    return False


def _dsl_callable(func: Any) -> bool:
    """Whether calling ``func`` is a form of docs/dsl.md: a method of a parameter symbol,
    a property handle or a condition (``A.contain(B)``, ``F.Open.eq(x)``, ``c.named(...)``),
    or one of the DSL's functions and markers (``ELEMENT``, ``KEY``, ``DESC``,
    ``abstract``, ``any_of``). Any other callable of the runtime (``use_ontology``, say)
    is refused: a file under check must not change what the run checks the others with."""
    from ezskiros_runtime.dsl import conditions, markers, symbols

    owner = getattr(func, "__self__", None)
    if owner is not None and isinstance(owner, (symbols.Symbol, symbols.PropertyHandle,
                                                conditions.Cond)):
        return True
    if isinstance(func, symbols.PropertyHandle):
        return True
    return any(func is allowed for allowed in (markers.ELEMENT, markers.KEY, markers.DESC,
                                               conditions.abstract, conditions.any_of))


def _bound_param(key: Any) -> Any:
    """``self.param("k")``: the runtime's ``SkillDescription.param``."""
    from ezskiros_runtime.dsl.symbols import Symbol

    if not isinstance(key, str):
        raise DescriptionError(f"self.param(...) needs a str key, got {key!r}")
    return Symbol(key)


def _trusted(value: Any, node: ast.AST) -> None:
    """Raise ``Unreadable`` unless operating on ``value`` runs only the runtime's code or
    Python's own on literals: the reading must never call into the lab's code."""
    if isinstance(value, (*_LITERAL_TYPES, list, tuple, dict, set)):
        return
    if any(value is known for known in (*_BUILTIN_TYPES.values(), *_TYPING)):
        return
    if isinstance(value, types.ModuleType) and (
            value.__name__ == "typing" or value.__name__.startswith(RUNTIME)):
        return
    kind = value if isinstance(value, type) else type(value)
    module = getattr(kind, "__module__", "") or ""
    own = getattr(value, "__module__", "") or ""
    if module.startswith(RUNTIME) or module == "typing" or own == "typing" \
            or (callable(value) and own.startswith(RUNTIME)):
        return
    raise Unreadable(node, f"a value of type {kind.__name__}")


def _as_import_error(exc: BaseException) -> BaseException:
    """What ``from ezskiros_runtime.ontology import skirso`` raises: the runtime's
    ``UnknownPrefixError`` (an ImportError) for a prefix, Python's for anything else."""
    if isinstance(exc, ImportError):
        return exc
    return ImportError(str(exc))


def _class_error(name: str, line: int, exc: BaseException, raised_at: int | None,
                 path: str) -> Finding:
    """The loader's finding for a class of the file ``path`` whose instantiation raises
    ``exc``."""
    where = f" (line {raised_at})" if raised_at is not None else ""
    return class_error(name, line, f"{type(exc).__name__}: {str(exc) or repr(exc)}{where}",
                       path)


def _own_description(node: ast.ClassDef) -> ast.FunctionDef | None:
    found = None
    for item in node.body:
        if isinstance(item, ast.FunctionDef) and item.name == "description":
            found = item
        elif isinstance(item, ast.AsyncFunctionDef) and item.name == "description":
            found = None
    return found


def _overrides_create(node: ast.ClassDef) -> bool:
    return any(isinstance(item, (ast.FunctionDef, ast.AsyncFunctionDef))
               and item.name == "createDescription" for item in node.body)


def _parameters(func: ast.FunctionDef) -> list[ast.arg]:
    a = func.args
    return [*a.posonlyargs, *a.args, *a.kwonlyargs]


def _with_defaults(arguments: ast.arguments) -> list[tuple[ast.arg, ast.expr | None, bool]]:
    """(parameter, its default or None, keyword-only) of every parameter, ``self`` first."""
    positional = [*arguments.posonlyargs, *arguments.args]
    first = len(positional) - len(arguments.defaults)
    found: list[tuple[ast.arg, ast.expr | None, bool]] = [
        (arg, arguments.defaults[i - first] if i >= first else None, False)
        for i, arg in enumerate(positional)]
    found += [(arg, default, True)
              for arg, default in zip(arguments.kwonlyargs, arguments.kw_defaults,
                                          strict=True)]
    return found


def _bound_names(node: ast.stmt) -> Iterator[str]:
    """The names a statement that is not read may bind at module level."""
    for child in walk(node):
        if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            yield child.name
        elif isinstance(child, ast.Name) and isinstance(child.ctx, ast.Store):
            yield child.id
        elif isinstance(child, ast.alias):
            yield child.asname or child.name.split(".")[0]


def _target_names(target: ast.expr) -> Iterator[str]:
    for child in walk(target):
        if isinstance(child, ast.Name):
            yield child.id


def _relocate(node: ast.AST, at: ast.AST) -> None:
    """Line numbers of a string annotation's expression: the string's own."""
    for child in ast.walk(node):
        if hasattr(child, "lineno"):
            child.lineno = getattr(at, "lineno", 0)


_SHAPES: dict[type, str] = {
    ast.For: "a loop", ast.While: "a loop", ast.If: "a branch (if)",
    ast.Try: "a try statement", ast.With: "a with statement",
    ast.Expr: "an expression statement (a call)", ast.Return: "a return",
    ast.Lambda: "a lambda", ast.ListComp: "a comprehension",
    ast.GeneratorExp: "a generator", ast.IfExp: "a conditional expression",
    ast.BoolOp: "a boolean operator (and/or)", ast.Assign: "an assignment",
    ast.AnnAssign: "an assignment", ast.AugAssign: "an assignment",
    ast.FunctionDef: "a function definition", ast.Call: "a call"}


def shape_of(node: ast.AST) -> str:
    """A statement or expression the reading does not evaluate, as a reader would name it."""
    for kind, name in _SHAPES.items():
        if isinstance(node, kind):
            return name
    return f"a {type(node).__name__} the static reading does not evaluate"


__all__ = ["StaticLoad", "Unreadable", "read_ezskiros_statically", "shape_of"]
