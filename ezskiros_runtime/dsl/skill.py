"""``SkillDescription``: the base class of EzSkiROS descriptions, on whichever backend.

It *is* a SkiROS2 ``SkillDescription`` (SkiROS2's own class on a robot, the legacy
re-implementation elsewhere), so the skill manager, ``setDescription`` and every legacy method
keep working. Its ``createDescription`` traces ``description`` and lowers it through the
backend's public API; ``__init__`` then lets the backend run ``generateDefParams`` as usual
and finally runs the early checks (docs/dsl.md, "Lowering order").

A class without ``description`` declares nothing (it still gets SkiROS2's automatic
``Robot``), and a class that overrides ``createDescription`` itself is plain legacy code.
"""

from __future__ import annotations

import sys
from typing import Any

from ..diagnostics import DescriptionError, Finding
from .backend import Backend, select_backend
from .check_context import Trace
from .checking import report, run_checks
from .collectors import CollectorSlot
from .conditions import Cond
from .lowering import lower_checked, lower_condition
from .symbols import Symbol
from .tracing import find_description, trace

BACKEND: Backend = select_backend()
"""The backend chosen when this module was imported (see ``backend.py``)."""

_Base: Any = BACKEND.SkillDescription


class SkillDescription(_Base):
    """Derive from this and define ``description(self, <params>)`` (docs/dsl.md)."""

    pre_conditions = CollectorSlot("pre")
    hold_conditions = CollectorSlot("hold")
    post_conditions = CollectorSlot("post")

    findings: list[Finding]
    """What the early checks found when this instance was built (empty when clean)."""

    def __init_subclass__(cls, **kwargs: Any) -> None:
        """Note the module's file: with no ontology configured from the working directory,
        the pyproject.toml above it names the ontology (``active.note_source_file``)."""
        super().__init_subclass__(**kwargs)
        from ..ontology.active import note_source_file

        note_source_file(getattr(sys.modules.get(cls.__module__), "__file__", None))

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        self.findings = []
        self._ez_trace: Trace | None = None
        super().__init__(*args, **kwargs)
        traced = self._ez_trace
        if traced is not None:
            report(self.findings, traced.func)

    def createDescription(self) -> None:
        """Trace ``description`` (if the class has one) and lower it to the backend."""
        func = find_description(type(self), SkillDescription)
        if func is None:
            return
        traced = trace(self, func)
        self._ez_trace = traced
        # Checked before lowering, reported after generateDefParams (step 5)
        self.findings = run_checks(traced)
        lower_checked(self, traced.specs, traced.recorded, self.findings, BACKEND)

    def param(self, key: str) -> Symbol:
        """The symbol of any key, declared or not: ``self.param("Target Location")``."""
        if not isinstance(key, str):
            raise DescriptionError(f"self.param(...) needs a str key, got {key!r}")
        return Symbol(key)

    def _ez_add_live(self, which: str, cond: Cond) -> None:
        """A ``+=`` outside tracing (e.g. in ``modifyDescription``) lowers immediately."""
        if not self.__dict__.get("_ez_tracing", False):
            lower_condition(self, which, cond)


__all__ = ["BACKEND", "SkillDescription"]
