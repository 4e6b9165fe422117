"""What a legacy description declares, as plain picklable data with source lines.

The IR the codemod reads (``codemod/core/ir.py``) holds libcst nodes (comments) that are
heavy to send between processes. These facts keep only what the early checks need (keys,
values, types, conditions and the line of each), so a worker returns them with its
``FileResult`` and ``check`` runs the runtime's checks on them without importing the user's
code. ``codemod/core/declared.py`` derives them from the IR.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any


@dataclass(frozen=True)
class ParamFact:
    """One ``addParam``: ``mode`` is ``element``, ``type`` or ``literal`` (as ``ParamSpec``).

    ``own`` is False for a parameter inlined from a base class's ``createDescription``.
    """

    key: str
    kind: str
    mode: str
    line: int
    value: Any = None
    type_name: str | None = None
    element_type: str | None = None
    options: tuple[str, ...] = ()
    own: bool = True


@dataclass(frozen=True)
class CondFact:
    """One condition as its factory's arguments; children for or-conditions."""

    kind: str
    line: int
    subject: str | None = None
    vocabulary: str | None = None
    object: str | None = None
    operator: str | None = None
    value: Any = None
    desired: bool = True
    label: str | None = None
    children: tuple[CondFact, ...] = ()


@dataclass(frozen=True)
class StaticDescription:
    """The parameters and the ``(which, condition)`` additions of one description."""

    params: tuple[ParamFact, ...] = ()
    conditions: tuple[tuple[str, CondFact], ...] = field(default_factory=tuple)
