"""``ezmigrate verify`` and verifying ``rewrite`` through the command line, on real files.

Exit codes of ``verify``: 0 when every class is equivalent, 1 when one differs or is
missing, 2 when a file cannot be loaded. ``--ignore-order`` and ``--ignore-labels`` relax
exactly that and nothing else. ``rewrite`` verifies before writing and writes a file only
when every converted skill in it verified.
"""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from verify_support import (
    FAILS_IN_BOTH,
    LATE_CONSTANT,
    LEGACY,
    MIGRATED,
    PAPER_AXIOMS,
    cli,
    edit,
    file_entry,
    read_json,
    skills_of,
    snapshot,
    tree,
)

FILES = ("pick_and_place.py", "descriptions.py", "conditions.py")
CLASSES = 16  # 3 + 6 + 7 description classes in those files


@pytest.fixture(scope="module")
def before(tmp_path_factory) -> Path:
    return tree(tmp_path_factory.mktemp("before"), {n: LEGACY / n for n in FILES})


def _after(tmp_path: Path, name: str = "after") -> Path:
    return tree(tmp_path / name, {n: MIGRATED / n for n in FILES})


def test_equivalent_trees_exit_0_and_every_class_is_proven(before, tmp_path):
    after = _after(tmp_path)
    run = cli("verify", before, after, "--report", tmp_path / "r.json")
    assert run.returncode == 0, run.stderr
    assert f"3 files compared, {CLASSES} classes, {CLASSES} equivalent" in run.stderr
    report = read_json(tmp_path / "r.json")
    assert len(report["skills"]) == CLASSES
    assert all(s["equivalent"] is True and s["status"] == "converted" and "diff" not in s
               for s in report["skills"]), report["skills"]


def test_two_files_can_be_compared_directly(before, tmp_path):
    run = cli("verify", before / "pick_and_place.py", MIGRATED / "pick_and_place.py")
    assert run.returncode == 0, run.stderr
    assert "1 files compared, 3 classes, 3 equivalent" in run.stderr
    same = cli("verify", before / "pick_and_place.py", before / "pick_and_place.py")
    assert same.returncode == 0 and "3 equivalent" in same.stderr


@pytest.fixture(scope="module")
def flipped(before, tmp_path_factory) -> tuple[Path, Path]:
    """Navigate's last post-condition lost its ``~`` (and Navigate's parameters are also
    reordered, which the relaxed runs must forgive without forgiving the flip)."""
    tmp = tmp_path_factory.mktemp("flipped")
    after = _after(tmp)
    edit(after / "descriptions.py", "self.post_conditions += ~ Turtle.at(Start)",
         "self.post_conditions += Turtle.at(Start)")
    edit(after / "descriptions.py",
         "Start: INFERRED[skiros.Location],\n                    Goal: skiros.Location,",
         "Goal: skiros.Location,\n                    Start: INFERRED[skiros.Location],")
    return tmp, after


def test_a_difference_exits_1_and_shows_both_sides_in_legacy_notation(before, flipped):
    tmp, after = flipped
    run = cli("verify", before, after, "--report", tmp / "r.json")
    assert run.returncode == 1, run.stderr
    assert "descriptions.py:" in run.stderr and "Navigate" in run.stderr
    legacy_side = "getRelationCond('NotTurtleAtStart', 'skiros:at', 'Turtle', 'Start', False)"
    migrated_side = "getRelationCond('TurtleAtStart', 'skiros:at', 'Turtle', 'Start', True)"
    assert f"- {legacy_side}" in run.stderr and f"+ {migrated_side}" in run.stderr
    report = read_json(tmp / "r.json")
    navigate = skills_of(report, "descriptions.py")["Navigate"]
    assert navigate["equivalent"] is False and navigate["status"] == "failed"
    sides = {(d["where"], d["before"], d["after"]) for d in navigate["diff"]}
    assert ("post", legacy_side, migrated_side) in sides
    others = [s for s in report["skills"] if s["class"] != "Navigate"]
    assert len(others) == CLASSES - 1 and all(s["equivalent"] is True for s in others)


