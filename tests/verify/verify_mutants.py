"""Single-field mutants of migrated EzSkiROS descriptions, for the mutation test.

A mutant changes exactly one field of one parameter or condition of one skill in the
migrated source: a parameter's kind, class or type, default, description, options, key or
position; a condition's list, negation (``~``), subject/object order, relation or property,
operator, value (or only its type: ``1`` vs ``1.0``), label, kind, subject, position, or
its presence (dropped, duplicated); an or-condition's negation, children and their order.
Mutants that are the same description by construction are never made: ``REQUIRED[T]``
is not offered for a bare ``T``, options are only added to elements (SkiROS2 ignores them
on values), a relation is not reversed when subject and object are the same parameter, and
two conditions are only swapped when the original models of the two differ.

Mutants are made as text splices at libcst positions of the original source (cheap: a few
thousand per run), each one as a *clone class* ``<Skill>__m<N>(<Skill>)`` whose
``description`` method is the original one with the splice. The legacy side gets the same
clone names as ``class <Skill>__m<N>(<Skill>): pass``, so the comparison of the two loads
matches every mutant with its legacy original by name, and all mutants of a file are
loaded in one child: one verification job per side and file, not per mutant.
"""

from __future__ import annotations

import ast
import json
from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field
from typing import Any

import libcst as cst
from libcst.metadata import MetadataWrapper, PositionProvider

from ezskiros_runtime.model import Condition, SkillModel

KINDS = ("REQUIRED", "OPTIONAL", "INFERRED")
TYPE_OBJECTS = {"float": "int", "int": "float", "str": "bool", "bool": "str", "dict": "list",
                "list": "dict"}
OTHER_CLASSES = {"skiros": ("Location", "Product"), "rparts": ("GripperEffector", "ArmDevice"),
                 "cora": ("Robot", "RobotGroup"), "sumo": ("Agent", "Artifact"),
                 "corax": ("Design", "DesignObject")}
OTHER_RELATION = {"contain": "at", "at": "contain"}
OTHER_PROPERTY = {"ContainerState": "StateProperty"}
OTHER_OPERATOR = {"==": ">=", ">=": ">", ">": "<", "<": "<=", "<=": "==",
                  "=": ">=", "!=": "=="}
METHOD_OPERATORS = {"eq": "=", "gt": ">", "lt": "<", "ge": ">=", "le": "<="}
"""``F.Open.eq(False)``: the method of a property handle for each SkiROS2 operator."""
OPERATOR_METHODS = {**{op: m for m, op in METHOD_OPERATORS.items()}, "==": "eq"}
LISTS = ("pre_conditions", "hold_conditions", "post_conditions")
ALIAS = "_mut_"
"""Prefix of the names the mutants use for DSL names and namespaces (imported once per
file under these aliases, so a module's own aliases never matter)."""
DSL_IMPORTS = ("REQUIRED", "OPTIONAL", "INFERRED", "ELEMENT", "KEY", "DESC", "abstract",
               "Lock", "Consume", "Annotated")
NAMESPACES = tuple(OTHER_CLASSES)


@dataclass(frozen=True)
class Mutant:
    """One mutant: ``clone`` is its class name, ``method`` its ``description`` source."""

    module: str
    cls: str
    clone: str
    operator: str
    where: str
    method: str

    def describe(self) -> str:
        return f"{self.module}::{self.cls} {self.operator} at {self.where} (as {self.clone})"


@dataclass
class Skill:
    """A migrated description class and what its mutants are made of."""

    module: str
    name: str
    method: str
    """The ``description`` method's source, from the start of its ``def`` line."""
    mutants: list[Mutant] = field(default_factory=list)
    control: str = ""
    """Name of the unmutated clone (must verify equivalent: the harness itself is sound)."""


Splice = tuple[int, int, str]


