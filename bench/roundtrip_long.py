"""The long run of the round-trip property test: 10,000 generated legacy modules.

Same machinery as ``tests/verify/test_verify_roundtrip.py`` (``tests/strategies/
roundtrip.py``): hypothesis draws legacy modules from ``tests/strategies/legacy_source.py``,
each is migrated with ``migrate()``, both versions are written as files and loaded in
isolated children through the verification pool, and every class must compare equivalent.
The run goes in chunks (one hypothesis run of ``--chunk`` examples per seed, repeats across
chunks dropped) so that progress shows and a time budget can stop it between chunks.

    .venv/bin/python bench/roundtrip_long.py --modules 10000
    .venv/bin/python bench/roundtrip_long.py --modules 500 --chunk 250   # a quick look

Prints one line per chunk, then the summary, the skip reasons, and every failure with both
versions of its module (failing modules are also kept under ``--keep``). Exit 0 when every
module round-tripped, 1 otherwise.
"""

from __future__ import annotations

import argparse
import json
import shutil
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))

from hypothesis import HealthCheck, Phase, given, seed, settings  # noqa: E402
from strategies.legacy_source import GeneratedModule, legacy_modules_with_names  # noqa: E402
from strategies.roundtrip import RoundTrip  # noqa: E402

from ezmigrate.codemod.migrate import Settings  # noqa: E402
from ezskiros_runtime.ontology.load import load_index  # noqa: E402


def _chunk(trip: RoundTrip, strategy_args: dict[str, object], examples: int,
           chunk_seed: int) -> None:
    """One hypothesis run: ``examples`` draws with a fixed seed, all handed to ``trip``."""

    @seed(chunk_seed)
    @settings(max_examples=examples, deadline=None, database=None, derandomize=False,
              phases=[Phase.generate], suppress_health_check=list(HealthCheck))
    @given(legacy_modules_with_names(**strategy_args))  # type: ignore[arg-type]
    def draw(module: GeneratedModule) -> None:
        trip.add(module)

    draw()


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--modules", type=int, default=10_000,
                        help="distinct generated modules to round-trip")
    parser.add_argument("--chunk", type=int, default=500, help="examples per hypothesis run")
    parser.add_argument("--seed", type=int, default=20261121, help="seed of the first chunk")
    parser.add_argument("--jobs", type=int, default=2, help="migrate and verify workers")
    parser.add_argument("--max-minutes", type=float, default=60.0,
                        help="start no new chunk after this long")
    parser.add_argument("--max-classes", type=int, default=3)
    parser.add_argument("--max-params", type=int, default=8)
    parser.add_argument("--max-conditions", type=int, default=8)
    parser.add_argument("--keep", type=Path, default=ROOT / "bench" / "out" / "roundtrip",
                        help="folder for failing modules and the JSON summary")
    args = parser.parse_args(argv)

    strategy_args = {"max_classes": args.max_classes, "max_params": args.max_params,
                     "max_conditions": args.max_conditions, "undeclared_keys": True}
    work = Path(tempfile.mkdtemp(prefix="ezmigrate-roundtrip-"))
    trip = RoundTrip(work, Settings(index=load_index()), jobs=args.jobs, limit=args.modules,
                     keep_failures=200)
    started = time.monotonic()
    chunk = 0
    stopped_early = False
    try:
        while not trip.full:
            if time.monotonic() - started > args.max_minutes * 60:
                stopped_early = True
                break
            _chunk(trip, strategy_args, args.chunk, args.seed + chunk)
            report = trip.run()
            chunk += 1
            elapsed = time.monotonic() - started
            print(f"chunk {chunk}: {report.examples} examples, {report.modules} modules, "
                  f"{report.classes} classes, {report.equivalent} equivalent, "
                  f"{report.failure_count} failures, {elapsed / 60:.1f} min", flush=True)
            for folder in ("before", "after"):  # keep the disk small; failures are kept below
                shutil.rmtree(work / folder, ignore_errors=True)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    report = trip.report
    elapsed = time.monotonic() - started
    print()
    print(report.summary())
    print(f"{chunk} chunks of {args.chunk} examples, seeds {args.seed}..{args.seed + chunk - 1},"
          f" {elapsed / 60:.1f} min" + (" (stopped by --max-minutes)" if stopped_early else ""))
    print("constructs seen (modules containing each):", dict(report.kinds.most_common()))
    for line in report.skip_lines():
        print("skipped:", line)
    args.keep.mkdir(parents=True, exist_ok=True)
    for index, failure in enumerate(report.failures):
        (args.keep / f"failure_{index:03d}.txt").write_text(failure.explain(), encoding="utf-8")
    if report.failures:
        print(report.explain(10))
    summary = {
        "modules": report.modules, "examples": report.examples, "classes": report.classes,
        "converted": report.converted, "unchanged": report.unchanged,
        "skipped": dict(report.skipped), "compared": report.compared,
        "equivalent": report.equivalent, "static_models_checked": report.static_models_checked,
        "failures": report.failure_count, "minutes": round(elapsed / 60, 2),
        "chunks": chunk, "chunk": args.chunk, "first_seed": args.seed,
        "stopped_early": stopped_early, "strategy": strategy_args,
        "seconds": {k: round(v, 1) for k, v in report.seconds.items()},
    }
    (args.keep / "summary.json").write_text(json.dumps(summary, indent=2) + "\n",
                                            encoding="utf-8")
    return 0 if report.failure_count == 0 and not stopped_early else 1


if __name__ == "__main__":
    sys.exit(main())
