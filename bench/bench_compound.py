"""What compound-skill checks add to ``ezmigrate check``: 200 compound skills, 1 in 4 traced.

The repository is written here: 50 modules, each with four legacy descriptions, their
primitive implementations, and four compound skills over them (trees of four to six
children with remaps and specifies, some under processor nodes); in each module one
compound builds its tree in a loop, so only tracing reads it (a sandboxed child per
module). ``check``'s core (``run_check``, warm) is timed with the compound analysis and
without it (``CheckSettings(compounds=False)``), interleaved, median of the rounds.

    .venv/bin/python bench/bench_compound.py --runs 5
"""

from __future__ import annotations

import argparse
import random
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HEADER = """\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.primitive import PrimitiveBase
from skiros2_common.core.world_element import Element
from skiros2_skill.core.skill import ParallelFs, SerialStar, Selector, SkillBase
"""
TYPES = ["skiros:Location"]  # one class: the generated trees are free of mistakes


def _module(rng: random.Random, number: int) -> tuple[str, int, int]:
    """(source, compound skills, traced ones) of one module."""
    names = [f"Step{number}x{i}" for i in range(4)]
    out = [HEADER]
    for name in names:
        out.append(f"\n\nclass {name}(SkillDescription):\n    def createDescription(self):\n"
                   f"        self.addParam(\"Target\", Element(\"{rng.choice(TYPES)}\"), "
                   "ParamTypes.Required)\n"
                   "        self.addParam(\"Speed\", 0.5, ParamTypes.Optional)\n")
        out.append(f"\n\nclass {name.lower()}_impl(PrimitiveBase):\n"
                   f"    def createDescription(self):\n"
                   f"        self.setDescription({name}(), self.__class__.__name__)\n\n"
                   "    def execute(self):\n        return self.success(\"done\")\n")
    for index in range(4):
        task = f"Task{number}x{index}"
        out.append(f"\n\nclass {task}(SkillDescription):\n    def createDescription(self):\n"
                   "        self.addParam(\"Place\", Element(\"skiros:Location\"), "
                   "ParamTypes.Required)\n"
                   "        self.addParam(\"Pause\", 1.0, ParamTypes.Optional)\n")
        children = [f"self.skill(\"{rng.choice(names)}\", \"\", remap={{\"Target\": \"Place\"}}, "
                    f"specify={{\"Speed\": {rng.choice([0.1, 0.2, 0.3])}}})"
                    for _ in range(rng.randint(3, 5))]
        body = ["        skill.setProcessor(SerialStar())"]
        if index == 0:  # built in a loop: only tracing reads it
            body += ["        for name in ({}):".format(", ".join(repr(n) for n in names[:3])),
                     "            skill(self.skill(name, \"\", remap={\"Target\": \"Place\"}))",
                     "        skill(self.skill(\"Wait\", \"\", specify={\"Duration\": "
                     "self.params[\"Pause\"].value}))"]
        else:
            body += ["        skill(", *[f"            {c}," for c in children[:-1]],
                     "            self.skill(ParallelFs())(",
                     f"                {children[-1]},",
                     "                self.skill(\"Wait\", \"\", specify={\"Duration\": 1.0}),",
                     "            ),", "        )"]
        out.append(f"\n\nclass {task.lower()}(SkillBase):\n    def createDescription(self):\n"
                   f"        self.setDescription({task}(), self.__class__.__name__)\n\n"
                   "    def expand(self, skill):\n" + "\n".join(body) + "\n")
    return "".join(out), 4, 1


def generate(root: Path, modules: int = 50, seed: int = 0) -> tuple[int, int]:
    """Write the repository; (compound skills, traced ones)."""
    rng = random.Random(seed)
    package = root / "lab_tasks" / "src" / "lab_tasks"
    package.mkdir(parents=True)
    (package / "__init__.py").write_text("")
    compounds = traced = 0
    for number in range(modules):
        source, c, t = _module(rng, number)
        (package / f"tasks_{number:03d}.py").write_text(source, encoding="utf-8")
        compounds, traced = compounds + c, traced + t
    return compounds, traced


def _time(root: Path, jobs: int, compounds: bool) -> tuple[float, int]:
    from ezmigrate.checking.pipeline import run_check
    from ezmigrate.checking.run import CheckSettings
    from ezmigrate.verify.pool import PoolConfig
    from ezskiros_runtime.ontology.index import bundled_ontology_path
    from ezskiros_runtime.ontology.load import load_index

    index = load_index([bundled_ontology_path()])
    start = time.perf_counter()
    outcome = run_check([root], index, PoolConfig(workers=jobs), CheckSettings(compounds=compounds))
    seconds = time.perf_counter() - start
    return seconds, sum(1 for d in outcome.diagnostics if d.code.startswith("EZ3"))


def _command(root: Path, jobs: int, compounds: bool) -> float:
    """Wall seconds of ``ezmigrate check`` in a fresh process (``--ignore EZ3``: without)."""
    start = time.perf_counter()
    subprocess.run([sys.executable, "-m", "ezmigrate", "check", "-q", "--exit-zero", "-j",
                    str(jobs), *(() if compounds else ("--ignore", "EZ3")), str(root)],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - start


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--jobs", "-j", type=int, default=2)
    args = parser.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp) / "repo"
        compounds, traced = generate(root)
        _time(root, args.jobs, True)  # warm imports, caches and the worker zygote
        without, with_, command_without, command_with = [], [], [], []
        found = 0
        for _ in range(args.runs):
            without.append(_time(root, args.jobs, False)[0])
            seconds, found = _time(root, args.jobs, True)
            with_.append(seconds)
            command_without.append(_command(root, args.jobs, False))
            command_with.append(_command(root, args.jobs, True))
        print(f"{compounds} compound skills ({traced} traced), {found} EZ3 findings")
        print("| measured | without compound checks (s) | with (s) | ratio |")
        print("|---|---:|---:|---:|")
        for what, a, b in (("check core (warm)", without, with_),
                           ("check command", command_without, command_with)):
            x, y = statistics.median(a), statistics.median(b)
            print(f"| {what} | {x:.3f} | {y:.3f} | {y / x:.2f}x |")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
