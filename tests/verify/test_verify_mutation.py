"""Mutation test of the equivalence check: every single-field mutant of every migrated skill
in ``fixtures/migrated`` is reported not equivalent to its legacy original.

Mutants come from ``verify_mutants`` (one field of one parameter or condition each); they
are loaded with their legacy originals through the real verification path (the zygote pool,
one isolated child per file, ``compare_outcomes``). Unmutated clones of every skill are
loaded the same way and must verify equivalent, and so must a set of rewrites that keep the
meaning: without those controls, a harness that broke every clone would "catch" everything.
"""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import pytest
from verify_mutants import Mutant, Skill, after_source, before_source, skill_mutants

from ezmigrate.verify.compare_files import ClassVerdict, compare_outcomes
from ezmigrate.verify.pool import PoolConfig, job_for, run_jobs
from ezmigrate.verify.protocol import LoadOutcome
from ezskiros_runtime.model import SkillModel

ROOT = Path(__file__).resolve().parents[2]
LEGACY = ROOT / "fixtures" / "legacy"
MIGRATED = ROOT / "fixtures" / "migrated"
POOL = PoolConfig(workers=2, timeout=120.0)

OPERATORS = {
    "param-kind", "param-class", "param-type", "param-default", "param-description",
    "param-key", "param-option-added", "param-option-removed", "param-swap",
    "cond-dropped", "cond-duplicated", "cond-list", "cond-swapped", "cond-negation",
    "cond-label", "cond-kind", "cond-swap-subject-object", "cond-relation", "cond-property",
    "cond-operator", "cond-value", "cond-value-type", "cond-class", "cond-subject",
    "or-child-dropped", "or-child-duplicated", "or-children-swapped",
}


def _pairs() -> list[tuple[str, bytes, bytes]]:
    """(name, legacy bytes, migrated bytes) of every migrated fixture holding a skill."""
    pairs = []
    for path in sorted(MIGRATED.glob("*.py")):
        data = path.read_bytes()
        if b"def description(" in data:
            pairs.append((path.name, (LEGACY / path.name).read_bytes(), data))
    return pairs


def _load(tmp: Path, files: list[tuple[str, bytes, bytes]]) -> list[tuple[LoadOutcome,
                                                                           LoadOutcome]]:
    """Write each (name, before, after) pair as real files and load both sides."""
    jobs = []
    for index, (name, before, after) in enumerate(files):
        folder = tmp / f"{index:04d}"
        for side, data in (("before", before), ("after", after)):
            (folder / side).mkdir(parents=True)
            (folder / side / name).write_bytes(data)
            jobs.append(job_for(folder / side / name))
    outcomes = run_jobs(jobs, POOL)
    return [(outcomes[2 * i], outcomes[2 * i + 1]) for i in range(len(files))]


def _verdicts(before: LoadOutcome, after: LoadOutcome, what: str) -> dict[str, ClassVerdict]:
    for side, outcome in (("legacy", before), ("migrated", after)):
        assert outcome.loaded, f"{what}: the {side} side did not load: {outcome.status}: " \
                               f"{outcome.message}\n{outcome.stderr[-2000:]}"
    return {v.name: v for v in compare_outcomes(before, after)}


@pytest.fixture(scope="module")
def mutation_run(tmp_path_factory: pytest.TempPathFactory) -> dict[str, object]:
    tmp = tmp_path_factory.mktemp("mutation")
    pairs = _pairs()
    baseline = _load(tmp / "baseline", pairs)
    skills: dict[str, list[Skill]] = {}
    originals: dict[str, ClassVerdict] = {}
    for (name, _, migrated), (before, after) in zip(pairs, baseline, strict=True):
        verdicts = _verdicts(before, after, f"{name} (unmutated)")
        originals.update({f"{name}::{k}": v for k, v in verdicts.items()})
        models = {m["name"]: SkillModel.from_json(m) for m in after.models}
        skills[name] = skill_mutants(name, migrated, models)
    files = [(name, before_source(legacy, skills[name], [m for s in skills[name]
                                                          for m in s.mutants]),
              after_source(migrated, skills[name], [m for s in skills[name] for m in s.mutants]))
             for name, legacy, migrated in pairs]
    loaded = _load(tmp / "mutants", files)
    verdicts: dict[tuple[str, str], ClassVerdict | str] = {}
    retry: list[tuple[str, bytes, bytes, Mutant | None]] = []
    by_name = {name: (legacy, migrated) for name, legacy, migrated in pairs}
    for (name, _, _), (before, after) in zip(files, loaded, strict=True):
        if before.loaded and after.loaded:
            verdicts.update({(name, v.name): v for v in compare_outcomes(before, after)})
            continue
        # one mutant broke its whole file: load each mutant of that file on its own
        legacy, migrated = by_name[name]
        retry.append((name, before_source(legacy, skills[name], []),
                      after_source(migrated, skills[name], []), None))
        for skill in skills[name]:
            for mutant in skill.mutants:
                retry.append((name, before_source(legacy, [], [mutant]),
                              after_source(migrated, [], [mutant]), mutant))
    if retry:
        singles = _load(tmp / "singles", [(n, b, a) for n, b, a, _ in retry])
        for (name, _, _, mutant), (before, after) in zip(retry, singles, strict=True):
            if mutant is None:
                verdicts.update({(name, v.name): v for v in compare_outcomes(before, after)})
            elif before.loaded and after.loaded:
                for v in compare_outcomes(before, after):
                    if v.name == mutant.clone:
                        verdicts[(name, v.name)] = v
            else:
                verdicts[(name, mutant.clone)] = f"file not loadable: {after.status}: " \
                                                 f"{after.message}"
    return {"pairs": pairs, "skills": skills, "originals": originals, "verdicts": verdicts,
            "retried_files": sum(1 for *_, m in retry if m is None)}


