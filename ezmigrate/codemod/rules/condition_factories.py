"""Condition factories and condition classes <-> EzSkiROS condition expressions.

Legacy (legacy-skiros2-api.md §4, §7)                    EzSkiROS (docs/dsl.md)
``getRelationCond(l, "skiros:contain", "A", "B", True)``  ``A.contain(B)``
``... False``                                              ``~ A.contain(B)``
``getAbstractRelationCond(...)``                           ``abstract(A.contain(B))``
``getPropCond(l, "skiros:Open", "F", "=", False, True)``  ``F.Open.eq(False)`` (``.gt`` ...)
``getHasPropCond(l, "skiros:Position", "O", True)``       ``O.has(skiros.Position)``
``getIsSpecifiedCond(l, "O", True)``                       ``O.is_specified()``
``getGenerateCond(l, "O", True)``                          ``O.generated()``
``getOnTypeCond(l, "O", "skiros:Product")``                ``O.is_a(skiros.Product)``
``ConditionRelation(l, "skiros:contain", "A", "B", True)`` same as its factory
A label that the convention would not produce is written with ``.named("...")``.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    import libcst as cst
else:
    from ..core.lazy_cst import cst

from ezskiros_runtime.labels import conventional_label

from ..core.context import ExtractContext, bind_arguments
from ..core.emit import EmitContext
from ..core.ir import CondSpec, Literal, Unsupported
from ..core.registry import condition_emitter, condition_replayer
from ..core.replay import literal_value as lit

RELATION_ARGS = ("label", "relation", "subject_key", "object_key", "desired_state")
FACTORIES: dict[str, tuple[str, tuple[str, ...]]] = {
    "getRelationCond": ("relation", RELATION_ARGS),
    "getAbstractRelationCond": ("abstract_relation", RELATION_ARGS),
    "getPropCond": ("property", ("label", "property", "subject_key", "operator", "value",
                                 "desired_state")),
    "getHasPropCond": ("has_property", ("label", "property", "subject_key", "desired_state")),
    "getIsSpecifiedCond": ("is_specified", ("label", "subject_key", "desired_state")),
    "getGenerateCond": ("generate", ("label", "subject_key", "desired_state")),
    "getOnTypeCond": ("on_type", ("label", "subject_key", "type")),
}
CLASSES = {
    "ConditionRelation": "getRelationCond",
    "AbstractConditionRelation": "getAbstractRelationCond",
    "ConditionProperty": "getPropCond",
    "ConditionHasProperty": "getHasPropCond",
    "ConditionIsSpecified": "getIsSpecifiedCond",
    "ConditionGenerate": "getGenerateCond",
    "ConditionOnType": "getOnTypeCond",
}
OPERATORS = {"=": "eq", ">": "gt", "<": "lt", ">=": "ge", "<=": "le"}
"""SkiROS2 operator -> the method of a property handle written for it (``F.Open.eq(False)``).