def test_relaxing_order_and_labels_never_forgives_a_real_difference(before, flipped):
    _, after = flipped
    run = cli("verify", before, after, "--ignore-order", "--ignore-labels")
    assert run.returncode == 1, run.stderr
    assert "Navigate" in run.stderr and "1 not equivalent" in run.stderr


def test_missing_files_and_classes_exit_1(before, tmp_path):
    after = _after(tmp_path)
    (after / "conditions.py").unlink()
    text = (after / "descriptions.py").read_text(encoding="utf-8")
    start = text.index("class Dock(")
    end = text.index("\nclass ", start)
    (after / "descriptions.py").write_text(text[:start] + text[end + 1:], encoding="utf-8")
    run = cli("verify", before, after, "--report", tmp_path / "r.json")
    assert run.returncode == 1, run.stderr
    report = read_json(tmp_path / "r.json")
    assert file_entry(report, "conditions.py")["error"] == "missing after migration"
    dock = skills_of(report, "descriptions.py")["Dock"]
    assert dock["equivalent"] is False and "missing" in dock["reason"]


def test_a_file_that_cannot_be_loaded_exits_2_and_the_others_are_still_compared(before,
                                                                                tmp_path):
    after = _after(tmp_path)
    with (after / "pick_and_place.py").open("a", encoding="utf-8") as handle:
        handle.write("\nraise RuntimeError('robot configuration missing')\n")
    run = cli("verify", before, after, "--report", tmp_path / "r.json")
    assert run.returncode == 2, run.stderr
    assert "pick_and_place.py: the migrated version could not be loaded" in run.stderr
    assert "RuntimeError: robot configuration missing" in run.stderr
    report = read_json(tmp_path / "r.json")
    assert "import-error" in file_entry(report, "pick_and_place.py")["error"]
    compared = [s for s in report["skills"] if s["file"] != "pick_and_place.py"]
    assert len(compared) == CLASSES - 3 and all(s["equivalent"] is True for s in compared)


@pytest.fixture(scope="module")
def relaxed(before, tmp_path_factory) -> Path:
    """Only order (Navigate: two post-conditions swapped) and a label (OpenDrawer) differ."""
    after = _after(tmp_path_factory.mktemp("relaxed"))
    edit(after / "descriptions.py",
         "        self.post_conditions += Turtle.at(Goal)\n"
         "        self.post_conditions += ~ Turtle.at(Start)\n",
         "        self.post_conditions += ~ Turtle.at(Start)\n"
         "        self.post_conditions += Turtle.at(Goal)\n")
    edit(after / "conditions.py", '.named("Holding")', '.named("Gripping")')
    return after


@pytest.mark.parametrize(("flags", "code", "failing", "wording"), [
    ((), 1, {"Navigate", "OpenDrawer"}, "Equivalence: verified by loading both versions."),
    (("--ignore-order",), 1, {"OpenDrawer"}, "ignoring parameter/condition order."),
    (("--ignore-labels",), 1, {"Navigate"}, "ignoring labels."),
    (("--ignore-order", "--ignore-labels"), 0, set(),
     "ignoring parameter/condition order and labels."),
])
def test_ignore_order_and_ignore_labels_relax_exactly_that(before, relaxed, tmp_path, flags,
                                                           code, failing, wording):
    run = cli("verify", before, relaxed, *flags, "--report", tmp_path / "r.md")
    assert run.returncode == code, run.stderr
    markdown = (tmp_path / "r.md").read_text(encoding="utf-8")
    assert wording in markdown.splitlines()[2]
    shown = {line.split("**")[1] for line in markdown.splitlines()
             if line.startswith("- **") and line.endswith(": failed (EZ903)")}
    assert shown == failing, markdown
    if "Navigate" in failing:
        assert "same post-conditions in a different order" in markdown


# -- rewrite ------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def rewritten(tmp_path_factory):
    """A verifying rewrite over: a file whose Move differs when run (a constant rebound
    after the class), a file whose skill loads in neither version, and a good file."""
    folder = tree(tmp_path_factory.mktemp("rewrite") / "skills", {
        "late_constant.py": LATE_CONSTANT, "calibrate.py": FAILS_IN_BOTH,
        "descriptions.py": LEGACY / "descriptions.py"})
    original = snapshot(folder)
    report = folder.parent / "r.json"
    run = cli("rewrite", folder, "--report", report)
    return folder, original, run, read_json(report)


