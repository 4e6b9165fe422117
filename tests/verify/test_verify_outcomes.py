"""What ``verify`` and a verifying ``rewrite`` say beyond equivalence, on real files.

A skill the EzSkiROS runtime refuses at load is never "equivalent" nor written; findings
and a failed load's captured output reach the reports; the reports name how equivalence
was judged and survive file names that are not UTF-8; a file may be compared with a
folder; a syntax error is told apart from syntax newer than this Python; and a file left
byte for byte as it was is not an error because it cannot be imported.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

import pytest
from verify_support import (
    HEADER,
    LEGACY,
    MIGRATED,
    PAPER_AXIOMS,
    cli,
    file_entry,
    read_json,
    skills_of,
    tree,
)

VIOLATION = "ontology_violations.py"


def _hard_violation(folder: Path, legacy: bool) -> Path:
    """``ontology_violations.py`` with PlaceOnPose's Target a skiros:Product: under the
    paper's axiom (PAPER_AXIOMS) skiros:hasA ranges over skiros:TransformationPose, which no
    Product is (an error, not a warning)."""
    source = (LEGACY if legacy else MIGRATED) / VIOLATION
    text = source.read_text(encoding="utf-8")
    old, new = (('Element("skiros:Location")', 'Element("skiros:Product")') if legacy
                else ("INFERRED[skiros.Location]", "INFERRED[skiros.Product]"))
    assert text.count(old) == 1
    return tree(folder, {VIOLATION: text.replace(old, new)})


def test_rewrite_skips_a_skill_the_runtime_rejects_with_the_finding_and_its_line(tmp_path):
    folder = _hard_violation(tmp_path / "skills", legacy=True)
    run = cli("rewrite", folder, "--report", tmp_path / "r.json", *PAPER_AXIOMS)
    assert run.returncode == 0, run.stderr
    place = skills_of(read_json(tmp_path / "r.json"), VIOLATION)["PlaceOnPose"]
    assert (place["status"], place["equivalent"]) == ("skipped", None)
    assert place["reason"] == (
        "EzSkiROS rejects this skill when it loads: skiros:hasA expects object of class "
        "skiros:TransformationPose, but parameter Target is skiros:Product (line 31 once "
        "migrated). The legacy code has the same problem (SkiROS2 accepted it silently); "
        "fix the description or the ontology, then migrate")
    text = (folder / VIOLATION).read_text(encoding="utf-8")  # AttachCamera still lands
    assert "class AttachCamera(EzSkillDescription):" in text
    assert 'Element("skiros:Product"), ParamTypes.Inferred' in text  # PlaceOnPose as it was
    assert skills_of(read_json(tmp_path / "r.json"), VIOLATION)["AttachCamera"]["status"] \
        == "converted"


def test_verify_fails_a_rejected_class_and_lists_its_findings(tmp_path):
    before = _hard_violation(tmp_path / "before", legacy=True)
    after = _hard_violation(tmp_path / "after", legacy=False)
    run = cli("verify", before, after, "--report", tmp_path / "r.json", *PAPER_AXIOMS)
    assert run.returncode == 1, run.stderr
    skills = skills_of(read_json(tmp_path / "r.json"), VIOLATION)
    place, attach = skills["PlaceOnPose"], skills["AttachCamera"]
    assert (place["status"], place["equivalent"]) == ("failed", None)
    assert place["reason"].endswith("parameter Target is skiros:Product (line 31)")
    assert {(f["kind"], f["line"]) for f in place["findings"]} == {("range", 31)}
    assert (attach["status"], attach["equivalent"]) == ("converted", True)
    assert [f["kind"] for f in attach["findings"]] == ["range-unproven"]
    assert "1 equivalent, 1 not equivalent" in run.stderr


FAILS_TO_LOAD = HEADER + '''
import sys

print("calibration table missing", file=sys.stderr)
raise RuntimeError("robot configuration missing")
'''


def test_verify_reports_what_an_unloadable_version_printed(tmp_path):
    before = tree(tmp_path / "before", {"pick_and_place.py": LEGACY / "pick_and_place.py"})
    after = tree(tmp_path / "after", {"pick_and_place.py": FAILS_TO_LOAD})
    run = cli("verify", before, after, "--report", tmp_path / "r.json")
    assert run.returncode == 2, run.stderr
    notes = file_entry(read_json(tmp_path / "r.json"), "pick_and_place.py")["notes"]
    assert notes == ["stderr of the migrated version while loading:\n"
                     "calibration table missing"]


def test_verify_reports_say_what_equivalence_ignored(tmp_path):
    before = tree(tmp_path / "before", {"pick_and_place.py": LEGACY / "pick_and_place.py"})
    after = tree(tmp_path / "after", {"pick_and_place.py": MIGRATED / "pick_and_place.py"})
    run = cli("verify", before, after, "--ignore-order", "--ignore-labels",
              "--report", tmp_path / "r.json")
    assert run.returncode == 0, run.stderr
    assert read_json(tmp_path / "r.json")["options"] == {
        "verified": True, "ignore_order": True, "ignore_labels": True}
    assert run.stderr.splitlines()[-1] == (
        "ezmigrate: 1 files compared, 3 classes, 3 equivalent, 0 not equivalent "
        "(ignoring parameter/condition order and labels)")
    strict = cli("verify", before, after, "--report", tmp_path / "s.json")
    assert read_json(tmp_path / "s.json")["options"]["ignore_order"] is False
    assert "ignoring" not in strict.stderr


@pytest.mark.parametrize("suffix", [".json", ".md"])
def test_verify_reports_a_file_name_that_is_not_utf8(tmp_path, suffix):
    name = os.fsdecode(b"caf\xe9.py")
    before = tree(tmp_path / "before", {name: LEGACY / "pick_and_place.py"})
    after = tree(tmp_path / "after", {name: MIGRATED / "pick_and_place.py"})
    run = cli("verify", before, after, "--report", tmp_path / f"r{suffix}")
    assert run.returncode == 0, run.stderr
    assert "3 equivalent" in run.stderr
    assert "caf\\udce9.py" in (tmp_path / f"r{suffix}").read_text(encoding="utf-8")


def test_a_file_is_compared_with_the_file_of_its_name_in_a_folder(tmp_path):
    before = tree(tmp_path / "before", {"pick_and_place.py": LEGACY / "pick_and_place.py"})
    after = tree(tmp_path / "after", {"pick_and_place.py": MIGRATED / "pick_and_place.py"})
    for pair in ((before / "pick_and_place.py", after), (before, after / "pick_and_place.py")):
        run = cli("verify", *pair)
        assert run.returncode == 0, run.stderr
        assert "1 files compared, 3 classes, 3 equivalent" in run.stderr
    other = tree(tmp_path / "other", {"descriptions.py": MIGRATED / "descriptions.py"})
    for pair in ((before / "pick_and_place.py", other), (other, before / "pick_and_place.py")):
        run = cli("verify", *pair)
        assert run.returncode == 2, run.stderr
        assert "internal error" not in run.stderr
        assert f"cannot compare the file {before / 'pick_and_place.py'} with the folder " \
               f"{other}" in run.stderr


PYTHON2 = HEADER + '''

class Legacy(SkillDescription):
    def createDescription(self):
        print "describing"
'''


def _load_error(tmp_path: Path, name: str, data: bytes) -> str:
    """The stderr of ``verify`` on a file that does not compile against a version that does,
    with no other Python to be found (none on PATH but ours, no pyenv): nothing loads it."""
    before = tree(tmp_path / "before", {name: data})
    after = tree(tmp_path / "after", {name: HEADER})
    alone = {"PYENV_ROOT": str(tmp_path / "no-pyenv"),
             "PATH": os.pathsep.join([str(Path(sys.executable).parent), "/usr/bin", "/bin"])}
    run = cli("verify", before, after, env=alone)
    assert run.returncode == 2, run.stderr
    return run.stderr


def test_invalid_syntax_is_reported_with_line_and_column_not_as_newer_python(tmp_path):
    """Only syntax libcst parses and this Python does not is "newer than this Python"."""
    python2 = _load_error(tmp_path / "py2", "py2.py", PYTHON2.encode())
    assert "cannot import under Python" not in python2
    assert "SyntaxError in py2.py at line 8, column 9: Missing parentheses" in python2
    nul = _load_error(tmp_path / "nul", "nul.py", HEADER.encode() + b"SPEED = 1\0\n")
    assert "cannot import under Python" not in nul
    assert "SyntaxError in nul.py at line 4, column 10: source code string cannot contain " \
           "null bytes" in nul
    if sys.version_info < (3, 12):  # a nested f-string quote is valid from 3.12 on
        newer = _load_error(tmp_path / "newer", "newer.py",
                            HEADER.encode() + b'LABEL = f"{"nested"}"\n')
        assert f"cannot import under Python 3.{sys.version_info.minor}" in newer


def test_a_byte_identical_unloadable_file_is_a_note_not_an_error(tmp_path):
    before = tree(tmp_path / "before", {"py2.py": PYTHON2,
                                        "pick_and_place.py": LEGACY / "pick_and_place.py"})
    after = tree(tmp_path / "after", {"py2.py": PYTHON2,
                                      "pick_and_place.py": MIGRATED / "pick_and_place.py"})
    run = cli("verify", before, after, "--report", tmp_path / "r.json")
    assert run.returncode == 0, run.stderr
    assert "py2.py: unchanged, not loadable: " in run.stderr
    entry = file_entry(read_json(tmp_path / "r.json"), "py2.py")
    assert entry["error"] is None and entry["notes"][0].startswith("unchanged, not loadable")
    (after / "py2.py").write_text(PYTHON2 + "\n# touched\n", encoding="utf-8")
    changed = cli("verify", before, after)
    assert changed.returncode == 2, changed.stderr
    assert "py2.py: the legacy version could not be loaded" in changed.stderr
