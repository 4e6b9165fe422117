"""What the early checks report, as data, and the exceptions and warning category they raise.

A ``Finding`` is plain data so that ``ezmigrate`` can put it in a report and a test can assert
on its fields; the message is only one of them. The exceptions carry the findings that caused
them, so a caller that catches ``SkillTypeError`` still has the structured facts.

This module imports nothing from the rest of the runtime but the catalogue of codes (itself
a leaf): the namespaces, the DSL and the legacy loader all depend on it, never the other way
round.
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Sequence
from dataclasses import asdict, dataclass
from typing import Any, Literal

from .codes import code_for

Severity = Literal["error", "warning", "info"]
SEVERITIES: tuple[str, ...] = ("error", "warning", "info")


@dataclass(frozen=True)
class Finding:
    """One problem found in a skill description.

    ``kind`` is a stable identifier (``"range"``, ``"unknown-vocabulary"``, ...) that policy
    and reports key on; ``message`` is the human sentence without location, which ``str()``
    prefixes with ``file:line: Skill:`` so that editors and terminals can jump to the line.
    It is the one finding type of every pass, here and in ``ezmigrate``: the early checks,
    a class that could not be loaded (``class_error``), the compound and world checks and
    the findings a migration keeps for its reviewer.
    """

    kind: str
    severity: str
    message: str
    file: str | None
    line: int | None
    skill: str
    param: str | None = None
    relation: str | None = None
    expected: str | None = None
    actual: str | None = None
    suggestions: tuple[str, ...] = ()
    subject: str = ""
    """What else the finding is about: a scene's element, an ontology term, a child skill,
    the prefix no loaded ontology defines (the scene diagram highlights it; one cause is
    reported once by it)."""
    fix: str | None = None
    """The suggested fix, when the pass knows one (``Did you mean ...?``)."""
    legacy_line: int | None = None
    """The line in the legacy file when ``line`` is that of the file migrated from it
    (``ezmigrate rewrite``'s report names the written line, which a reviewer opens, and this
    one beside it); None when no file was rewritten. A field of the finding rather than a
    map beside the report, so that every printer reads one finding, as it reads a skill's
    own ``legacy_line``."""

    @property
    def code(self) -> str:
        """The stable code of ``kind`` in the catalogue (``ezskiros_runtime.codes``)."""
        return code_for(self.kind)

    @property
    def location(self) -> str:
        """``path:line`` (relative to the working directory when below it), or ``""``."""
        if not self.file:
            return ""
        path = _readable_path(self.file)
        return f"{path}:{self.line}" if self.line is not None else path

    def __str__(self) -> str:
        where = self.location
        prefix = f"{where}: " if where else ""
        return f"{prefix}{self.skill}: {self.message}"

    def to_json(self) -> dict[str, Any]:
        """A JSON-ready dict (suggestions as a list)."""
        data = asdict(self)
        data["suggestions"] = list(self.suggestions)
        data["code"] = self.code
        return data

    @classmethod
    def from_json(cls, data: dict[str, Any]) -> Finding:
        """The finding ``to_json`` wrote (across a process boundary): ``code`` is derived."""
        fields = {k: v for k, v in data.items() if k in cls.__dataclass_fields__}
        return cls(**{**fields, "suggestions": tuple(data.get("suggestions") or ())})


def class_error(skill: str, line: int | None, message: str, file: str | None = None,
                kind: str = "description") -> Finding:
    """The finding of a description class that could not be loaded at all (instantiating it
    raised): an error at the ``class`` statement's ``line``, whose ``message`` is the
    exception. ``kind`` is ``"not-upstream-api"`` for a fork's API (legacy-skiros2-api.md
    §7), ``"not-declarative"`` for a ``ConditionFunction``, ``"description"`` for anything
    else: all three EZ108, as ``check`` reports them. The loader and ``check``'s reading of
    an EzSkiROS file (``ezmigrate/lint/ezskiros_static.py``) make them here, so that both
    give the same finding."""
    return Finding(kind, "error", message, file, line, skill)


def _readable_path(path: str) -> str:
    """Shorten absolute paths below the working directory; leave everything else alone."""
    try:
        relative = os.path.relpath(path)
    except ValueError:  # another drive on Windows
        return path
    return path if relative.startswith("..") else relative


class SkillTypeError(TypeError):
    """A skill description violates the ontology (or, in strict mode, has any finding).

    Raised at instantiation, before the robot moves. The message has one line per error, each
    naming the file and line of the offending ``+=``; ``findings`` keeps them as data.
    """

    def __init__(self, findings: Sequence[Finding]) -> None:
        self.findings: tuple[Finding, ...] = tuple(findings)
        super().__init__("\n".join(str(f) for f in self.findings) or "skill type error")


class DescriptionError(TypeError):
    """The DSL itself is used wrongly (``*args``, ``~`` on ``is_a``, a malformed marker).

    Unlike ``SkillTypeError`` this is not about the ontology: the description cannot even be
    lowered, so it is raised at once where the mistake happens.
    """


class UnknownPrefixError(ImportError):
    """``from ezskiros_runtime.ontology import skirso``: no such prefix in the ontology.

    An ``ImportError``, not an ``AttributeError``: Python replaces an ``AttributeError``
    raised during ``from ... import`` by its own message, which would drop the "did you
    mean". It is raised only for lookups made by an import statement; ``ontology.skirso``,
    ``hasattr`` and ``getattr(..., default)`` get an ``UnknownVocabularyError`` (an
    ``AttributeError``), so they keep their usual meaning.
    """

    def __init__(self, message: str, *, name: str, suggestions: Iterable[str] = ()) -> None:
        super().__init__(message, name="ezskiros_runtime.ontology")
        self.prefix = name
        self.suggestions = tuple(suggestions)


class UnknownVocabularyError(AttributeError):
    """A namespace or ontology-module attribute names nothing the active ontology defines.

    An ``AttributeError`` so that ``hasattr(skiros, "Foo")`` and ``getattr(..., default)``
    keep their usual meaning; ``suggestions`` are the closest names in ``prefix.Name`` form.
    """

    def __init__(self, message: str, *, name: str, suggestions: Iterable[str] = ()) -> None:
        super().__init__(message)
        self.name = name
        self.suggestions: tuple[str, ...] = tuple(suggestions)


class EzSkirosWarning(UserWarning):
    """The category of every warning the early checks emit (filter it with ``-W``)."""


def did_you_mean(suggestions: Sequence[str]) -> str:
    """`` (did you mean a or b?)`` or ``""``: the one phrasing every message uses."""
    if not suggestions:
        return ""
    if len(suggestions) == 1:
        return f" (did you mean {suggestions[0]}?)"
    return f" (did you mean {', '.join(suggestions[:-1])} or {suggestions[-1]}?)"


__all__ = [
    "SEVERITIES",
    "DescriptionError",
    "EzSkirosWarning",
    "Finding",
    "Severity",
    "SkillTypeError",
    "UnknownVocabularyError",
    "class_error",
    "did_you_mean",
]
