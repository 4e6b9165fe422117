"""Parameter annotations: kind markers, ``ELEMENT``, ``KEY`` and the option markers.

These are the words a description signature is written in (docs/dsl.md, "Parameters"). They
only *describe*: turning them into ``addParam`` arguments is ``parameters.py``'s job, so this
module has no dependency on a backend or an ontology.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, List

from ..diagnostics import DescriptionError

OPTION_NAMES: tuple[str, ...] = ("Lock", "Consume", "Unspecify", "RespectType", "Output")


@dataclass(frozen=True)
class Option:
    """A ``ParamOptions`` member by name; lowered with ``getattr(ParamOptions, name)`` so the
    same marker works with SkiROS2's enum and with the legacy backend's."""

    name: str

    def __repr__(self) -> str:
        return self.name


Lock = Option("Lock")
Consume = Option("Consume")
Unspecify = Option("Unspecify")
RespectType = Option("RespectType")
Output = Option("Output")


@dataclass(frozen=True)
class KEY:
    """The skill key of a parameter whose key is no Python identifier (``KEY("On/Off")``)."""

    key: str

    def __post_init__(self) -> None:
        if not isinstance(self.key, str):
            raise DescriptionError(f"KEY(...) needs a str, got {self.key!r}")


@dataclass(frozen=True)
class DESC:
    """A parameter's description (``OPTIONAL[float, DESC("m/s")]``).

    A bare string item works too, but linters (pyflakes, ruff F821/UP037) read a string
    inside an annotation as a forward reference, and ruff's autofix would unquote it; the
    migrator therefore always writes ``DESC``.
    """

    text: str

    def __post_init__(self) -> None:
        if not isinstance(self.text, str):
            raise DescriptionError(f"DESC(...) needs a str, got {self.text!r}")


@dataclass(frozen=True)
class ElementType:
    """``ELEMENT(":C")``: an Element parameter whose type string is kept verbatim.

    ``type_string`` ``None`` means ``Element()`` without arguments (type ``"Unknown"``).
    """

    type_string: str | None = None

    def __repr__(self) -> str:
        return "ELEMENT()" if self.type_string is None else f"ELEMENT({self.type_string!r})"


def ELEMENT(type_string: Any = None) -> ElementType:
    """An Element parameter of this verbatim type string (or an OWL class, by its qname)."""
    if type_string is None or isinstance(type_string, str):
        return ElementType(type_string)
    qname = getattr(type_string, "qname", None)
    if isinstance(qname, str):
        return ElementType(qname)
    raise DescriptionError(f"ELEMENT(...) needs a type string or an OWL class, got "
                           f"{type_string!r}")


@dataclass(frozen=True)
class ParamAnnotation:
    """A fully parsed annotation: kind, type (``None`` for a bare marker) and extras."""

    kind: str
    type: Any = None
    description: str = ""
    options: tuple[str, ...] = ()
    key: str | None = None


class Kind:
    """``INFERRED`` / ``OPTIONAL`` / ``REQUIRED``: subscript with the type and extra items, or
    use bare with a default whose value is passed as is."""

    def __init__(self, marker: str, kind: str) -> None:
        self._marker = marker
        self.kind = kind

    def __repr__(self) -> str:
        return self._marker

    def __getitem__(self, items: Any) -> ParamAnnotation:
        items = items if isinstance(items, tuple) else (items,)
        if not items:
            raise DescriptionError(f"{self._marker}[...] needs the parameter type first")
        first, rest = items[0], items[1:]
        if not _is_type_item(first):
            raise DescriptionError(
                f"{self._marker}[...]: the first item must be the type (an OWL class, "
                f"ELEMENT(...), or a Python type), got {first!r}")
        description, options, key = _items(self._marker, rest, None, (), None)
        return ParamAnnotation(self.kind, first, description or "", options, key)


def _is_type_item(item: Any) -> bool:
    """Whether an annotation item can be the parameter's type (not a description, option,
    key or kind marker)."""
    return not isinstance(item, (str, DESC, Option, KEY, Kind, ParamAnnotation, AnnotatedForm))


def _items(marker: str, items: tuple[Any, ...], description: str | None,
           options: tuple[str, ...], key: str | None
           ) -> tuple[str | None, tuple[str, ...], str | None]:
    """The description, options and key that ``items`` add to those given (the items after
    the type, in ``KIND[...]`` or ``Annotated[...]``)."""
    found = list(options)
    for item in items:
        if isinstance(item, (str, DESC)):
            text = item.text if isinstance(item, DESC) else item
            if description is not None:
                raise DescriptionError(
                    f"{marker}[...] has two descriptions: {description!r} and {text!r}")
            description = text
        elif isinstance(item, Option):
            found.append(item.name)
        elif isinstance(item, KEY):
            if key is not None:
                raise DescriptionError(f"{marker}[...] has two KEY(...) items")
            key = item.key
        else:
            raise DescriptionError(
                f"{marker}[...]: unexpected item {item!r}; after the type come a "
                f"description (DESC(...)), options ({', '.join(OPTION_NAMES)}) and KEY(...)")
    return description, tuple(found), key


class AnnotatedForm:
    """``Annotated[A, items...]``: the annotation ``A`` with more items after its type, the
    spelling that keeps strings (``DESC("...")``, ``KEY("...")``, ``ELEMENT("...")``) out of
    the parts of an annotation that linters parse.

    pyflakes (flake8's F rules) reads every string literal inside an annotation as a forward
    reference (F722, F821), except in the items after the first of a subscript named
    ``Annotated`` and inside ``Literal[...]``; ruff reads strings that are call arguments
    as values. So ``Annotated[skiros.Product, DESC("The object")]`` is
    ``REQUIRED[skiros.Product, DESC("The object")]``, ``Annotated[OPTIONAL[float],
    DESC("m/s")]`` is ``OPTIONAL[float, DESC("m/s")]``, and when ``A`` is a bare kind marker
    the first item, if it is a type, is the type: ``Annotated[INFERRED, ELEMENT(":Cam"),
    Lock]`` is ``INFERRED[ELEMENT(":Cam"), Lock]``.

    This is the DSL's own form, not ``typing.Annotated``: Python 3.8 (ROS Noetic) has none,
    and ``typing.Annotated`` refuses a kind marker as its first item before Python 3.11.
    """

    def __repr__(self) -> str:
        return "Annotated"

    def __getitem__(self, items: Any) -> ParamAnnotation:
        items = items if isinstance(items, tuple) else (items,)
        if len(items) < 2:
            raise DescriptionError(
                "Annotated[...] needs the annotation and at least one item after it, e.g. "
                "Annotated[skiros.Product, DESC(\"...\")]")
        head, rest = items[0], items[1:]
        if isinstance(head, (str, DESC, Option, KEY, AnnotatedForm)):
            raise DescriptionError(
                f"Annotated[...]: the first item must be the annotation (a type, a kind "
                f"marker or KIND[...]), got {head!r}")
        annotation = parse_annotation(head)
        tp = annotation.type
        if tp is None and _is_type_item(rest[0]):
            tp, rest = rest[0], rest[1:]
        description, options, key = _items(
            "Annotated", rest, annotation.description or None, annotation.options,
            annotation.key)
        return ParamAnnotation(annotation.kind, tp, description or "", options, key)


Annotated = AnnotatedForm()
"""``Annotated[A, items...]``: see ``AnnotatedForm``."""

INFERRED = Kind("INFERRED", "Inferred")
OPTIONAL = Kind("OPTIONAL", "Optional")
REQUIRED = Kind("REQUIRED", "Required")

LIST = List
"""``LIST[float]``: a list-valued parameter, the spelling that runs on every Python the robot
has. ``list[float]`` raises ``TypeError`` when the class is defined under ROS Noetic's Python
3.8; ``LIST`` is ``typing.List``, so both spellings mean the same from 3.9 on."""


def parse_annotation(annotation: Any) -> ParamAnnotation:
    """Any annotation as a ``ParamAnnotation``: a bare type is ``REQUIRED[type]``, a bare
    marker keeps ``type=None``, a missing annotation is a bare ``REQUIRED``."""
    if isinstance(annotation, ParamAnnotation):
        return annotation
    if isinstance(annotation, Kind):
        return ParamAnnotation(annotation.kind)
    if annotation is None:
        return ParamAnnotation("Required")
    if isinstance(annotation, AnnotatedForm):
        raise DescriptionError("a bare Annotated needs the annotation and its items: "
                               "Annotated[skiros.Product, DESC(\"...\")]")
    if isinstance(annotation, (Option, KEY, DESC, str)):
        raise DescriptionError(
            f"annotation {annotation!r} needs a kind marker, e.g. REQUIRED[float, ...]")
    return ParamAnnotation("Required", annotation)


__all__ = [
    "DESC",
    "ELEMENT",
    "INFERRED",
    "KEY",
    "LIST",
    "OPTIONAL",
    "OPTION_NAMES",
    "REQUIRED",
    "Annotated",
    "AnnotatedForm",
    "Consume",
    "ElementType",
    "Kind",
    "Lock",
    "Option",
    "Output",
    "ParamAnnotation",
    "RespectType",
    "Unspecify",
    "parse_annotation",
]
