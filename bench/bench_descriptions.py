"""Description loading: instantiate 1,000 generated EzSkiROS descriptions, checks included.

What a robot pays at launch is one instantiation per skill class: tracing the description
(evaluating its string annotations once), lowering it through the backend, SkiROS2's
``generateDefParams`` and the early checks. So every round writes and imports a *fresh*
module of 1,000 classes (new functions, so no DSL cache can help) and times instantiating
each class once, with the ontology index already loaded ("warm ontology"). The median over
rounds is the headline figure. Two more figures: instantiating the same classes again (the
signature cache warm) and the checks alone (``run_checks`` on the recorded traces).

The generated skills are realistic (3-8 parameters, 2-6 conditions, relations with and
without domain/range, property conditions, an or-condition, ``Lock`` options, string
annotations) and use only vocabulary of the bundled ontology, so they load without findings;
the script verifies that, so a check that silently stopped working would show up here.

    .venv/bin/python bench/bench_descriptions.py [--skills 1000] [--rounds 7]
"""

from __future__ import annotations

import argparse
import importlib
import os
import platform
import random
import statistics
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

HEADER = '''from __future__ import annotations

from ezskiros_runtime import (ELEMENT, INFERRED, OPTIONAL, REQUIRED, KEY, Lock,
                              SkillDescription, abstract)
from ezskiros_runtime.ontology import cora, rparts, skiros, sumo
'''

EXTRA_PARAMS = [
    ("Pose", "INFERRED[skiros.GraspingPose]", "Object.hasA(Pose)"),
    ("Camera", "REQUIRED[skiros.DepthCamera, Lock]", "Camera.at(Location)"),
    ("Speed", 'OPTIONAL[float, "m/s"] = 0.5', None),
    ("Frame", 'OPTIONAL[str] = ""', None),
    ("Box", 'ELEMENT(":Container")', "Box.contain(Object)"),
    ("Flag", 'REQUIRED[bool, KEY("Publish/Tf")] = True', None),
    ("Arm", "INFERRED[rparts.GripperEffector]", "Arm.contain(Object)"),
]
"""(name, annotation, a pre-condition mentioning it or None): INFERRED ones need theirs."""

CONDITIONS = [
    ("post", "Gripper.contain(Object)"),
    ("post", "~ Location.contain(Object)"),
    ("hold", "Object.PositionX > 0.0"),
    ("pre", "Gripper.PublishTf == True"),
    ("pre", "Gripper.contain(Object) | Location.contain(Object)"),
    ("post", 'Object.is_a(skiros.Product)'),
    ("pre", 'Gripper.relation("skiros:at", Location).named("Mounted")'),
    ("hold", "abstract(Location.contain(Object))"),
]


def skill_source(number: int, rng: random.Random) -> str:
    """One description class with 3-8 parameters and 2-6 conditions."""
    extras = rng.sample(EXTRA_PARAMS, rng.randint(0, 5))
    params = ["Gripper: rparts.GripperEffector", "Object: skiros.Product",
              "Location: INFERRED[skiros.Location]"]
    conditions = [("pre", "Location.contain(Object)"), ("pre", "~ Gripper.contain(Object)")]
    for name, annotation, mention in extras:
        params.append(f"{name}: {annotation}")
        if mention is not None and len(conditions) < 6:
            conditions.append(("pre", mention))
    wanted = rng.randint(2, 6)
    for which, text in rng.sample(CONDITIONS, len(CONDITIONS)):
        if len(conditions) >= wanted:
            break
        conditions.append((which, text))
    ordered = sorted(params, key=lambda p: "=" in p)  # defaults last
    body = "\n".join(f"        self.{which}_conditions += {text}" for which, text in conditions)
    signature = ",\n                    ".join(ordered)
    return (f"\n\nclass Skill{number}(SkillDescription):\n"
            f"    def description(self, {signature}):\n{body}\n")


