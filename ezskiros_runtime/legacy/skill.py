"""Stand-in for ``skiros2_skill.core.skill``: ``SkillBase`` plus SkiROS2's re-exports.

Legacy files import ``SkillDescription``, ``ParamOptions`` and processors from here as often
as from their home modules (legacy-skiros2-api.md §1), so this module re-exports them (and
``ParamTypes``/``Element``, which user files also pick up from here). Compound skills build
trees in ``expand`` (§6); nothing here runs them, the methods only record their arguments.
"""

from __future__ import annotations

from typing import Any

from . import processors as _processors
from .abstract_skill import ParamOptions, SkillCore, SkillDescription, State
from .params import ParamTypes
from .primitive import PrimitiveBase
from .processors import (
    NoFail,
    ParallelFf,
    ParallelFs,
    Processor,
    RetryOnFail,
    Selector,
    SelectorStar,
    Sequential,
    Serial,
    SerialStar,
)
from .world_element import Element

__all__ = [
    "Element",
    "NoFail",
    "ParallelFf",
    "ParallelFs",
    "ParamOptions",
    "ParamTypes",
    "PrimitiveBase",
    "Processor",
    "RetryOnFail",
    "Selector",
    "SelectorStar",
    "Sequential",
    "Serial",
    "SerialStar",
    "SkillBase",
    "SkillCore",
    "SkillDescription",
    "SkillWrapper",
    "State",
]


class SkillWrapper:
    """A node of a behaviour tree: ``self.skill("Type", "label", remap=..., specify=...)``.

    Calling a node with other nodes adds them as children, as in SkiROS2's
    ``skill(self.skill(...), self.skill(...))``.
    """

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        self.args = args
        self.kwargs = kwargs
        self.children: list[Any] = []
        self.processor: Any = None

    def __call__(self, *children: Any) -> SkillWrapper:
        self.children.extend(children)
        return self

    def setProcessor(self, processor: Any) -> None:
        self.processor = processor


class SkillBase(SkillCore):
    """A compound skill implementation (never expanded here)."""

    _children: list[Any]
    _processor: Any

    def expand(self, skill: Any) -> None:
        """Build the tree under ``skill``; overridden by every real compound skill."""

    def skill(self, *args: Any, **kwargs: Any) -> SkillWrapper:
        return SkillWrapper(*args, **kwargs)

    def setProcessor(self, processor: Any) -> None:
        self._processor = processor

    def __call__(self, *children: Any) -> SkillBase:
        self.__dict__.setdefault("_children", []).extend(children)
        return self


def __getattr__(name: str) -> type[Processor]:
    """Processors of other SkiROS2 branches, re-exported like the named ones (PEP 562)."""
    if _processors.is_camel_case(name):
        return _processors.processor_class(name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
