"""How serious each kind of finding is: defaults, strict mode, per-kind overrides.

The defaults are the catalogue's (``codes.RULES``): the paper's rule that type violations
are errors (the skill must not load) and unknown vocabulary a warning (SkiROS2 accepts it,
and real projects use vocabulary from files we may not have) is written there, once.
Strict mode turns every finding into an error, for CI. ``collecting()`` lets ``check()``
and the migrator load a description without raising, to *report* instead.
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from contextlib import contextmanager
from contextvars import ContextVar
from types import TracebackType

from ..codes import RULES, rule_for

STRICT_ENV = "EZSKIROS_STRICT"
LEVELS: tuple[str, ...] = ("error", "warning", "info", "off")

DEFAULT_SEVERITY: dict[str, str] = {
    kind: rule.severity for rule in RULES for kind in rule.kinds}
"""Each finding kind's severity (``range-unproven``, the one spelling from the runtime to
the reports), as the one catalogue (``codes.RULES``) gives it: nothing here is typed by
hand."""

_overrides: dict[str, str] = {}
_strict: list[bool | None] = [None]
_raising: ContextVar[bool] = ContextVar("ezskiros_raising", default=True)


def is_strict() -> bool:
    """Strict mode: set by ``strict()``, else ``EZSKIROS_STRICT`` (1/true/yes/on)."""
    if _strict[0] is not None:
        return _strict[0]
    return os.environ.get(STRICT_ENV, "").strip().lower() in ("1", "true", "yes", "on")


class StrictMode:
    """What ``strict()`` returns: already applied, and a context manager that restores the
    previous setting on exit (``with strict(): ...``)."""

    def __init__(self, previous: bool | None) -> None:
        self.previous = previous

    def __enter__(self) -> StrictMode:
        return self

    def __exit__(self, exc_type: type[BaseException] | None, exc: BaseException | None,
                 tb: TracebackType | None) -> None:
        _strict[0] = self.previous

    def __bool__(self) -> bool:
        return is_strict()


def strict(enabled: bool | None = True) -> StrictMode:
    """Turn strict mode on (``True``), off (``False``) or back to the environment (``None``)."""
    previous = _strict[0]
    _strict[0] = enabled
    return StrictMode(previous)


def set_severity(kind: str, level: str | None) -> None:
    """Override the severity of one finding kind (``None`` restores the default)."""
    if level is None:
        _overrides.pop(kind, None)
        return
    if level not in LEVELS:
        raise ValueError(f"severity {level!r}: expected one of {', '.join(LEVELS)}")
    rule_for(kind)  # a kind no rule lists is a typo: UnknownKind, never a silent override
    _overrides[kind] = level


def severity_of(kind: str) -> str:
    """The effective level: an explicit ``"off"`` stays off, strict makes the rest errors."""
    level = _overrides.get(kind) or rule_for(kind).severity
    if level == "off":
        return level
    return "error" if is_strict() else level


def raising() -> bool:
    """False inside ``collecting()``: findings are only recorded, never raised or warned."""
    return _raising.get()


@contextmanager
def collecting() -> Iterator[None]:
    """Load descriptions without raising ``SkillTypeError`` or emitting warnings."""
    token = _raising.set(False)
    try:
        yield
    finally:
        _raising.reset(token)


__all__ = ["DEFAULT_SEVERITY", "LEVELS", "STRICT_ENV", "StrictMode", "collecting",
           "is_strict", "raising", "set_severity", "severity_of", "strict"]
