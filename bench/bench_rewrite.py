"""``rewrite --dry-run --no-verify`` against its physical floor; ``verify`` in classes/s.

    .venv/bin/python bench/bench_rewrite.py [--runs 5] [--verify-runs 3] [--jobs 2]
                                            [--out DIR] [--markdown PATH] [--quick]

The tree is the lab shape of ``bench/generate_repo.py`` (2,000 modules, one in ten a legacy
skill file, seed 0), generated once and cached under ``bench/out/`` (gitignored; the tree
gets a ``git init`` of its own, because ezmigrate respects ``.gitignore``) or under
``--out``.

**The floor** is the work no migration tool can avoid on this tree: read every ``.py``
file (to find the skills), and parse with LibCST and print back each skill file (the
files that change; ``rewrite`` is a LibCST codemod). It runs with as many processes as the
command has jobs (a ``fork`` pool, the files split evenly; pool start-up and the
``import libcst`` in every worker are timed), so the ratio command / floor is what
ezmigrate adds on top: interpreter start-up, its imports, the ontology, discovery,
analysis, the transform, diffs. The single-process floor is shown for reference.

**The command** is ``python -m ezmigrate rewrite --dry-run --no-verify -j JOBS TREE`` in a
fresh process (diffs to ``/dev/null``); its summary on stderr is checked (no failure, the
skills the manifest calls convertible converted, every file scanned). Rounds interleave
floor and command so both see the same machine load; cells are medians.

**verify** compares the tree with a copy migrated once per run (``rewrite --no-verify
--output-dir``), as ``python -m ezmigrate verify -j JOBS --report R.json TREE COPY``;
classes per second = classes in the report over the median wall time.

Every measurement also records CPU time (user + system of all the processes it started, from
``getrusage(RUSAGE_CHILDREN)``): on a shared machine the CPU ratio is steadier than the wall
ratio, which other jobs inflate whenever they take a core the measurement wanted.

Children run as in ``bench/bench_repo.py``: compiled bytecode under a private
``PYTHONPYCACHEPREFIX`` and a private, primed ontology cache. One untimed round of every
measurement primes them and the page cache.
"""

from __future__ import annotations

import argparse
import json
import multiprocessing
import os
import re
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Sequence
from contextlib import redirect_stdout
from dataclasses import dataclass, field
from pathlib import Path

from bench_check import _generator
from bench_repo import child_env, machine_facts

HERE = Path(__file__).resolve().parent
REPO = HERE.parent
FILES, SKILL_SHARE, SEED = 2000, 0.1, 0
MANIFEST = ".generated-repo.json"
_REWRITE = re.compile(r"(\d+) files? scanned, (\d+) skills? found, (\d+) converted, "
                      r"(\d+) skipped, (\d+) failed")
_VERIFY = re.compile(r"(\d+) files compared, (\d+) classes, (\d+) equivalent")


# -- the tree ------------------------------------------------------------------------------

@dataclass(frozen=True)
class Tree:
    """The generated tree: every ``.py`` file, the skill files among them, the manifest."""

    root: Path
    files: list[Path]
    skill_files: list[Path]
    classes: int
    convertible: int

    @property
    def other_files(self) -> list[Path]:
        skills = set(self.skill_files)
        return [path for path in self.files if path not in skills]


def ensure_tree(out: Path) -> Tree:
    """The cached tree under ``out``, generated (and ``git init``-ed) if missing."""
    root = out / f"repo-{FILES}-share{SKILL_SHARE:g}-seed{SEED}"
    if not (root / MANIFEST).is_file():
        if root.exists():
            shutil.rmtree(root)
        print(f"generating {root} ...", file=sys.stderr)
        with redirect_stdout(sys.stderr):
            _generator().main([str(root), "--files", str(FILES), "--skill-share",
                               str(SKILL_SHARE), "--seed", str(SEED)])
    if not (root / ".git").exists():
        subprocess.run(["git", "init", "-q", str(root)], check=True)
    manifest = json.loads((root / MANIFEST).read_text(encoding="utf-8"))
    entries = manifest["skill_files"]
    return Tree(root, sorted(root.rglob("*.py")),
                sorted(root / entry["path"] for entry in entries),
                sum(len(entry["classes"]) for entry in entries),
                manifest["summary"]["convertible_skills"])


