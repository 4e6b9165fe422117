"""Ontology load, cold vs warm cache, each run in a fresh Python process.

Why fresh processes: the point of the cache is launch time. In a long-lived process rdflib
would already be imported after the first run and the cold figure would flatter us; a new
interpreter per run makes the cold path pay for importing rdflib, as a real launch does.

Cold: an empty cache folder per run (hash, miss, import rdflib, parse, index, write).
Warm: the same cache folder, primed once (hash, unpickle; rdflib is never imported).

Three figures per run, all medians over fresh processes:
- "load": the `load_index(...)` call, timed inside the child after importing the index
  module. This is the load itself: rdflib's import (cold only), reading and hashing the
  files, parsing or unpickling, and the first use of hashlib/pickle.
- "import + load": the same plus importing `ezskiros_runtime.ontology.index` (dataclasses,
  pathlib, ...), which any program using the runtime pays once whatever the cache does.
- "process": the whole child from our side, interpreter start-up included.

Bytecode: children get a private PYTHONPYCACHEPREFIX (primed by one run) so modules are
compiled once, as in an installed package, even where PYTHONDONTWRITEBYTECODE is set;
`--no-bytecode` makes every child compile every module from source instead.

    .venv/bin/python bench/bench_ontology.py [--runs 7] [--no-bytecode]
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
SKIROS2 = REPO / ".." / "shared" / "ontology" / "skiros2"

CHILD = """
import json, sys, time
started = time.perf_counter()
from ezskiros_runtime.ontology.load import load_index
imported = time.perf_counter()
index = load_index(sys.argv[1:] or None)
done = time.perf_counter()
print(json.dumps({"load": done - imported, "import_and_load": done - started,
                  "rdflib": "rdflib" in sys.modules, "classes": len(index.classes)}))
"""


@dataclass(frozen=True)
class Run:
    """One child process: times inside and around it, and whether rdflib was imported."""

    load: float
    import_and_load: float
    process: float
    rdflib_imported: bool
    classes: int


def child_environment(pycache: Path | None) -> dict[str, str]:
    env = dict(os.environ)
    env.pop("EZSKIROS_ONTOLOGY", None)
    if pycache is None:
        env["PYTHONDONTWRITEBYTECODE"] = "1"
    else:
        env.pop("PYTHONDONTWRITEBYTECODE", None)
        env["PYTHONPYCACHEPREFIX"] = str(pycache)
    return env


def run_child(paths: list[str], cache_dir: Path, base_env: dict[str, str]) -> Run:
    env = {**base_env, "EZSKIROS_CACHE_DIR": str(cache_dir)}
    started = time.perf_counter()
    result = subprocess.run(
        [sys.executable, "-c", CHILD, *paths],
        capture_output=True,
        text=True,
        env=env,
        cwd=REPO,
        check=True,
    )
    process = time.perf_counter() - started
    data = json.loads(result.stdout)
    return Run(data["load"], data["import_and_load"], process, data["rdflib"], data["classes"])


def measure(
    paths: list[str], runs: int, scratch: Path, env: dict[str, str]
) -> tuple[list[Run], list[Run]]:
    warm_dir = scratch / "warm"
    run_child(paths, warm_dir, env)  # fills the bytecode cache (if any) and the index cache
    cold: list[Run] = []
    warm: list[Run] = []
    for i in range(runs):  # interleaved, so background load hits both alike
        cold.append(run_child(paths, scratch / f"cold-{i}", env))
        warm.append(run_child(paths, warm_dir, env))
    if not all(r.rdflib_imported for r in cold) or any(r.rdflib_imported for r in warm):
        raise SystemExit("unexpected: cold runs must import rdflib, warm runs must not")
    return cold, warm


def median_ms(runs: list[Run], attribute: str) -> float:
    return statistics.median(getattr(r, attribute) for r in runs) * 1000


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--runs", type=int, default=7, help="runs per case (median reported)")
    parser.add_argument(
        "--no-bytecode",
        action="store_true",
        help="children compile every module from source (PYTHONDONTWRITEBYTECODE=1)",
    )
    args = parser.parse_args()
    if args.runs < 1:
        parser.error("--runs must be at least 1")
    if not SKIROS2.is_dir():
        raise SystemExit(f"missing the shared SkiROS2 ontology at {SKIROS2}")

    cases = [
        ("../shared/ontology/skiros2 (6 OWL files)", [str(SKIROS2)]),
        ("bundled skiros-core.ttl", []),
    ]
    rows = []
    with tempfile.TemporaryDirectory(prefix="bench-ontology-") as scratch:
        env = child_environment(None if args.no_bytecode else Path(scratch) / "pycache")
        for label, paths in cases:
            case_dir = Path(scratch) / str(len(rows))
            cold, warm = measure(paths, args.runs, case_dir, env)
            rows.append((label, cold, warm))

    bytecode = "compiled from source every run" if args.no_bytecode else "bytecode cached"
    print(f"median of {args.runs} fresh processes per cell; {bytecode}; times in ms\n")
    print("| ontology | classes | measured | cold (empty cache) | warm (cache hit) | speed-up |")
    print("|---|---:|---|---:|---:|---:|")
    for label, cold, warm in rows:
        for measured, attribute in (
            ("load", "load"),
            ("import + load", "import_and_load"),
            ("process", "process"),
        ):
            cold_ms, warm_ms = median_ms(cold, attribute), median_ms(warm, attribute)
            print(
                f"| {label} | {cold[0].classes} | {measured} | {cold_ms:.1f} | {warm_ms:.1f} "
                f"| {cold_ms / warm_ms:.1f}x |"
            )


if __name__ == "__main__":
    main()
