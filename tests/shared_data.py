"""The real SkiROS2 OWL files, read from ``../shared`` beside the checkout (never copied).

CI lays ``shared/`` next to the clone; a developer's fresh clone has no such folder. Tests
that need the files ask ``skiros2()``: outside CI they are skipped with that reason, so the
README's test command passes in any clone; in CI (``CI`` set) a missing folder fails the
test instead, so those tests can never pass there by not running.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
SKIROS2 = REPO.parent / "shared" / "ontology" / "skiros2"


def skiros2() -> Path:
    """The folder of SkiROS2's public OWL files; skips (fails in CI) when it is absent."""
    if not SKIROS2.is_dir():
        message = f"the shared SkiROS2 ontology is missing at {SKIROS2}"
        if os.environ.get("CI"):
            pytest.fail(f"{message}: CI must run the tests that read it")
        pytest.skip(message)
    return SKIROS2
