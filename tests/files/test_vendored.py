"""A vendored copy of SkiROS2's own Python is not the lab's code: passed over with one note.

Labs vendor the framework or its standard skill libraries next to their own packages.
``rewrite`` and ``check`` at the repository root leave those folders alone (one note each),
as ontology discovery leaves vendored core ``.owl`` files alone; naming the folder, or
``--include-vendored``, takes them in. The same packages in SkiROS2's own repositories (the
standard library, a fork of the framework) are their maintainers' code: migrated as any.
"""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from ezmigrate.checking.launch import launch_files
from ezmigrate.files.discover import discover
from ezskiros_runtime.ontology.discovery import discover as discover_ontology
from ezskiros_runtime.ontology.vendored import VendoredRule, holds_only_skiros2, upstream_package

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures"


@pytest.fixture
def lab(tmp_path: Path) -> Path:
    """A lab workspace: its own package, a vendored skiros2_std_skills (by folder name) and
    a vendored framework package renamed on disk (known by its package.xml)."""
    root = tmp_path / "ws"
    own = root / "cell" / "src" / "cell"
    own.mkdir(parents=True)
    shutil.copy(FIXTURES / "legacy" / "pick_and_place.py", own / "skills.py")
    std = root / "third_party_skills" / "skiros2_std_skills" / "src" / "skiros2_std_skills"
    std.mkdir(parents=True)
    shutil.copy(FIXTURES / "legacy" / "descriptions.py", std / "std.py")
    renamed = root / "framework_copy"
    (renamed / "src").mkdir(parents=True)
    (renamed / "package.xml").write_text("<package>\n  <name>skiros2_skill</name>\n</package>\n")
    shutil.copy(FIXTURES / "legacy" / "conditions.py", renamed / "src" / "core.py")
    return root


def _run(*args: object, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "ezmigrate", *map(str, args)], cwd=cwd,
                          capture_output=True, text=True, timeout=600, check=False)


def test_vendored_packages_are_known_by_folder_or_package_xml(lab: Path) -> None:
    rule = VendoredRule(lab)
    assert rule.package(lab / "third_party_skills" / "skiros2_std_skills") == \
        "skiros2_std_skills"
    assert rule.package(lab / "framework_copy") == "skiros2_skill"
    assert rule.package(lab / "cell") is None
    assert rule.package(lab / "third_party_skills") is None


def test_a_run_at_the_root_passes_over_vendored_code_with_one_note_each(lab: Path) -> None:
    found, notes = discover([lab])
    assert [c.relative for c in found] == ["cell/src/cell/skills.py"]
    vendored = [note for note in notes if "vendored copy of SkiROS2" in note]
    assert len(vendored) == 2, notes
    included, _ = discover([lab], include_vendored=True)
    assert len(included) == 3


def test_naming_a_vendored_folder_includes_all_of_it(lab: Path) -> None:
    named = lab / "third_party_skills" / "skiros2_std_skills"
    found, notes = discover([named])
    assert [c.relative for c in found] == ["src/skiros2_std_skills/std.py"]
    assert not notes


@pytest.mark.parametrize("command", ["rewrite", "check"])
def test_rewrite_and_check_say_what_they_passed_over(lab: Path, command: str) -> None:
    extra = ("--dry-run", "--no-verify") if command == "rewrite" else ("--exit-zero",)
    run = _run(command, *extra, ".", cwd=lab)
    assert run.returncode == 0, run.stderr
    notes = [line for line in run.stderr.splitlines() if "vendored copy" in line]
    assert len(notes) == 2 and "--include-vendored" in notes[0], run.stderr
    assert "std.py" not in run.stdout and "core.py" not in run.stdout
    everything = _run(command, *extra, "--include-vendored", ".", cwd=lab)
    assert "vendored copy" not in everything.stderr
    if command == "rewrite":
        assert "std.py" in everything.stdout  # its diff is shown


def _std_lib(root: Path) -> Path:
    """A repository shaped like SkiROS2's standard library: two SkiROS2 packages (one known
    by its folder, one by its package.xml), a licence, nothing else."""
    skills = root / "skiros2_std_skills"
    (skills / "src" / "skiros2_std_skills").mkdir(parents=True)
    (skills / "package.xml").write_text("<package>\n  <name>skiros2_std_skills</name>\n"
                                        "</package>\n")
    shutil.copy(FIXTURES / "legacy" / "descriptions.py",
                skills / "src" / "skiros2_std_skills" / "std.py")
    reasoners = root / "reasoners_renamed"
    (reasoners / "src").mkdir(parents=True)
    (reasoners / "package.xml").write_text("<package>\n  <name>skiros2_std_reasoners</name>"
                                           "\n</package>\n")
    (reasoners / "src" / "reasoner.py").write_text("X = 1\n")
    (root / "LICENSE.md").write_text("BSD\n")
    return root


def _git_init(root: Path) -> None:
    subprocess.run(["git", "init", "-q", str(root)], check=True)