class _Source:
    """The module text, libcst positions, and local names of the DSL and namespaces."""

    def __init__(self, data: bytes) -> None:
        wrapper = MetadataWrapper(cst.parse_module(data))
        self.module = wrapper.module
        self.positions = wrapper.resolve(PositionProvider)
        self.text = self.module.code
        starts = [0]
        for line in self.text.splitlines(keepends=True):
            starts.append(starts[-1] + len(line))
        self.line_starts = starts
        self.dsl: dict[str, str] = {}
        self.namespaces: dict[str, str] = {}
        for stmt in self.module.body:
            if not isinstance(stmt, cst.SimpleStatementLine):
                continue
            for small in stmt.body:
                if isinstance(small, cst.ImportFrom) and isinstance(small.names, Sequence):
                    source = self.module.code_for_node(small.module) if small.module else ""
                    for alias in small.names:
                        real = self.module.code_for_node(alias.name)
                        local = alias.asname.name.value if alias.asname else real  # type: ignore[union-attr]
                        if source == "ezskiros_runtime":
                            self.dsl[local] = real
                        elif source == "ezskiros_runtime.ontology":
                            self.namespaces[local] = real
        self.constants = _module_constants(self.text)

    def offset(self, line: int, column: int) -> int:
        return self.line_starts[line - 1] + column

    def span(self, node: cst.CSTNode) -> tuple[int, int]:
        pos = self.positions[node]
        return self.offset(pos.start.line, pos.start.column), \
            self.offset(pos.end.line, pos.end.column)

    def code(self, node: cst.CSTNode) -> str:
        start, end = self.span(node)
        return self.text[start:end]

    def dsl_name(self, node: cst.BaseExpression) -> str | None:
        """The DSL name a local ``Name`` stands for (``OPTIONAL``, ``abstract``...)."""
        return self.dsl.get(node.value) if isinstance(node, cst.Name) else None


def _module_constants(text: str) -> dict[str, Any]:
    """Top-level ``NAME = <literal>`` assignments (the last one wins, as at run time)."""
    constants: dict[str, Any] = {}
    for node in ast.parse(text).body:
        if isinstance(node, ast.Assign) and len(node.targets) == 1 \
                and isinstance(node.targets[0], ast.Name):
            try:
                constants[node.targets[0].id] = ast.literal_eval(node.value)
            except ValueError:
                constants.pop(node.targets[0].id, None)
    return constants


def changed_value(value: Any) -> Any:
    """A different value of exactly the same type (``None`` when there is none)."""
    if isinstance(value, bool):
        return not value
    if isinstance(value, int):
        return value + 1
    if isinstance(value, float):
        return value + 1.0 if abs(value) < 1e15 else value * 2
    if isinstance(value, str):
        return value + "x"
    if isinstance(value, list) and value:
        return [changed_value(value[0]), *value[1:]]
    if isinstance(value, dict):
        return {**value, "mutant": 1}
    return None


def retyped_value(value: Any) -> Any:
    """The same number as another type (``1`` -> ``1.0``, ``True`` -> ``1``), or ``None``."""
    if isinstance(value, bool):
        return int(value)
    if isinstance(value, int):
        return float(value)
    return None


def literal(value: Any) -> str:
    return json.dumps(value, ensure_ascii=False) if isinstance(value, str) else repr(value)


def other_vocabulary(text: str) -> str:
    """A different verbatim vocabulary string; ``skiros:x`` <-> ``:x`` resolve to the same
    IRI but SkiROS2 stores them verbatim, so even that must not be equivalent."""
    if text.startswith("skiros:"):
        return text[len("skiros"):]
    if text.startswith(":"):
        return "skiros" + text
    if ":" in text:
        return text + "2"
    return "skiros:" + text


def _apply(text: str, base: int, splices: Sequence[Splice]) -> str:
    for start, end, new in sorted(splices, reverse=True):
        text = text[:start - base] + new + text[end - base:]
    return text


# -- parameters ---------------------------------------------------------------------------


@dataclass
class _Param:
    node: cst.Param
    name: str
    key: str
    annotation: cst.BaseExpression | None
    default: cst.BaseExpression | None
    kind_node: cst.Name | None
    """The kind marker's ``Name`` (``OPTIONAL`` in ``OPTIONAL[...]`` or alone)."""
    type_node: cst.BaseExpression | None
    items: list[cst.BaseExpression]
    """Subscript items after the type (description, options, ``KEY``)."""
    element: str | None
    """The namespace-or-``ELEMENT`` kind of the type: ``ns``, ``ELEMENT`` or ``None``."""


