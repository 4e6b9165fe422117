"""Stand-in for ``skiros2_common.core.primitive`` (``PrimitiveBase``) and
``skiros2_common.core.primitive_thread`` (``PrimitiveThreadBase``).

Primitives are *implementations* (legacy-skiros2-api.md §2): files define them next to their
descriptions, so they must import and their classes must be definable, but ezmigrate never
runs them. Every hook is a no-op that returns what SkiROS2's contract expects.
"""

from __future__ import annotations

from typing import Any

from .abstract_skill import SkillCore, State

__all__ = ["PrimitiveBase", "PrimitiveThreadBase"]


class PrimitiveBase(SkillCore):
    """A primitive skill implementation (never executed here)."""

    def onInit(self) -> bool:
        return True

    def onStart(self) -> bool:
        return True

    def onPreempt(self) -> State:
        return State.Failure

    def onEnd(self) -> bool:
        return True

    def execute(self) -> State:
        return State.Success

    def success(self, msg: str = "", code: Any = None) -> State:
        return State.Success

    def fail(self, msg: str = "", code: Any = None) -> State:
        return State.Failure

    def step(self, msg: str = "") -> State:
        return State.Running


class PrimitiveThreadBase(PrimitiveBase):
    """A primitive whose work runs in a thread (``run``); equally never executed here."""

    def run(self) -> State:
        return State.Success

    def onRunning(self) -> State:
        return State.Running