@pytest.mark.parametrize("with_git", [True, False])
def test_skiros2s_own_repository_is_its_maintainers_code(tmp_path: Path,
                                                         with_git: bool) -> None:
    root = _std_lib(tmp_path / "skiros2_std_lib_fork")
    if with_git:
        _git_init(root)
    assert holds_only_skiros2(root)
    found, notes = discover([root])
    assert [c.relative for c in found] == ["reasoners_renamed/src/reasoner.py",
                                           "skiros2_std_skills/src/skiros2_std_skills/std.py"]
    assert not [note for note in notes if "vendored" in note], notes


def test_the_git_top_level_is_the_repository_even_below_it(tmp_path: Path) -> None:
    """A lab's workspace repository holding the standard library in ``src/``: naming the
    ``src`` folder does not make the library the lab's own."""
    root = tmp_path / "ws"
    _std_lib(root / "src" / "std")
    (root / "src" / "lab_skills").mkdir(parents=True)
    (root / "src" / "lab_skills" / "package.xml").write_text(
        "<package>\n  <name>lab_skills</name>\n</package>\n")
    _git_init(root)
    assert not holds_only_skiros2(root)
    found, notes = discover([root / "src"])
    assert found == []
    assert len([note for note in notes if "vendored copy" in note]) == 2, notes


def test_a_python_file_outside_skiros2s_packages_makes_the_repository_a_labs(
        tmp_path: Path) -> None:
    root = _std_lib(tmp_path / "demo")
    (root / "run_demo.py").write_text("print('hello')\n")
    assert not holds_only_skiros2(root)
    found, _ = discover([root])
    assert [c.relative for c in found] == ["run_demo.py"]


def test_no_skiros2_package_is_no_skiros2_repository(tmp_path: Path) -> None:
    (tmp_path / "LICENSE.md").write_text("MIT\n")
    assert not holds_only_skiros2(tmp_path)
    assert upstream_package(tmp_path) is None


def test_rewrite_at_the_root_of_a_std_lib_converts_it(tmp_path: Path) -> None:
    root = _std_lib(tmp_path / "std_lib")
    _git_init(root)
    run = _run("rewrite", "--dry-run", "--no-verify", ".", cwd=root)
    assert run.returncode == 0, run.stderr
    assert "vendored" not in run.stderr
    assert "skiros2_std_skills/src/skiros2_std_skills/std.py" in run.stdout, run.stdout
    assert "+    def description(self" in run.stdout, run.stdout


def test_vendored_owl_folders_and_launch_files_are_passed_over(lab: Path) -> None:
    """The ontology and launch-file searches apply the same rule as the Python walk."""
    std = lab / "third_party_skills" / "skiros2_std_skills"
    (std / "owl").mkdir()
    (std / "owl" / "std.owl").write_text("")
    (std / "launch").mkdir()
    (std / "launch" / "demo.launch").write_text('<launch><arg name="init_scene" '
                                                'value="a.turtle"/></launch>\n')
    (lab / "cell" / "owl").mkdir()
    (lab / "cell" / "owl" / "lab.ttl").write_text("")
    (lab / "cell" / "robot.launch").write_text('<launch><arg name="init_scene" '
                                               'value="b.turtle"/></launch>\n')
    found = discover_ontology(lab)
    assert found.files == (lab / "cell" / "owl" / "lab.ttl",)
    assert found.vendored == (std / "owl" / "std.owl",)
    assert launch_files(lab) == [lab / "cell" / "robot.launch"]
    # in SkiROS2's own repository, its package's owl/ folder is its own
    assert discover_ontology(std).files == (std / "owl" / "std.owl",)


@pytest.mark.parametrize("marker", ["CATKIN_IGNORE", "COLCON_IGNORE", "AMENT_IGNORE"])
def test_a_folder_the_ros_build_ignores_is_passed_over_with_a_note(lab: Path,
                                                                  marker: str) -> None:
    (lab / "cell" / marker).write_text("")
    found, notes = discover([lab], include_vendored=True)
    assert "cell/src/cell/skills.py" not in [c.relative for c in found]
    assert [n for n in notes if marker in n] == [
        f"{lab / 'cell'}: skipped, its {marker} keeps it out of the ROS build"]
    named, _ = discover([lab / "cell"])  # named: the user's choice
    assert [c.relative for c in named] == ["src/cell/skills.py"]


def test_the_searches_of_one_command_ask_about_each_folder_once(
        lab: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Within ``shared_rules`` (a ``check`` run) the ontology, launch-file and file searches
    under one folder share their answers; outside it each search decides afresh, so a
    repository changed between two searches is seen as it is now."""
    from ezskiros_runtime.ontology import vendored

    asked: list[str] = []
    real = vendored.VendoredRule._package

    def counting(rule: vendored.VendoredRule, folder: Path) -> str | None:
        asked.append(str(folder))
        return real(rule, folder)

    monkeypatch.setattr(vendored.VendoredRule, "_package", counting)
    with vendored.shared_rules():
        discover_ontology(lab)
        launch_files(lab)
        found, _ = discover([lab])
    assert asked and len(asked) == len(set(asked))  # each folder once
    assert "third_party_skills/skiros2_std_skills/src/skiros2_std_skills/std.py" not in {
        c.relative for c in found}
    renamed = lab / "framework_copy" / "package.xml"
    renamed.write_text("<package>\n  <name>cell_tools</name>\n</package>\n")
    assert "framework_copy/src/core.py" in {c.relative for c in discover([lab])[0]}
