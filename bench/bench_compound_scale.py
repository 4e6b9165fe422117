"""``check`` on a compound-heavy 2,000-file tree: is compound analysis linear? (issue 31)

``bench/generate_repo.py`` writes lab-shaped trees whose few compound skills have no remap,
so the checks that look at what a tree's other nodes write never run there. This script
adds what a lab's compound packages look like to such a tree: ``--packages`` packages, each
with its own copy of a library of step descriptions (the same names in every package, so a
child is read from the nearest definition, ``SkillIndex.nearest``) and three levels of
compound skills over them: tasks of 8-14 remapped steps (some under a processor node),
missions of 5-8 remapped tasks, and a campaign of every mission. Each package seeds four
mistakes (a remap key nobody declares, a dangling remap target, an unknown specify key, a
remap of a key the steps below the child already remapped), so the findings compared are
not empty.

    .venv/bin/python bench/bench_compound_scale.py --out /tmp/compound2000   # write it
    .venv/bin/python bench/bench_compound_scale.py --runs 2 --checkout . --checkout /tmp/old

Without ``--out`` it times ``ezmigrate check --no-cache --output-format json`` in a fresh
process for each checkout (``PYTHONPATH``, the same interpreter; min of ``--runs``), says
whether their JSON outputs are byte-identical, and times the floor: read and ``ast.parse``
every ``.py`` file in one process, as ``bench_check.py`` defines it, and read every file but
parse only those holding a skill (what ``check`` itself must parse).
"""

from __future__ import annotations

import argparse
import ast
import contextlib
import json
import os
import random
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from bench_check import _generator

HERE = Path(__file__).resolve().parent
STEPS = 12
TASKS = 10
MISSIONS = 4
HEADER = """\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.primitive import PrimitiveBase
from skiros2_common.core.world_element import Element
from skiros2_skill.core.skill import ParallelFs, SerialStar, Sequential, SkillBase
"""


def _description(name: str, params: list[tuple[str, str | None]]) -> str:
    lines = [f"\n\nclass {name}(SkillDescription):\n", "    def createDescription(self):\n"]
    for key, element in params:
        value = f"Element(\"{element}\")" if element else "0.5"
        kind = "Required" if element else "Optional"
        lines.append(f"        self.addParam(\"{key}\", {value}, ParamTypes.{kind})\n")
    return "".join(lines)


def _implementation(name: str, base: str, body: list[str]) -> str:
    return (f"\n\nclass {name.lower()}_impl({base}):\n    def createDescription(self):\n"
            f"        self.setDescription({name}(), self.__class__.__name__)\n\n"
            + "".join(body))


def _call(kind: str, remap: dict[str, str], specify: dict[str, float] | None = None) -> str:
    extra = f", specify={specify!r}" if specify else ""
    return f"self.skill(\"{kind}\", \"\", remap={remap!r}{extra})"


def _expand(children: list[str], processor: str = "Sequential") -> list[str]:
    return ["    def expand(self, skill):\n", f"        skill.setProcessor({processor}())\n",
            "        skill(\n", *[f"            {c},\n" for c in children], "        )\n"]


def _steps() -> str:
    """The step library every package copies: leaf descriptions and their primitives."""
    out = [HEADER]
    for i in range(STEPS):
        name = f"Step{i}"
        out.append(_description(name, [("Target", "skiros:Location"),
                                       ("Object", "skiros:Location"), ("Speed", None)]))
        out.append(_implementation(name, "PrimitiveBase", [
            "    def execute(self):\n", "        return self.success(\"done\")\n"]))
    return "".join(out)


def _tasks(rng: random.Random, package: int) -> str:
    """Tasks of 8-14 steps, each remapped onto the task's parameters."""
    out = [HEADER]
    for t in range(TASKS):
        name = f"Task{package}x{t}"
        out.append(_description(name, [("Place", "skiros:Location"),
                                       ("Item", "skiros:Location"), ("Pace", None)]))
        children = [_call(f"Step{rng.randrange(STEPS)}", {"Target": "Place", "Object": "Item"},
                          {"Speed": rng.choice([0.1, 0.2, 0.3])})
                    for _ in range(rng.randint(8, 14))]
        if t == 0:  # seeded: a remap key no step declares, a specify key none has
            children[1] = _call("Step0", {"Targte": "Place"})
            children[2] = _call("Step1", {"Target": "Place"}, {"Sped": 0.1})
        if t == 1:  # seeded: a target nothing of the tree declares nor writes
            children[0] = _call("Step2", {"Target": "Lost"})
        children[-2:] = [f"self.skill(ParallelFs())(\n                {children[-2]},\n"
                         f"                {children[-1]})"]
        out.append(_implementation(name, "SkillBase", _expand(children, "SerialStar")))
    return "".join(out)


