"""``self.pre_conditions += c``: collectors that remember *where* each condition was added.

The file and line of the ``+=`` is what a type error must name (the paper's checker could
not), so the collector captures its caller's frame at the moment of ``+=``. During tracing
conditions are only recorded (lowering happens after every ``addParam``, docs/dsl.md step 4);
after the description is built, ``+=`` lowers at once, so implementation code may still add
conditions the EzSkiROS way.
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import Any

from ..diagnostics import DescriptionError
from .conditions import Cond

LISTS: tuple[str, ...] = ("pre", "hold", "post")


@dataclass(frozen=True)
class Recorded:
    """One ``+=``: which list, the condition, and the file and line of the statement."""

    which: str
    condition: Cond
    file: str
    line: int


def record(records: list[Recorded], which: str, item: Any, file: str, line: int
           ) -> list[Cond]:
    """One ``self.<which>_conditions += item`` at ``file:line``: each condition of ``item``
    (one, or a list or tuple of them) appended to ``records``; a ``DescriptionError`` for
    anything else. What tracing does, and what ``ezmigrate check`` does reading the
    statement from its syntax."""
    items = item if isinstance(item, (list, tuple)) else (item,)
    for cond in items:
        if not isinstance(cond, Cond):
            raise DescriptionError(
                f"self.{which}_conditions += ... takes conditions (A.contain(B), "
                f"F.Open.eq(False), ...), got {cond!r}")
    added = [Recorded(which, cond, file, line) for cond in items]
    records.extend(added)
    return list(items)


class ConditionCollector:
    """The object behind ``self.pre_conditions`` (and hold/post) of one description."""

    __slots__ = ("_live", "_records", "_which")

    def __init__(self, which: str, records: list[Recorded],
                 live: Callable[[str, Cond], None] | None = None) -> None:
        self._which = which
        self._records = records
        self._live = live

    def __iadd__(self, item: Any) -> ConditionCollector:
        frame = sys._getframe(1)
        for cond in record(self._records, self._which, item, frame.f_code.co_filename,
                           frame.f_lineno):
            if self._live is not None:
                self._live(self._which, cond)
        return self

    def __iter__(self) -> Iterator[Cond]:
        return (r.condition for r in self._records if r.which == self._which)

    def __len__(self) -> int:
        return sum(1 for r in self._records if r.which == self._which)

    def __repr__(self) -> str:
        return f"<{self._which}_conditions: {list(self)!r}>"


class CollectorSlot:
    """Descriptor for ``pre_conditions`` & co.: reading gives the instance's collector, and
    assignment accepts only that collector back (which is what ``+=`` does)."""

    def __init__(self, which: str) -> None:
        self.which = which
        self.attribute = f"_ez_{which}_collector"

    def __set_name__(self, owner: type, name: str) -> None:
        self.public = name

    def __get__(self, instance: Any, owner: type | None = None) -> Any:
        if instance is None:
            return self
        collector = instance.__dict__.get(self.attribute)
        if collector is None:
            collector = ConditionCollector(self.which, instance.__dict__.setdefault(
                "_ez_recorded", []), getattr(instance, "_ez_add_live", None))
            instance.__dict__[self.attribute] = collector
        return collector

    def __set__(self, instance: Any, value: Any) -> None:
        if value is not instance.__dict__.get(self.attribute):
            raise DescriptionError(
                f"self.{self.public} collects conditions with +=; it cannot be assigned")


__all__ = ["LISTS", "CollectorSlot", "ConditionCollector", "Recorded", "record"]
