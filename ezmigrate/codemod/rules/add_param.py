"""``self.addParam(key, value, param_type, options=[], description="")`` <-> a signature entry.

Legacy (legacy-skiros2-api.md §3, §8)           EzSkiROS (docs/dsl.md)
``addParam("O", Element("skiros:P"), Required)``  ``O: skiros.P``
``addParam("S", 0.5, ParamTypes.Optional)``      ``S: OPTIONAL[float] = 0.5``
``addParam("S", 0.5, 1, [], "m/s")``             ``S: Annotated[OPTIONAL[float], DESC("m/s")]``
                                                 ``= 0.5``
``addParam("S", float, 0, "m/s")``               ``S: float,  # m/s``  (quirk: "m/s" lands in
                                                 options; the text stays, as a comment)
``addParam("C", Element(":Cam"), 2, [Lock])``    ``C: Annotated[INFERRED, ELEMENT(":Cam"), Lock]``
``addParam("On/Off", True, Required)``           ``On_Off: Annotated[bool, KEY("On/Off")] = True``

Strings go in ``Annotated[...]``'s items, never inside ``KIND[...]`` (pyflakes F722, F821).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import libcst as cst
else:
    from ..core.lazy_cst import cst

from ..core.context import ExtractContext, bind_arguments
from ..core.emit import EmitContext
from ..core.ir import (
    ElementValue,
    ExtractedSkill,
    Literal,
    OpaqueValue,
    ParamOp,
    ParamValue,
    TypeValue,
    Unsupported,
)
from .condition_lists import statement_comments

ARGUMENTS = ("key", "value", "param_type", "options", "description")
KINDS = ("Required", "Optional", "Inferred")
MARKERS = {"Required": "REQUIRED", "Optional": "OPTIONAL", "Inferred": "INFERRED"}
OPTIONS = ("Consume", "Unspecify", "Lock", "RespectType", "Output")
TYPE_OBJECTS = ("float", "int", "str", "bool", "dict", "list", "tuple")
DEFAULT_TYPES = (bool, int, float, str, dict, tuple)


def add_param(stmt: cst.BaseSmallStatement, ctx: ExtractContext) -> list[ParamOp] | None:
    """Read one ``addParam`` call into a ``ParamOp``."""
    if not isinstance(stmt, cst.Expr) or ctx.self_method(stmt.value) != "addParam":
        return None
    call = stmt.value
    assert isinstance(call, cst.Call)
    args = bind_arguments(call, ARGUMENTS, 3, "addParam", ctx)
    line = ctx.line(call)
    key = ctx.string(args["key"], f"the key of addParam at line {line}")
    options, options_text = _options(args.get("options"), ctx)
    description = code = None
    if "description" in args:
        description = ctx.string(args["description"], f"the description of {key!r}")
        code = _description_code(args["description"], ctx)
    op = ParamOp(key, _value(args["value"], ctx), _kind(args["param_type"], ctx), options,
                 description, line, options_text=options_text, description_code=code)
    op.comments = statement_comments(stmt, ctx)  # inside a multi-line call
    param_findings(op, ctx.skill)
    return [op]


def _description_code(node: cst.BaseExpression, ctx: ExtractContext) -> str:
    """How the signature spells a description: as written when that reads the same value in
    the class body (a literal, a module constant the class does not rebind), else the
    literal it resolves to (a local of ``createDescription`` does not exist there)."""
    if isinstance(node, cst.Name) and ctx.constant(node) is not None \
            and node.value not in ctx.class_names:
        return node.value
    found = ctx.resolved(node)
    assert found is not None  # ctx.string accepted it
    return found.code


def _value(node: cst.BaseExpression, ctx: ExtractContext) -> ParamValue:
    if isinstance(node, cst.Call) and ctx.names.symbol(node.func) == "Element":
        return _element(node, ctx)
    if ctx.names.symbol(node) == "Element":
        raise Unsupported(f"addParam at line {ctx.line(node)} passes the Element class itself; "
                          "declare an element type, e.g. Element(\"sumo:Object\")", node)
    if isinstance(node, cst.Name) and node.value in TYPE_OBJECTS and node.value not in ctx.locals:
        return TypeValue(node.value)
    literal = ctx.literal(node)
    if literal is not None:
        return literal
    if isinstance(node, (cst.Name, cst.Attribute)):
        root: cst.BaseExpression = node
        while isinstance(root, cst.Attribute):
            root = root.value
        if isinstance(root, cst.Name) and root.value not in (ctx.self_name, *ctx.locals,
                                                             *ctx.opaque_locals):
            if root.value in ctx.class_names or root.value == ctx.class_name:
                raise Unsupported(
                    f"the value of addParam at line {ctx.line(node)} is "
                    f"`{ctx.code(node).strip()}`; as a default in the signature it would be "
                    f"read in the class body, where {ctx.class_name} "
                    + ("is not defined yet" if root.value == ctx.class_name else
                       f"binds its own `{root.value}`")
                    + " (rename one of them, then migrate)", node)
            known = ctx.constants.get(node.value) if isinstance(node, cst.Name) else None
            return OpaqueValue(ctx.code(node).strip(), known)
    raise Unsupported(f"the value of addParam at line {ctx.line(node)} is "
                      f"`{ctx.code(node).strip()}`, computed at run time", node)


def _element(call: cst.Call, ctx: ExtractContext) -> ElementValue:
    args = bind_arguments(call, ("etype", "label", "eid"), 0, "Element", ctx)
    extra = [what for name, what in (("label", "a label"), ("eid", "an id")) if name in args]
    if extra:
        raise Unsupported(
            f"Element(...) at line {ctx.line(call)} passes {' and '.join(extra)}; upstream "
            "Element(etype, label=\"\", eid=-1) accepts that, but an EzSkiROS parameter is "
            "typed by its class alone and has no place for it (pass only the type, or keep "
            "this skill as it is)", call)
    if "etype" not in args:
        return ElementValue("Unknown")
    return ElementValue(ctx.string(args["etype"], f"the Element type at line {ctx.line(call)}"))


def _kind(node: cst.BaseExpression, ctx: ExtractContext) -> str:
    member = ctx.names.member(node, "ParamTypes")
    if member in KINDS:
        return member
    if member is not None:
        raise Unsupported(fork_kind(member, ctx.line(node)), node)
    literal = ctx.literal(node)
    if literal is not None and type(literal.value) is int and 0 <= literal.value < len(KINDS):
        return KINDS[literal.value]
    raise Unsupported(f"the parameter type `{ctx.code(node).strip()}` at line {ctx.line(node)} "
                      "is not ParamTypes.Required/Optional/Inferred", node)


def fork_kind(member: str, line: int) -> str:
    """Why a skill is kept whose parameter kind is a ``ParamTypes`` member upstream SkiROS2
    lacks (``lint/plain_reader.py`` words it so too)."""
    return f"ParamTypes.{member} at line {line} is not upstream SkiROS2 API (a fork's extension)"


def _options(node: cst.BaseExpression | None, ctx: ExtractContext) -> tuple[list[str], str | None]:
    if node is None:
        return [], None
    literal = ctx.literal(node)
    if literal is not None and isinstance(literal.value, str):
        return [], literal.value  # SkiROS2 iterates the characters and matches nothing
    if isinstance(node, (cst.List, cst.Tuple)):
        names = []
        for element in node.elements:
            member = ctx.names.member(element.value, "ParamOptions")
            if member not in OPTIONS or not isinstance(element, cst.Element):
                break
            names.append(member)
        else:
            return names, None
    raise Unsupported(f"the options `{ctx.code(node).strip()}` at line {ctx.line(node)} are not "
                      "a list of ParamOptions members", node)


def param_findings(op: ParamOp, skill: ExtractedSkill) -> None:
    """The silent quirks of one ``addParam`` that migration keeps (and ``check`` reports)."""
    if op.options_text is not None:
        skill.finding("description-in-options", op.line,
                          f"addParam({op.key!r}) passes {op.options_text!r} in the options slot:"
                          " SkiROS2 ignores it and the description stays empty (a migration keeps "
                          "the text as a comment on the parameter's line, meaning unchanged; "
                          "to make it the description, run `ezmigrate check --fix` on the "
                          "legacy file first, then `rewrite`: after `rewrite` there is "
                          "nothing left to fix)")
    if op.options and not (isinstance(op.value, ElementValue) and not op.value.is_class):
        skill.finding("options-ignored", op.line,
                          f"ParamOptions on {op.key!r} have no effect: SkiROS2 only expands "
                          "them for Element values (dropped, meaning unchanged)")


def annotation(op: ParamOp, python_name: str, ctx: EmitContext) -> tuple[str, str | None]:
    """The annotation and default source text of a parameter (``None``: no default).

    ``python_name`` is the name the signature gives it; when it is not the key itself
    (a key that is no identifier, or a key declared twice) a ``KEY(...)`` item says the key.

    The items that hold a string (``DESC(...)``, ``KEY(...)``, a verbatim ``ELEMENT("...")``
    type) go after the annotation in ``Annotated[...]`` (docs/dsl.md): pyflakes parses every
    other string of an annotation as a forward reference (F722, F821). Where the module
    binds ``Annotated`` itself, they stay inside the kind marker's brackets.
    """
    options = [ctx.use(o) for o in op.options] if isinstance(op.value, ElementValue) else []
    desc = [f"{ctx.use('DESC')}({op.description_code or ctx.quote(op.description)})"] \
        if op.description else []
    key = [f"{ctx.use('KEY')}({ctx.quote(op.key)})"] if python_name != op.key else []
    strings = desc + key
    marker = MARKERS[op.kind]
    if isinstance(op.value, OpaqueValue) and op.value.known is None:
        if options or strings:
            raise Unsupported(f"parameter {op.key!r} at line {op.line} has a default known "
                              "only at run time and a description, option or key escape")
        return ctx.use(marker), op.value.code
    type_text, default = _type_and_default(op, ctx)
    verbatim = _verbatim_element(op, ctx)
    if (strings or verbatim) and ctx.aliases.get("Annotated", "Annotated") == "Annotated":
        if verbatim:  # ``INFERRED[...]`` needs a type first: the bare marker, then the items
            head, items = ctx.use(marker), [type_text, *options, *strings]
        else:
            head, items = _kind_form(op.kind, marker, type_text, options, ctx), strings
        return f"{ctx.use('Annotated')}[{', '.join([head, *items])}]", default
    if op.kind == "Required" and not options and not strings:
        return type_text, default
    return f"{ctx.use(marker)}[{', '.join([type_text, *desc, *options, *key])}]", default


def _kind_form(kind: str, marker: str, type_text: str, options: list[str],
               ctx: EmitContext) -> str:
    """``skiros.C`` for a required parameter without options, else ``KIND[type, options]``."""
    if kind == "Required" and not options:
        return type_text
    return f"{ctx.use(marker)}[{', '.join([type_text, *options])}]"


def _verbatim_element(op: ParamOp, ctx: EmitContext) -> bool:
    """Whether the parameter's type is written ``ELEMENT("...")`` (a string)."""
    value = op.value
    return isinstance(value, ElementValue) and value.type_string not in (None, "Unknown") \
        and ctx.class_ref(value.type_string) is None