def _read_param(src: _Source, node: cst.Param) -> _Param:
    annotation = node.annotation.annotation if node.annotation else None
    kind_node: cst.Name | None = None
    inner = annotation
    added: list[cst.BaseExpression] = []
    if isinstance(annotation, cst.Subscript) and src.dsl_name(annotation.value) == "Annotated":
        # ``Annotated[A, items...]`` is ``A`` with the items after its type (docs/dsl.md)
        parts = [e.slice.value for e in annotation.slice if isinstance(e.slice, cst.Index)]
        inner, added = parts[0], parts[1:]
    type_node: cst.BaseExpression | None = inner
    items: list[cst.BaseExpression] = []
    if isinstance(inner, cst.Subscript) and src.dsl_name(inner.value) in KINDS:
        assert isinstance(inner.value, cst.Name)
        kind_node = inner.value
        elements = [e.slice.value for e in inner.slice
                    if isinstance(e.slice, cst.Index)]
        type_node, items = elements[0], elements[1:]
    elif inner is not None and src.dsl_name(inner) in KINDS:
        assert isinstance(inner, cst.Name)
        kind_node, type_node = inner, None
        if added and _item_kind(src, added[0]) == "other" and src.dsl_name(added[0]) is None:
            type_node, added = added[0], added[1:]  # a bare kind: its first item is the type
    items = [*items, *added]
    element = None
    if isinstance(type_node, cst.Attribute) and isinstance(type_node.value, cst.Name) \
            and type_node.value.value in src.namespaces:
        element = src.namespaces[type_node.value.value]
    elif isinstance(type_node, cst.Call) and src.dsl_name(type_node.func) == "ELEMENT":
        element = "ELEMENT"
    key = node.name.value
    for item in items:
        if isinstance(item, cst.Call) and src.dsl_name(item.func) == "KEY":
            key = ast.literal_eval(src.code(item.args[0].value))
    return _Param(node, node.name.value, key, annotation, node.default, kind_node, type_node,
                  items, element)


def _item_kind(src: _Source, item: cst.BaseExpression) -> str:
    if isinstance(item, cst.SimpleString | cst.ConcatenatedString):
        return "description"
    if isinstance(item, cst.Call):
        name = src.dsl_name(item.func)
        return {"DESC": "description", "KEY": "key"}.get(name or "", "other")
    if src.dsl_name(item) in ("Lock", "Consume", "Unspecify", "RespectType", "Output"):
        return "option"
    return "other"


def _expands(src: _Source, p: _Param) -> bool:
    return p.element is not None and any(_item_kind(src, i) == "option" for i in p.items)


def _param_mutants(src: _Source, params: list[_Param],
                   parameters: cst.Parameters) -> Iterator[tuple[str, str, list[Splice]]]:
    # a key declared again is replaced by the later declaration, in the first one's place
    # (SkiROS2, §8.3): of the first one only its key, its position and the conditions its
    # options generated (which use the element type for RespectType) survive
    replaced = [any(q.key == p.key for q in params[i + 1:]) for i, p in enumerate(params)]
    again = [any(q.key == p.key for q in params[:i]) for i, p in enumerate(params)]
    for p, dead in zip(params, replaced, strict=True):
        for mutant in _one_param(src, p):
            operator = mutant[0]
            names = {src.dsl_name(i) for i in p.items}
            if dead and not (operator in ("param-key", "param-option-added",
                                          "param-option-removed")
                             or (operator == "param-class" and "RespectType" in names)):
                continue
            yield mutant
    # reorder: swap neighbours; every parameter becomes keyword-only so that any order is
    # valid Python (the DSL reads both kinds of parameter the same way, in order)
    first = parameters.params[0]
    self_text = src.code(first.name)
    start, end = src.span(parameters)
    texts = [src.text[src.span(p.node.name)[0]:max(src.span(x)[1] for x in
                                                   (p.node.name, p.annotation, p.default)
                                                   if x is not None)] for p in params]
    for i in range(len(params) - 1):
        a, b = params[i], params[i + 1]
        if a.key == b.key and texts[i].split(":", 1)[1:] == texts[i + 1].split(":", 1)[1:]:
            continue  # the same declaration twice: swapping changes nothing
        if (again[i] or again[i + 1]) and not (_expands(src, a) and _expands(src, b)):
            continue  # a redeclaration has no position of its own: only its options' order
        order = [*texts[:i], texts[i + 1], texts[i], *texts[i + 2:]]
        yield "param-swap", f"params {a.key!r}<->{b.key!r}", \
            [(start, end, f"{self_text}, *, " + ", ".join(order))]


