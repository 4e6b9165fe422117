"""Lowering: parameter specs and condition expressions -> the backend's public API calls.

This is the only module that talks to the backend description (SkiROS2's own class or the
legacy re-implementation), and it uses only what legacy code uses: ``addParam``, the
condition factories, ``getOrCond().addCondition`` and ``add{Pre,Hold,Post}Condition``. That
is what makes a migrated skill behave exactly like its legacy original on a real robot:
SkiROS2 itself expands options, replaces duplicate keys and appends conditions.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from ..diagnostics import Finding, SkillTypeError
from .backend import Backend
from .collectors import Recorded
from .conditions import Cond
from .parameters import ParamSpec

ADDERS: dict[str, str] = {
    "pre": "addPreCondition",
    "hold": "addHoldCondition",
    "post": "addPostCondition",
}


def param_value(spec: ParamSpec, backend: Backend) -> Any:
    """The ``addParam`` value: a fresh ``Element`` each time, the type object, or the default
    (lists and dicts copied, so instances never share a mutable default)."""
    if spec.value_mode == "element":
        element = backend.Element
        return element() if spec.element_type is None else element(spec.element_type)
    if spec.value_mode == "literal" and type(spec.value) in (list, dict):
        return spec.value.copy()
    return spec.value


def lower_param(description: Any, spec: ParamSpec, backend: Backend) -> None:
    """``addParam(key, value, ParamTypes.<kind>, [ParamOptions...], description)``."""
    options = [getattr(backend.ParamOptions, name) for name in spec.options]
    description.addParam(spec.key, param_value(spec, backend),
                         getattr(backend.ParamTypes, spec.kind), options, spec.description)


def build_condition(description: Any, cond: Cond) -> Any:
    """The backend condition object for ``cond``, built by the matching factory."""
    kind = cond.kind
    if kind == "or":
        result = description.getOrCond(cond.desired)
        for child in cond.children:
            result.addCondition(build_condition(description, child))
        return result
    label = cond.final_label
    if kind == "relation":
        return description.getRelationCond(label, cond.vocabulary, cond.subject, cond.object,
                                           cond.desired)
    if kind == "abstract_relation":
        return description.getAbstractRelationCond(label, cond.vocabulary, cond.subject,
                                                   cond.object, cond.desired)
    if kind == "property":
        return description.getPropCond(label, cond.vocabulary, cond.subject, cond.operator,
                                       cond.value, cond.desired)
    if kind == "has_property":
        return description.getHasPropCond(label, cond.vocabulary, cond.subject, cond.desired)
    if kind == "is_specified":
        return description.getIsSpecifiedCond(label, cond.subject, cond.desired)
    if kind == "generate":
        return description.getGenerateCond(label, cond.subject, cond.desired)
    if kind == "on_type":
        return description.getOnTypeCond(label, cond.subject, cond.vocabulary)
    raise ValueError(f"unknown condition kind {kind!r}")  # pragma: no cover - Cond kinds


def lower_condition(description: Any, which: str, cond: Cond) -> None:
    """Build ``cond`` and add it to the ``which`` list (``pre``/``hold``/``post``)."""
    getattr(description, ADDERS[which])(build_condition(description, cond))


def lower_all(description: Any, specs: Iterable[ParamSpec], recorded: Iterable[Recorded],
              backend: Backend) -> None:
    """Steps (3) and (4): every ``addParam`` in signature order, then every condition in
    ``+=`` order (each list keeps its own order; across lists the order of the source is
    kept, so the call sequence matches the legacy code it was migrated from)."""
    for spec in specs:
        lower_param(description, spec, backend)
    for record in recorded:
        lower_condition(description, record.which, record.condition)


def lower_checked(description: Any, specs: Iterable[ParamSpec],
                  recorded: Iterable[Recorded], findings: Iterable[Finding],
                  backend: Backend) -> None:
    """``lower_all``, where a failure of the backend on a description the early checks
    already found errors in raises those errors (``SkillTypeError``) instead: SkiROS2
    itself rejects some bad defaults ([] or mixed lists) with a less helpful message."""
    try:
        lower_all(description, specs, recorded, backend)
    except Exception as exc:
        errors = [f for f in findings if f.severity == "error"]
        if errors:
            raise SkillTypeError(errors) from exc
        raise


__all__ = ["ADDERS", "build_condition", "lower_all", "lower_checked", "lower_condition",
           "lower_param", "param_value"]
