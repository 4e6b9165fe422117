"""Precision of ``ezmigrate check`` per rule on real repositories, against verdicts by hand.

    python bench/bench_precision.py CHECKOUTS [--verdicts bench/verdicts.csv] [--markdown]

CHECKOUTS is a folder of git checkouts, one per repository, each named ``owner+name``
(``RobotLabLTH+skiros2_std_lib``). In each, ``ezmigrate check --no-cache --output-format
json .`` runs at the root, as a lab runs it. Every warning and error line is looked up in
the verdicts (repository, path, line, code: one line each, judged against SkiROS2's source
and saying which function makes it real or not). The script prints, per code, the lines
reported, how many were judged real and false, and those no verdict covers; then the real
findings of the verdicts that the run no longer reports as a warning or an error, so that a
change which buys precision by losing a real defect shows. The exit status is 1 when a line
has no verdict or precision is below ``--floor`` (0.9), so that the figure in docs/rules.md
cannot be claimed of a run that was not judged.
"""

from __future__ import annotations

import argparse
import csv
import json
import subprocess
import sys
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
VERDICTS = ROOT / "bench" / "verdicts.csv"
Key = tuple[str, str, int, str]


def read_verdicts(path: Path) -> dict[Key, dict[str, str]]:
    """``{(repository, path, line, code): row}`` of the verdicts file."""
    with path.open(encoding="utf-8", newline="") as handle:
        return {(r["repository"], r["path"], int(r["line"]), r["code"]): r
                for r in csv.DictReader(handle)}


def flagged(checkout: Path, python: str) -> list[dict[str, object]]:
    """The warning and error findings of ``check`` at the root of ``checkout``."""
    run = subprocess.run([python, "-m", "ezmigrate", "check", "--no-cache", "--output-format",
                          "json", "."], cwd=checkout, capture_output=True, text=True,
                         stdin=subprocess.DEVNULL, check=False, timeout=1800)
    if run.returncode not in (0, 1):
        raise SystemExit(f"{checkout}: check exited {run.returncode}: {run.stderr[-500:]}")
    return [d for d in json.loads(run.stdout) if d["severity"] != "info"]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("checkouts", type=Path)
    parser.add_argument("--verdicts", type=Path, default=VERDICTS)
    parser.add_argument("--python", default=sys.executable)
    parser.add_argument("--floor", type=float, default=0.9)
    parser.add_argument("--markdown", action="store_true", help="print the table only")
    args = parser.parse_args(argv)
    verdicts = read_verdicts(args.verdicts)
    reported: Counter[str] = Counter()
    real: Counter[str] = Counter()
    false: Counter[str] = Counter()
    unjudged: list[str] = []
    seen: set[Key] = set()
    repositories = 0
    for checkout in sorted(p for p in args.checkouts.iterdir() if (p / ".git").exists()):
        repositories += 1
        repository = checkout.name.replace("+", "/", 1)
        for d in flagged(checkout, args.python):
            key = (repository, str(d["path"]), int(str(d["line"])), str(d["code"]))
            seen.add(key)
            code = key[3]
            reported[code] += 1
            verdict = verdicts.get(key)
            if verdict is None:
                unjudged.append(f"{repository} {key[1]}:{key[2]} {code} {d['severity']}: "
                                f"{str(d['message'])[:160]}")
            elif verdict["verdict"] == "real":
                real[code] += 1
            else:
                false[code] += 1
    lost = [f"{k[0]} {k[1]}:{k[2]} {k[3]}" for k, v in sorted(verdicts.items())
            if v["verdict"] == "real" and k not in seen]
    total, good = sum(reported.values()), sum(real.values())
    precision = good / total if total else 1.0
    lines = ["| code | reported | real | false | unjudged | precision |",
             "|---|---:|---:|---:|---:|---:|"]
    for code in sorted(reported):
        share = f"{real[code] / reported[code]:.0%}"
        lines.append(f"| {code} | {reported[code]} | {real[code]} | {false[code]} | "
                     f"{reported[code] - real[code] - false[code]} | {share} |")
    lines.append(f"| **all** | **{total}** | **{good}** | **{sum(false.values())}** | "
                 f"**{len(unjudged)}** | **{precision:.0%}** |")
    print("\n".join(lines))
    if not args.markdown:
        print(f"\n{repositories} repositories; warning and error lines: {total}, judged real "
              f"{good} ({precision:.1%})")
        for line in unjudged:
            print(f"unjudged: {line}")
        for line in lost:
            print(f"real, no longer a warning or error: {line}")
    return 1 if unjudged or precision < args.floor else 0


if __name__ == "__main__":
    raise SystemExit(main())
