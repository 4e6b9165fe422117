"""Verification of converted skills before ``rewrite`` writes anything (filled in by issue 4)."""

from __future__ import annotations

from ..runner import Migrated
from ..session import RewriteOptions


def verify_migrated(migrated: list[Migrated], options: RewriteOptions) -> None:
    """Placeholder: verification is not wired yet, so results stay unverified."""
    return None
