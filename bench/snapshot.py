"""Every output of ezmigrate on the fixture trees and a generated tree, for before/after diffs.

    python bench/snapshot.py OUT [--python PYTHON] [--generated-files 300]

A refactoring that claims "behaviour unchanged" proves it by running this at the commit
before and at its own, with the same interpreter, and comparing the two folders with
``diff -r``: every tree is copied to the same path (``/tmp/ezmigrate-snapshot/<tree>``) so
that paths in the outputs agree. For each tree it keeps stdout, stderr and the exit code of
``check --output-format json``, ``check`` (text), ``rewrite --dry-run --report r.md`` and
``rewrite --report r.json`` (each report too), and after the last one the SHA-256 of every
file of the tree. ``--python`` names the interpreter whose ``ezmigrate`` runs (a checkout's
venv, or this one with ``PYTHONPATH`` pointing at another checkout).
"""

from __future__ import annotations

import argparse
import hashlib
import os
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
WORK = Path("/tmp/ezmigrate-snapshot")
COMMANDS: dict[str, tuple[str, ...]] = {
    "check-json": ("check", "--output-format", "json", "--no-cache", "."),
    "check-text": ("check", "--no-cache", "."),
    "dry-run": ("rewrite", "--dry-run", "--report", "r.md", "."),
    "rewrite": ("rewrite", "--report", "r.json", "."),
}


def trees(generated_files: int, python: str) -> list[Path]:
    """The fixture trees (each folder of ``fixtures/``) and one generated tree."""
    found = sorted(p for p in (ROOT / "fixtures").iterdir() if p.is_dir())
    generated = WORK / "sources" / "generated"
    if not generated.exists():
        subprocess.run([python, str(ROOT / "bench" / "generate_repo.py"), str(generated),
                        "--files", str(generated_files), "--seed", "7"], check=True,
                       stdout=subprocess.DEVNULL)
    return [*found, generated]


def run_tree(source: Path, out: Path, python: str) -> None:
    """Copy ``source`` to its fixed path, run every command there, keep what they said."""
    work = WORK / "work" / source.name
    for name, args in COMMANDS.items():
        if work.exists():
            shutil.rmtree(work)
        shutil.copytree(source, work, symlinks=True)
        subprocess.run(["git", "init", "-q", str(work)], check=True)
        run = subprocess.run([python, "-m", "ezmigrate", *args], cwd=work,
                             capture_output=True, text=True, stdin=subprocess.DEVNULL,
                             env={**os.environ, "NO_COLOR": "1"}, check=False, timeout=1800)
        target = out / source.name / name
        target.mkdir(parents=True, exist_ok=True)
        (target / "stdout").write_text(run.stdout, encoding="utf-8")
        (target / "stderr").write_text(run.stderr, encoding="utf-8")
        (target / "exit").write_text(f"{run.returncode}\n", encoding="utf-8")
        for report in ("r.md", "r.json"):
            if (work / report).exists():
                shutil.copy(work / report, target / report)
                (work / report).unlink()
    hashes = []
    for path in sorted(work.rglob("*")):
        if path.is_file() and ".git" not in path.relative_to(work).parts \
                and ".ezmigrate_cache" not in path.parts:
            digest = hashlib.sha256(path.read_bytes()).hexdigest()
            hashes.append(f"{digest}  {path.relative_to(work)}")
    (out / source.name / "hashes").write_text("\n".join(hashes) + "\n", encoding="utf-8")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out", type=Path)
    parser.add_argument("--python", default=sys.executable)
    parser.add_argument("--generated-files", type=int, default=300)
    args = parser.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    for tree in trees(args.generated_files, args.python):
        run_tree(tree, args.out, args.python)
    outputs = sum(1 for _ in args.out.rglob("stdout"))
    hashes = sum(len(p.read_text().splitlines()) for p in args.out.rglob("hashes"))
    print(f"outputs={outputs} hashes={hashes} out={args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
