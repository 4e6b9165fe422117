"""Bounded ontology reading (issue 41): time and peak memory of a subClassOf chain, and
how fast the hostile files of the issue are refused.

Why fresh processes: peak memory (``ru_maxrss``) only grows within a process, so every
measurement gets an interpreter of its own, with an empty cache folder for the cold load
(parse, index, write the JSON entry) and the same folder again for the warm one.

Chains of 1k, 2k, 4k, 8k and 10k ``rdfs:subClassOf`` triples (plus the same chain of
``rdfs:subPropertyOf`` with a domain at the top, with ``--properties``); before the fix, 10k
took 18-44 s, 3.1 GB and wrote a 251 MB pickle. Then the issue's hostile files at full size:
the 1,000,000-triple Turtle file (35 MB) and 80,000 uses of a 256-character entity.

    .venv/bin/python bench/bench_ontology_bounds.py [--runs 3] [--properties]
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "tests"))

from hostile_ontology import CHAIN, chain_turtle, entity_owl  # noqa: E402

LENGTHS = (1000, 2000, 4000, 8000, 10000)

CHILD = """
import json, resource, sys, time
from pathlib import Path
from ezskiros_runtime.ontology.errors import OntologyLoadError
from ezskiros_runtime.ontology.load import load_index
started = time.perf_counter()
try:
    index = load_index([sys.argv[1]], cache_dir=Path(sys.argv[2]))
    answer = index.is_subclass(sys.argv[3], sys.argv[4]) if len(sys.argv) > 4 else None
    refused = None
except OntologyLoadError as error:
    answer, refused = None, str(error)
seconds = time.perf_counter() - started
peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
print(json.dumps({"seconds": seconds, "peak_mb": peak, "answer": answer,
                  "refused": refused}))
"""


def child(path: Path, cache: Path, *query: str) -> dict[str, object]:
    env = {k: v for k, v in os.environ.items() if not k.startswith("EZSKIROS_")}
    run = subprocess.run([sys.executable, "-c", CHILD, str(path), str(cache), *query],
                         capture_output=True, text=True, env=env, cwd=REPO, check=True,
                         timeout=600)
    result: dict[str, object] = json.loads(run.stdout)
    return result


def chain_row(length: int, runs: int, scratch: Path, properties: bool) -> str:
    folder = scratch / f"chain-{length}"
    folder.mkdir()
    path = folder / "chain.ttl"
    path.write_text(chain_turtle(length, properties=properties), encoding="utf-8")
    query = (CHAIN + "C1", CHAIN + f"C{length}")
    cold, warm = [], []
    for run in range(runs):
        cache = folder / f"cache-{run}"
        cold.append(child(path, cache, *query))
        warm.append(child(path, cache, *query))
    assert all(r["answer"] is True for r in cold + warm), (cold, warm)
    entry = sum(p.stat().st_size for p in (folder / "cache-0").glob("ontology-index-*"))

    def median(rows: list[dict[str, object]], key: str) -> float:
        return statistics.median(float(str(r[key])) for r in rows)

    return (f"| {length:,} | {path.stat().st_size / 1024:.0f} KB | "
            f"{median(cold, 'seconds'):.2f} | {median(cold, 'peak_mb'):.0f} | "
            f"{median(warm, 'seconds') * 1000:.0f} | {median(warm, 'peak_mb'):.0f} | "
            f"{entry / 1024:.0f} KB |")


def hostile_rows(scratch: Path) -> list[str]:
    rows = []
    big = scratch / "million.ttl"
    with big.open("w", encoding="utf-8") as stream:
        stream.write(f"@prefix ex: <{CHAIN}> .\n"
                     "@prefix rdfs: <http://www.w3.org/2000/01/rdf-schema#> .\n")
        for n in range(1_000_000):
            stream.write(f"ex:C{n} rdfs:subClassOf ex:C{n + 1} .\n")
    entity = scratch / "entity.owl"
    entity.write_text(entity_owl(80_000, 256), encoding="utf-8")
    for label, path in (("1,000,000 triples, Turtle", big),
                        ("80,000 uses of a 256-character entity", entity)):
        result = child(path, scratch / "hostile-cache")
        refused = str(result["refused"]).replace(str(scratch) + "/", "")
        rows.append(f"| {label} | {path.stat().st_size / 1e6:.1f} MB | "
                    f"{float(str(result['seconds'])):.2f} | "
                    f"{float(str(result['peak_mb'])):.0f} | {refused.split(' (set ')[0]} |")
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--runs", type=int, default=3, help="runs per length (median)")
    parser.add_argument("--properties", action="store_true",
                        help="add the same chain of sub-properties")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="bench-bounds-") as folder:
        scratch = Path(folder)
        kind = "subClassOf and subPropertyOf" if args.properties else "subClassOf"
        print(f"Python {sys.version.split()[0]}; {kind} chain; median of {args.runs} fresh "
              "processes per row\n")
        print("| chain | file | cold s | cold peak MB | warm ms | warm peak MB | cache entry |")
        print("|---:|---:|---:|---:|---:|---:|---:|")
        for length in LENGTHS:
            print(chain_row(length, args.runs, scratch, args.properties), flush=True)
        print("\n| hostile file (default limits) | size | s | peak MB | outcome |")
        print("|---|---:|---:|---:|---|")
        for row in hostile_rows(scratch):
            print(row, flush=True)


if __name__ == "__main__":
    main()