def _missions(rng: random.Random, package: int) -> str:
    """Missions of 5-8 tasks and a campaign of every mission: compounds of compounds."""
    out = [HEADER]
    missions = [f"Mission{package}x{m}" for m in range(MISSIONS)]
    for m, name in enumerate(missions):
        out.append(_description(name, [("Where", "skiros:Location"),
                                       ("What", "skiros:Location")]))
        children = [_call(f"Task{package}x{rng.randrange(TASKS)}",
                          {"Place": "Where", "Item": "What"})
                    for _ in range(rng.randint(5, 8))]
        if m == 0:  # seeded: a key the task's steps declare, and already remapped
            children[0] = _call(f"Task{package}x3", {"Target": "Where"})
        out.append(_implementation(name, "SkillBase", _expand(children)))
    campaign = f"Campaign{package}"
    out.append(_description(campaign, [("Site", "skiros:Location"),
                                       ("Cargo", "skiros:Location")]))
    out.append(_implementation(campaign, "SkillBase", _expand(
        [_call(m, {"Where": "Site", "What": "Cargo"}) for m in missions])))
    return "".join(out)


def generate(root: Path, files: int = 2000, packages: int = 14, seed: int = 7) -> int:
    """Write the tree: ``files`` modules in all, three per compound package; the number of
    compound skills."""
    _generator().generate(root, files - 3 * packages, 0.1, seed)
    rng = random.Random(seed)
    for package in range(packages):
        folder = root / f"lab_compound_{package:02d}" / "src" / f"lab_compound_{package:02d}"
        folder.mkdir(parents=True)
        (folder / "__init__.py").write_text("")
        (folder / "steps.py").write_text(_steps(), encoding="utf-8")
        (folder / "tasks.py").write_text(_tasks(rng, package), encoding="utf-8")
        (folder / "missions.py").write_text(_missions(rng, package), encoding="utf-8")
    return packages * (TASKS + MISSIONS + 1)


SKILL_MARK = b"createDescription"
"""In every description and implementation: a file without it holds no skill."""


def floor(root: Path, skills_only: bool = False) -> float:
    """Seconds to read every Python file under ``root`` and ``ast.parse`` it (with
    ``skills_only``, only the files that hold a skill: ``check`` parses no other)."""
    start = time.perf_counter()
    for path in sorted(root.rglob("*.py")):
        data = path.read_bytes()
        if skills_only and SKILL_MARK not in data:
            continue
        with contextlib.suppress(SyntaxError):
            ast.parse(data)
    return time.perf_counter() - start


def command(root: Path, checkout: Path, jobs: int) -> tuple[float, bytes]:
    """Wall seconds and stdout of ``ezmigrate check`` run from ``checkout``."""
    env = {**os.environ, "PYTHONPATH": str(checkout.resolve()), "NO_COLOR": "1"}
    start = time.perf_counter()
    run = subprocess.run([sys.executable, "-m", "ezmigrate", "check", "--no-cache",
                          "--exit-zero", "--output-format", "json", "-j", str(jobs), "."],
                         cwd=root, env=env, check=True, capture_output=True)
    return time.perf_counter() - start, run.stdout


def measure(root: Path, checkouts: list[Path], runs: int, jobs: int) -> None:
    """Print the floor and, per checkout, the best time; then whether outputs agree."""
    floors: list[float] = []
    skill_floors: list[float] = []
    best, outputs = {c: float("inf") for c in checkouts}, {}
    for _ in range(runs):  # interleaved, so that every checkout sees the same machine
        floors.append(floor(root))
        skill_floors.append(floor(root, skills_only=True))
        for checkout in checkouts:
            seconds, outputs[checkout] = command(root, checkout, jobs)
            best[checkout] = min(best[checkout], seconds)
    print(f"floor (read + ast.parse every file): {min(floors):.3f} s; "
          f"(read every file + ast.parse skill files): {min(skill_floors):.3f} s")
    for checkout in checkouts:
        found = len(json.loads(outputs[checkout]))
        print(f"{checkout}: check --no-cache -j {jobs}: {best[checkout]:.3f} s, "
              f"{found} findings")
    same = len(set(outputs.values())) == 1
    print("outputs byte-identical" if same else "OUTPUTS DIFFER")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, help="write the tree here and stop")
    parser.add_argument("--files", type=int, default=2000)
    parser.add_argument("--packages", type=int, default=14)
    parser.add_argument("--seed", type=int, default=7)
    parser.add_argument("--runs", type=int, default=2)
    parser.add_argument("--jobs", "-j", type=int, default=2)
    parser.add_argument("--checkout", type=Path, action="append",
                        help="a source tree to run ezmigrate from (repeatable; default: this)")
    args = parser.parse_args(argv)
    if args.out is not None:
        print(f"{generate(args.out, args.files, args.packages, args.seed)} compound skills "
              f"in {args.out}")
        return 0
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp) / "repo"
        print(f"{generate(root, args.files, args.packages, args.seed)} compound skills")
        measure(root, args.checkout or [HERE.parent], args.runs, args.jobs)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
