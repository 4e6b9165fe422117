"""Errors of the legacy backend.

They are separate classes (rather than plain ``ValueError``) because callers act on the kind:
the loader turns a :class:`NotUpstreamAPIError` into a skill that is *skipped* with the reason
"not upstream SkiROS2 API" (legacy-skiros2-api.md §7, forks), a :class:`NotDeclarativeError`
into a skill that cannot be migrated (a ``ConditionFunction``), and anything else into a plain
load error. Each error still derives from the builtin that real SkiROS2 (or Python) would raise
in the same place, so ``except TypeError`` in user code behaves as before.
"""

from __future__ import annotations

__all__ = [
    "LegacyError",
    "ModuleLoadError",
    "NotDeclarativeError",
    "NotUpstreamAPIError",
    "ParamValueError",
    "UnknownMemberError",
    "UnsupportedConstructError",
]


class LegacyError(Exception):
    """Base class of every error the legacy backend raises on purpose."""


class NotUpstreamAPIError(LegacyError, TypeError):
    """A construct that exists only in forks of SkiROS2 (``ParamTypes.SharedInput``, tuple keys,
    ``addParam(remap=...)``); upstream SkiROS2 would fail too (§7)."""


class UnknownMemberError(NotUpstreamAPIError, AttributeError):
    """``ParamTypes.SharedInput`` and friends: an enum member upstream SkiROS2 does not have.

    Also an ``AttributeError`` so that ``hasattr``/``getattr(..., default)`` keep working.
    """


class ParamValueError(LegacyError, ValueError):
    """A parameter value SkiROS2 rejects: an empty list or a list of mixed types (§8.4)."""


class NotDeclarativeError(LegacyError):
    """A condition with no declarative form (``ConditionFunction`` wraps arbitrary Python), so
    it has no normalized model and the skill cannot be proven equivalent (§7)."""


class UnsupportedConstructError(LegacyError):
    """A legacy call whose effect the backend does not reproduce, raised instead of silently
    producing a model that might differ from what SkiROS2 builds."""


class ModuleLoadError(LegacyError):
    """Importing a legacy file failed: no class in it can be loaded.

    ``line`` is the line *in that file* where the failure surfaced (for a failing import of a
    sibling, the import statement); ``origin`` is ``file:line`` of the innermost user frame
    when that differs (the sibling's own line).
    """

    def __init__(self, path: str, line: int | None, exc_type: str, message: str,
                 origin: str | None = None) -> None:
        self.path = path
        self.line = line
        self.exc_type = exc_type
        self.message = message
        self.origin = origin
        where = f"{path}:{line}" if line is not None else path
        via = f" (raised at {origin})" if origin else ""
        super().__init__(f"{where}: cannot import module: {exc_type}: {message}{via}")
