"""Checks on the description's own structure, independent of ontology types.

- a default that does not fit its annotation (the DSL promises type-exact defaults);
- an INFERRED Element parameter that no pre-condition mentions: the skill manager then
  grounds it by type alone, to the first matching element (arbitrary when several fit);
- a condition on a key the description never declares (SkiROS2 keeps it silently);
- the same condition required to hold and not to hold in one list, a property wanted equal
  to two values, or numeric bounds no value fits (none of these can ever be met).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from ..diagnostics import did_you_mean
from ..model import typed
from ..notation import render_condition
from ..ontology.suggest import closest_names
from .check_context import ROBOT_KEY, CheckContext
from .collectors import Recorded

_MENTIONING_OPTIONS = frozenset({"Lock", "RespectType"})
"""Options whose expansion adds a pre-condition on the parameter itself."""


def check_defaults(ctx: CheckContext) -> None:
    """Every default fits its annotation (docs/dsl.md rules)."""
    for spec in ctx.trace.specs:
        if spec.mismatch is not None:
            file, line = ctx.param_location(spec.name)
            ctx.add("default-type", f"parameter {spec.key}: {spec.mismatch}", file, line,
                    param=spec.key)


def check_inferable(ctx: CheckContext) -> None:
    """Every INFERRED Element parameter is mentioned by some pre-condition (Robot aside:
    SkiROS2's skill manager binds the executing robot itself).

    SkiROS2 does not fail on one that is not: it grounds any non-Optional Element
    parameter by its type alone, to the first matching element of the world model. That
    is right when one element fits and arbitrary when several do, which is what the
    finding says. A parameter that is no Element is never grounded this way: not judged.
    """
    mentioned = {key for record in ctx.trace.recorded if record.which == "pre"
                 for key in record.condition.param_keys()}
    # a key no parameter declares, one letter from one that is, is that parameter
    # misspelt: reported as such (undeclared_parameter), not again as this one unmentioned
    from ..world.postconditions import one_edit

    for key in mentioned - set(ctx.params):
        close = [k for k in ctx.params if one_edit(key, k)]
        if len(close) == 1:
            mentioned.add(close[0])
    for key, spec in ctx.params.items():
        if spec.kind != "Inferred" or key == ROBOT_KEY or key in mentioned \
                or not spec.is_element:
            continue
        if _MENTIONING_OPTIONS.intersection(spec.options):
            continue
        file, line = ctx.param_location(spec.name)
        kind = spec.element_type or "any type"
        ctx.add("uninferable",
                f"INFERRED parameter {key} is mentioned by no pre-condition, so SkiROS2 "
                f"grounds it by type alone, to the first element of {kind} in the world "
                "model: ambiguous when several elements fit (add a pre-condition relating "
                "it to another parameter, or make it REQUIRED)",
                file, line, param=key, actual=spec.element_type)


def check_declared(ctx: CheckContext) -> None:
    """Conditions refer only to declared keys (or SkiROS2's automatic Robot).

    Only ``self.param("key")`` can name another key, and a faithful migration keeps a
    legacy typo there verbatim (``"Hreon"`` beside a parameter ``Hero``), so the closest
    declared keys are suggested, ranked as misspelt vocabulary is."""
    declared = (*ctx.params, ROBOT_KEY)
    for record in ctx.trace.recorded:
        for key in dict.fromkeys(record.condition.param_keys()):
            if key in ctx.params or key == ROBOT_KEY:
                continue
            hints = tuple(closest_names(key, declared))
            ctx.add("undeclared-parameter",
                    f"{record.which}-condition {record.condition.final_label} refers to "
                    f"{key!r}, which the description does not declare (SkiROS2 keeps the "
                    "condition, but nothing can ever bind that key)"
                    f"{did_you_mean(hints)}", record.file, record.line, param=key,
                    suggestions=hints)


def check_contradictions(ctx: CheckContext) -> None:
    """No condition is wanted both true and false in the same list (pre and post may
    disagree: that is what a skill changes)."""
    seen: dict[tuple[str, Any], Recorded] = {}
    reported: set[tuple[str, Any]] = set()
    for record in ctx.trace.recorded:
        cond = record.condition
        if cond.kind == "on_type":
            continue
        identity = (record.which, cond.identity())
        first = seen.get(identity)
        if first is None:
            seen[identity] = record
            continue
        if first.condition.desired == cond.desired or identity in reported:
            continue
        reported.add(identity)
        ctx.add("contradiction",
                f"{record.which}-condition {render_condition(cond.to_model())} contradicts "
                f"line {first.line}, which requires the opposite: it can never be met",
                record.file, record.line, param=cond.subject, relation=cond.vocabulary)
    _check_equal_values(ctx)
    _check_bounds(ctx)


def _check_equal_values(ctx: CheckContext) -> None:
    """One list cannot want a property equal to two different values (``L.Open == True``
    and ``L.Open == False``): SkiROS2 compares the property's one value with each."""
    wanted: dict[tuple[str, str | None, str | None], Recorded] = {}
    for record in ctx.trace.recorded:
        cond = record.condition
        if cond.kind != "property" or cond.operator != "=" or cond.desired is not True:
            continue
        first = wanted.setdefault((record.which, cond.vocabulary, cond.subject), record)
        if first is not record and typed(first.condition.value) != typed(cond.value):
            ctx.add("contradiction",
                    f"{record.which}-condition {render_condition(cond.to_model())} wants "
                    f"{cond.vocabulary} of {cond.subject} to be {cond.value!r}, but line "
                    f"{first.line} wants {first.condition.value!r}: it can never be met",
                    record.file, record.line, param=cond.subject, relation=cond.vocabulary)


@dataclass(frozen=True)
class _Bound:
    """One side of a numeric condition's interval: ``X > 3.0`` is the lower bound 3.0,
    strict; ``X == 2`` is both bounds 2, not strict."""

    value: float
    strict: bool
    record: Recorded


_LOWER = {">": True, ">=": False, "=": False}
_UPPER = {"<": True, "<=": False, "=": False}
"""Operator -> strictness of the lower / upper bound it sets."""


def _numeric(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _empty(lower: _Bound, upper: _Bound) -> bool:
    """No number lies between the bounds."""
    if lower.value != upper.value:
        return lower.value > upper.value
    return lower.strict or upper.strict


def _tighter(old: _Bound | None, new: _Bound, sign: int) -> _Bound:
    """The bound that leaves fewer values (``sign`` 1 for lower bounds, -1 for upper)."""
    if old is None or sign * new.value > sign * old.value:
        return new
    return new if new.value == old.value and new.strict and not old.strict else old


def _check_bounds(ctx: CheckContext) -> None:
    """One list cannot bound a numeric property so that no value fits (``a.X > 3.0`` and
    ``a.X < 1.0``). Two ``==`` conditions are left to ``_check_equal_values``."""
    lowers: dict[tuple[str, str | None, str | None], _Bound] = {}
    uppers: dict[tuple[str, str | None, str | None], _Bound] = {}
    reported: set[tuple[str, str | None, str | None]] = set()
    for record in ctx.trace.recorded:
        cond = record.condition
        if cond.kind != "property" or cond.desired is not True or not _numeric(cond.value):
            continue
        group = (record.which, cond.vocabulary, cond.subject)
        if cond.operator in _LOWER:
            bound = _Bound(float(cond.value), _LOWER[cond.operator], record)
            lowers[group] = _tighter(lowers.get(group), bound, 1)
        if cond.operator in _UPPER:
            bound = _Bound(float(cond.value), _UPPER[cond.operator], record)
            uppers[group] = _tighter(uppers.get(group), bound, -1)
        lower, upper = lowers.get(group), uppers.get(group)
        if lower is None or upper is None or group in reported or not _empty(lower, upper):
            continue
        other = lower.record if lower.record is not record else upper.record
        if other.condition.operator == "=" and cond.operator == "=":
            continue  # two different values: already a contradiction of its own
        reported.add(group)
        ctx.add("contradiction",
                f"{record.which}-condition {render_condition(cond.to_model())} and line "
                f"{other.line} ({render_condition(other.condition.to_model())}) leave no "
                f"value of {cond.vocabulary} for {cond.subject}: they can never both hold",
                record.file, record.line, param=cond.subject, relation=cond.vocabulary)


__all__ = ["check_contradictions", "check_declared", "check_defaults", "check_inferable"]