def display(path: Path) -> str:
    """``path`` relative to the repository when inside it (for the printed commands)."""
    return str(path.relative_to(REPO)) if path.is_relative_to(REPO) else str(path)


# -- the floor -----------------------------------------------------------------------------

@dataclass(frozen=True)
class Share:
    """One worker's part of the floor: files only read, and skill files read and parsed."""

    read: list[Path]
    parse: list[Path]


def _floor_worker(share: Share) -> tuple[int, int, int]:
    """Runs in a pool worker: its pid, files done, skill files not printed back identically."""
    import libcst  # timed: the workers of the command import it too

    for path in share.read:
        path.read_bytes()
    mismatches = 0
    for path in share.parse:
        data = path.read_bytes()
        mismatches += libcst.parse_module(data).code != data.decode("utf-8")
    return os.getpid(), len(share.read) + len(share.parse), mismatches


def shares(tree: Tree, processes: int) -> list[Share]:
    """The tree split evenly: every ``processes``-th other file and skill file."""
    others, skills = tree.other_files, tree.skill_files
    return [Share(others[i::processes], skills[i::processes]) for i in range(processes)]


@dataclass(frozen=True)
class Timing:
    wall: float
    cpu: float  # user + system seconds of every child process reaped meanwhile


def _children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def floor(tree: Tree, processes: int) -> Timing:
    """The floor with ``processes`` forked workers, pool start-up included."""
    if "libcst" in sys.modules:  # forked workers would inherit it: the import would be free
        raise SystemExit("libcst is imported in the parent; the floor would not pay for it")
    parts = shares(tree, processes)
    cpu, start = _children_cpu(), time.perf_counter()
    pool = multiprocessing.get_context("fork").Pool(processes)
    results = pool.map(_floor_worker, parts, chunksize=1)
    pool.close()
    pool.join()
    timing = Timing(time.perf_counter() - start, _children_cpu() - cpu)
    if len({pid for pid, _, _ in results}) != processes:
        raise SystemExit(f"floor: {processes} shares did not run in {processes} processes")
    if sum(done for _, done, _ in results) != len(tree.files):
        raise SystemExit("floor: not every file was read")
    if any(mismatch for _, _, mismatch in results):
        raise SystemExit("floor: LibCST did not print a skill file back identically")
    return timing


# -- the commands --------------------------------------------------------------------------

def ezmigrate(*args: str) -> list[str]:
    return [sys.executable, "-m", "ezmigrate", *args]


def run(argv: Sequence[str], env: dict[str, str]) -> tuple[Timing, int, str]:
    """Times, exit code and stderr of ``argv`` (stdout discarded)."""
    cpu, start = _children_cpu(), time.perf_counter()
    process = subprocess.run(list(argv), cwd=REPO, env=env, stdin=subprocess.DEVNULL,
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                             check=False)
    return (Timing(time.perf_counter() - start, _children_cpu() - cpu), process.returncode,
            process.stderr)


def fail(what: str, code: int, stderr: str) -> SystemExit:
    print(stderr[-3000:], file=sys.stderr)
    return SystemExit(f"{what}: unexpected result (exit {code}), stderr above")


def rewrite_argv(tree: Tree, jobs: int) -> list[str]:
    return ezmigrate("rewrite", "--dry-run", "--no-verify", "-j", str(jobs), str(tree.root))