def test_a_class_that_is_not_equivalent_is_held_and_its_neighbour_lands(rewritten):
    """Every class converted in a written file verified: ``Move`` (not equivalent) stays as
    it was, the file is migrated again without it, and ``Stop`` beside it is written."""
    folder, original, run, report = rewritten
    assert run.returncode == 1, run.stderr
    move = skills_of(report, "late_constant.py")["Move"]
    assert move["status"] == "failed" and move["equivalent"] is False
    assert "not equivalent" in move["reason"]
    assert [(d["before"], d["after"]) for d in move["diff"]] == [
        ("addParam('Speed', 1.0, ParamTypes.Optional)",
         "addParam('Speed', 0.5, ParamTypes.Optional)")]
    stop = skills_of(report, "late_constant.py")["Stop"]
    assert stop["status"] == "converted" and stop["equivalent"] is True
    # the line of the file written (its imports changed), as the report and check give it
    assert "late_constant.py:10: Move: failed: not equivalent" in run.stderr
    text = (folder / "late_constant.py").read_text(encoding="utf-8")
    assert text != original["late_constant.py"].decode()
    move_source = text[text.index("class Move"):text.index("class Stop")]
    assert 'self.addParam("Speed", SPEED, ParamTypes.Optional)' in move_source  # as it was
    assert "def description(self," in text[text.index("class Stop"):]


def test_rewrite_writes_no_file_in_which_a_converted_skill_cannot_be_loaded(rewritten):
    folder, original, _, report = rewritten
    assert (folder / "calibrate.py").read_bytes() == original["calibrate.py"]
    calibrate = skills_of(report, "calibrate.py")["Calibrate"]
    assert calibrate["status"] == "failed" and calibrate["equivalent"] is None
    assert "cannot be verified" in calibrate["reason"] and "KeyError" in calibrate["reason"]


def test_rewrite_still_writes_the_files_that_verified(rewritten):
    folder, _, _, report = rewritten
    assert (folder / "descriptions.py").read_bytes() == (MIGRATED / "descriptions.py").read_bytes()
    assert all(s["status"] == "converted" and s["equivalent"] is True
               for s in skills_of(report, "descriptions.py").values())


def test_without_verification_the_wrong_rewrite_is_written_and_verify_then_catches_it(
        tmp_path):
    folder = tree(tmp_path / "skills", {"late_constant.py": LATE_CONSTANT})
    before = tree(tmp_path / "before", {"late_constant.py": LATE_CONSTANT})
    run = cli("rewrite", folder, "--no-verify")
    assert run.returncode == 0, run.stderr
    assert "Speed: OPTIONAL = SPEED" in (folder / "late_constant.py").read_text()
    proof = cli("verify", before, folder)
    assert proof.returncode == 1, proof.stderr
    assert "Move" in proof.stderr and "1 not equivalent" in proof.stderr
    shutil.rmtree(folder)


PLAIN_WITH_MARKER = '''"""A helper module: importing it leaves a marker file."""
from pathlib import Path

Path(__file__).with_name("IMPORTED").write_text("imported")


def speed_limit() -> float:
    return 0.5
'''


def test_identical_modules_without_descriptions_are_not_imported(before, tmp_path):
    """The bulk of a monorepo: same bytes on both sides, no description marker."""
    after = _after(tmp_path)
    for root in (before, after):
        (root / "helpers.py").write_text(PLAIN_WITH_MARKER, encoding="utf-8")
    try:
        run = cli("verify", before, after)
        assert run.returncode == 0, run.stderr
        assert f"4 files compared, {CLASSES} classes, {CLASSES} equivalent" in run.stderr
        assert not (before / "IMPORTED").exists() and not (after / "IMPORTED").exists()
        # the same module, changed on one side, is loaded (and compared) after all
        edit(after / "helpers.py", "return 0.5", "return 1.0")
        changed = cli("verify", before, after)
        assert changed.returncode == 0, changed.stderr
        assert (before / "IMPORTED").exists() and (after / "IMPORTED").exists()
    finally:
        for root in (before, after):
            for name in ("helpers.py", "IMPORTED"):
                (root / name).unlink(missing_ok=True)


