"""Render model parts in legacy SkiROS2 notation, for diffs and review reports.

Reviewers know the legacy API, so a difference is shown as the ``addParam`` or factory call
that would produce each side, not as our internal field names.
"""

from __future__ import annotations

from .model import Condition, Param, Typed, untyped

_FACTORIES = {
    "relation": "getRelationCond",
    "abstract_relation": "getAbstractRelationCond",
    "property": "getPropCond",
    "has_property": "getHasPropCond",
    "is_specified": "getIsSpecifiedCond",
    "generate": "getGenerateCond",
    "on_type": "getOnTypeCond",
    "or": "getOrCond",
}


def literal(value: Typed | None) -> str:
    """A typed value as Python source (``0.5``, ``'x'``, ``True``)."""
    return "None" if value is None else repr(untyped(value))


def render_param(p: Param) -> str:
    """``addParam("X", Element("skiros:C"), ParamTypes.Required, [ParamOptions.Lock], "d")``."""
    if p.data_type == "Element":
        value = "Element" if p.element_type is None else f"Element({p.element_type!r})"
    elif not p.values:
        value = p.data_type
    elif len(p.values) == 1:
        value = literal(p.values[0])
    else:
        value = repr([untyped(v) for v in p.values])
    args = [repr(p.key), value, f"ParamTypes.{p.kind}"]
    if p.options or p.description:
        args.append("[" + ", ".join(f"ParamOptions.{o}" for o in p.options) + "]")
    if p.description:
        args.append(repr(p.description))
    return f"addParam({', '.join(args)})"


def render_condition(c: Condition) -> str:
    """The factory call that builds ``c``; an or-condition lists its children."""
    name = _FACTORIES.get(c.kind, c.kind)
    desired = literal(c.desired_state)
    if c.kind in ("relation", "abstract_relation"):
        args = [repr(c.label), repr(c.vocabulary), repr(c.subject), repr(c.object), desired]
    elif c.kind == "property":
        args = [repr(c.label), repr(c.vocabulary), repr(c.subject), repr(c.operator),
                literal(c.value), desired]
    elif c.kind == "has_property":
        args = [repr(c.label), repr(c.vocabulary), repr(c.subject), desired]
    elif c.kind in ("is_specified", "generate"):
        args = [repr(c.label), repr(c.subject), desired]
    elif c.kind == "on_type":
        args = [repr(c.label), repr(c.subject), repr(c.vocabulary)]
    elif c.kind == "or":
        children = ", ".join(render_condition(x) for x in c.children)
        return f"{name}({desired}) <- [{children}]"
    else:
        args = [repr(c.label)]
    return f"{name}({', '.join(args)})"