def timed_rewrite(tree: Tree, jobs: int, env: dict[str, str]) -> tuple[Timing, list[int]]:
    """Times of the dry run and its summary: scanned, found, converted, skipped, failed.

    ``--dry-run`` without ``--check`` exits 0 when every skill converts (README, exit codes).
    """
    timing, code, stderr = run(rewrite_argv(tree, jobs), env)
    found = _REWRITE.findall(stderr)
    counts = [int(x) for x in found[-1]] if found else []
    if (code != 0 or not counts or counts[0] != len(tree.files) or counts[4] != 0
            or counts[2] < 0.95 * tree.convertible):
        raise fail("rewrite --dry-run --no-verify", code, stderr)
    return timing, counts


def migrated_copy(tree: Tree, copy: Path, jobs: int, env: dict[str, str]) -> None:
    """``tree`` migrated into ``copy`` (untimed), the AFTER side of ``verify``."""
    _, code, stderr = run(ezmigrate("rewrite", "--no-verify", "-j", str(jobs), "--output-dir",
                                    str(copy), str(tree.root)), env)
    if code != 0:
        raise fail("rewrite --no-verify --output-dir", code, stderr)
    subprocess.run(["git", "init", "-q", str(copy)], check=True)  # see the module doc
    for path in copy.rglob("*.py"):  # the page cache, as for the tree
        path.read_bytes()


def verify_argv(tree: Tree, copy: Path, jobs: int, report: Path) -> list[str]:
    return ezmigrate("verify", "-j", str(jobs), "--report", str(report), str(tree.root),
                     str(copy))


def timed_verify(tree: Tree, copy: Path, jobs: int,
                 env: dict[str, str]) -> tuple[Timing, int, int]:
    """Times of ``verify``, classes compared and classes equivalent (from its report).

    Exit 0 when every class is equivalent, 1 when some class is not (README, exit codes).
    """
    with tempfile.TemporaryDirectory(prefix="bench-rewrite-") as scratch:
        report = Path(scratch, "verify.json")
        timing, code, stderr = run(verify_argv(tree, copy, jobs, report), env)
        skills = json.loads(report.read_text(encoding="utf-8"))["skills"] if report.is_file() \
            else []
    compared, equivalent = len(skills), sum(s.get("equivalent") is True for s in skills)
    found = _VERIFY.findall(stderr)
    if (code != (0 if equivalent == compared else 1) or not found
            or [int(x) for x in found[-1][1:]] != [compared, equivalent]
            or compared != tree.classes):
        raise fail("verify", code, stderr)
    return timing, compared, equivalent


# -- rounds --------------------------------------------------------------------------------

@dataclass
class Results:
    floor: list[Timing] = field(default_factory=list)
    floor_single: list[Timing] = field(default_factory=list)
    rewrite: list[Timing] = field(default_factory=list)
    verify: list[Timing] = field(default_factory=list)
    rewrite_counts: list[int] = field(default_factory=list)
    compared: int = 0
    equivalent: int = 0
    primed: bool = True  # an untimed round ran first (not with --quick)


def rewrite_rounds(tree: Tree, jobs: int, runs: int, env: dict[str, str],
                   results: Results) -> None:
    """Interleaved rounds: floor with ``jobs`` processes, floor with one, the command."""
    for number in range(runs):
        results.floor.append(floor(tree, jobs))
        results.floor_single.append(floor(tree, 1))
        timing, results.rewrite_counts = timed_rewrite(tree, jobs, env)
        results.rewrite.append(timing)
        print(f"[round {number + 1}/{runs}] floor {results.floor[-1].wall:.3f} s ({jobs} "
              f"processes), {results.floor_single[-1].wall:.3f} s (1); rewrite "
              f"{timing.wall:.3f} s ({timing.cpu:.3f} s CPU)", file=sys.stderr)


def verify_rounds(tree: Tree, copy: Path, jobs: int, runs: int, env: dict[str, str],
                  results: Results) -> None:
    for number in range(runs):
        timing, results.compared, results.equivalent = timed_verify(tree, copy, jobs, env)
        results.verify.append(timing)
        print(f"[verify {number + 1}/{runs}] {timing.wall:.3f} s ({timing.cpu:.3f} s CPU), "
              f"{results.compared} classes", file=sys.stderr)


