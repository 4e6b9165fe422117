"""Condition expressions: what ``A.contain(B)``, ``F.Open.eq(False)`` and ``c1 | c2`` build.

A ``Cond`` is an immutable record of one future factory call (docs/dsl.md, "Conditions"):
nothing reaches the backend until ``lowering.py`` turns it into ``getRelationCond(...)`` and
friends. Keeping it as data lets the checks look at it first and lets ``~``, ``|``,
``.named`` and ``abstract`` be pure functions.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

from ..diagnostics import DescriptionError
from ..labels import OR_LABEL, conventional_label


@dataclass(frozen=True)
class VocabularyNote:
    """How ``A.name`` was resolved when it was not unambiguous: kept for the checks.

    ``status`` is ``"unknown"`` (fell back to the default prefix) or ``"ambiguous"`` (several
    prefixes define the local name; ``candidates`` lists them).
    """

    written: str
    status: str
    candidates: tuple[str, ...] = ()


@dataclass(frozen=True, eq=False)
class Cond:
    """One condition, as the arguments of its factory call plus DSL bookkeeping.

    ``kind`` uses the model's names (``relation``, ``abstract_relation``, ``property``,
    ``has_property``, ``is_specified``, ``generate``, ``on_type``, ``or``). ``piped`` marks
    or-conditions built by ``|`` (the only ones ``|`` flattens).
    """

    kind: str
    subject: str | None = None
    vocabulary: str | None = None
    object: str | None = None
    operator: str | None = None
    value: Any = None
    desired: bool = True
    label: str | None = None
    children: tuple[Cond, ...] = ()
    piped: bool = False
    note: VocabularyNote | None = None

    @property
    def final_label(self) -> str:
        """The explicit label, else the conventional one for the final desired state."""
        if self.kind == "or":
            return OR_LABEL
        if self.label is not None:
            return self.label
        return conventional_label(self.kind, subject=self.subject, vocabulary=self.vocabulary,
                                  object=self.object, desired_state=self.desired)

    def named(self, label: str) -> Cond:
        """The same condition with an explicit label (kept through ``~``)."""
        if self.kind == "or":
            raise DescriptionError('or-conditions are always labelled "or"; .named() cannot '
                                   "change that")
        if not isinstance(label, str):
            raise DescriptionError(f".named(...) needs a str label, got {label!r}")
        return replace(self, label=label)

    def __invert__(self) -> Cond:
        if self.kind == "on_type":
            raise DescriptionError("~ on is_a(...) has no meaning: getOnTypeCond takes no "
                                   "desired state")
        return replace(self, desired=not self.desired)

    def __or__(self, other: Any) -> Cond:
        if not isinstance(other, Cond):
            return NotImplemented
        if self.kind == "or" and self.piped and self.desired:
            children = (*self.children, other)
        else:
            children = (self, other)
        return Cond("or", children=children, piped=True)

    def __bool__(self) -> bool:
        raise DescriptionError(
            "a condition has no truth value during tracing: use | for 'or', and add "
            "conditions one by one for 'and' (and/or/not/if do not work on conditions)")

    def param_keys(self) -> tuple[str, ...]:
        """Every parameter key this condition (and its children) refers to."""
        if self.kind == "or":
            return tuple(k for child in self.children for k in child.param_keys())
        return tuple(k for k in (self.subject, self.object) if k is not None)

    def identity(self) -> tuple[Any, ...]:
        """What makes two conditions 'the same condition' apart from label and desired state
        (used to find contradictions). Values are compared type-exactly."""
        from ..model import typed

        if self.kind == "or":
            children = tuple((c.identity(), c.desired) for c in self.children)
            return ("or", children)
        return (self.kind, self.vocabulary, self.subject, self.object, self.operator,
                typed(self.value) if self.kind == "property" else None)

    def __repr__(self) -> str:
        from ..notation import render_condition

        return f"<condition {render_condition(self.to_model())}>"

    def to_model(self) -> Any:
        """This condition as a ``model.Condition`` (for rendering and tests)."""
        from ..model import Condition, typed

        if self.kind == "or":
            return Condition("or", OR_LABEL, desired_state=typed(self.desired),
                             children=tuple(c.to_model() for c in self.children))
        return Condition(
            self.kind, self.final_label, vocabulary=self.vocabulary, subject=self.subject,
            object=self.object, operator=self.operator,
            value=typed(self.value) if self.kind == "property" else None,
            desired_state=None if self.kind == "on_type" else typed(self.desired))


def abstract(condition: Cond) -> Cond:
    """``abstract(A.contain(B))``: the same relation over abstract (class-level) elements."""
    if not isinstance(condition, Cond) or condition.kind not in ("relation",
                                                                 "abstract_relation"):
        raise DescriptionError(f"abstract(...) needs a relation condition such as "
                               f"abstract(A.contain(B)), got {condition!r}")
    return replace(condition, kind="abstract_relation")


def any_of(*conditions: Cond) -> Cond:
    """An or-condition with exactly these children: no flattening, unlike ``|``."""
    for c in conditions:
        if not isinstance(c, Cond):
            raise DescriptionError(f"any_of(...) takes conditions, got {c!r}")
    return Cond("or", children=tuple(conditions), piped=False)


__all__ = ["Cond", "VocabularyNote", "abstract", "any_of"]
