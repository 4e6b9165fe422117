"""Stand-in for ``skiros2_skill.core.processors``: behaviour-tree processors, as names only.

``expand`` methods build trees with them (legacy-skiros2-api.md §6), but ezmigrate never runs
an implementation; files must merely import and define their classes. SkiROS2 branches differ
in which processors exist, so besides the common ones any other CamelCase name resolves to a
generic processor class (module ``__getattr__``, PEP 562), created once per name so that
``from ... import X`` twice gives the same class.
"""

from __future__ import annotations

from typing import Any

__all__ = [
    "NoFail",
    "ParallelFf",
    "ParallelFs",
    "Processor",
    "RetryOnFail",
    "Selector",
    "SelectorStar",
    "Sequential",
    "Serial",
    "SerialStar",
]


class Processor:
    """A processor: remembers its arguments, does nothing else."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        self.args = args
        self.kwargs = kwargs

    def __repr__(self) -> str:
        return f"{type(self).__name__}()"


class Sequential(Processor):
    pass


class Serial(Processor):
    pass


class SerialStar(Processor):
    pass


class Selector(Processor):
    pass


class SelectorStar(Processor):
    pass


class ParallelFf(Processor):
    pass


class ParallelFs(Processor):
    pass


class RetryOnFail(Processor):
    pass


class NoFail(Processor):
    pass


_generated: dict[str, type[Processor]] = {}


def is_camel_case(name: str) -> bool:
    """``Sequential``, ``ParallelFf``: what a processor name looks like (not ``_x``, ``FOO``)."""
    return name[:1].isupper() and not name.isupper() and name.isidentifier()


def processor_class(name: str) -> type[Processor]:
    """The generic processor class called ``name`` (one per name)."""
    cls = _generated.get(name)
    if cls is None:
        cls = type(name, (Processor,), {"__module__": __name__, "__doc__": "Generic processor."})
        _generated[name] = cls
    return cls


def __getattr__(name: str) -> type[Processor]:
    if is_camel_case(name):
        return processor_class(name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