# -- reporting -----------------------------------------------------------------------------

def wall(timings: Sequence[Timing]) -> float:
    return statistics.median(t.wall for t in timings)


def cpu(timings: Sequence[Timing]) -> float:
    return statistics.median(t.cpu for t in timings)


def spread(timings: Sequence[Timing]) -> str:
    return f"{min(t.wall for t in timings):.3f}-{max(t.wall for t in timings):.3f}"


def rounds(count: int) -> str:
    return f"{count} round{'s' * (count != 1)}"


def loadavg() -> str:
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def header(tree: Tree, jobs: int, results: Results, facts: dict[str, str],
           load: tuple[str, str]) -> list[str]:
    """Title, how to reproduce, the machine, the tree, the commands timed."""
    size = sum(path.stat().st_size for path in tree.files) / 2**20
    skill_size = sum(path.stat().st_size for path in tree.skill_files) / 2**20
    root = display(tree.root)
    return [
        f"## `rewrite --dry-run --no-verify` against its floor; `verify` in classes/s "
        f"({jobs} jobs)", "",
        "Command (from the repository root):", "",
        f"    .venv/bin/python bench/bench_rewrite.py --jobs {jobs} " + (
            f"--runs {len(results.rewrite)} --verify-runs {len(results.verify)}"
            if results.primed else "--quick"), "",
        f"Machine: `nproc` = {facts['cores']} ({facts['cpu']}); load average (1, 5, 15 min) "
        f"{load[0]} before the measured rounds, {load[1]} after. Python {facts['python']}, "
        f"libcst {facts['libcst']}. Code at {facts['commit']}. Date: {facts['date']}.", "",
        f"Tree: `{root}` (`generate_repo.py OUT --files {FILES} --skill-share {SKILL_SHARE:g} "
        f"--seed {SEED}`): {len(tree.files)} `.py` files ({size:.1f} MiB), of which "
        f"{len(tree.skill_files)} skill files ({skill_size:.1f} MiB) with {tree.classes} "
        "description classes.", "",
        "Commands timed (`python` = the venv's interpreter; children run with a private "
        "`PYTHONPYCACHEPREFIX` and a primed ontology cache; "
        f"{'one untimed round of everything first' if results.primed else 'no priming round'}"
        "):", "",
        f"    python -m ezmigrate rewrite --dry-run --no-verify -j {jobs} {root}",
        f"    python -m ezmigrate rewrite --no-verify -j {jobs} --output-dir COPY {root}"
        "   # once, untimed",
        f"    python -m ezmigrate verify -j {jobs} --report R.json {root} COPY", ""]


def rewrite_table(tree: Tree, jobs: int, results: Results) -> list[str]:
    f2, f1, rw = wall(results.floor), wall(results.floor_single), wall(results.rewrite)
    c2, c1, crw = cpu(results.floor), cpu(results.floor_single), cpu(results.rewrite)
    scanned, found, converted, skipped, failed = results.rewrite_counts
    return [
        f"Floor: read all {len(tree.files)} files and `libcst.parse_module(data).code` each "
        "skill file, in a `fork` pool of N processes (files split evenly; pool start-up and "
        "`import libcst` in the workers timed; interpreter start-up not included). "
        f"{rounds(len(results.rewrite))}, floor and command interleaved; medians. CPU = user "
        "+ system of all processes started.", "",
        f"| measured | wall s | wall min-max s | CPU s | wall vs floor ({jobs} processes) | "
        f"wall vs floor (1 process) | CPU vs floor ({jobs} processes) |",
        "|---|---:|---:|---:|---:|---:|---:|",
        f"| floor, {jobs} processes | {f2:.3f} | {spread(results.floor)} | {c2:.3f} | 1.00x "
        f"| {f2 / f1:.2f}x | 1.00x |",
        f"| floor, 1 process (reference) | {f1:.3f} | {spread(results.floor_single)} | "
        f"{c1:.3f} | {f1 / f2:.2f}x | 1.00x | {c1 / c2:.2f}x |",
        f"| `rewrite --dry-run --no-verify -j {jobs}` ({scanned} files scanned, {found} skills "
        f"found, {converted} converted, {skipped} skipped, {failed} failed) | {rw:.3f} | "
        f"{spread(results.rewrite)} | {crw:.3f} | **{rw / f2:.2f}x** | {rw / f1:.2f}x | "
        f"{crw / c2:.2f}x |", ""]


