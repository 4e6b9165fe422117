"""Large repositories (issue 5): ezmigrate against LibCST's own runner, on the same trees.

    .venv/bin/python bench/bench_repo.py [--sizes 200,2000,20000] [--jobs 2] [--runs 3]

For each size a synthetic repository is generated once (``bench/generate_repo.py``, 10 %
skill files, seed 0) and cached under ``bench/out/`` (gitignored). Each tree gets a
``git init`` of its own: ``bench/out`` is ignored by this repository's ``.gitignore``, and
ezmigrate respects ``.gitignore``, so without it ezmigrate would see no file at all. The
commands below then run on the same tree, alternating (the order rotates every round, so
that a slow minute on a shared machine hits every command alike), and the table shows
medians:

(a) ``ezmigrate rewrite --dry-run --no-verify -j J TREE`` against
    ``python -m libcst.tool codemod -x bench.noop_codemod.NoOp -j J --no-format
    --hide-progress TREE`` (a codemod that changes nothing; run from a folder holding only a
    ``.libcst.codemod.yaml`` with no formatter and the tree as ``repo_root``). The harness
    checks once per tree that both tools see exactly the same ``.py`` files.
(b) ``ezmigrate rewrite --dry-run -j J TREE`` (with verification) and
    ``ezmigrate verify -j J TREE AFTER`` (AFTER: the tree migrated once with
    ``rewrite --output-dir``), as skills per second: verified skills (``converted`` in the
    summary) or compared classes, over the wall time. For ``rewrite`` the verification phase
    alone is also shown: skills over (median with verification - median without).
(v) the verification step alone: a small driver migrates the tree (untimed), then times
    ``project.verify_changed`` (the verification ``rewrite`` runs), zygote start-up included.
(c) ontology load, cold (empty cache folder) against warm (cache primed), each in a fresh
    process: ``load_index(['../shared/ontology/skiros2'])`` timed inside the process.
(d) peak memory of every command above, three ways:
    - tree RSS: the largest sum of ``VmRSS`` over the command's live process tree (the
      process and all its descendants, found by scanning ``/proc/*/stat``), sampled every
      ``--sample-ms`` ms; shared pages count once per process, so this overstates;
    - tree PSS: the same sum with ``Pss`` from ``/proc/PID/smaps_rollup`` (shared pages
      divided among the processes sharing them), which is what the tree really occupies;
    - largest process: ``ru_maxrss`` from ``wait4`` (the largest peak RSS of the command's
      process and every descendant it reaped; exact, not sampled).
    Short-lived verification children (a few ms each) may fall between two samples.

Every command runs with ``PYTHONPYCACHEPREFIX=bench/out/pycache`` and without
``PYTHONDONTWRITEBYTECODE``, so that both tools load compiled bytecode as an installed
package would (this environment sets ``PYTHONDONTWRITEBYTECODE=1``), and with a private,
primed ontology cache (``EZSKIROS_CACHE_DIR``) except in the cold runs of (c). One round
on a 20-file tree primes the bytecode and the page cache before the measured rounds.

Besides the Markdown tables on stdout, every measured run is kept in
``bench/out/bench_repo-<timestamp>.json``.
"""

from __future__ import annotations

import argparse
import datetime as _dt
import json
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from collections.abc import Sequence
from dataclasses import asdict, dataclass
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
OUT = REPO / "bench" / "out"
SKIROS2 = REPO.parent / "shared" / "ontology" / "skiros2"
PAGE = os.sysconf("SC_PAGE_SIZE")


# -- measuring one command -----------------------------------------------------------------

@dataclass
class Run:
    """One measured command: times in seconds, memory in MiB."""

    label: str
    files: int
    wall: float
    cpu: float
    tree_rss: float
    tree_pss: float
    max_rss: float
    returncode: int
    summary: str = ""


