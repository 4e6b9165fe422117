"""Measured precision of the rules, rendered into docs/rules.md by ``rules_doc``.

The public repositories' figures come from ``bench/verdicts.csv`` (every warning and error
line of ``check`` at their roots, judged by hand; ``bench/bench_precision.py`` measures a
run against it, since CI has no copy of those repositories). The fixtures' figures are what
``tests/lint/test_world_check.py`` (EZ4xx) and ``tests/lint/test_lab_precision.py`` (every
code, on ``fixtures/lab_repo``) measure with every finding labelled by hand; the tests fail
when a run reports other figures than these, so the document cannot claim what the tool
does not do.
"""

from __future__ import annotations

import csv
from dataclasses import dataclass
from pathlib import Path

from ezskiros_runtime.codes import BY_CODE


@dataclass(frozen=True)
class Row:
    """One code: findings reported and how many of them a person judged real; its severity
    is the catalogue's (info rows count apart: they claim no mistake)."""

    code: str
    reported: int
    real: int
    reported_as: str | None = None
    """The severity the findings had when it is lower than the catalogue's (EZ905 is info
    outside a skill library, and for Python 2 syntax a Python 2 robot reads)."""

    @property
    def severity(self) -> str:
        return self.reported_as or BY_CODE[self.code].severity


WORLD_MODEL_PATHS = ("fixtures/legacy", "fixtures/migrated", "fixtures/compound_repo",
                     "fixtures/ros_repo", "fixtures/world_repo", "fixtures/rejected")
WORLD_MODEL_SCENE = "fixtures/world_repo/owl/scenes/cell.turtle"
WORLD_MODEL: tuple[Row, ...] = (
    Row("EZ401", 17, 17),
    Row("EZ402", 0, 0),
    Row("EZ403", 1, 1),
    Row("EZ404", 1, 1),
    Row("EZ405", 1, 1),
    Row("EZ406", 2, 2),
    Row("EZ407", 1, 1),
    Row("EZ408", 1, 1),
    Row("EZ409", 8, 8),
)


LAB_REPOSITORY_PATH = "fixtures/lab_repo"
LAB_REPOSITORY: tuple[Row, ...] = (
    Row("EZ209", 2, 2),
    Row("EZ306", 1, 1),
    Row("EZ307", 1, 1),
    Row("EZ309", 1, 1),
    Row("EZ310", 1, 1),
    Row("EZ311", 1, 1),
    Row("EZ313", 2, 2),
    Row("EZ314", 1, 1),
    Row("EZ315", 1, 1),
    Row("EZ319", 1, 1),
    Row("EZ407", 1, 1),
    Row("EZ905", 1, 1, "info"),
)
"""``check fixtures/lab_repo`` (every code, default selection), each finding labelled by
hand in ``tests/lint/test_lab_precision.py``."""
LAB_REPOSITORY_BEFORE = (17, 8, 3)
"""The same repository checked by the release before issue 21 (997718f): warnings and
errors reported, real ones, and real mistakes it did not report (EZ314 shown as EZ305
info, EZ315 and EZ309 hidden behind untraceable trees)."""


def _table(rows: tuple[Row, ...]) -> list[str]:
    flagged = [r for r in rows if r.severity != "info"]
    reported, real = sum(r.reported for r in flagged), sum(r.real for r in flagged)
    out = ["| code | severity | reported | real | precision |", "|---|---|---:|---:|---:|"]
    for r in rows:
        out.append(f"| {r.code} | {r.severity} | {r.reported} | {r.real} | "
                   f"{_share(r.real, r.reported)} |")
    out.append(f"| **warnings and errors** | | **{reported}** | **{real}** | "
               f"**{_share(real, reported)}** |")
    return [*out, ""]


def _share(real: int, reported: int) -> str:
    return f"{real / reported:.0%}" if reported else "-"


VERDICTS = Path(__file__).resolve().parents[2] / "bench" / "verdicts.csv"
"""Every warning and error ``check`` reported at the root of the public SkiROS2 repositories,
judged by hand against SkiROS2's source (``bench/bench_precision.py`` measures a run
against it)."""
PUBLIC_BEFORE = (126, 37)
"""Warning and error lines on the same repositories before the severity contract (issue
30): reported, judged real."""


def public_rows(path: Path = VERDICTS) -> tuple[Row, ...]:
    """One row per code of the verdicts' warning and error lines."""
    with path.open(encoding="utf-8", newline="") as handle:
        rows = [r for r in csv.DictReader(handle) if r["severity"] in ("warning", "error")]
    codes = sorted({r["code"] for r in rows})
    return tuple(Row(code, sum(r["code"] == code for r in rows),
                     sum(r["code"] == code and r["verdict"] == "real" for r in rows))
                 for code in codes)


def _public_section() -> list[str]:
    with VERDICTS.open(encoding="utf-8", newline="") as handle:
        repositories = len({r["repository"] for r in csv.DictReader(handle)})
    before_reported, before_real = PUBLIC_BEFORE
    return [
        "## Precision on the public SkiROS2 repositories",
        "",
        "Measured as a lab runs it: `ezmigrate check .` at the root of 21 public SkiROS2 "
        "repositories (SkiROS2 itself, its standard, test and template libraries and their "
        "forks, and the labs' repositories), every warning and error line judged by hand "
        "against SkiROS2's source, each verdict naming the function that makes it real or "
        f"not: `bench/verdicts.csv` ({repositories} repositories with a warning or an "
        "error, commit, path, line, code, verdict, why). `python bench/bench_precision.py "
        "FOLDER` runs `check` over a folder of checkouts and prints this table against the "
        "verdicts; it fails on a line no verdict covers. These repositories were not "
        "written for the tool.",
        "",
        *_table(public_rows()),
        f"Before the severity contract the same repositories gave {before_reported} warning "
        f"and error lines, {before_real} of them real "
        f"({_share(before_real, before_reported)}).",
        "",
    ]