REJECTED = LEGACY.parent / "rejected" / "type_errors.py"


def test_rewrite_skips_skills_the_runtime_would_refuse_and_leaves_the_file(tmp_path):
    """Equivalent is not enough: a migrated skill that raises SkillTypeError when it loads
    would stop the robot's launch, so it is skipped with the finding and nothing is written."""
    folder = tree(tmp_path / "skills", {"type_errors.py": REJECTED})
    before = (folder / "type_errors.py").read_bytes()
    run = cli("rewrite", folder, "--report", tmp_path / "r.json", *PAPER_AXIOMS)
    assert run.returncode == 0, run.stderr
    assert (folder / "type_errors.py").read_bytes() == before
    skills = {s["class"]: s for s in read_json(tmp_path / "r.json")["skills"]}
    assert set(skills) == {"HandOver", "CheckTool", "MountCamera"}
    for skill in skills.values():
        assert skill["status"] == "skipped" and skill["equivalent"] is None, skill
        assert skill["reason"].startswith("EzSkiROS rejects this skill when it loads"), skill
    assert "parameter Gripper is rparts:GripperEffector" in skills["HandOver"]["reason"]
    assert "HandOver: skipped: EzSkiROS rejects" in run.stderr


def test_verify_fails_a_migrated_class_the_runtime_would_refuse(tmp_path):
    """The same skills migrated by hand (the codemod's core, which no check stops): same
    model, but no load. ``rewrite --no-verify`` holds them back (issue 22, item 4)."""
    from ezmigrate.codemod.migrate import migrate

    legacy = tree(tmp_path / "legacy", {"type_errors.py": REJECTED})
    forced = migrate(REJECTED.read_bytes()).new_source
    assert isinstance(forced, bytes)
    migrated = tree(tmp_path / "migrated", {"type_errors.py": forced})
    run = cli("verify", legacy, migrated, *PAPER_AXIOMS)
    assert run.returncode == 1, run.stderr
    assert run.stderr.count("EzSkiROS rejects the migrated class when it loads") == 3
    assert "3 classes, 0 equivalent, 3 not equivalent" in run.stderr
    unverified = cli("rewrite", legacy, "--no-verify", "--output-dir", tmp_path / "copy",
                     *PAPER_AXIOMS)
    assert unverified.stderr.count("skipped: EzSkiROS rejects this skill when it loads") == 3
    assert (tmp_path / "copy" / "type_errors.py").read_bytes() == REJECTED.read_bytes()


def test_a_refused_class_is_held_and_the_rest_of_its_file_still_lands(tmp_path):
    """The file is migrated again with the refused classes left as they were (and a child
    inheriting the problem with them), verified again, and written."""
    source = REJECTED.read_text(encoding="utf-8") + '''

class FineOne(SkillDescription):
    def createDescription(self):
        self.addParam("Camera", Element("skiros:DepthCamera"), ParamTypes.Required)


class FineChild(HandOver):
    def createDescription(self):
        HandOver.createDescription(self)
        self.addParam("Extra", 1.0, ParamTypes.Optional)
'''
    original = tree(tmp_path / "original", {"type_errors.py": source})
    folder = tree(tmp_path / "skills", {"type_errors.py": source})
    run = cli("rewrite", folder, "--report", tmp_path / "r.json", *PAPER_AXIOMS)
    assert run.returncode == 0, run.stderr  # skipped with a reason: the run did its work
    statuses = {s["class"]: s["status"] for s in read_json(tmp_path / "r.json")["skills"]}
    assert statuses == {"HandOver": "skipped", "CheckTool": "skipped",
                        "MountCamera": "skipped", "FineOne": "converted",
                        "FineChild": "skipped"}
    text = (folder / "type_errors.py").read_text(encoding="utf-8")
    assert "class FineOne(EzSkillDescription):" in text
    assert text.count("def createDescription(self):") == 5  # 4 held + the implementation
    proof = cli("verify", original, folder, *PAPER_AXIOMS)
    assert proof.returncode == 0, proof.stderr
    assert "5 classes, 5 equivalent" in proof.stderr