def _one_param(src: _Source, p: _Param) -> Iterator[tuple[str, str, list[Splice]]]:
    where = f"param {p.key!r}"
    if p.annotation is None:
        return
    a_start, a_end = src.span(p.annotation)
    type_text = src.code(p.type_node) if p.type_node is not None else None
    item_texts = [src.code(i) for i in p.items]
    kinds = [_item_kind(src, i) for i in p.items]

    def annotation(kind: str, items: list[str]) -> list[Splice]:
        assert type_text is not None
        return [(a_start, a_end, f"{ALIAS}{kind}[{', '.join([type_text, *items])}]")]

    # kind: one mutant per other kind (a bare type is REQUIRED: REQUIRED[T] is no mutant)
    current = src.dsl_name(p.kind_node) if p.kind_node is not None else "REQUIRED"
    for kind in KINDS:
        if kind == current:
            continue
        if p.kind_node is not None:
            k_start, k_end = src.span(p.kind_node)
            yield "param-kind", where, [(k_start, k_end, ALIAS + kind)]
        else:
            yield "param-kind", where, annotation(kind, [])
    if p.type_node is None:  # ``S: OPTIONAL = CONSTANT``: the value decides everything
        pass
    else:
        # class or type
        t_start, t_end = src.span(p.type_node)
        if p.element is not None and p.element != "ELEMENT":
            assert isinstance(p.type_node, cst.Attribute)
            current_class = p.type_node.attr.value
            other = next(c for c in OTHER_CLASSES[p.element] if c != current_class)
            yield "param-class", where, [(t_start, t_end, f"{ALIAS}{p.element}.{other}")]
        elif p.element == "ELEMENT":
            assert isinstance(p.type_node, cst.Call)
            if p.type_node.args:
                arg = p.type_node.args[0].value
                s_start, s_end = src.span(arg)
                value = other_vocabulary(ast.literal_eval(src.code(arg)))
                yield "param-class", where, [(s_start, s_end, literal(value))]
            else:  # Element() has type "Unknown"
                yield "param-class", where, [(t_start, t_end, f'{ALIAS}ELEMENT("skiros:Product")')]
        elif p.default is None and isinstance(p.type_node, cst.Name) \
                and p.type_node.value in TYPE_OBJECTS:
            yield "param-type", where, [(t_start, t_end, TYPE_OBJECTS[p.type_node.value])]
        # description: change it, or add one
        if "description" in kinds:
            item = p.items[kinds.index("description")]
            target = item.args[0].value if isinstance(item, cst.Call) else item
            d_start, d_end = src.span(target)
            text = ast.literal_eval(src.code(target))
            yield "param-description", where, [(d_start, d_end, literal(text + " (mutant)"))]
        else:
            yield "param-description", where, annotation(
                current or "REQUIRED", [*item_texts, f'{ALIAS}DESC("mutant description")'])
        # key: change it, or give one
        if "key" in kinds:
            item = p.items[kinds.index("key")]
            assert isinstance(item, cst.Call)
            k_start, k_end = src.span(item.args[0].value)
            yield "param-key", where, [(k_start, k_end, literal(p.key + "_mutant"))]
        else:
            yield "param-key", where, annotation(
                current or "REQUIRED", [*item_texts, f"{ALIAS}KEY({literal(p.key + '_mutant')})"])
        # options: only where SkiROS2 applies them (Element instances)
        if p.element is not None:
            options = [t for t, k in zip(item_texts, kinds, strict=True) if k == "option"]
            names = {src.dsl_name(i) for i in p.items}
            added = "Lock" if "Lock" not in names else "Consume"
            if added not in names:
                yield "param-option-added", where, annotation(
                    current or "REQUIRED", [*item_texts, ALIAS + added])
            if options:
                rest = list(item_texts)
                rest.remove(options[0])
                yield "param-option-removed", where, annotation(current or "REQUIRED", rest)
    # default
    if p.default is not None:
        d_start, d_end = src.span(p.default)
        code = src.code(p.default)
        try:
            value = ast.literal_eval(code)
        except ValueError:
            value = src.constants.get(code)
        new = changed_value(value)
        if new is not None:
            yield "param-default", where, [(d_start, d_end, literal(new))]


# -- conditions ---------------------------------------------------------------------------


