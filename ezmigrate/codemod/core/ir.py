"""The intermediate form of one legacy description: the legacy API calls it makes, as data.

Extraction turns ``createDescription`` into a list of these operations; replay feeds them
to the legacy backend to get the static model; emission writes them as EzSkiROS. Keeping the
calls (not the model) in the middle is what lets one rule own one construct end to end.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from ...report.results import review_finding

if TYPE_CHECKING:
    import libcst as cst

    from ezskiros_runtime.diagnostics import Finding
else:
    from .lazy_cst import cst


class Unsupported(Exception):
    """A construct that cannot be translated faithfully; the whole skill is then skipped.

    ``reason`` is written for the user: what was found and what they can do about it.
    """

    def __init__(self, reason: str, node: cst.CSTNode | None = None) -> None:
        super().__init__(reason)
        self.reason = reason
        self.node = node


@dataclass
class Literal:
    """A literal Python value with the exact source text it was written as (``1e-3``)."""

    value: Any
    code: str


@dataclass
class ElementValue:
    """``Element("type")`` (``type_string`` verbatim) or the ``Element`` class (``None``)."""

    type_string: str | None
    is_class: bool = False


@dataclass
class TypeValue:
    """A Python type object used as the value: ``float``, ``str``, ``dict`` ..."""

    name: str


@dataclass
class OpaqueValue:
    """A value written as an expression (a module constant): passed on as written.

    ``known`` is the literal a module-level constant is bound to, when it is bound once;
    its type then gives the parameter's annotation.
    """

    code: str
    known: Literal | None = None


ParamValue = Literal | ElementValue | TypeValue | OpaqueValue


@dataclass
class Comments:
    """The comments that belonged to a legacy statement, kept as libcst nodes.

    ``leading`` are the original lines above the statement (comments and blank lines),
    ``inner`` the comments inside a multi-line call, ``trailing`` the end-of-line comment.
    """

    leading: list[cst.EmptyLine] = field(default_factory=list)
    inner: list[str] = field(default_factory=list)
    trailing: cst.Comment | None = None

    def texts(self) -> list[str]:
        """All comment texts, top to bottom (for places that can only hold plain lines)."""
        lines = [line.comment.value for line in self.leading if line.comment is not None]
        return lines + self.inner + ([self.trailing.value] if self.trailing else [])


@dataclass
class ParamOp:
    """One ``addParam`` call, resolved.

    ``options`` holds the ``ParamOptions`` member names; ``options_text`` is set instead when
    a string landed in the options slot (the silent-drop quirk of legacy-skiros2-api.md §3).
    ``description`` is ``None`` when none was passed.
    """

    key: str
    value: ParamValue
    kind: str
    options: list[str]
    description: str | None
    line: int
    options_text: str | None = None
    description_code: str | None = None
    comments: Comments = field(default_factory=Comments)


@dataclass
class CondSpec:
    """One condition object, as built by a factory or a condition class.

    For ``kind == "or"`` the children list is shared with every reference to the object, so
    an ``addCondition`` after ``addPreCondition`` is still seen, as in SkiROS2.
    """

    kind: str
    label: Literal | None
    line: int
    vocabulary: str | None = None
    subject: str | None = None
    object: str | None = None
    operator: str | None = None
    value: Literal | None = None
    desired: Literal | None = None
    children: list[CondSpec] = field(default_factory=list)


@dataclass
class AddCondition:
    """``addPreCondition`` / ``addHoldCondition`` / ``addPostCondition`` of a condition."""

    which: str
    condition: CondSpec
    line: int
    comments: Comments = field(default_factory=Comments)


@dataclass
class KeptStatement:
    """A statement that stays as written (``self.setAvailableForPlanning(False)``).

    ``literal_local`` names the local a ``name = "literal"`` statement binds: once extraction
    inlined every read of it, the assignment is dead and goes (its comments stay).
    """

    node: cst.BaseSmallStatement
    line: int
    comments: Comments = field(default_factory=Comments)
    literal_local: str | None = None


@dataclass
class CommentOnly:
    """Comments of a statement that disappears (a local assignment that gets inlined)."""

    comments: Comments


Operation = ParamOp | AddCondition | KeptStatement | CommentOnly


@dataclass
class ExtractedSkill:
    """Everything extraction learnt about one description class."""

    name: str
    line: int
    operations: list[Operation] = field(default_factory=list)
    docstring: cst.SimpleStatementLine | None = None
    footer: list[cst.EmptyLine] = field(default_factory=list)
    has_create_description: bool = True
    findings: list[Finding] = field(default_factory=list)
    inlined_at: dict[int, int] = field(default_factory=dict)
    """``id`` of an operation inlined from a base's ``createDescription`` -> the line of that
    call in this file (the operation's own lines may belong to another file)."""

    def params(self) -> list[ParamOp]:
        return [op for op in self.operations if isinstance(op, ParamOp)]

    def conditions(self) -> list[AddCondition]:
        return [op for op in self.operations if isinstance(op, AddCondition)]

    def source_lines(self) -> dict[tuple[str, str], int]:
        """First line in this file that mentions a term: ``("key", k)`` for a condition's
        subject or object, ``("type", t)`` for an Element type, ``("vocabulary", v)`` for a
        condition's relation, property or class. Lets findings point at their cause."""
        lines: dict[tuple[str, str], int] = {}
        for op in self.operations:
            inlined = self.inlined_at.get(id(op))
            if isinstance(op, ParamOp) and isinstance(op.value, ElementValue) \
                    and op.value.type_string is not None:
                lines.setdefault(("type", op.value.type_string), inlined or op.line)
            elif isinstance(op, AddCondition):
                pending = [op.condition]
                while pending:
                    spec = pending.pop(0)
                    line = inlined or spec.line
                    for key in (spec.subject, spec.object):
                        if key is not None:
                            lines.setdefault(("key", key), line)
                    if spec.vocabulary is not None:
                        lines.setdefault(("vocabulary", spec.vocabulary), line)
                    pending += spec.children
        return lines

    def finding(self, kind: str, line: int, message: str) -> None:
        """Record something worth a reviewer's eye that migration keeps as it was."""
        self.findings.append(review_finding(kind, self.name, line, message))
