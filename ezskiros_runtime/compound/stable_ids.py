"""``id()`` that gives the same numbers on every run, while a compound skill is traced.

Why: real ``expand`` methods label nodes or specify values with ``id(self)`` (to tell
instances apart on the robot). Traced as they are, the labels are memory addresses, so the
review report and ``check``'s findings changed between two runs on the same code. While
``stable_ids()`` is active, ``id`` numbers objects 1, 2, 3... in the order they are first
asked about: one object keeps one number, two objects never share one (each is held until
the block ends, so no address is reused), and the same ``expand`` gives the same tree.
Runs in the robot's Python (3.8 and newer).
"""

from __future__ import annotations

import builtins
from contextlib import contextmanager
from typing import Any, Iterator


@contextmanager
def stable_ids() -> Iterator[None]:
    """Replace ``builtins.id`` by a numbering that is the same on every run, for the block."""
    real_id = builtins.id
    numbered: dict[int, tuple[Any, int]] = {}

    def stable_id(obj: Any) -> int:
        key = real_id(obj)
        found = numbered.get(key)
        if found is None:
            found = numbered[key] = (obj, len(numbered) + 1)
        return found[1]

    builtins.id = stable_id
    try:
        yield
    finally:
        builtins.id = real_id