@dataclass
class _Cond:
    """A condition expression: ``node`` is all of it, ``core`` what is left without ``~``
    and ``.named``; ``children`` for an or-condition."""

    node: cst.BaseExpression
    core: cst.BaseExpression
    label: cst.BaseExpression | None
    kind: str
    children: list[_Cond] = field(default_factory=list)


def _peel(src: _Source, expr: cst.BaseExpression) -> tuple[cst.BaseExpression,
                                                           cst.BaseExpression | None]:
    label = None
    node = expr
    while True:
        if isinstance(node, cst.UnaryOperation) and isinstance(node.operator, cst.BitInvert):
            node = node.expression
        elif isinstance(node, cst.Call) and isinstance(node.func, cst.Attribute) \
                and node.func.attr.value == "named" and len(node.args) == 1:
            label = node.args[0].value
            node = node.func.value
        else:
            return node, label


def _or_children(node: cst.BaseExpression) -> list[cst.BaseExpression]:
    """``a | b | c`` flattens its left operand only (docs/dsl.md)."""
    assert isinstance(node, cst.BinaryOperation)
    left = node.left
    first = _or_children(left) if isinstance(left, cst.BinaryOperation) \
        and isinstance(left.operator, cst.BitOr) else [left]
    return [*first, node.right]


def _read_cond(src: _Source, expr: cst.BaseExpression) -> _Cond:
    core, label = _peel(src, expr)
    if isinstance(core, cst.BinaryOperation) and isinstance(core.operator, cst.BitOr):
        return _Cond(expr, core, label, "or|", [_read_cond(src, c) for c in _or_children(core)])
    if isinstance(core, cst.Call) and src.dsl_name(core.func) == "any_of":
        return _Cond(expr, core, label, "any_of",
                     [_read_cond(src, a.value) for a in core.args])
    if isinstance(core, cst.Call) and src.dsl_name(core.func) == "abstract":
        return _Cond(expr, core, label, "abstract")
    if isinstance(core, cst.Comparison):
        return _Cond(expr, core, label, "compare")
    if isinstance(core, cst.Call) and isinstance(core.func, cst.Attribute) \
            and core.func.attr.value in METHOD_OPERATORS \
            and isinstance(core.func.value, cst.Attribute):  # F.Open.eq(False)
        return _Cond(expr, core, label, "property-method")
    if isinstance(core, cst.Call) and isinstance(core.func, cst.Attribute):
        method = core.func.attr.value
        kind = method if method in ("relation", "property", "has", "is_specified",
                                    "generated", "is_a") else "attribute-relation"
        return _Cond(expr, core, label, kind)
    raise AssertionError(f"unknown condition form: {src.code(expr)}")


def _relation_parts(src: _Source, call: cst.Call) -> tuple[cst.BaseExpression,
                                                            cst.BaseExpression,
                                                            cst.BaseExpression | None]:
    """(subject, object, verbatim vocabulary string node or None) of a relation call."""
    assert isinstance(call.func, cst.Attribute)
    if call.func.attr.value == "relation":
        return call.func.value, call.args[1].value, call.args[0].value
    return call.func.value, call.args[0].value, None