class _TreeSampler(threading.Thread):
    """Polls the process tree under ``root`` and keeps the largest RSS and PSS sums."""

    def __init__(self, root: int, interval: float) -> None:
        super().__init__(daemon=True)
        self.root, self.interval = root, interval
        self.rss = self.pss = 0
        self.samples = 0
        self._parent: dict[int, int] = {}  # pid -> parent pid, of every process seen
        self._stop_event = threading.Event()

    def run(self) -> None:
        while not self._stop_event.is_set():
            self._sample()
            self._stop_event.wait(self.interval)

    def stop(self) -> None:
        self._stop_event.set()
        self.join()

    def _sample(self) -> None:
        live = {int(name) for name in os.listdir("/proc") if name.isdigit()}
        for gone in self._parent.keys() - live:
            del self._parent[gone]
        for pid in live - self._parent.keys():  # a new process: read its parent once
            try:
                with open(f"/proc/{pid}/stat", "rb") as handle:
                    stat = handle.read()
                self._parent[pid] = int(stat[stat.rindex(b")") + 2:].split()[1])
            except (OSError, ValueError, IndexError):
                continue
        children: dict[int, list[int]] = {}
        for pid, ppid in self._parent.items():
            children.setdefault(ppid, []).append(pid)
        tree, todo = [], [self.root]
        while todo:
            pid = todo.pop()
            tree.append(pid)
            todo.extend(children.get(pid, ()))
        rss = pss = 0
        for pid in tree:
            try:
                with open(f"/proc/{pid}/statm", "rb") as handle:
                    rss += int(handle.read().split()[1]) * PAGE
                with open(f"/proc/{pid}/smaps_rollup", "rb") as handle:
                    match = re.search(rb"^Pss:\s+(\d+) kB", handle.read(), re.M)
                    pss += int(match[1]) * 1024 if match else 0
            except (OSError, ValueError):
                continue
        self.rss, self.pss = max(self.rss, rss), max(self.pss, pss)
        self.samples += 1


def measure(label: str, files: int, command: Sequence[str], *, cwd: Path,
            env: dict[str, str], interval: float) -> tuple[Run, str]:
    """Run ``command``; its figures and its stderr (stdout is discarded)."""
    with tempfile.TemporaryFile() as err:
        started = time.perf_counter()
        process = subprocess.Popen(list(command), cwd=cwd, env=env, stdin=subprocess.DEVNULL,
                                   stdout=subprocess.DEVNULL, stderr=err)
        sampler = _TreeSampler(process.pid, interval)
        sampler.start()
        _, status, usage = os.wait4(process.pid, 0)
        wall = time.perf_counter() - started
        sampler.stop()
        process.returncode = os.waitstatus_to_exitcode(status)
        err.seek(0)
        stderr = err.read().decode("utf-8", "replace")
    mib = 1024 * 1024
    run = Run(label, files, wall, usage.ru_utime + usage.ru_stime, sampler.rss / mib,
              sampler.pss / mib, usage.ru_maxrss / 1024, process.returncode)
    return run, stderr


# -- trees ---------------------------------------------------------------------------------

def tree_path(files: int, share: float, seed: int) -> Path:
    return OUT / f"repo-{files}-share{share:g}-seed{seed}"


def ensure_tree(files: int, share: float, seed: int, env: dict[str, str]) -> Path:
    """The cached tree for these arguments, generated (and ``git init``-ed) if missing."""
    tree = tree_path(files, share, seed)
    if not (tree / ".generated-repo.json").is_file():
        if tree.exists():
            shutil.rmtree(tree)
        print(f"generating {tree.name} ...", file=sys.stderr)
        subprocess.run([sys.executable, str(REPO / "bench" / "generate_repo.py"), str(tree),
                        "--files", str(files), "--skill-share", str(share), "--seed",
                        str(seed)], check=True, env=env, stdout=subprocess.DEVNULL)
    if not (tree / ".git").exists():
        subprocess.run(["git", "init", "-q", str(tree)], check=True)
    return tree


def libcst_cwd(tree: Path) -> Path:
    """A folder holding only the LibCST configuration for ``tree`` (the runner's cwd)."""
    folder = OUT / f"{tree.name}-libcst"
    folder.mkdir(parents=True, exist_ok=True)
    (folder / ".libcst.codemod.yaml").write_text(
        "# written by bench/bench_repo.py\n"
        'generated_code_marker: "@generated"\n'
        "formatter: []\n"
        "blacklist_patterns: []\n"
        "modules: []\n"
        f"repo_root: {json.dumps(str(tree))}\n", encoding="utf-8")
    return folder


