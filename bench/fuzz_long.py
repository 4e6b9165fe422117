"""The long fuzz run of the safety guarantees (the CI test runs the same checks, bounded).

Every example is a batch of mutated ``fixtures/legacy`` sources (deletions, insertions,
truncations, byte garbage, wrong encodings, line endings...) and one real ``ezmigrate
rewrite`` subprocess over it; a quarter of the batches verify (child processes import both
versions). Each batch must give exit 0, 1 or 2, no traceback, only files that parse written,
and byte-identical files for everything not processed, skipped or failed
(``tests/safety/fuzz_support.py`` has the exact checks).

    .venv/bin/python bench/fuzz_long.py --examples 400 [--seed N] [--files 12]

Prints a one-line tally, or the falsifying batch (and saves it under bench/out/fuzz/).
"""

from __future__ import annotations

import argparse
import platform
import random
import shutil
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "tests" / "safety"))

from fuzz_support import Tally, batches, check_batch  # noqa: E402
from hypothesis import HealthCheck, given, seed, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--examples", type=int, default=400)
    parser.add_argument("--files", type=int, default=12, help="most files per batch")
    parser.add_argument("--seed", type=int, default=random.randrange(1, 10**9))
    args = parser.parse_args()
    tally = Tally()
    scratch = Path(tempfile.mkdtemp(prefix="ezmigrate-fuzz-"))
    failed: list[list[bytes]] = []
    reasons: list[str] = []
    counter = iter(range(10**9))

    @seed(args.seed)
    @settings(max_examples=args.examples, deadline=None, database=None,
              suppress_health_check=list(HealthCheck))
    @given(sources=batches(3, args.files), verify=st.sampled_from([False, False, False, True]))
    def run(sources: list[bytes], verify: bool) -> None:
        try:
            check_batch(scratch / f"batch{next(counter)}", sources, verify=verify, tally=tally)
        except BaseException as error:
            failed.append(sources)
            reasons.append(f"verify={verify}: {type(error).__name__}: {error}"[:4000])
            raise

    started = time.monotonic()
    print(f"python {platform.python_version()}, seed {args.seed}, {args.examples} examples, "
          f"up to {args.files} files each", flush=True)
    try:
        run()
    except Exception as error:  # the falsifying example was printed by hypothesis
        out = REPO / "bench" / "out" / "fuzz"
        out.mkdir(parents=True, exist_ok=True)
        for index, data in enumerate(failed[-1] if failed else []):
            (out / f"mutant_{index}.py").write_bytes(data)
        print(f"FAILED after {time.monotonic() - started:.0f} s: "
              f"{str(error).splitlines()[-1][-300:]}\n(the last failing batch is in {out})")
        for reason in dict.fromkeys(reasons):  # each distinct failure once
            print(f"--- {reason}")
        print(tally.line())
        return 1
    print(f"passed: {tally.line()}; wall {time.monotonic() - started:.0f} s")
    shutil.rmtree(scratch, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