Not ``F.Open == False``: pycodestyle and ruff flag that (E712) in every lab's CI, and their
fixes turn it into ``not F.Open`` or ``F.Open``, which is no longer the condition."""


def factory_condition(node: cst.BaseExpression, ctx: ExtractContext) -> CondSpec | None:
    """``self.getXCond(...)`` or ``ConditionX(...)`` with literal arguments."""
    if not isinstance(node, cst.Call):
        return None
    factory = ctx.self_method(node)
    if factory not in FACTORIES:
        symbol = ctx.names.symbol(node.func)
        if symbol == "ConditionFunction":
            raise Unsupported(f"ConditionFunction at line {ctx.line(node)} wraps Python code; "
                              "it is not declarative and has no EzSkiROS form", node)
        factory = CLASSES.get(symbol or "")
        if factory is None:
            return None
    kind, names = FACTORIES[factory]
    args = bind_arguments(node, names, len(names), factory, ctx)
    line = ctx.line(node)

    def lit(name: str) -> Literal:
        found = ctx.resolved(args[name])
        if found is None:
            raise Unsupported(f"the {name} of {factory} at line {line} is "
                              f"`{ctx.code(args[name]).strip()}`, computed at run time", node)
        return found

    vocab = args.get("relation") or args.get("property") or args.get("type")
    return CondSpec(
        kind=kind, label=lit("label"), line=line,
        vocabulary=None if vocab is None else ctx.string(vocab, f"the vocabulary at line {line}"),
        subject=ctx.string(args["subject_key"], f"the subject key at line {line}"),
        object=(ctx.string(args["object_key"], f"the object key at line {line}")
                if "object_key" in args else None),
        operator=(ctx.string(args["operator"], f"the operator at line {line}")
                  if "operator" in args else None),
        value=lit("value") if "value" in args else None,
        desired=lit("desired_state") if "desired_state" in args else None,
    )


def desired_value(spec: CondSpec) -> object:
    """The raw desired state (on-type conditions have none, which counts as True)."""
    return True if spec.desired is None else spec.desired.value


def with_label(spec: CondSpec, expression: str, ctx: EmitContext, *, wrap: bool = False) -> str:
    """Append ``.named(...)`` when the legacy label differs from the convention."""
    assert spec.label is not None
    label = spec.label.value
    expected = conventional_label(spec.kind, subject=spec.subject, vocabulary=spec.vocabulary,
                                  object=spec.object, desired_state=desired_value(spec))
    if type(label) is str and label == expected:
        return expression
    if type(label) is not str:
        raise Unsupported(f"the label at line {spec.line} is {spec.label.code}, not a string")
    return f"({expression}).named({spec.label.code})" if wrap else \
        f"{expression}.named({spec.label.code})"


def negated(spec: CondSpec, expression: str) -> str:
    """Prefix ``~`` for desired state False; other non-True states cannot be written."""
    desired = desired_value(spec)
    if desired is True:
        return expression
    if desired is False:
        return f"~{expression}" if expression.startswith("(") else f"~ {expression}"
    raise Unsupported(f"the desired state at line {spec.line} is {desired!r}, not True or False")


@condition_emitter("relation", "abstract_relation")
def emit_relation(spec: CondSpec, ctx: EmitContext) -> str:
    assert spec.vocabulary is not None and spec.subject is not None and spec.object is not None
    subject, obj = ctx.subject(spec.subject), ctx.subject(spec.object)
    short = ctx.short_property(spec.vocabulary)
    text = (f"{subject}.{short}({obj})" if short
            else f"{subject}.relation({ctx.quote(spec.vocabulary)}, {obj})")
    text = with_label(spec, text, ctx)
    if spec.kind == "abstract_relation":
        text = f"{ctx.use('abstract')}({text})"
    return negated(spec, text)


@condition_emitter("property")
def emit_property(spec: CondSpec, ctx: EmitContext) -> str:
    assert spec.vocabulary is not None and spec.subject is not None and spec.value is not None
    assert spec.operator is not None
    subject = ctx.subject(spec.subject)
    short = ctx.short_property(spec.vocabulary)
    if short and spec.operator in OPERATORS:
        text = f"{subject}.{short}.{OPERATORS[spec.operator]}({spec.value.code})"
    else:
        text = (f"{subject}.property({ctx.quote(spec.vocabulary)}, {ctx.quote(spec.operator)}, "
                f"{spec.value.code})")
    return negated(spec, with_label(spec, text, ctx))


@condition_emitter("has_property")
def emit_has_property(spec: CondSpec, ctx: EmitContext) -> str:
    assert spec.vocabulary is not None and spec.subject is not None
    ref = ctx.property_ref(spec.vocabulary) or ctx.quote(spec.vocabulary)
    return negated(spec, with_label(spec, f"{ctx.subject(spec.subject)}.has({ref})", ctx))


@condition_emitter("is_specified", "generate")
def emit_state(spec: CondSpec, ctx: EmitContext) -> str:
    assert spec.subject is not None
    method = "is_specified" if spec.kind == "is_specified" else "generated"
    return negated(spec, with_label(spec, f"{ctx.subject(spec.subject)}.{method}()", ctx))


@condition_emitter("on_type")
def emit_on_type(spec: CondSpec, ctx: EmitContext) -> str:
    assert spec.vocabulary is not None and spec.subject is not None
    ref = ctx.class_ref(spec.vocabulary) or ctx.quote(spec.vocabulary)
    return with_label(spec, f"{ctx.subject(spec.subject)}.is_a({ref})", ctx)


@condition_replayer("relation")
def replay_relation(desc: Any, spec: CondSpec) -> object:
    return desc.getRelationCond(lit(spec.label), spec.vocabulary or "", spec.subject or "",
                                spec.object or "", lit(spec.desired))


@condition_replayer("abstract_relation")
def replay_abstract_relation(desc: Any, spec: CondSpec) -> object:
    return desc.getAbstractRelationCond(lit(spec.label), spec.vocabulary or "",
                                        spec.subject or "", spec.object or "",
                                        lit(spec.desired))


@condition_replayer("property")
def replay_property(desc: Any, spec: CondSpec) -> object:
    return desc.getPropCond(lit(spec.label), spec.vocabulary or "", spec.subject or "",
                            spec.operator or "", lit(spec.value), lit(spec.desired))


@condition_replayer("has_property")
def replay_has_property(desc: Any, spec: CondSpec) -> object:
    return desc.getHasPropCond(lit(spec.label), spec.vocabulary or "", spec.subject or "",
                               lit(spec.desired))


@condition_replayer("is_specified")
def replay_is_specified(desc: Any, spec: CondSpec) -> object:
    return desc.getIsSpecifiedCond(lit(spec.label), spec.subject or "", lit(spec.desired))


@condition_replayer("generate")
def replay_generate(desc: Any, spec: CondSpec) -> object:
    return desc.getGenerateCond(lit(spec.label), spec.subject or "", lit(spec.desired))


@condition_replayer("on_type")
def replay_on_type(desc: Any, spec: CondSpec) -> object:
    return desc.getOnTypeCond(lit(spec.label), spec.subject or "", spec.vocabulary or "")
