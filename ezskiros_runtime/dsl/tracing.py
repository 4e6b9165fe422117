"""Steps (1) and (2) of the lowering order: evaluate the signature, run the body on symbols.

The body of ``description`` is ordinary Python; calling it with one ``Symbol`` per parameter
makes every condition it builds a record (via the collectors) instead of a world-model query.
The evaluated signature is cached per function and ontology index, because annotation
strings need an ``eval`` and that dominates the cost of a 1,000-skill launch otherwise.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from .check_context import Trace
from .parameters import ParamSpec, call_arguments, evaluate_signature
from .symbols import Symbol
from .vocabulary import active

_SIGNATURES: dict[Callable[..., Any], tuple[object, tuple[ParamSpec, ...]]] = {}


def find_description(cls: type, base: type) -> Callable[..., Any] | None:
    """The ``description`` method ``cls`` defines or inherits from an EzSkiROS class below
    ``base`` (the runtime's ``SkillDescription``); None when there is none."""
    for klass in cls.__mro__:
        if klass is base:
            return None
        func = klass.__dict__.get("description")
        if func is not None:
            if not callable(func):
                raise TypeError(f"{klass.__qualname__}.description must be a method")
            return func
    return None


def signature_of(func: Callable[..., Any]) -> tuple[ParamSpec, ...]:
    """The parameter specs of ``func``, evaluated once per active ontology index."""
    index = active()
    cached = _SIGNATURES.get(func)
    if cached is not None and cached[0] is index:
        return cached[1]
    specs = evaluate_signature(func)
    _SIGNATURES[func] = (index, specs)
    return specs


def trace(instance: Any, func: Callable[..., Any]) -> Trace:
    """Run ``func(instance, *symbols)`` and return what it declared and recorded."""
    specs = signature_of(func)
    symbols = {spec.name: Symbol(spec.key) for spec in specs}
    args, kwargs = call_arguments(specs, symbols)
    records = instance.__dict__.setdefault("_ez_recorded", [])
    start = len(records)
    instance.__dict__["_ez_tracing"] = True
    try:
        func(instance, *args, **kwargs)
    finally:
        instance.__dict__["_ez_tracing"] = False
    return Trace(type(instance).__name__, func, specs, tuple(records[start:]))


__all__ = ["find_description", "signature_of", "trace"]
