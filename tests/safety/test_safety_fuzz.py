"""Fuzz ``rewrite`` with mutated legacy sources (see ``fuzz_support``): exit 0, 1 or 2,
never a traceback, every written file parses, every file not processed or skipped is
byte-identical. CI runs a bounded number of examples (EZMIGRATE_FUZZ_EXAMPLES, default 12,
about a minute); ``bench/fuzz_long.py`` runs the same checks for longer."""

from __future__ import annotations

import itertools
import os

from fuzz_support import batches, check_batch
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

EXAMPLES = int(os.environ.get("EZMIGRATE_FUZZ_EXAMPLES", "12"))
_COUNTER = itertools.count()


@settings(max_examples=EXAMPLES, deadline=None, database=None,
          derandomize=bool(os.environ.get("CI")),
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow,
                                 HealthCheck.data_too_large])
@given(sources=batches(), verify=st.sampled_from([False, False, False, True]))
def test_rewrite_survives_mutated_sources(tmp_path, sources, verify):
    check_batch(tmp_path / f"batch{next(_COUNTER)}", sources, verify=verify)
