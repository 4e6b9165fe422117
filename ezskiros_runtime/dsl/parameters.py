"""The signature of ``description(self, ...)`` as the list of ``addParam`` calls it means.

Step (1) of the lowering order (docs/dsl.md): every parameter after ``self``, in order, with
its annotation (evaluated in the function's module globals when it is a string) and default,
becomes a ``ParamSpec``. The spec knows the exact ``addParam`` arguments and, for the checks,
the parameter's OWL class and whether its default fits its annotation.
"""

from __future__ import annotations

import inspect
import types
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, get_origin

from ..diagnostics import DescriptionError
from .markers import ElementType, ParamAnnotation, parse_annotation

_EMPTY = inspect.Parameter.empty


@dataclass(frozen=True)
class ParamSpec:
    """One parameter: the ``addParam`` arguments plus what the checks need.

    ``value_mode`` says how ``addParam``'s value is built: ``"element"`` (a fresh
    ``Element(element_type)``, or ``Element()`` when ``element_type`` is None), ``"type"``
    (the type object ``value``) or ``"literal"`` (the default ``value`` as written).
    ``mismatch`` is the reason the default does not fit the annotation, if it does not.
    """

    name: str
    key: str
    kind: str
    value_mode: str
    value: Any = None
    element_type: str | None = None
    options: tuple[str, ...] = ()
    description: str = ""
    mismatch: str | None = None
    keyword_only: bool = False

    @property
    def is_element(self) -> bool:
        return self.value_mode == "element"


def _element_type(tp: Any) -> tuple[bool, str | None]:
    """(is it an element type, its verbatim type string) for an annotation's type item."""
    if isinstance(tp, ElementType):
        return True, tp.type_string
    qname = getattr(tp, "qname", None)
    if isinstance(tp, type) and isinstance(qname, str) and hasattr(tp, "iri"):
        return True, qname
    return False, None


def _generic_origin(tp: Any) -> Any:
    """``list`` for ``list[float]``, ``typing.List[float]`` and the DSL's ``LIST[float]``;
    None for anything that is not a subscripted generic. ``typing.get_origin`` reads all
    three alike, where ``types.GenericAlias`` exists only from Python 3.9 (the robot's ROS
    Noetic runs 3.8, where ``typing.List[float]`` is the only spelling that runs)."""
    return get_origin(tp) if getattr(tp, "__args__", None) else None


def _type_name(tp: Any) -> str:
    return getattr(tp, "__name__", None) or repr(tp)


def _default_mismatch(tp: Any, default: Any) -> str | None:
    """Why ``default`` does not fit the annotated type (docs/dsl.md rules), or None."""
    if _generic_origin(tp) is list:
        (item,) = getattr(tp, "__args__", None) or (object,)
        if type(default) is not list or not default:
            return f"list[{_type_name(item)}] needs a non-empty list default, got {default!r}"
        wrong = [x for x in default if type(x) is not item]
        if wrong:
            return (f"list[{_type_name(item)}] default {default!r} has item {wrong[0]!r} of "
                    f"type {type(wrong[0]).__name__}")
        return None
    if type(default) is not tp:
        return (f"default {default!r} is {type(default).__name__}, but the annotation says "
                f"{_type_name(tp)}")
    return None


def _spec(name: str, ann: ParamAnnotation, default: Any, keyword_only: bool) -> ParamSpec:
    key = ann.key if ann.key is not None else name
    mode, value, element_type, mismatch = _value(name, ann, default)
    return ParamSpec(name=name, key=key, kind=ann.kind, value_mode=mode, value=value,
                     element_type=element_type, options=ann.options,
                     description=ann.description, mismatch=mismatch, keyword_only=keyword_only)


def star_parameters(qualname: str) -> DescriptionError:
    """The error of a ``description`` (``qualname``: ``Pick.description``) that takes
    ``*args`` or ``**kwargs``: whether traced or read from its syntax (``ezmigrate
    check``), the same words."""
    return DescriptionError(f"{qualname}: *args / **kwargs are not skill parameters; "
                            "declare every parameter explicitly")


def spec_of(name: str, annotation: Any, default: Any, keyword_only: bool) -> ParamSpec:
    """One parameter from its evaluated annotation and default (``_EMPTY`` for none): what
    ``evaluate_signature`` does per parameter, for a caller that evaluated them itself
    (``ezmigrate check`` reads the signature from the syntax, without running the module)."""
    return _spec(name, parse_annotation(annotation), _EMPTY if default is NO_DEFAULT else default,
                 keyword_only)


