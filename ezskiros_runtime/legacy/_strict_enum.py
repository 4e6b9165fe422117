"""An ``Enum`` metaclass whose unknown members name the fork API they come from.

Forks of SkiROS2 add members such as ``ParamTypes.SharedInput`` (legacy-skiros2-api.md §7).
Upstream SkiROS2 fails on them with a bare ``AttributeError: SharedInput``; we fail too, but
with :class:`~.errors.UnknownMemberError`, which the loader reports as "not upstream SkiROS2
API" so the skill is skipped with a reason instead of looking like a crash.
"""

from __future__ import annotations

from enum import EnumMeta
from typing import Any

from .errors import UnknownMemberError


class StrictEnumType(EnumMeta):
    """``EnumMeta`` with a clear error for members that upstream SkiROS2 does not define."""

    def __getattr__(cls, name: str) -> Any:
        try:
            return super().__getattr__(name)  # type: ignore[misc]
        except AttributeError:
            if name.startswith("_"):
                raise
            members = ", ".join(cls.__members__)
            raise UnknownMemberError(
                f"{cls.__name__}.{name} is not upstream SkiROS2 API (a fork's extension); "
                f"upstream {cls.__name__} has only {members}"
            ) from None
