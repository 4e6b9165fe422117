"""What every early check needs: the traced description, the index, and a findings sink.

The checks run on the *traced* description (parameter specs and recorded ``+=`` conditions,
each with its file and line), not on the backend's lists: that is where the source
positions are, and option-generated conditions (``Lock`` ...) are SkiROS2's, not the user's.
"""

from __future__ import annotations

import ast
import inspect
import textwrap
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from ..diagnostics import Finding
from .collectors import Recorded
from .parameters import ParamSpec
from .policy import severity_of
from .vocabulary import normalized_name, to_iri

if TYPE_CHECKING:
    from ..ontology.index import OntologyIndex

ROBOT_KEY = "Robot"
ROBOT_TYPE = "sumo:Agent"
"""SkiROS2's automatic parameter (``generateDefParams``): key and Element type."""


@dataclass(frozen=True)
class Trace:
    """A traced description: the function, its parameters and the recorded conditions."""

    skill: str
    func: Callable[..., Any] | None
    specs: tuple[ParamSpec, ...]
    recorded: tuple[Recorded, ...]
    locations: Mapping[str, tuple[str, int]] = field(default_factory=dict)
    """File and line of each parameter, when the description was read from its syntax
    (``ezmigrate check`` reads it without running it: ``func`` is then None)."""
    defined_at: tuple[str | None, int | None] = (None, None)
    """File and line of ``def description`` when ``func`` is None."""


@dataclass
class CheckContext:
    """Shared state of one check run; ``add`` applies the severity policy."""

    trace: Trace
    index: OntologyIndex
    findings: list[Finding] = field(default_factory=list)

    def __post_init__(self) -> None:
        self.params: dict[str, ParamSpec] = {}
        for spec in self.trace.specs:  # a redeclared key replaces the first (SkiROS2 §8.3)
            self.params[spec.key] = spec
        self._classes: dict[str, tuple[str | None, str]] = {}

    @property
    def skill(self) -> str:
        return self.trace.skill

    def add(self, kind: str, message: str, file: str | None, line: int | None,
            unresolved: bool = False, **details: Any) -> None:
        """Record a finding unless policy switched its kind off. ``unresolved``: the check
        could not decide (a prefix no loaded file defines: the lab's ontology may simply
        not be loaded here), so the finding is ``info``, which the robot does not print and
        strict mode does not raise."""
        severity = severity_of(kind)
        if unresolved and severity != "off":
            severity = "info"
        if severity != "off":
            self.findings.append(Finding(kind, severity, message, file, line, self.skill,
                                         **details))

    def element_type(self, key: str) -> str | None:
        """The verbatim Element type of a parameter key (the automatic Robot included)."""
        spec = self.params.get(key)
        if spec is None:
            return ROBOT_TYPE if key == ROBOT_KEY else None
        return spec.element_type if spec.is_element else None

    def class_of(self, key: str) -> tuple[str | None, str]:
        """(class IRI or None when unknown/not an element, display name) of a parameter."""
        cached = self._classes.get(key)
        if cached is None:
            type_string = self.element_type(key)
            if type_string is None or type_string == "Unknown":
                cached = (None, type_string or "")
            else:
                iri = to_iri(self.index, type_string)
                known = iri is not None and self.index.is_class(iri)
                cached = (iri if known else None, normalized_name(self.index, type_string))
            self._classes[key] = cached
        return cached

    def param_location(self, name: str) -> tuple[str | None, int | None]:
        """File and line of parameter ``name`` in the ``def description`` signature (looked up
        in the source only on this error path; the ``def`` line when the source is gone or
        cannot be read: a lookup must never make a valid class unloadable)."""
        known = self.trace.locations.get(name)
        if known is not None:
            return known
        func = self.trace.func
        if func is None:
            return self.trace.defined_at
        code = getattr(func, "__code__", None)
        file = code.co_filename if code is not None else None
        first = code.co_firstlineno if code is not None else None
        try:
            lines, start = inspect.getsourcelines(func)
            tree = ast.parse(textwrap.dedent("".join(lines)))
        except Exception:  # OSError, TokenError, SyntaxError, ...: no source, no harm
            return file, first
        for node in ast.walk(tree):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                args = node.args
                for arg in (*args.posonlyargs, *args.args, *args.kwonlyargs):
                    if arg.arg == name:
                        return file, start + arg.lineno - 1
                break
        return file, first


__all__ = ["ROBOT_KEY", "ROBOT_TYPE", "CheckContext", "Trace"]