def _cond_mutants(src: _Source, c: _Cond, where: str, names: list[tuple[str, str]],
                  child_models: Sequence[Condition] | None
                  ) -> Iterator[tuple[str, str, list[Splice]]]:
    start, end = src.span(c.node)
    text = src.text[start:end]
    # negation
    if isinstance(c.node, cst.UnaryOperation) and isinstance(c.node.operator, cst.BitInvert):
        yield "cond-negation", where, [(start, end, f"({src.code(c.node.expression)})")]
    else:
        yield "cond-negation", where, [(start, end, f"~({text})")]
    if c.kind in ("or|", "any_of"):
        yield from _or_mutants(src, c, where, names, child_models)
        return
    # label
    if c.label is not None:
        l_start, l_end = src.span(c.label)
        value = ast.literal_eval(src.code(c.label))
        yield "cond-label", where, [(l_start, l_end, literal(value + "Mutant"))]
    else:
        yield "cond-label", where, [(start, end, f'({text}).named("EzMutantLabel")')]
    core = c.core
    c_start, c_end = src.span(core)
    subject: cst.BaseExpression | None = None
    if c.kind == "abstract":
        assert isinstance(core, cst.Call)
        inner = core.args[0].value
        yield "cond-kind", where, [(c_start, c_end, src.code(inner))]
        assert isinstance(inner, cst.Call)
        subject, obj, vocab = _relation_parts(src, inner)
        yield from _relation_mutants(src, inner, subject, obj, vocab, where)
    elif c.kind in ("attribute-relation", "relation"):
        assert isinstance(core, cst.Call)
        yield "cond-kind", where, [(c_start, c_end, f"{ALIAS}abstract({src.code(core)})")]
        subject, obj, vocab = _relation_parts(src, core)
        yield from _relation_mutants(src, core, subject, obj, vocab, where)
    elif c.kind == "compare":
        assert isinstance(core, cst.Comparison) and len(core.comparisons) == 1
        left, target = core.left, core.comparisons[0]
        assert isinstance(left, cst.Attribute)
        subject = left.value
        op = src.module.code_for_node(target.operator).strip()
        left_text, right_text = src.code(left), src.code(target.comparator)
        yield "cond-operator", where, [(c_start, c_end,
                                        f"{left_text} {OTHER_OPERATOR[op]} {right_text}")]
        p_start, p_end = src.span(left.attr)
        other = OTHER_PROPERTY.get(left.attr.value, "ContainerState")
        yield "cond-property", where, [(p_start, p_end, other)]
        yield from _value_mutants(src, target.comparator, where)
    elif c.kind == "property-method":
        assert isinstance(core, cst.Call) and isinstance(core.func, cst.Attribute)
        handle = core.func.value
        assert isinstance(handle, cst.Attribute)
        subject = handle.value
        m_start, m_end = src.span(core.func.attr)
        operator = METHOD_OPERATORS[core.func.attr.value]
        yield "cond-operator", where, [(m_start, m_end,
                                        OPERATOR_METHODS[OTHER_OPERATOR[operator]])]
        p_start, p_end = src.span(handle.attr)
        other = OTHER_PROPERTY.get(handle.attr.value, "ContainerState")
        yield "cond-property", where, [(p_start, p_end, other)]
        yield from _value_mutants(src, core.args[0].value, where)
    elif c.kind == "property":
        assert isinstance(core, cst.Call) and isinstance(core.func, cst.Attribute)
        subject = core.func.value
        vocab, operator, value = (a.value for a in core.args)
        yield from _string_mutant(src, vocab, "cond-property", where, other_vocabulary)
        yield from _string_mutant(src, operator, "cond-operator", where,
                                  lambda s: OTHER_OPERATOR.get(s, "="))
        yield from _value_mutants(src, value, where)
    elif c.kind == "has":
        assert isinstance(core, cst.Call) and isinstance(core.func, cst.Attribute)
        subject = core.func.value
        arg = core.args[0].value
        a_start, a_end = src.span(arg)
        current = ast.literal_eval(src.code(arg)) if isinstance(arg, cst.SimpleString) \
            else "skiros:" + src.code(arg).rsplit(".", 1)[-1]
        other = "skiros:Orientation" if current != "skiros:Orientation" else "skiros:Position"
        yield "cond-property", where, [(a_start, a_end, literal(other))]
    elif c.kind in ("is_specified", "generated"):
        assert isinstance(core, cst.Call) and isinstance(core.func, cst.Attribute)
        subject = core.func.value
        m_start, m_end = src.span(core.func.attr)
        other = "generated" if c.kind == "is_specified" else "is_specified"
        yield "cond-kind", where, [(m_start, m_end, other)]
    elif c.kind == "is_a":
        assert isinstance(core, cst.Call) and isinstance(core.func, cst.Attribute)
        subject = core.func.value
        arg = core.args[0].value
        a_start, a_end = src.span(arg)
        if isinstance(arg, cst.SimpleString):
            yield from _string_mutant(src, arg, "cond-class", where, other_vocabulary)
        else:
            assert isinstance(arg, cst.Attribute) and isinstance(arg.value, cst.Name)
            prefix = src.namespaces[arg.value.value]
            other = next(x for x in OTHER_CLASSES[prefix] if x != arg.attr.value)
            yield "cond-class", where, [(a_start, a_end, f"{ALIAS}{prefix}.{other}")]
    # subject: another parameter
    if subject is not None:
        s_start, s_end = src.span(subject)
        current_key = _symbol_key(src, subject, names)
        other_name = next((n for n, k in names if k != current_key), None)
        if other_name is not None:
            yield "cond-subject", where, [(s_start, s_end, other_name)]


