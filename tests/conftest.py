"""Test-session setup shared by every test package.

Tests use a private ontology cache so that a run never reads or writes the user's real
``~/.cache/ezskiros`` (and so that a stale cache can never make a test pass).
"""

from __future__ import annotations

import os
import tempfile
from collections.abc import Callable
from typing import Any

import pytest

_CACHE = tempfile.mkdtemp(prefix="ezskiros-test-cache-")
os.environ.setdefault("EZSKIROS_CACHE_DIR", _CACHE)


_SUMMARY = pytest.StashKey[list[str]]()


@pytest.fixture
def summary_line(request: pytest.FixtureRequest) -> Callable[[str], None]:
    """Adds a line to the end of pytest's output, shown even under ``-q`` (unlike print): the
    figures a proof test measured (mutants caught, examples run) belong in CI's log."""
    return request.config.stash.setdefault(_SUMMARY, []).append


def pytest_terminal_summary(terminalreporter: Any, exitstatus: int,
                            config: pytest.Config) -> None:
    for line in config.stash.get(_SUMMARY, []):
        terminalreporter.write_line(line)
