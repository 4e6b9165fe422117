"""Test-session setup shared by every test package.

Tests use a private ontology cache so that a run never reads or writes the user's real
``~/.cache/ezskiros`` (and so that a stale cache can never make a test pass).
"""

from __future__ import annotations

import os
import tempfile

_CACHE = tempfile.mkdtemp(prefix="ezskiros-test-cache-")
os.environ.setdefault("EZSKIROS_CACHE_DIR", _CACHE)