def verify_table(tree: Tree, jobs: int, results: Results) -> list[str]:
    ve, cve = wall(results.verify), cpu(results.verify)
    return [
        f"`verify`, {rounds(len(results.verify))} (classes compared = entries of its JSON "
        "report; medians):", "",
        "| measured | wall s | wall min-max s | CPU s | classes compared | equivalent | "
        "classes/s |", "|---|---:|---:|---:|---:|---:|---:|",
        f"| `verify -j {jobs} {display(tree.root)} COPY` | {ve:.3f} | "
        f"{spread(results.verify)} | {cve:.3f} | {results.compared} | {results.equivalent} | "
        f"**{results.compared / ve:.1f}** |"]


def markdown(tree: Tree, jobs: int, results: Results, facts: dict[str, str],
             load: tuple[str, str]) -> str:
    return "\n".join([*header(tree, jobs, results, facts, load),
                      *rewrite_table(tree, jobs, results),
                      *verify_table(tree, jobs, results)]) + "\n"


def prime(tree: Tree, copy: Path, jobs: int, env: dict[str, str]) -> None:
    """One untimed round of everything: bytecode, ontology cache, page cache, branch caches."""
    floor(tree, jobs)
    floor(tree, 1)
    timed_rewrite(tree, jobs, env)
    timed_verify(tree, copy, jobs, env)


# -- main ----------------------------------------------------------------------------------

def parse_args(argv: list[str] | None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--jobs", "-j", type=int, default=2,
                        help="jobs of the commands and processes of the floor (default 2)")
    parser.add_argument("--runs", type=int, default=5,
                        help="interleaved floor/rewrite rounds (default 5)")
    parser.add_argument("--verify-runs", type=int, default=3,
                        help="verify rounds (default 3)")
    parser.add_argument("--out", type=Path, default=HERE / "out",
                        help="folder for the cached tree and the caches (default bench/out)")
    parser.add_argument("--markdown", type=Path, help="also write the Markdown to this file")
    parser.add_argument("--quick", action="store_true",
                        help="one round of each (a smoke test)")
    args = parser.parse_args(argv)
    if args.quick:
        args.runs = args.verify_runs = 1
    if min(args.jobs, args.runs, args.verify_runs) < 1:
        parser.error("--jobs, --runs and --verify-runs must be at least 1")
    return args


def main(argv: list[str] | None = None) -> int:
    args = parse_args(argv)
    out: Path = args.out.resolve()
    out.mkdir(parents=True, exist_ok=True)
    env = {**child_env(out / "ontology-cache"), "PYTHONPYCACHEPREFIX": str(out / "pycache")}
    tree = ensure_tree(out)
    results = Results(primed=not args.quick)
    with tempfile.TemporaryDirectory(prefix=f"{tree.root.name}-migrated-", dir=out) as tmp:
        copy = Path(tmp)
        for path in tree.files:  # the page cache, for every measurement alike
            path.read_bytes()
        migrated_copy(tree, copy, args.jobs, env)
        if not args.quick:
            prime(tree, copy, args.jobs, env)
        before = loadavg()
        rewrite_rounds(tree, args.jobs, args.runs, env, results)
        verify_rounds(tree, copy, args.jobs, args.verify_runs, env, results)
        after = loadavg()
    text = markdown(tree, args.jobs, results, machine_facts(), (before, after))
    print(text)
    if args.markdown is not None:
        args.markdown.parent.mkdir(parents=True, exist_ok=True)
        args.markdown.write_text(text, encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