def same_files(tree: Path) -> int:
    """Checks that LibCST's runner and ezmigrate see the same ``.py`` files; their count."""
    from libcst.codemod._cli import gather_files

    from ezmigrate.files.discover import discover

    theirs = {os.path.realpath(p) for p in gather_files([str(tree)])}
    candidates, _ = discover([tree])
    ours = {os.path.realpath(c.path) for c in candidates}
    if theirs != ours:
        raise SystemExit(f"{tree}: the tools see different files "
                         f"({len(theirs - ours)} only LibCST, {len(ours - theirs)} only "
                         "ezmigrate)")
    return len(ours)


def ensure_after(tree: Path, jobs: int, env: dict[str, str]) -> Path:
    """``tree`` migrated once into a sibling folder (the AFTER side of ``verify``)."""
    after = OUT / f"{tree.name}-after"
    marker = after / ".bench-complete"
    if marker.is_file():
        return after
    if after.exists():
        shutil.rmtree(after)
    print(f"migrating {tree.name} into {after.name} ...", file=sys.stderr)
    subprocess.run([sys.executable, "-m", "ezmigrate", "rewrite", "-j", str(jobs),
                    "--output-dir", str(after), str(tree)], cwd=REPO, env=env,
                   stdout=subprocess.DEVNULL, check=False)
    subprocess.run(["git", "init", "-q", str(after)], check=True)  # see the module doc
    marker.write_text("", encoding="utf-8")
    return after


# -- the commands --------------------------------------------------------------------------

@dataclass
class Command:
    key: str
    label: str
    argv: list[str]
    cwd: Path


def commands_for(tree: Path, files: int, jobs: int, baseline: bool, verify_command: bool,
                 parts: set[str], env: dict[str, str]) -> list[Command]:
    py = sys.executable
    j = str(jobs)
    found: list[Command] = []
    if "a" in parts or "b" in parts:
        found.append(Command("nover", "ezmigrate rewrite --dry-run --no-verify",
                             [py, "-m", "ezmigrate", "rewrite", "--dry-run", "--no-verify",
                              "-j", j, str(tree)], REPO))
    if "a" in parts and baseline:
        found.append(Command("libcst", "LibCST no-op codemod",
                             [py, "-m", "libcst.tool", "codemod", "-x",
                              "bench.noop_codemod.NoOp", "-j", j, "--no-format",
                              "--hide-progress", str(tree)], libcst_cwd(tree)))
    if "b" in parts:
        found.append(Command("verify_rw", "ezmigrate rewrite --dry-run (verifying)",
                             [py, "-m", "ezmigrate", "rewrite", "--dry-run", "-j", j,
                              str(tree)], REPO))
        if verify_command:
            after = ensure_after(tree, jobs, env)
            found.append(Command("verify_cmd", "ezmigrate verify",
                                 [py, "-m", "ezmigrate", "verify", "-j", j, str(tree),
                                  str(after)], REPO))
    return found


_REWRITE = re.compile(r"(\d+) files? scanned, (\d+) skills? found, (\d+) converted, (\d+) "
                      r"skipped, (\d+) failed, \d+ unchanged; (\d+) files?")
_VERIFY = re.compile(r"(\d+) files compared, (\d+) classes, (\d+) equivalent")
_LIBCST = re.compile(r"Finished codemodding (\d+) files")


def summary_of(stderr: str) -> str:
    for pattern in (_REWRITE, _VERIFY, _LIBCST):
        found = pattern.findall(stderr)
        if found:
            return " ".join(found[-1]) if isinstance(found[-1], tuple) else found[-1]
    return ""


# -- the verification step alone (b) ------------------------------------------------------