def _symbol_key(src: _Source, node: cst.BaseExpression, names: list[tuple[str, str]]) -> str:
    if isinstance(node, cst.Name):
        return next((k for n, k in names if n == node.value), node.value)
    assert isinstance(node, cst.Call)  # self.param("k")
    return str(ast.literal_eval(src.code(node.args[0].value)))


def _relation_mutants(src: _Source, call: cst.Call, subject: cst.BaseExpression,
                      obj: cst.BaseExpression, vocab: cst.BaseExpression | None,
                      where: str) -> Iterator[tuple[str, str, list[Splice]]]:
    s_start, s_end = src.span(subject)
    o_start, o_end = src.span(obj)
    if src.code(subject) != src.code(obj):
        yield "cond-swap-subject-object", where, [(s_start, s_end, src.code(obj)),
                                                  (o_start, o_end, src.code(subject))]
    if vocab is not None:
        yield from _string_mutant(src, vocab, "cond-relation", where, other_vocabulary)
    else:
        assert isinstance(call.func, cst.Attribute)
        r_start, r_end = src.span(call.func.attr)
        yield "cond-relation", where, [(r_start, r_end,
                                        OTHER_RELATION.get(call.func.attr.value, "contain"))]


def _string_mutant(src: _Source, node: cst.BaseExpression, operator: str, where: str,
                   change: Any) -> Iterator[tuple[str, str, list[Splice]]]:
    start, end = src.span(node)
    yield operator, where, [(start, end, literal(change(ast.literal_eval(src.code(node)))))]


def _value_mutants(src: _Source, node: cst.BaseExpression,
                   where: str) -> Iterator[tuple[str, str, list[Splice]]]:
    start, end = src.span(node)
    value = ast.literal_eval(src.code(node))
    yield "cond-value", where, [(start, end, literal(changed_value(value)))]
    retyped = retyped_value(value)
    if retyped is not None:
        yield "cond-value-type", where, [(start, end, literal(retyped))]


def _or_mutants(src: _Source, c: _Cond, where: str, names: list[tuple[str, str]],
                child_models: Sequence[Condition] | None
                ) -> Iterator[tuple[str, str, list[Splice]]]:
    c_start, c_end = src.span(c.core)
    texts = [src.code(child.node) for child in c.children]

    def rebuilt(parts: list[str]) -> str:
        if c.kind == "any_of":
            assert isinstance(c.core, cst.Call)
            return f"{src.code(c.core.func)}({', '.join(parts)})"
        return " | ".join(f"({p})" for p in parts)

    for i, child in enumerate(c.children):
        models = child_models[i].children if child_models is not None \
            and child_models[i].kind == "or" else None
        yield from _cond_mutants(src, child, f"{where} child {i + 1}", names,
                                            models)
        others = texts[:i] + texts[i + 1:]
        yield "or-child-dropped", f"{where} child {i + 1}", [(c_start, c_end, rebuilt(others))]
        yield "or-child-duplicated", f"{where} child {i + 1}", [
            (c_start, c_end, rebuilt([*texts[:i + 1], texts[i], *texts[i + 1:]]))]
        if i + 1 < len(texts) and child_models is not None \
                and child_models[i] != child_models[i + 1]:
            swapped = [*texts[:i], texts[i + 1], texts[i], *texts[i + 2:]]
            yield "or-children-swapped", f"{where} children {i + 1}<->{i + 2}", [
                (c_start, c_end, rebuilt(swapped))]


# -- classes ------------------------------------------------------------------------------


def _statements(src: _Source, method: cst.FunctionDef) -> list[tuple[cst.AugAssign, str]]:
    """The ``self.<list> += <condition>`` statements of the body, with their list."""
    found = []
    assert isinstance(method.body, cst.IndentedBlock)
    for stmt in method.body.body:
        if not isinstance(stmt, cst.SimpleStatementLine):
            continue
        for small in stmt.body:
            if isinstance(small, cst.AugAssign) and isinstance(small.operator, cst.AddAssign) \
                    and isinstance(small.target, cst.Attribute) \
                    and small.target.attr.value in LISTS:
                found.append((small, small.target.attr.value))
    return found


