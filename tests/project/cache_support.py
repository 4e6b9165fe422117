"""Shared by the cache tests: ``ezmigrate check`` run as a lab runs it, a real process in the
repository's folder, its findings as JSON (the bytes the cache must not change)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path


def check_json(repo: Path, *extra: str) -> subprocess.CompletedProcess[str]:
    """``ezmigrate check --exit-zero --output-format json [extra] .`` in ``repo``."""
    return subprocess.run([sys.executable, "-m", "ezmigrate", "check", "--exit-zero",
                           "--output-format", "json", *extra, "."], cwd=repo,
                          capture_output=True, text=True, timeout=600, check=False)
