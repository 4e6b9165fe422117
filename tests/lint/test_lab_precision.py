"""The precision table of docs/rules.md for ``fixtures/lab_repo``, measured: every
finding ``check`` reports there is labelled by hand below, and the table's figures are what
the run gives (issue 21: at least 9 warnings and errors in 10 real)."""

from __future__ import annotations

import json
from pathlib import Path

from check_support import cli

from ezmigrate.cli.rules_precision import LAB_REPOSITORY, LAB_REPOSITORY_PATH

ROOT = Path(__file__).resolve().parents[2]
SKILLS = "lab_skills/src/lab_skills"

LABELS: dict[tuple[str, int, str], str] = {
    ("lab_drivers/lab_drivers/base.py", 30, "EZ306"):
        "Src remapped onto Robot, which WmSetRelation declares itself (SkiROS2's automatic "
        "parameter): SkiROS2 rejects the remap",
    ("lab_skills/owl/kitting_cell.turtle", 13, "EZ407"):
        "info: lab:Workbench is declared only by the scene, as the message says",
    (f"{SKILLS}/descriptions.py", 53, "EZ209"): "skiros:Prodcut, a typo of skiros:Product",
    (f"{SKILLS}/descriptions.py", 61, "EZ209"):
        "prefix acme defined nowhere (3 uses, reported once): the world model never "
        "matches those types",
    (f"{SKILLS}/legacy_calibration.py", 19, "EZ905"):
        "Python 2 print statement: the module cannot load under ROS 1 Noetic's Python 3",
    (f"{SKILLS}/tasks.py", 29, "EZ314"):
        "fetch_part already remaps Container to Shelf: kit_parts' Bin never reaches Pick",
    (f"{SKILLS}/tasks.py", 31, "EZ315"): "self.params['Pause'] without .value",
    (f"{SKILLS}/tasks.py", 56, "EZ319"):
        "Pressure is added by spray_coat's modifyDescription to the wrapper, which runs at "
        "grounding (SkillWrapper.setInstance), after specify was applied: the 3.0 is dropped",
    (f"{SKILLS}/tasks.py", 57, "EZ307"):
        "Nozzle is added by spray_coat to itself, not to the wrapper: the value is dropped",
    (f"{SKILLS}/tasks.py", 58, "EZ311"): "the spray gun passed as Place's gripper",
    (f"{SKILLS}/tasks.py", 69, "EZ310"):
        "info: RetryOnFail, once for its 3 uses, on ros2_roscon24_workshop only",
    (f"{SKILLS}/tasks.py", 81, "EZ313"):
        "info: inspect_twice adds its children in a loop, which check does not run",
    (f"{SKILLS}/tasks.py", 91, "EZ313"): "info: scan_world queries the world model",
    (f"{SKILLS}/tasks.py", 93, "EZ309"): "specfiy=: TypeError when the branch runs",
}
"""Every finding of the measured run, judged against SkiROS2's semantics (shared docs); a
false one would be listed with a reason starting "FALSE:"."""


def test_the_lab_repository_table_of_docs_rules_md_is_what_check_measures():
    run = cli(LAB_REPOSITORY_PATH, "--output-format", "json", "--exit-zero", cwd=ROOT)
    assert run.returncode == 0, run.stderr
    base = ROOT / LAB_REPOSITORY_PATH
    reported = [((ROOT / str(d["path"])).relative_to(base).as_posix(), int(d["line"]),
                 str(d["code"])) for d in json.loads(run.stdout)]
    assert sorted(w for w in reported if w not in LABELS) == [], "label these by hand"
    assert sorted(w for w in LABELS if w not in reported) == [], "labelled, not reported"
    for row in LAB_REPOSITORY:
        hits = [w for w in reported if w[2] == row.code]
        real = [w for w in hits if not LABELS[w].startswith("FALSE")]
        assert (row.code, len(hits), len(real)) == (row.code, row.reported, row.real)
    assert {r.code for r in LAB_REPOSITORY} == {w[2] for w in reported}
    flagged = [r for r in LAB_REPOSITORY if r.severity != "info"]
    assert sum(r.real for r in flagged) >= 0.9 * sum(r.reported for r in flagged)
