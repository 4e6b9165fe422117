"""Symbolic parameters: what ``description(self, A, B, ...)`` receives while it is traced.

``A`` stands for the parameter key ``"A"``. Attribute access names an ontology property
(``A.contain`` -> ``skiros:contain``) and gives a ``PropertyHandle``; calling the handle with
another symbol builds a relation condition, comparing it with a literal (``F.Open.eq(False)``,
or ``F.Open == False``) builds a property condition. The other condition kinds are methods,
whose names are therefore never properties (docs/dsl.md).
"""

from __future__ import annotations

from typing import Any

from ..diagnostics import DescriptionError
from .conditions import Cond, VocabularyNote
from .vocabulary import active, qname_of, resolve_property

RESERVED: frozenset[str] = frozenset(
    {"relation", "property", "has", "is_specified", "generated", "is_a", "named", "key"})


def _object_key(value: Any, what: str) -> str:
    if isinstance(value, Symbol):
        return value.key
    raise DescriptionError(
        f"{what} needs a parameter as its object (a parameter of description(...) or "
        f'self.param("key")), got {value!r}')


class Symbol:
    """The symbolic value of one parameter key during tracing."""

    __slots__ = ("_key",)
    _key: str

    def __init__(self, key: str) -> None:
        object.__setattr__(self, "_key", key)

    @property
    def key(self) -> str:
        """The skill key this symbol stands for (``KEY("On/Off")`` gives ``"On/Off"``)."""
        return self._key

    def __repr__(self) -> str:
        return f"<parameter {self._key}>"

    def __getattr__(self, name: str) -> PropertyHandle:
        if name.startswith("_"):
            raise AttributeError(name)
        vocabulary, note = resolve_property(active(), name)
        return PropertyHandle(self._key, vocabulary, note)

    def __setattr__(self, name: str, value: Any) -> None:
        raise DescriptionError(f"parameter {self._key} is symbolic while the description is "
                               f"traced; it cannot be assigned {name!r}")

    def __bool__(self) -> bool:
        raise DescriptionError(f"parameter {self._key} is symbolic while the description is "
                               "traced: it has no truth value (conditions go into "
                               "self.pre_conditions += ...)")

    def relation(self, relation: Any, other: Any) -> Cond:
        """``A.relation("cora:robotPart", B)``: a relation given verbatim."""
        vocabulary = qname_of(relation, "relation(...)")
        return Cond("relation", self._key, vocabulary, _object_key(other, "relation(...)"))

    def property(self, prop: Any, operator: str, value: Any) -> Cond:
        """``F.property("skiros:Open", "=", False)``: property and operator given verbatim."""
        if not isinstance(operator, str):
            raise DescriptionError(f"property(...) needs the operator as a str, got "
                                   f"{operator!r}")
        return Cond("property", self._key, qname_of(prop, "property(...)"),
                    operator=operator, value=value)

    def has(self, prop: Any) -> Cond:
        """``O.has(skiros.Position)``: the element has the property at all."""
        return Cond("has_property", self._key, qname_of(prop, "has(...)"))

    def is_specified(self) -> Cond:
        """``O.is_specified()``: the parameter has a value."""
        return Cond("is_specified", self._key)

    def generated(self) -> Cond:
        """``O.generated()``: the skill creates the element."""
        return Cond("generate", self._key)

    def is_a(self, owl_type: Any) -> Cond:
        """``O.is_a(skiros.Product)`` / ``O.is_a(":Product")``: the element's type."""
        return Cond("on_type", self._key, qname_of(owl_type, "is_a(...)"))

    def named(self, label: str) -> Cond:
        """Only conditions have labels; this exists so ``A.named`` is never a property."""
        raise DescriptionError(f"parameter {self._key} is not a condition: .named(...) "
                               "applies to conditions such as A.contain(B).named(...)")


class PropertyHandle:
    """``A.contain`` / ``F.Open``: a property of a parameter, waiting to become a condition."""

    __slots__ = ("note", "subject", "vocabulary")

    def __init__(self, subject: str, vocabulary: str, note: VocabularyNote | None) -> None:
        self.subject = subject
        self.vocabulary = vocabulary
        self.note = note

    def __repr__(self) -> str:
        return f"<{self.subject}.{self.vocabulary}>"

    def __call__(self, other: Any) -> Cond:
        return Cond("relation", self.subject, self.vocabulary,
                    _object_key(other, f"{self.subject}.{self.vocabulary}(...)"),
                    note=self.note)

    def _compare(self, operator: str, value: Any) -> Cond:
        if isinstance(value, (Symbol, PropertyHandle, Cond)):
            raise DescriptionError(
                f"{self.subject}.{self.vocabulary} {operator} ...: property conditions compare "
                f"with a literal value, got {value!r}")
        return Cond("property", self.subject, self.vocabulary, operator=operator, value=value,
                    note=self.note)

    # The methods below are the form the migrator writes. ``F.Open == False`` reads well
    # but every linter flags it (pycodestyle / ruff E712), and their fixes rewrite it to
    # ``not F.Open`` or ``F.Open``, which asks for the truth of a handle and changes the
    # condition. A method call is a form no linter flags and no fix rewrites. The
    # comparison operators stay for code written by hand (docs/dsl.md).

    def eq(self, value: Any) -> Cond:
        """``F.Open.eq(False)``: the property equals ``value`` (SkiROS2's ``"="``)."""
        return self._compare("=", value)

    def gt(self, value: Any) -> Cond:
        """``A.PositionX.gt(0.5)``: the property is greater than ``value``."""
        return self._compare(">", value)

    def lt(self, value: Any) -> Cond:
        """``A.PositionX.lt(0.5)``: the property is less than ``value``."""
        return self._compare("<", value)

    def ge(self, value: Any) -> Cond:
        """``A.PositionX.ge(0.5)``: the property is at least ``value``."""
        return self._compare(">=", value)

    def le(self, value: Any) -> Cond:
        """``A.PositionX.le(0.5)``: the property is at most ``value``."""
        return self._compare("<=", value)

    def ne(self, value: Any) -> Cond:
        """Exists so that ``A.prop.ne(v)`` explains itself instead of an AttributeError."""
        raise DescriptionError(f"{self.subject}.{self.vocabulary}.ne(...) has no SkiROS2 "
                               "operator: write ~ A.prop.eq(value)")

    def __eq__(self, value: object) -> Cond:  # type: ignore[override]
        return self._compare("=", value)

    def __ne__(self, value: object) -> Cond:  # type: ignore[override]
        raise DescriptionError(f"{self.subject}.{self.vocabulary} != ... has no SkiROS2 "
                               "operator: write ~ (A.prop == value) or ~ A.prop.eq(value)")

    def __gt__(self, value: Any) -> Cond:
        return self._compare(">", value)

    def __lt__(self, value: Any) -> Cond:
        return self._compare("<", value)

    def __ge__(self, value: Any) -> Cond:
        return self._compare(">=", value)

    def __le__(self, value: Any) -> Cond:
        return self._compare("<=", value)

    __hash__ = None  # type: ignore[assignment]

    def __bool__(self) -> bool:
        raise DescriptionError(f"{self.subject}.{self.vocabulary} is not a condition yet: "
                               "call it with a parameter or compare it with a value "
                               "(.eq(v), .gt(v), ... or ==, >, ...)")


__all__ = ["RESERVED", "PropertyHandle", "Symbol"]