NO_DEFAULT = _EMPTY
"""The default of a parameter that has none, for ``spec_of``."""


def _value(name: str, ann: ParamAnnotation, default: Any
           ) -> tuple[str, Any, str | None, str | None]:
    """(value mode, value, element type string, default mismatch) of one parameter."""
    if ann.type is None:  # bare kind marker (or no annotation): the default is the value
        if default is _EMPTY:
            raise DescriptionError(
                f"parameter {name}: a kind marker without a type needs a default value "
                f"(write e.g. {name}: OPTIONAL[float] or {name}: OPTIONAL = CONSTANT)")
        return "literal", default, None, None
    is_element, type_string = _element_type(ann.type)
    if is_element:
        mismatch = None if default is _EMPTY else (
            f"an Element parameter takes no default, got {default!r}")
        return "element", None, type_string, mismatch
    if _generic_origin(ann.type) is not None:
        if _generic_origin(ann.type) is not list:
            raise DescriptionError(f"parameter {name}: only list[T] is supported as a generic "
                                   f"type, got {ann.type!r}")
        if default is _EMPTY:
            raise DescriptionError(f"parameter {name}: {ann.type!r} needs a non-empty list "
                                   "default (SkiROS2 takes the item type from it)")
    elif not isinstance(ann.type, type):
        raise DescriptionError(
            f"parameter {name}: {ann.type!r} is not a type; use an OWL class (skiros.C), "
            "ELEMENT(...), a Python type, or a bare kind marker with a default")
    if default is _EMPTY:
        return "type", ann.type, None, None
    return "literal", default, None, _default_mismatch(ann.type, default)


_CODE: dict[str, types.CodeType] = {}
"""Compiled annotation strings: real skill files repeat the same few annotations a lot."""


def _evaluate(annotation: str, module_globals: dict[str, Any]) -> Any:
    code = _CODE.get(annotation)
    if code is None:
        code = _CODE[annotation] = compile(annotation, "<annotation>", "eval")
    return eval(code, module_globals)  # the documented rule: the module's globals


def _raw_parameters(func: Callable[..., Any]) -> list[tuple[str, Any, bool]]:
    """(name, default, keyword-only) of every parameter after ``self``, read from the code
    object: ``inspect.signature`` does the same but costs more than the rest of tracing."""
    code = getattr(func, "__code__", None)
    if code is None:
        raise DescriptionError(f"description must be a plain function, got {func!r}")
    if code.co_flags & (inspect.CO_VARARGS | inspect.CO_VARKEYWORDS):
        raise star_parameters(func.__qualname__)
    positional = code.co_varnames[:code.co_argcount]
    keyword = code.co_varnames[code.co_argcount:code.co_argcount + code.co_kwonlyargcount]
    defaults = getattr(func, "__defaults__", None) or ()
    kwdefaults = getattr(func, "__kwdefaults__", None) or {}
    first_default = len(positional) - len(defaults)
    found = [(name, defaults[i - first_default] if i >= first_default else _EMPTY, False)
             for i, name in enumerate(positional)]
    found += [(name, kwdefaults.get(name, _EMPTY), True) for name in keyword]
    return found[1:]  # self


def evaluate_signature(func: Callable[..., Any]) -> tuple[ParamSpec, ...]:
    """The parameters of ``description`` in signature order (``self`` excluded)."""
    module_globals = getattr(func, "__globals__", {})
    annotations = getattr(func, "__annotations__", None) or {}
    specs: list[ParamSpec] = []
    for name, default, keyword_only in _raw_parameters(func):
        annotation = annotations.get(name)
        if isinstance(annotation, str):
            annotation = _evaluate(annotation, module_globals)
        specs.append(_spec(name, parse_annotation(annotation), default, keyword_only))
    return tuple(specs)


def call_arguments(specs: tuple[ParamSpec, ...], symbols: dict[str, Any]
                   ) -> tuple[list[Any], dict[str, Any]]:
    """Arguments that pass each parameter its symbol: keyword-only ones by name, the others
    by position (positional-only parameters cannot be passed by name)."""
    args = [symbols[s.name] for s in specs if not s.keyword_only]
    kwargs = {s.name: symbols[s.name] for s in specs if s.keyword_only}
    return args, kwargs


__all__ = ["NO_DEFAULT", "ParamSpec", "call_arguments", "evaluate_signature", "spec_of",
           "star_parameters"]