@dataclass(frozen=True)
class Recalled:
    """One rule's recall by bug injection: the mutation operator whose bugs are the rule's
    to find, how many mutants of it were made, and how many the rule found (a warning or
    an error on the mutated statement)."""

    code: str
    operator: str
    mutants: int
    found: int


RECALL: tuple[Recalled, ...] = (
    Recalled("EZ104", "condition-key-typo", 40, 40),
    Recalled("EZ109", "params-key-typo", 40, 40),
    Recalled("EZ201", "relation-domain", 40, 40),
    Recalled("EZ209", "class-typo", 40, 37),
    Recalled("EZ209", "relation-typo", 40, 40),
    Recalled("EZ209", "property-typo", 40, 36),
    Recalled("EZ301", "child-type-typo", 40, 40),
    Recalled("EZ304", "remap-key-typo", 40, 38),
    Recalled("EZ307", "specify-key-typo", 40, 39),
    Recalled("EZ317", "processor-typo", 40, 39),
    Recalled("EZ318", "child-label-typo", 40, 36),
)
"""``python bench/bench_recall.py /work/labs`` (seed 42, 11 repositories), the run of
bench/RESULTS.md's last section: per rule, the operator whose mutants it is there to find
and how many of them it found."""
RECALL_ALL = (440, 425)
"""Mutants made and found (any code) in that run."""
COLLATERAL = 2
"""Mutants of that run with a new warning or error outside the mutated statement."""


def _recall_section() -> list[str]:
    made, found = RECALL_ALL
    out = [
        "## Recall on the public SkiROS2 repositories",
        "",
        "Measured by bug injection with `python bench/bench_recall.py CHECKOUTS` on 11 of"
        " those repositories (the checkouts bench/RESULTS.md names, seed 42): one typo (a"
        " letter dropped, swapped or doubled) of one literal of a skill's code per "
        "mutant, `check` run at the root, and a mutant found when a new warning or error "
        "lies on the mutated statement. Per rule, the operator whose bugs it is there to "
        "find (EZ201: a relation swapped for one whose domain excludes the subject). "
        "Rules without a row have no operator: their recall is not measured.",
        "",
        "| code | operator | mutants | found | recall |",
        "|---|---|---:|---:|---:|",
        *(f"| {r.code} | {r.operator} | {r.mutants} | {r.found} | "
          f"{_share(r.found, r.mutants)} |" for r in RECALL),
        f"| **all operators** | | **{made}** | **{found}** | **{_share(found, made)}** |",
        "",
        f"Collateral: {COLLATERAL} of {made} mutants "
        f"({COLLATERAL / made:.1%}) gave a new warning or error outside the mutated "
        "statement.",
        "",
    ]
    return out


def precision_section() -> list[str]:
    """The "Precision" part of docs/rules.md (and the recall beside it)."""
    before_reported, before_real, missed = LAB_REPOSITORY_BEFORE
    out = [
        *_public_section(),
        *_recall_section(),
        "## Precision of EZ4xx (world model)",
        "",
        f"Measured with `ezmigrate check {' '.join(WORLD_MODEL_PATHS)} --select EZ4` (each "
        f"finding labelled by hand in `tests/lint/test_world_check.py`), EZ409 with "
        f"`--scene {WORLD_MODEL_SCENE}` on `fixtures/world_repo`. `fixtures/world_repo` is a "
        "lab repository with scenes written for this measurement (one saved by SkiROS2, one "
        "edited by hand); the legacy and migrated corpora were written before these checks "
        "existed. The goal is at least 9 real warnings or errors in 10.",
        "",
        *_table(WORLD_MODEL),
        "## Precision on a lab repository (every code)",
        "",
        f"Measured with `ezmigrate check {LAB_REPOSITORY_PATH}` (default selection; each "
        "finding labelled by hand in `tests/lint/test_lab_precision.py`). The repository "
        "has the shapes that made `check` untrustworthy on public SkiROS2 code: a Python 2 "
        "module defining a description other trees use, a description defined in two "
        "packages, a ROS 2 package using the ros2 standard library, a launch file with "
        "`workspace_dir`, `init_scene`, `libraries_list` and `skill_list`, a scene that "
        "declares a lab class only by typing an individual, `modifyDescription`, "
        "`remap=\"\"`, a processor of one upstream branch, and a tree that queries the "
        "world model. Its mistakes were written in on purpose, except the EZ306 (a remap "
        "onto the automatic Robot parameter of WmSetRelation), which the run found; the "
        "findings were labelled after the run. A fixture written by the tool's author "
        "flatters it: the figures say that these shapes no longer give false findings, "
        "not what a stranger's repository gives. Info findings claim no mistake and are "
        "listed apart.",
        "",
        *_table(LAB_REPOSITORY),
        f"The release before these rules (997718f) reported {before_reported} warnings and "
        f"errors on the same repository, {before_real} of them real "
        f"({_share(before_real, before_reported)}), and missed {missed} real mistakes.",
        "",
    ]
    return out


__all__ = ["COLLATERAL", "LAB_REPOSITORY", "LAB_REPOSITORY_BEFORE", "LAB_REPOSITORY_PATH",
           "PUBLIC_BEFORE", "RECALL", "RECALL_ALL", "VERDICTS", "WORLD_MODEL",
           "WORLD_MODEL_PATHS", "WORLD_MODEL_SCENE", "Recalled", "Row", "precision_section",
           "public_rows"]
