"""Calls noted across processes: a test that forks workers cannot see their calls in its
own lists, so each call appends a line to a file, which every process shares (appends of
one short line do not interleave)."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest


def log_calls(monkeypatch: pytest.MonkeyPatch, owner: object, name: str, log: Path,
              label: Callable[..., str]) -> None:
    """Replace ``owner.name`` (before any fork: workers inherit it) by itself noting
    ``label(*args)`` in ``log`` at each call, wherever it runs."""
    real = getattr(owner, name)

    def noted(*args: Any, **kwargs: Any) -> Any:
        with log.open("a", encoding="utf-8") as stream:
            stream.write(label(*args) + "\n")
        return real(*args, **kwargs)

    monkeypatch.setattr(owner, name, noted)


def logged(log: Path) -> list[str]:
    """The lines noted so far (none when nothing was called)."""
    return log.read_text(encoding="utf-8").splitlines() if log.exists() else []
