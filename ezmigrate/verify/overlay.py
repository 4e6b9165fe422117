"""Import sibling modules from given bytes instead of their files (inside a load child).

When ``moves.py`` derives from a description in ``base.py`` and both are migrated, the
migrated ``moves.py`` must be verified against the migrated ``base.py``, which is not on
disk yet. This finder serves those modules' source from memory, with the bytecode cache
bypassed, for the duration of one load.
"""

from __future__ import annotations

import importlib.machinery
import os
import sys
from collections.abc import Iterator, Mapping, Sequence
from contextlib import contextmanager
from importlib.machinery import ModuleSpec
from types import ModuleType


class _BytesLoader(importlib.machinery.SourceFileLoader):
    """A source loader whose source is given; it never reads or writes bytecode."""

    def __init__(self, fullname: str, path: str, data: bytes) -> None:
        super().__init__(fullname, path)
        self._data = data

    def get_data(self, path: str) -> bytes:
        if os.path.realpath(path) == os.path.realpath(self.path):
            return self._data
        return super().get_data(path)

    def path_stats(self, path: str) -> Mapping[str, float]:
        raise OSError("overlay: no bytecode cache")  # SourceLoader then compiles the source


class _OverlayFinder:
    def __init__(self, overlays: Mapping[str, bytes]) -> None:
        self.overlays = {os.path.realpath(p): data for p, data in overlays.items()}

    def find_spec(self, fullname: str, path: Sequence[str] | None,
                  target: ModuleType | None = None) -> ModuleSpec | None:
        spec = importlib.machinery.PathFinder.find_spec(fullname, path)
        if spec is None or spec.origin is None:
            return None
        data = self.overlays.get(os.path.realpath(spec.origin))
        if data is None:
            return None
        spec.loader = _BytesLoader(fullname, spec.origin, data)
        return spec


@contextmanager
def overlaid(overlays: Mapping[str, bytes]) -> Iterator[None]:
    """Serve ``overlays`` (absolute path -> source bytes) while the block runs."""
    if not overlays:
        yield
        return
    finder = _OverlayFinder(overlays)
    sys.meta_path.insert(0, finder)
    try:
        yield
    finally:
        sys.meta_path.remove(finder)
