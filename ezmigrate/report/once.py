"""One cause, one finding: the findings a single cause repeats kept once, with a count.

A prefix no loaded file defines, a processor upstream lacks, a property the lab's ontology
makes spatial, a property nothing sets: each is one mistake (or one fact) however many
lines show it, so the reader gets it once, at its first place, saying how many others
there are (docs/rules.md, severity contract). Every pass that reports such a cause goes
through ``once_per_cause``, so the rule is kept the same way everywhere.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Callable, Sequence
from typing import TypeVar

T = TypeVar("T")


def once_per_cause(items: Sequence[T], cause: Callable[[T], str | None],
                   counted: Callable[[T, str, int], T]) -> list[T]:
    """``items`` in order, those with the same ``cause`` (None: an item of its own) kept at
    the first only, which ``counted(item, cause, uses)`` rewrites when there were several."""
    first: dict[str, int] = {}
    uses: Counter[str] = Counter()
    kept: list[T] = []
    for item in items:
        key = cause(item)
        if key is not None:
            uses[key] += 1
            if key in first:
                continue
            first[key] = len(kept)
        kept.append(item)
    for key, at in first.items():
        if uses[key] > 1:
            kept[at] = counted(kept[at], key, uses[key])
    return kept