def _type_and_default(op: ParamOp, ctx: EmitContext) -> tuple[str, str | None]:
    value = op.value
    if isinstance(value, ElementValue):
        if value.type_string == "Unknown":
            return f"{ctx.use('ELEMENT')}()", None
        assert value.type_string is not None
        ref = ctx.class_ref(value.type_string)
        return (ref or f"{ctx.use('ELEMENT')}({ctx.quote(value.type_string)})"), None
    if isinstance(value, TypeValue):
        return value.name, None
    if isinstance(value, OpaqueValue):
        assert value.known is not None
        return literal_type(value.known, op, ctx.list_type), value.code
    return literal_type(value, op, ctx.list_type), value.code


def literal_type(value: Literal, op: ParamOp,
                 list_type: Callable[[str], str] = "list[{}]".format) -> str:
    """The annotation of a literal default, or ``Unsupported`` when SkiROS2 rejects it;
    ``list_type`` spells a list of an item type (``EmitContext.list_type``)."""
    items = value.value
    if isinstance(items, list):
        if not items:
            raise Unsupported(f"parameter {op.key!r} at line {op.line} has the default [], "
                              "which SkiROS2 rejects when the skill loads")
        first = type(items[0])
        if first not in DEFAULT_TYPES or any(type(x) is not first for x in items):
            raise Unsupported(f"parameter {op.key!r} at line {op.line} has a list default of "
                              "mixed or unsupported types, which SkiROS2 rejects")
        return list_type(first.__name__)
    if type(items) not in DEFAULT_TYPES:
        raise Unsupported(f"parameter {op.key!r} at line {op.line} has a default of type "
                          f"{type(items).__name__}, which SkiROS2 parameters do not support")
    return type(items).__name__
