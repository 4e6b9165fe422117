"""``ezmigrate check`` on legacy repositories against the floor: read and ``ast.parse``.

The floor is what any linter of these files must at least do: read every Python file and
parse it once with ``ast``, in one process. ``check`` is timed two ways: its core
(``run_check``) in this process once imports and the ontology are warm (the work that
scales with the repository), and the whole command in a fresh process (start-up, ontology
load and output included). Rounds interleave floor and check so that both see the same
machine load; each cell is the median.

Repositories come from ``bench/generate_repo.py``: ``skills`` has a legacy description in
every file (the worst case for the ratio), ``lab`` one file in ten, as a lab's monorepo,
``messy`` half of its skill files in forms the fast path leaves to the codemod.

    .venv/bin/python bench/bench_check.py --runs 5 --markdown bench/out/check.md
"""

from __future__ import annotations

import argparse
import ast
import contextlib
import importlib.util
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
SHAPES = {  # name: (files, skill share, messy share)
    "skills": (200, 1.0, 0.0),
    "lab": (2000, 0.1, 0.0),
    "messy": (200, 1.0, 0.5),
}


def _generator():  # type: ignore[no-untyped-def]
    spec = importlib.util.spec_from_file_location("generate_repo", HERE / "generate_repo.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules["generate_repo"] = module
    spec.loader.exec_module(module)
    return module


def floor(root: Path) -> float:
    """Seconds to read and ``ast.parse`` every Python file under ``root``."""
    start = time.perf_counter()
    for path in sorted(root.rglob("*.py")):
        data = path.read_bytes()
        with contextlib.suppress(SyntaxError):  # a Python 2 file: the parse was paid for
            ast.parse(data)
    return time.perf_counter() - start


def core(root: Path, jobs: int) -> tuple[float, int, int]:
    """Seconds of ``run_check`` (warm), skills seen, findings before selection."""
    from ezmigrate.checking.pipeline import run_check
    from ezmigrate.verify.pool import PoolConfig
    from ezskiros_runtime.ontology.index import bundled_ontology_path
    from ezskiros_runtime.ontology.load import load_index

    index = load_index([bundled_ontology_path()])
    start = time.perf_counter()
    outcome = run_check([root], index, PoolConfig(workers=jobs))
    return time.perf_counter() - start, outcome.skills, len(outcome.diagnostics)


def command(root: Path, jobs: int) -> float:
    """Wall seconds of ``ezmigrate check --no-cache ROOT`` in a fresh process (with its
    cache, every round after the first would be answered from the first's)."""
    start = time.perf_counter()
    subprocess.run([sys.executable, "-m", "ezmigrate", "check", "-q", "--exit-zero",
                    "--no-cache", "-j", str(jobs), str(root)], check=True,
                   stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    return time.perf_counter() - start


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--jobs", "-j", type=int, default=2)
    parser.add_argument("--shapes", default=",".join(SHAPES))
    parser.add_argument("--markdown", type=Path, help="also write the table to this file")
    args = parser.parse_args(argv)
    core(HERE, args.jobs)  # warm the imports and the ontology cache once
    rows = ["| repository | files | skills | floor (s) | check core (s) | ratio | "
            "check command (s) | ratio |", "|---|---:|---:|---:|---:|---:|---:|---:|"]
    with tempfile.TemporaryDirectory() as tmp:
        for name in args.shapes.split(","):
            files, share, messy = SHAPES[name]
            root = Path(tmp) / name
            _generator().generate(root, files, skill_share=share, seed=0, messy_share=messy)
            floors, cores, commands = [], [], []
            skills = 0
            for _ in range(args.runs):
                floors.append(floor(root))
                seconds, skills, _found = core(root, args.jobs)
                cores.append(seconds)
                commands.append(command(root, args.jobs))
            f, c, w = (statistics.median(x) for x in (floors, cores, commands))
            count = sum(1 for _ in root.rglob("*.py"))
            rows.append(f"| {name} | {count} | {skills} | {f:.3f} | {c:.3f} | {c / f:.2f}x | "
                        f"{w:.3f} | {w / f:.2f}x |")
            print(rows[-1], flush=True)
    text = "\n".join(rows) + "\n"
    if args.markdown:
        args.markdown.parent.mkdir(parents=True, exist_ok=True)
        args.markdown.write_text(text, encoding="utf-8")
    print(text)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