def skill_mutants(module: str, data: bytes, models: dict[str, SkillModel]) -> list[Skill]:
    """Every skill of a migrated module (classes with a ``description`` method) with its
    mutants. ``models`` are the loaded models of the unmutated module (for swaps)."""
    src = _Source(data)
    skills = []
    for stmt in src.module.body:
        if not isinstance(stmt, cst.ClassDef) or not isinstance(stmt.body, cst.IndentedBlock):
            continue
        method = next((s for s in stmt.body.body if isinstance(s, cst.FunctionDef)
                       and s.name.value == "description"), None)
        if method is None:
            continue
        name = stmt.name.value
        pos = src.positions[method]
        m_start = src.line_starts[pos.start.line - 1]
        m_end = src.offset(pos.end.line, pos.end.column)
        method_text = src.text[m_start:m_end]
        skill = Skill(module, name, method_text)
        params = [_read_param(src, p) for p in
                  [*method.params.params[1:], *method.params.kwonly_params]]
        names = [(p.name, p.key) for p in params]
        edits = list(_param_mutants(src, params, method.params)) if params else []
        statements = _statements(src, method)
        model = models[name]
        for which in LISTS:
            mine = [s for s, w in statements if w == which]
            conds = model.conditions(which.split("_")[0])
            if len(mine) > len(conds):
                raise AssertionError(f"{module}::{name}: more {which} statements than "
                                     "conditions in the loaded model")
            cond_models = conds[len(conds) - len(mine):]
            for i, stmt_node in enumerate(mine):
                where = f"{which.split('_')[0]} #{i + 1}"
                s_start, s_end = src.span(stmt_node)
                statement_text = src.code(stmt_node)
                edits.append(("cond-dropped", where, [(s_start, s_end, "pass")]))
                edits.append(("cond-duplicated", where,
                              [(s_start, s_end, f"{statement_text}; {statement_text}")]))
                t_start, t_end = src.span(stmt_node.target.attr)  # type: ignore[attr-defined]
                for other in LISTS:
                    if other != which:
                        edits.append(("cond-list", where, [(t_start, t_end, other)]))
                if i + 1 < len(mine) and cond_models[i] != cond_models[i + 1]:
                    n_start, n_end = src.span(mine[i + 1])
                    edits.append(("cond-swapped", f"{where}<->#{i + 2}",
                                  [(s_start, s_end, src.code(mine[i + 1])),
                                   (n_start, n_end, statement_text)]))
                cond = _read_cond(src, stmt_node.value)
                child_models = cond_models[i].children if cond_models[i].kind == "or" else None
                edits.extend(_cond_mutants(src, cond, where, names, child_models))
        skill.control = f"{name}__m0"
        for number, (operator, where, splices) in enumerate(edits, start=1):
            body = _apply(method_text, m_start, splices)
            skill.mutants.append(Mutant(module, name, f"{name}__m{number}", operator, where,
                                        body))
        skills.append(skill)
    return skills


def after_source(data: bytes, skills: Sequence[Skill], mutants: Sequence[Mutant]) -> bytes:
    """The migrated module plus the control clones of ``skills`` and the given mutants."""
    encoding = cst.parse_module(data).encoding
    names = ", ".join(f"{n} as {ALIAS}{n}" for n in DSL_IMPORTS)
    spaces = ", ".join(f"{n} as {ALIAS}{n}" for n in NAMESPACES)
    lines = [f"from ezskiros_runtime import {names}",
             f"from ezskiros_runtime.ontology import {spaces}", ""]
    for skill in skills:
        lines += [f"class {skill.control}({skill.name}):", skill.method, ""]
    for mutant in mutants:
        lines += [f"class {mutant.clone}({mutant.cls}):", mutant.method, ""]
    return data + b"\n\n" + "\n".join(lines).encode(encoding)


def before_source(data: bytes, skills: Sequence[Skill], mutants: Sequence[Mutant]) -> bytes:
    """The legacy module plus empty subclasses with the names of the clones."""
    lines = [f"class {s.control}({s.name}):\n    pass\n" for s in skills]
    lines += [f"class {m.clone}({m.cls}):\n    pass\n" for m in mutants]
    return data + b"\n\n" + "\n".join(lines).encode("ascii")
