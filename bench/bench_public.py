"""``ezmigrate check`` at the root of real repositories against the parse floor (issue 31).

    python bench/bench_public.py CHECKOUTS [--runs 2]

CHECKOUTS is a folder of repository checkouts (``bench_precision.py`` uses the same one).
For each, in one process, the floor: read every Python file ``check`` would read
(``discover``) and ``ast.parse`` those that hold ``createDescription`` (every description
and implementation does; the others ``check`` never parses). Then the whole command,
``check --no-cache --jobs 2 .`` (start-up and the ontology included), and a second ``check``
with the cache the first one left. Each figure is the minimum of ``--runs``; the totals
are over all the repositories, as a lab with many packages would see them.

``--alternate``: CHECKOUTS is one tree; the floor and ``check --no-cache`` alternate
``--runs`` times (the machine's state moves both alike), with the ratios of the minima and
of the medians.

``--whole``: CHECKOUTS is one tree, checked as one run (the folder of all the checkouts, or
a generated tree): the floor, ``check --no-cache``, a second ``check`` with the cache of
the first, and ``check`` after one file holding a description changed (a comment appended,
the cache of the run before), whose output must be the bytes ``--no-cache`` gives.
"""

from __future__ import annotations

import argparse
import ast
import contextlib
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from ezmigrate.files.discover import discover


def floor(checkout: Path) -> float:
    """Seconds to read every ``.py`` file under ``checkout`` with a plain ``os.walk`` and
    ``ast.parse`` those naming ``createDescription`` (issue 40: the physical floor, not the
    tool's own walk), in this running interpreter."""
    started = time.perf_counter()
    for folder, _, names in os.walk(checkout):
        for name in names:
            if name.endswith(".py"):
                try:
                    data = Path(folder, name).read_bytes()
                except OSError:
                    continue
                if b"createDescription" in data:
                    with contextlib.suppress(SyntaxError, ValueError):
                        ast.parse(data)
    return time.perf_counter() - started


CACHE = Path(tempfile.gettempdir()) / "ezmigrate-bench-cache"
"""The benchmark's own cache folder (``--cache-dir``), emptied where a run must start cold."""

CHILDREN = {**{k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"},
            "PYTHONPYCACHEPREFIX": str(Path(tempfile.gettempdir()) / "ezmigrate-bench-pycache")}
"""The commands' environment: bytecode compiled once into a private folder and loaded from
there, as an installed package loads it, even where ``PYTHONDONTWRITEBYTECODE`` is set
(without it, every run compiled every module it imports: tens of milliseconds a run, more
for a tree on ``PYTHONPATH`` than for the installed one). ``PYTHONPATH`` is kept, so that
two versions can be compared from worktrees."""


def command(checkout: Path, *extra: str) -> float:
    started = time.perf_counter()
    subprocess.run([sys.executable, "-m", "ezmigrate", "check", "--exit-zero", "--jobs", "2",
                    "--cache-dir", str(CACHE), *extra, "."], cwd=checkout, capture_output=True,
                   check=False, timeout=1800, env=CHILDREN)
    return time.perf_counter() - started


def _output(checkout: Path, *extra: str) -> str:
    return subprocess.run([sys.executable, "-m", "ezmigrate", "check", "--exit-zero",
                           "--jobs", "2", "--cache-dir", str(CACHE), "--output-format",
                           "json", *extra, "."],
                          cwd=checkout, capture_output=True, check=False, timeout=1800,
                          text=True, env=CHILDREN).stdout


def whole(tree: Path, runs: int) -> int:
    """The ``--whole`` measurement (see the module doc)."""
    command(tree, "--no-cache")  # untimed: compiles the bytecode, warms the page cache
    low = min(floor(tree) for _ in range(runs))
    first = min(command(tree, "--no-cache") for _ in range(runs))
    shutil.rmtree(CACHE, ignore_errors=True)
    command(tree)
    second = min(command(tree) for _ in range(runs))
    found, _ = discover([tree])
    edited = next(c.path for c in sorted(found, key=lambda c: str(c.path))
                  if b"createDescription" in c.path.read_bytes())
    original = edited.read_bytes()
    changed = []
    try:
        for number in range(runs):
            edited.write_bytes(original + f"# edited {number}\n".encode())
            changed.append(command(tree))
        same = _output(tree) == _output(tree, "--no-cache")
    finally:
        edited.write_bytes(original)
        shutil.rmtree(CACHE, ignore_errors=True)
    print("| tree | floor (s) | check --no-cache (s) | ratio | second check (s) | "
          "after one file changed (s) |")
    print("|---|---:|---:|---:|---:|---:|")
    print(f"| {tree.name} | {low:.3f} | {first:.2f} | {first / low:.1f}x | "
          f"{second:.2f} ({second / first:.2f}x) | {min(changed):.2f} "
          f"({min(changed) / first:.2f}x) |")
    print(f"\nafter the change, with the cache and with --no-cache: "
          f"{'byte-identical' if same else 'DIFFERENT'} ({edited.relative_to(tree)})")
    return 0 if same else 1


def alternate(tree: Path, runs: int) -> int:
    """``--alternate``: the floor and ``check --no-cache`` one after the other ``runs``
    times, so that both see the machine in the same state; the ratio of the minima (the
    ``--whole`` rule) and of the medians."""
    floors, checks = [], []
    command(tree, "--no-cache")  # untimed: compiles the bytecode, warms the page cache
    for _ in range(runs):
        floors.append(floor(tree))
        checks.append(command(tree, "--no-cache"))
    low, first = min(floors), min(checks)
    middle, typical = statistics.median(floors), statistics.median(checks)
    print("| tree | floor min / median (s) | check --no-cache min / median (s) | "
          "ratio of minima | ratio of medians |")
    print("|---|---:|---:|---:|---:|")
    print(f"| {tree.name} | {low:.3f} / {middle:.3f} | {first:.3f} / {typical:.3f} | "
          f"{first / low:.2f}x | {typical / middle:.2f}x |")
    return 0


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("checkouts", type=Path)
    parser.add_argument("--runs", type=int, default=2)
    parser.add_argument("--whole", action="store_true", help="one tree, one run")
    parser.add_argument("--alternate", action="store_true",
                        help="one tree: floor and check alternated --runs times")
    args = parser.parse_args(argv)
    if args.alternate:
        return alternate(args.checkouts, args.runs)
    if args.whole:
        return whole(args.checkouts, args.runs)
    totals = [0.0, 0.0, 0.0]
    print("| repository | floor (s) | check (s) | ratio | second check (s) |")
    print("|---|---:|---:|---:|---:|")
    for checkout in sorted(p for p in args.checkouts.iterdir() if p.is_dir()):
        command(checkout, "--no-cache")  # untimed: compiles the bytecode, warms the caches
        low = min(floor(checkout) for _ in range(args.runs))
        first = min(command(checkout, "--no-cache") for _ in range(args.runs))
        shutil.rmtree(CACHE, ignore_errors=True)
        command(checkout)
        second = min(command(checkout) for _ in range(args.runs))
        shutil.rmtree(CACHE, ignore_errors=True)
        totals = [totals[0] + low, totals[1] + first, totals[2] + second]
        print(f"| {checkout.name} | {low:.3f} | {first:.2f} | {first / low:.0f}x | "
              f"{second:.2f} |")
    print(f"| **all** | **{totals[0]:.2f}** | **{totals[1]:.2f}** | "
          f"**{totals[1] / totals[0]:.0f}x** | **{totals[2]:.2f}** |")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
