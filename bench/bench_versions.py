"""Two versions of ``ezmigrate check`` on one tree, their runs alternating.

    python bench/bench_versions.py TREE --before /tmp/wt-start --after . [--runs 11]
        [-- CHECK-ARGS...]

``--before`` and ``--after`` are source trees of ezmigrate (a ``git worktree`` of another
commit, or this checkout), each put first on ``PYTHONPATH``. Each round runs one, then the
other, so both meet the machine in the same state: on a shared machine whose speed moves
by a fifth within minutes, only such pairs compare. One untimed run of each first compiles
the bytecode into a private folder (as ``bench_public.py`` does). Printed per version: the
minimum and the median of the wall time, and of the CPU time of the command with the
children it reaped (the reading worker; git's subprocesses).

CHECK-ARGS default to ``--no-cache --jobs 2``; ``--exit-zero --output-format json .`` are
always added.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

PYCACHE = str(Path(tempfile.gettempdir()) / "ezmigrate-bench-pycache")


def _run(tree: Path, source: Path, args: list[str]) -> tuple[float, float]:
    """Wall and CPU seconds of one ``check`` with ``source`` first on the path."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    env.update(PYTHONPATH=str(source.resolve()), PYTHONPYCACHEPREFIX=PYCACHE)
    started = time.perf_counter()
    child = subprocess.Popen([sys.executable, "-m", "ezmigrate", "check", *args,
                              "--exit-zero", "--output-format", "json", "."], cwd=tree,
                             env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, _, usage = os.wait4(child.pid, 0)
    return time.perf_counter() - started, usage.ru_utime + usage.ru_stime


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("tree", type=Path)
    parser.add_argument("--before", type=Path, required=True)
    parser.add_argument("--after", type=Path, required=True)
    parser.add_argument("--runs", type=int, default=11)
    argv = sys.argv[1:]
    split = argv.index("--") if "--" in argv else len(argv)
    options = parser.parse_args(argv[:split])
    options.check = argv[split + 1:] or ["--no-cache", "--jobs", "2"]
    versions = {"before": options.before, "after": options.after}
    timed: dict[str, list[tuple[float, float]]] = {name: [] for name in versions}
    for source in versions.values():
        _run(options.tree, source, options.check)  # untimed: bytecode, page cache
    for _ in range(options.runs):
        for name, source in versions.items():
            timed[name].append(_run(options.tree, source, options.check))
    print(f"`check {' '.join(options.check)}` on {options.tree.name}, {options.runs} "
          "alternating rounds\n")
    print("| version | wall min / median (s) | CPU min / median (s) |")
    print("|---|---:|---:|")
    for name, runs in timed.items():
        walls, cpus = [w for w, _ in runs], [c for _, c in runs]
        print(f"| {name} ({versions[name]}) | {min(walls):.3f} / "
              f"{statistics.median(walls):.3f} | {min(cpus):.3f} / "
              f"{statistics.median(cpus):.3f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