def test_unmutated_skills_and_their_clones_verify_equivalent(mutation_run):
    originals = mutation_run["originals"]
    skills: dict[str, list[Skill]] = mutation_run["skills"]
    verdicts = mutation_run["verdicts"]
    assert originals and all(v.equivalent for v in originals.values()), \
        [(k, v.message, v.diff) for k, v in originals.items() if not v.equivalent]
    controls = [(name, s.control) for name, group in skills.items() for s in group]
    assert len(controls) >= 60
    broken = [(key, verdicts.get(key)) for key in controls
              if not isinstance(verdicts.get(key), ClassVerdict) or not verdicts[key].equivalent]
    assert not broken, broken


def test_every_single_field_mutant_is_reported_not_equivalent(mutation_run, summary_line):
    skills: dict[str, list[Skill]] = mutation_run["skills"]
    verdicts = mutation_run["verdicts"]
    mutants = [m for group in skills.values() for s in group for m in s.mutants]
    caught_by: Counter[str] = Counter()
    survivors = []
    for mutant in mutants:
        verdict = verdicts.get((mutant.module, mutant.clone))
        if verdict is None:
            survivors.append((mutant.describe(), "no verdict at all"))
        elif isinstance(verdict, str):
            caught_by["the file no longer loads"] += 1
        elif verdict.equivalent:
            survivors.append((mutant.describe(), mutant.method))
        elif verdict.verdict == "different":
            caught_by["a model difference"] += 1
        else:
            caught_by[f"a class that no longer loads ({verdict.verdict})"] += 1
    total = len(mutants)
    caught = sum(caught_by.values())
    per_operator = Counter(m.operator for m in mutants)
    summary_line(f"mutation test: {total} mutants of {sum(len(g) for g in skills.values())} "
                 f"skills in {len(skills)} files, {caught} caught ({100 * caught / total:.0f}%): "
                 + ", ".join(f"{n} by {why}" for why, n in caught_by.most_common()))
    summary_line("mutants per operator: " + ", ".join(f"{k} {v}" for k, v in
                                                      sorted(per_operator.items())))
    assert not survivors, "mutants reported equivalent:\n" + "\n\n".join(
        f"{d}\n{method}" for d, method in survivors[:10])
    assert caught == total
    assert set(per_operator) == OPERATORS  # every kind of mutation was made at least once
    assert total >= 1500


EQUIVALENT_REWRITES = {
    # (fixture, skill, old text in its description, new text): rewrites that keep the model
    "bare type is REQUIRED": ("descriptions.py", "Navigate", "Goal: skiros.Location",
                              "Goal: REQUIRED[skiros.Location]"),
    "verbatim relation": ("descriptions.py", "Navigate", "Turtle.at(Start)",
                          'Turtle.relation("skiros:at", Start)'),
    "keyword-only parameters": ("descriptions.py", "Dock", "def description(self,",
                                "def description(self, *,"),
    "explicit conventional label": ("pick_and_place.py", "Place",
                                    "self.post_conditions += ~ Gripper.contain(Object)",
                                    "self.post_conditions += ~ Gripper.contain(Object)"
                                    '.named("NotGripperContainObject")'),
    "named before or after ~": ("conditions.py", "OpenDrawer",
                                '~ Gripper.contain(Handle).named("EmptyHanded")',
                                '(~ Gripper.contain(Handle)).named("EmptyHanded")'),
    "option on a value (ignored by SkiROS2)": ("descriptions.py", "Undock",
                                               "Distance: OPTIONAL[float] = 0.3",
                                               "Distance: OPTIONAL[float, Lock] = 0.3"),
}


def test_rewrites_that_keep_the_meaning_verify_equivalent(tmp_path):
    """The other direction: the check is not merely sensitive to any textual change."""
    files = []
    for label, (fixture, skill, old, new) in EQUIVALENT_REWRITES.items():
        migrated = (MIGRATED / fixture).read_text(encoding="utf-8")
        start = migrated.index(f"class {skill}(")
        end = migrated.index("\nclass ", start + 1)
        body = migrated[start:end]
        assert old in body, label
        changed = "from ezskiros_runtime import REQUIRED, Lock\n" + migrated[:start] \
            + body.replace(old, new, 1) + migrated[end:]
        files.append((fixture, (LEGACY / fixture).read_bytes(), changed.encode("utf-8")))
    for (label, (_, skill, _, _)), (before, after) in zip(EQUIVALENT_REWRITES.items(),
                                                          _load(tmp_path, files), strict=True):
        verdict = _verdicts(before, after, label)[skill]
        assert verdict.equivalent, (label, verdict.message, verdict.diff)