VERIFY_STEP_CHILD = """
import json, resource, sys, time
from pathlib import Path
from ezmigrate.files.discover import discover
from ezmigrate.project.settle import settle, verify_changed
from ezmigrate.project.session import RewriteOptions
from ezmigrate.verify.pool import PoolConfig
from ezskiros_runtime.ontology.config import resolve_ontology_paths
from ezskiros_runtime.ontology.load import load_index

tree, jobs = Path(sys.argv[1]), int(sys.argv[2])
source = resolve_ontology_paths(None, start=tree)
index = load_index(list(source.paths) or None)
options = RewriteOptions(paths=[tree], dry_run=True, jobs=jobs,
                         pool=PoolConfig(workers=jobs,
                                         ontology=tuple(str(p) for p in source.paths)))
candidates, _ = discover([tree])
migrated = settle(candidates, index, jobs)
changed = [m for m in migrated if m.result.changed]
converted = sum(s.status == "converted" for m in changed for s in m.result.skills)
before = resource.getrusage(resource.RUSAGE_CHILDREN)
started = time.perf_counter()
verify_changed(migrated, options.checks)
seconds = time.perf_counter() - started
after = resource.getrusage(resource.RUSAGE_CHILDREN)
verified = sum(bool(s.equivalent) for m in changed for s in m.result.skills)
sys.stderr.write(json.dumps({"seconds": seconds, "changed": len(changed), "converted": converted,
                             "verified": verified,
                             "children_cpu": after.ru_utime + after.ru_stime
                             - before.ru_utime - before.ru_stime}))
"""
"""Times ``verify_changed`` (the verification ``settle`` runs for ``rewrite``) on the tree's
changed files."""


def verify_step_runs(tree: Path, files: int, jobs: int, rounds: int, env: dict[str, str],
                     interval: float) -> list[dict]:
    found = []
    for number in range(rounds):
        run, stderr = measure("verify step", files, [sys.executable, "-c", VERIFY_STEP_CHILD,
                                                     str(tree), str(jobs)],
                              cwd=REPO, env=env, interval=interval)
        inside = json.loads(stderr.strip().splitlines()[-1])
        found.append({**asdict(run), **inside})
        print(f"[{files} files, verification step {number + 1}/{rounds}] "
              f"{inside['seconds']:.2f} s, {inside['verified']} skills verified",
              file=sys.stderr)
    return found


# -- ontology (c) --------------------------------------------------------------------------

ONTOLOGY_CHILD = """
import json, sys, time
started = time.perf_counter()
from ezskiros_runtime.ontology.load import load_index
imported = time.perf_counter()
index = load_index(sys.argv[1:])
done = time.perf_counter()
sys.stderr.write(json.dumps({"load": done - imported, "rdflib": "rdflib" in sys.modules,
                             "classes": len(index.classes)}))
"""


def ontology_runs(runs: int, env: dict[str, str], interval: float) -> dict[str, list[dict]]:
    results: dict[str, list[dict]] = {"cold": [], "warm": []}
    with tempfile.TemporaryDirectory(prefix="bench-ontology-") as scratch:
        primed = Path(scratch, "primed")
        command = [sys.executable, "-c", ONTOLOGY_CHILD, str(SKIROS2)]
        measure("prime", 0, command, cwd=REPO, env={**env, "EZSKIROS_CACHE_DIR": str(primed)},
                interval=interval)
        for number in range(runs):
            for kind in (("cold", "warm") if number % 2 == 0 else ("warm", "cold")):
                cache = primed if kind == "warm" else Path(scratch, f"cold-{number}")
                run, stderr = measure(kind, 0, command, cwd=REPO,
                                      env={**env, "EZSKIROS_CACHE_DIR": str(cache)},
                                      interval=interval)
                inside = json.loads(stderr.strip().splitlines()[-1])
                if inside["rdflib"] != (kind == "cold"):
                    raise SystemExit(f"ontology {kind} run: rdflib imported = "
                                     f"{inside['rdflib']}")
                results[kind].append({**asdict(run), **inside})
    return results


# -- reporting -----------------------------------------------------------------------------

def median(values: Sequence[float]) -> float:
    return statistics.median(values) if values else float("nan")


def machine_facts() -> dict[str, str]:
    model = ""
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    import libcst

    try:
        from importlib.metadata import version

        libcst_version = version("libcst")
    except Exception:
        libcst_version = getattr(libcst, "__version__", "?")
    head = subprocess.run(["git", "-C", str(REPO), "rev-parse", "--short", "HEAD"],
                          capture_output=True, text=True, check=False).stdout.strip()
    dirty = subprocess.run(["git", "-C", str(REPO), "status", "--porcelain", "--",
                            "ezmigrate", "ezskiros_runtime"], capture_output=True, text=True,
                           check=False).stdout.strip()
    return {"cores": str(len(os.sched_getaffinity(0))), "cpu": model,
            "commit": head + (" + uncommitted changes" if dirty else ""),
            "python": platform.python_version(), "libcst": libcst_version,
            "date": _dt.date.today().isoformat(),
            "load": " ".join(f"{x:.1f}" for x in os.getloadavg())}


