"""The runs a lab repeats: ``rewrite`` on a tree it already migrated, and ``check`` twice.

A generated repository (``generate_repo.py``) is migrated once; then, each timed as a whole
command (wall clock, median of ``--runs``):
- ``rewrite --no-verify`` again: nothing to do, so it should cost about a read and a parse
  of each skill file, less than the migration did;
- ``check`` with an empty cache, then again with the cache it left (the second run on an
  unchanged repository), and with ``--no-cache``;
- ``check`` after one skill file changed (a comment appended; the cache of the run before),
  then ``--no-cache`` on the same tree: their outputs must be the same bytes.

    .venv/bin/python bench/bench_second_run.py --files 1000 --runs 3
"""

from __future__ import annotations

import argparse
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent


OUTPUTS: dict[str, set[str]] = {}
"""What each ``check`` printed on stdout, by command: speed never changes a finding."""


def _timed(args: list[str], cwd: Path, tree: str = "check") -> float:
    started = time.perf_counter()
    run = subprocess.run([sys.executable, "-m", "ezmigrate", *args], cwd=cwd, check=False,
                         capture_output=True, text=True, timeout=3600)
    elapsed = time.perf_counter() - started
    if args[0] == "check":
        OUTPUTS.setdefault(tree, set()).add(run.stdout)
    return elapsed


def _a_skill_file(repo: Path) -> Path:
    """The first file (in path order) holding a description, migrated or not."""
    return next(p for p in sorted(repo.rglob("*.py"))
                if b"SkillDescription" in p.read_bytes() and ".ezmigrate" not in str(p))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--files", type=int, default=1000)
    parser.add_argument("--skill-share", type=float, default=0.3)
    parser.add_argument("--runs", type=int, default=3)
    options = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="ezmigrate-second-") as folder:
        repo = Path(folder) / "repo"
        subprocess.run([sys.executable, str(HERE / "generate_repo.py"), str(repo), "--files",
                        str(options.files), "--skill-share", str(options.skill_share)],
                       check=True, capture_output=True)
        subprocess.run(["git", "init", "-q", str(repo)], check=True)
        migration = _timed(["rewrite", "--no-verify", "."], repo)
        rows = {"rewrite --no-verify (the migration)": [migration]}
        for _ in range(options.runs):
            rows.setdefault("rewrite --no-verify again (no-op)", []).append(
                _timed(["rewrite", "--no-verify", "."], repo))
            shutil.rmtree(Path(folder) / "cache", ignore_errors=True)
            rows.setdefault("check, empty cache", []).append(
                _timed(["check", "--exit-zero", "--cache-dir", str(Path(folder) / "cache"),
                        "--output-format", "json", "."], repo))
            rows.setdefault("check again, cache of the first", []).append(
                _timed(["check", "--exit-zero", "--cache-dir", str(Path(folder) / "cache"),
                        "--output-format", "json", "."], repo))
            rows.setdefault("check --no-cache", []).append(
                _timed(["check", "--exit-zero", "--no-cache", "--output-format", "json", "."],
                       repo))
            edited = _a_skill_file(repo)
            edited.write_bytes(edited.read_bytes() + b"# edited\n")
            rows.setdefault("check after one file changed, cache of the run before", []).append(
                _timed(["check", "--exit-zero", "--cache-dir", str(Path(folder) / "cache"),
                        "--output-format", "json", "."], repo, "changed"))
            _timed(["check", "--exit-zero", "--no-cache", "--output-format", "json", "."], repo,
                   "changed")
            edited.write_bytes(edited.read_bytes()[:-len(b"# edited\n")])
    print(f"| whole command ({options.files} files, skill share {options.skill_share}) "
          "| median s |")
    print("|---|---:|")
    for name, times in rows.items():
        print(f"| {name} | {statistics.median(times):.2f} |")
    same = all(len(outputs) == 1 for outputs in OUTPUTS.values())
    print(f"\ncheck's output with an empty cache, with its cache and with --no-cache, on the "
          f"tree and after one file changed: {'byte-identical' if same else 'DIFFERENT'}")
    if not same:
        raise SystemExit(1)


if __name__ == "__main__":
    main()