def write_module(folder: Path, name: str, skills: int, seed: int) -> Path:
    rng = random.Random(seed)
    path = folder / f"{name}.py"
    path.write_text(HEADER + "".join(skill_source(i, rng) for i in range(skills)))
    return path


class Clock:
    """Wall-clock and CPU time of a block: on a shared machine the CPU time is the fairer
    figure (other jobs inflate wall time), so both are reported."""

    def __enter__(self) -> Clock:
        self.wall, self.cpu = time.perf_counter(), time.process_time()
        return self

    def __exit__(self, *exc: object) -> None:
        self.wall = time.perf_counter() - self.wall
        self.cpu = time.process_time() - self.cpu


def time_round(folder: Path, name: str, skills: int, seed: int) -> dict[str, float]:
    """Import a fresh module and time one instantiation of each class, then a second."""
    from ezskiros_runtime.dsl.checking import run_checks

    write_module(folder, name, skills, seed)
    with Clock() as imported:
        module = importlib.import_module(name)
    classes = [getattr(module, f"Skill{i}") for i in range(skills)]
    with Clock() as first:
        instances = [cls() for cls in classes]
    with Clock() as again:
        for cls in classes:
            cls()
    with Clock() as checks:
        for instance in instances:
            run_checks(instance._ez_trace)
    findings = sum(len(i.findings) for i in instances)
    if findings:
        sample = next(f for i in instances for f in i.findings)
        raise SystemExit(f"generated skills should be clean, got {findings}: {sample}")
    params = sum(len(i.params) for i in instances)
    conditions = sum(len(i._ez_trace.recorded) for i in instances)
    result = {"params": params / skills, "conditions": conditions / skills}
    for key, clock in (("import", imported), ("first", first), ("again", again),
                       ("checks", checks)):
        result[key] = clock.wall
        result[key + "_cpu"] = clock.cpu
    return result


def machine() -> str:
    cpu = platform.processor() or platform.machine()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return (f"{cpu}, {os.cpu_count()} CPUs, {platform.system()} {platform.release()}, "
            f"Python {platform.python_version()}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--skills", type=int, default=1000)
    parser.add_argument("--rounds", type=int, default=7)
    args = parser.parse_args()

    from ezskiros_runtime.dsl.skill import BACKEND
    from ezskiros_runtime.ontology import load_index, use_ontology

    use_ontology(load_index())  # the bundled vocabulary, loaded before timing
    rounds = []
    with tempfile.TemporaryDirectory() as folder:
        sys.path.insert(0, folder)
        for number in range(args.rounds):
            rounds.append(time_round(Path(folder), f"bench_skills_{number}", args.skills,
                                     seed=number))
    rows = [
        ("instantiate once, fresh classes, checks included", "first"),
        ("instantiate again (signature cached)", "again"),
        ("of which: early checks alone", "checks"),
        ("importing the module (compile + class creation)", "import"),
    ]

    def ms(key: str, pick: Callable[[list[float]], float]) -> float:
        return pick([r[key] for r in rounds]) / args.skills * 1e3

    print(f"backend: {BACKEND.name}; machine: {machine()}; load average "
          f"{os.getloadavg()[0]:.1f}")
    print(f"{args.skills} skills x {args.rounds} rounds; per skill on average "
          f"{rounds[0]['params']:.1f} parameters (with the automatic Robot), "
          f"{rounds[0]['conditions']:.1f} conditions")
    print("| per skill description | CPU median ms | CPU best ms | wall median ms |")
    print("|---|---:|---:|---:|")
    for label, key in rows:
        print(f"| {label} | {ms(key + '_cpu', statistics.median):.3f} "
              f"| {ms(key + '_cpu', min):.3f} | {ms(key, statistics.median):.3f} |")
    headline = ms("first_cpu", statistics.median)
    verdict = "met" if headline < 1.0 else "NOT met"
    print(f"target < 1 ms per description including checks (CPU median {headline:.3f} ms): "
          f"{verdict}")


if __name__ == "__main__":
    main()