def markdown(results: dict, jobs: int) -> str:
    lines: list[str] = []
    sizes = results["sizes"]

    def runs_of(size: int, key: str) -> list[dict]:
        return results["runs"].get(str(size), {}).get(key, [])

    def med(size: int, key: str, what: str) -> float:
        return median([r[what] for r in runs_of(size, key)])

    def counts(size: int, key: str) -> list[int]:
        found = [r["summary"] for r in runs_of(size, key) if r["summary"]]
        return [int(x) for x in found[-1].split()] if found else []

    lines += ["(a) dry run without verification vs LibCST's runner with a no-op codemod, "
              f"{jobs} jobs, same files (medians; CPU = user + system of the whole process "
              "tree)", "",
              "| files | runs | ezmigrate wall s | LibCST wall s | ratio | ezmigrate CPU s | "
              "LibCST CPU s | CPU ratio |",
              "|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for size in sizes:
        ours, theirs = runs_of(size, "nover"), runs_of(size, "libcst")
        if not ours:
            continue
        files = ours[0]["files"]
        if theirs:
            a, b = med(size, "nover", "wall"), med(size, "libcst", "wall")
            c, d = med(size, "nover", "cpu"), med(size, "libcst", "cpu")
            lines.append(f"| {files} | {len(ours)}/{len(theirs)} | {a:.2f} | {b:.2f} | "
                         f"**{a / b:.3f}x** | {c:.2f} | {d:.2f} | {c / d:.3f}x |")
        else:
            a, c = med(size, "nover", "wall"), med(size, "nover", "cpu")
            lines.append(f"| {files} | {len(ours)}/- | {a:.2f} | not run | - | {c:.2f} | - "
                         "| - |")
    lines += ["", f"(b) verification, {jobs} jobs (medians; skills = verified skills of "
              "`rewrite`, classes compared by `verify`)", "",
              "| files | skills | rewrite verifying wall s | skills/s (whole command) | "
              "verification phase s | skills/s (verification) | verify wall s | classes | "
              "skills/s (verify) |",
              "|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for size in sizes:
        rw = runs_of(size, "verify_rw")
        if not rw:
            continue
        files = rw[0]["files"]
        skills = counts(size, "verify_rw")[2] if counts(size, "verify_rw") else 0
        wall = med(size, "verify_rw", "wall")
        phase = wall - med(size, "nover", "wall")
        vc = runs_of(size, "verify_cmd")
        classes = counts(size, "verify_cmd")[1] if counts(size, "verify_cmd") else 0
        vwall = med(size, "verify_cmd", "wall")
        lines.append(f"| {files} | {skills} | {wall:.2f} | {skills / wall:.1f} | {phase:.2f} | "
                     f"**{skills / phase:.1f}** | " + (
                         f"{vwall:.2f} | {classes} | {classes / vwall:.1f} |" if vc else
                         "not run | - | - |"))
    step_rows = [(size, results["verify_step"][str(size)]) for size in sizes
                 if str(size) in results.get("verify_step", {})]
    if step_rows:
        lines += ["", "(b, continued) the verification step alone: `project.verify_changed` (what "
                  "`rewrite` calls after migrating) timed inside one process, zygote start-up "
                  "included (medians)", "",
                  "| files | changed files | skills verified | seconds | **skills/s** | "
                  "CPU s (workers and children) |", "|---:|---:|---:|---:|---:|---:|"]
        for _, steps in step_rows:
            sec = median([r["seconds"] for r in steps])
            skills = steps[-1]["verified"]
            lines.append(f"| {steps[0]['files']} | {steps[-1]['changed']} | {skills} | "
                         f"{sec:.2f} | **{skills / sec:.1f}** | "
                         f"{median([r['children_cpu'] for r in steps]):.2f} |")
    lines += ["", "Scaling: wall (and CPU) time per file of the dry run without verification "
              "and of the verifying rewrite (medians)", "",
              "| files | no-verify ms/file | no-verify CPU ms/file | verifying ms/file |",
              "|---:|---:|---:|---:|"]
    per_file = []
    for size in sizes:
        nv = runs_of(size, "nover")
        if not nv:
            continue
        files = nv[0]["files"]
        ms = 1000 * med(size, "nover", "wall") / files
        per_file.append(ms)
        cpu = 1000 * med(size, "nover", "cpu") / files
        vr = runs_of(size, "verify_rw")
        vms = f"{1000 * med(size, 'verify_rw', 'wall') / files:.2f}" if vr else "-"
        lines.append(f"| {files} | {ms:.2f} | {cpu:.2f} | {vms} |")
    if len(per_file) > 1:
        lines += ["", f"Largest / smallest time per file (no-verify, wall): "
                  f"**{max(per_file) / min(per_file):.2f}x**"]
    onto = results.get("ontology")
    if onto:
        cold, warm = onto["cold"], onto["warm"]
        lc, lw = median([r["load"] for r in cold]), median([r["load"] for r in warm])
        pc, pw = median([r["wall"] for r in cold]), median([r["wall"] for r in warm])
        rc, rw_ = median([r["max_rss"] for r in cold]), median([r["max_rss"] for r in warm])
        lines += ["", f"(c) ontology load, `load_index(['../shared/ontology/skiros2'])`, fresh "
                  f"process per run, {len(cold)} cold / {len(warm)} warm runs (medians)", "",
                  "| | cold (empty cache) | warm (cache hit) | speed-up |",
                  "|---|---:|---:|---:|",
                  f"| load_index ms | {1000 * lc:.1f} | {1000 * lw:.1f} | **{lc / lw:.1f}x** |",
                  f"| whole process ms | {1000 * pc:.1f} | {1000 * pw:.1f} | {pc / pw:.1f}x |",
                  f"| peak RSS MiB | {rc:.1f} | {rw_:.1f} | |"]
    lines += ["", "(d) peak memory, MiB (medians over runs; tree = the command's process and "
              "all its descendants)", "",
              "| files | command | tree RSS (sampled) | tree PSS (sampled) | largest process "
              "(exact) |", "|---:|---|---:|---:|---:|"]
    for size in sizes:
        for key, label in (("nover", "rewrite --dry-run --no-verify"),
                           ("libcst", "LibCST no-op codemod"),
                           ("verify_rw", "rewrite --dry-run (verifying)"),
                           ("verify_cmd", "verify")):
            runs = runs_of(size, key)
            if runs:
                lines.append(f"| {runs[0]['files']} | {label} | "
                             f"{median([r['tree_rss'] for r in runs]):.0f} | "
                             f"{median([r['tree_pss'] for r in runs]):.0f} | "
                             f"{median([r['max_rss'] for r in runs]):.0f} |")
    return "\n".join(lines) + "\n"


# -- main ----------------------------------------------------------------------------------

def child_env(cache_dir: Path) -> dict[str, str]:
    env = dict(os.environ)
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    env.pop("EZSKIROS_ONTOLOGY", None)
    env["PYTHONPYCACHEPREFIX"] = str(OUT / "pycache")
    env["EZSKIROS_CACHE_DIR"] = str(cache_dir)
    env["PYTHONPATH"] = os.pathsep.join(
        [str(REPO), *filter(None, [os.environ.get("PYTHONPATH")])])
    return env


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--sizes", default="200,2000",
                        help="comma-separated numbers of files (default 200,2000)")
    parser.add_argument("--baseline-sizes", default=None,
                        help="sizes at which the LibCST runner runs too (default: sizes up "
                             "to 2000; it takes ~0.2 s of CPU per file)")
    parser.add_argument("--verify-command-sizes", default=None,
                        help="sizes at which `ezmigrate verify` runs (default: up to 2000; "
                             "it loads every file of both trees)")
    parser.add_argument("--jobs", "-j", type=int, default=2)
    parser.add_argument("--runs", type=int, default=3, help="rounds per size (default 3)")
    parser.add_argument("--small-runs", type=int, default=5,
                        help="rounds for trees of at most --small-max files (default 5)")
    parser.add_argument("--small-max", type=int, default=500)
    parser.add_argument("--ontology-runs", type=int, default=11)
    parser.add_argument("--parts", default="a,b,c,v",
                        help="which of a,b,c,v to run (v: the verification step of `rewrite` "
                             "timed alone; d, memory, comes with every run)")
    parser.add_argument("--skill-share", type=float, default=0.1)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--sample-ms", type=float, default=50.0)
    parser.add_argument("--markdown", type=Path, help="also write the tables to this file")
    args = parser.parse_args(argv)
    sizes = [int(s) for s in args.sizes.split(",") if s]
    baseline = ({int(s) for s in args.baseline_sizes.split(",") if s}
                if args.baseline_sizes is not None else {s for s in sizes if s <= 2000})
    verify_sizes = ({int(s) for s in args.verify_command_sizes.split(",") if s}
                    if args.verify_command_sizes is not None else {s for s in sizes if s <= 2000})
    parts = set(args.parts.split(","))
    interval = args.sample_ms / 1000
    OUT.mkdir(parents=True, exist_ok=True)
    cache = OUT / "ontology-cache"
    env = child_env(cache)
    facts = machine_facts()
    results: dict = {"facts": facts, "args": vars(args) | {"markdown": str(args.markdown)},
                     "sizes": sizes, "runs": {}}
    stamp = _dt.datetime.now().strftime("%Y%m%d-%H%M%S")
    raw = OUT / f"bench_repo-{stamp}.json"

    def save() -> None:
        raw.write_text(json.dumps(results, indent=1), encoding="utf-8")

    if parts & {"a", "b"}:  # prime bytecode, the ontology cache and every code path
        tiny = ensure_tree(20, args.skill_share, args.seed, env)
        for command in commands_for(tiny, 20, args.jobs, True, True, parts, env):
            measure("prime", 20, command.argv, cwd=command.cwd, env=env, interval=interval)
    for size in sizes:
        if not parts & {"a", "b"}:
            break
        tree = ensure_tree(size, args.skill_share, args.seed, env)
        files = same_files(tree)
        for path in tree.rglob("*.py"):  # the page cache, for every command alike
            path.read_bytes()
        commands = commands_for(tree, files, args.jobs, size in baseline, size in verify_sizes,
                                parts, env)
        rounds = args.small_runs if size <= args.small_max else args.runs
        per_size: dict[str, list[dict]] = {c.key: [] for c in commands}
        results["runs"][str(size)] = per_size
        for number in range(rounds):
            shift = number % len(commands)
            for command in commands[shift:] + commands[:shift]:
                run, stderr = measure(command.label, files, command.argv, cwd=command.cwd,
                                      env=env, interval=interval)
                run.summary = summary_of(stderr)
                if not run.summary:
                    print(stderr[-3000:], file=sys.stderr)
                    raise SystemExit(f"{command.label} on {tree.name}: no summary "
                                     f"(exit {run.returncode})")
                if command.key == "libcst" and int(run.summary) != files:
                    raise SystemExit(f"LibCST processed {run.summary} of {files} files")
                if command.key != "libcst" and int(run.summary.split()[0]) != files:
                    raise SystemExit(f"{command.label} saw {run.summary.split()[0]} of "
                                     f"{files} files")
                per_size[command.key].append(asdict(run))
                print(f"[{size} files, round {number + 1}/{rounds}] {command.label}: "
                      f"{run.wall:.2f} s wall, {run.cpu:.2f} s CPU, tree RSS "
                      f"{run.tree_rss:.0f} MiB ({run.summary})", file=sys.stderr)
                save()
    if "v" in parts:
        results["verify_step"] = {}
        for size in sizes:
            tree = ensure_tree(size, args.skill_share, args.seed, env)
            rounds = args.small_runs if size <= args.small_max else args.runs
            results["verify_step"][str(size)] = verify_step_runs(
                tree, same_files(tree), args.jobs, rounds, env, interval)
            save()
    if "c" in parts:
        results["ontology"] = ontology_runs(args.ontology_runs, env, interval)
        save()
    facts["load_after"] = " ".join(f"{x:.1f}" for x in os.getloadavg())
    text = (f"Machine: {facts['cores']} cores ({facts['cpu']}), Python {facts['python']}, "
            f"libcst {facts['libcst']}; {facts['date']}; code at {facts['commit']}; load "
            f"average {facts['load']} before, {facts['load_after']} after.\n\n"
            + markdown(results, args.jobs))
    save()
    print(text)
    if args.markdown is not None:
        args.markdown.write_text(text, encoding="utf-8")
    print(f"raw data: {raw}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
