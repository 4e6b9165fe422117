"""``check`` resolves vocabulary and scenes as the robot does, from its SkiROS2 launch file
(issue 21, pattern 5). Real launch files, scenes and skills in temporary git repositories,
the real CLI; each behaviour has its trigger and its near miss."""

from __future__ import annotations

import json
import subprocess
import textwrap
from pathlib import Path

from check_support import cli, legacy

from ezmigrate.checking.launch import read_launch

SKILL = legacy('self.addParam("Part", Element("lab:Widget"), ParamTypes.Required)')
OWL = """\
@prefix owl: <http://www.w3.org/2002/07/owl#> .
@prefix rdfs: <http://www.w3.org/2000/01/rdf-schema#> .
@prefix lab: <http://example.org/lab#> .
lab:Gadget a owl:Class .
"""
SCENE = """\
@prefix rdf: <http://www.w3.org/1999/02/22-rdf-syntax-ns#> .
@prefix owl: <http://www.w3.org/2002/07/owl#> .
@prefix skiros: <http://rvmi.aau.dk/ontologies/skiros.owl#> .
@prefix lab: <http://example.org/lab#> .
skiros:Scene-0 a skiros:Scene, owl:NamedIndividual ;
    skiros:contain lab:{kind}-1 .
lab:{kind}-1 a lab:{kind}, owl:NamedIndividual .
"""
LAUNCH = """\
<launch>
  <include file="$(find skiros2)/launch/skiros.launch">
    <arg name="workspace_dir" value="{workspace}"/>
    <arg name="init_scene" value="{scene}"/>
    <arg name="skill_list" value="[pick_widget]"/>
  </include>
</launch>
"""


def repo(tmp_path: Path, files: dict[str, str]) -> Path:
    for name, text in files.items():
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text(textwrap.dedent(text), encoding="utf-8")
    subprocess.run(["git", "init", "-q", str(tmp_path)], check=True)
    return tmp_path


def found(folder: Path, *args: str) -> list[tuple[str, str, str]]:
    """``(file name, code, severity)`` of ``check`` on a folder, or on one named file."""
    named, cwd = (folder.name, folder.parent) if folder.is_file() else (".", folder)
    run = cli(named, "--output-format", "json", *args, cwd=cwd)
    assert run.returncode in (0, 1), run.stderr
    return [(Path(str(d["path"])).name, str(d["code"]), str(d["severity"]))
            for d in json.loads(run.stdout)]


def test_a_class_the_init_scene_types_individuals_with_is_known(tmp_path: Path):
    base = {"pkg/skill.py": SKILL, "owl/lab.ttl": OWL,
            "launch/cell.launch": LAUNCH.format(workspace="../owl",
                                                scene="../scenes/cell.turtle")}
    typed = repo(tmp_path / "typed", {**base, "scenes/cell.turtle": SCENE.format(kind="Widget")})
    assert [f for f in found(typed) if f[1] != "EZ407"] == []  # EZ407: the scene's own info
    other = repo(tmp_path / "other", {**base, "scenes/cell.turtle": SCENE.format(kind="Gadget")})
    assert [f for f in found(other) if f[1] != "EZ407"] == [("skill.py", "EZ209", "warning")]


def test_the_init_scene_of_the_launch_file_is_checked(tmp_path: Path):
    broken = {"pkg/skill.py": legacy('self.addParam("P", Element("skiros:Location"), '
                                     'ParamTypes.Required)'),
              "scenes/cell.turtle": "this is not turtle\n"}
    launched = repo(tmp_path / "a", {**broken, "launch/cell.launch": LAUNCH.format(
        workspace="/nowhere", scene="../scenes/cell.turtle")})
    assert ("cell.turtle", "EZ402", "error") in found(launched)
    # a scene anywhere in the repository is checked, named by a launch file or not (issue 30)
    alone = repo(tmp_path / "b", broken)
    assert found(alone) == [("cell.turtle", "EZ402", "error")]
    fixed = repo(tmp_path / "c", {**broken, "scenes/cell.turtle": SCENE.format(kind="Gadget")})
    assert ("cell.turtle", "EZ402", "error") not in found(fixed)


def test_vocabulary_of_a_workspace_this_run_cannot_read_is_info(tmp_path: Path):
    files = {"pkg/skill.py": SKILL}
    elsewhere = repo(tmp_path / "a", {**files, "launch/cell.launch": LAUNCH.format(
        workspace="$(find lab_world)/owl", scene="cell.turtle")})
    [(_, code, severity)] = found(elsewhere)
    assert (code, severity) == ("EZ209", "info")
    run = cli(".", "--output-format", "json", cwd=elsewhere)
    assert "workspace_dir $(find lab_world)/owl could not be read" in run.stdout
    # near miss: no launch file, and the lab prefix defined, so the class is simply unknown
    assert found(repo(tmp_path / "b", {**files, "owl/lab.ttl": OWL})) == [
        ("skill.py", "EZ209", "warning")]


def test_an_undefined_prefix_is_reported_once_per_project_with_its_count(tmp_path: Path):
    two = legacy('self.addParam("A", Element("acme:Box"), ParamTypes.Required)\n'
                 'self.addParam("B", Element("acme:Crate"), ParamTypes.Required)')
    folder = repo(tmp_path / "a", {"one.py": two, "two.py": two})
    run = cli(".", "--output-format", "json", cwd=folder)
    shown = [d for d in json.loads(run.stdout) if d["code"] == "EZ209"]
    assert len(shown) == 1 and "4 uses of prefix 'acme'" in str(shown[0]["message"])
    single = repo(tmp_path / "b", {"one.py": legacy(
        'self.addParam("A", Element("acme:Box"), ParamTypes.Required)')})
    [only] = [d for d in json.loads(cli(".", "--output-format", "json", cwd=single).stdout)]
    assert "uses of prefix" not in str(only["message"])
    # a lab prefix is usually another package's ontology: info, as on the robot (issue 30)
    assert shown[0]["severity"] == only["severity"] == "info"


def test_several_launch_files_need_launch_to_choose(tmp_path: Path):
    files = {"pkg/skill.py": SKILL, "owl/lab.ttl": OWL,
             "launch/a.launch": LAUNCH.format(workspace="$(find far)/owl", scene="x.turtle"),
             "launch/b.launch": LAUNCH.format(workspace="/nowhere", scene="y.turtle")}
    folder = repo(tmp_path, files)
    run = cli(".", cwd=folder)
    assert "2 SkiROS2 launch files" in run.stderr and "--launch FILE" in run.stderr
    assert found(folder) == [("skill.py", "EZ209", "warning")]
    assert found(folder, "--launch", "launch/a.launch") == [("skill.py", "EZ209", "info")]


def test_a_ros2_launch_file_is_read_statically_where_its_values_are_literals(tmp_path: Path):
    path = tmp_path / "cell.launch.py"
    path.write_text(textwrap.dedent('''\
        from launch import LaunchDescription
        from launch.actions import DeclareLaunchArgument

        def generate_launch_description():
            return LaunchDescription([
                DeclareLaunchArgument("workspace_dir", default_value="/opt/lab/owl"),
                Node(package="skiros2_skill", parameters=[{
                    "libraries_list": ["lab_skills"], "skill_list": "[pick, place]",
                    "init_scene": some_function(),
                }]),
            ])
        '''), encoding="utf-8")
    launch = read_launch(path)
    assert launch.values == {"workspace_dir": "/opt/lab/owl", "libraries_list": "[lab_skills]",
                             "skill_list": "[pick, place]"}
    assert launch.listed("skill_list") == ["pick", "place"] and launch.scene() is None


def test_find_resolves_to_a_ros_package_of_the_repository():
    from ezmigrate.checking.launch import project_launch

    package = Path(__file__).resolve().parents[2] / "fixtures" / "noetic_package"
    launch, note = project_launch(package)
    assert note is None and launch is not None
    assert launch.folder("workspace_dir") == package / "owl"
    assert launch.workspace_unresolved is None
    assert launch.listed("libraries_list") == ["paint_cell", "skiros2_std_skills"]
    alone = read_launch(launch.path)  # no package known: $(find paint_cell) stays unresolved
    assert alone.folder("workspace_dir") is None
    assert alone.workspace_unresolved == "$(find paint_cell)/owl"


PACKAGE = "<package><name>lab_skills</name><buildtool_depend>catkin</buildtool_depend></package>"
TASK = legacy('self.addParam("Spot", Element("skiros:Location"), ParamTypes.Required)') + '''

from skiros2_skill.core.skill import PrimitiveBase, SkillBase


class Scan(SkillDescription):
    def createDescription(self):
        self.addParam("Area", Element("skiros:Location"), ParamTypes.Required)


class scan_lidar(PrimitiveBase):
    def createDescription(self):
        self.setDescription(Scan(), self.__class__.__name__)


class survey(SkillBase):
    def createDescription(self):
        self.setDescription(Skill(), self.__class__.__name__)

    def expand(self, skill):
        skill(self.skill("Scan", "", remap={"Area": "Spot"}))
'''


def test_a_child_whose_implementations_the_skill_list_does_not_load_is_said(tmp_path: Path):
    def launched(folder: Path, skills: str) -> list[tuple[str, str, str]]:
        launch = LAUNCH.format(workspace="/nowhere", scene="x.turtle").replace(
            "[pick_widget]", skills) + f"<!-- {libraries} -->"
        launch = launch.replace('<arg name="skill_list"', f'<arg name="libraries_list" '
                                f'value="{libraries}"/>\n    <arg name="skill_list"')
        return found(repo(folder, {"pkg/task.py": TASK, "launch/robot.launch": launch,
                                   "pkg/package.xml": PACKAGE}), "--select", "EZ3")

    libraries = "[lab_skills]"
    assert launched(tmp_path / "a", "[survey]") == [("task.py", "EZ316", "info")]
    assert launched(tmp_path / "b", "[survey, scan_lidar]") == []
    libraries = "[other_lab]"  # the launch file does not load this package: not judged
    assert launched(tmp_path / "c", "[survey]") == []


def test_a_named_file_sees_the_scenes_of_its_repository(tmp_path: Path):
    """pre-commit names the staged file only: a class its repository's scene types
    individuals with is still known (the run on the repository says the same)."""
    folder = repo(tmp_path, {"pkg/skill.py": SKILL, "owl/lab.ttl": OWL,
                             "owl/scenes/cell.turtle": SCENE.format(kind="Widget")})
    alone = [f for f in found(folder / "pkg" / "skill.py") if f[1] != "EZ407"]
    assert alone == [] == [f for f in found(folder) if f[1] != "EZ407"]
    (folder / "owl" / "scenes" / "cell.turtle").write_text(SCENE.format(kind="Gadget"))
    assert [f for f in found(folder / "pkg" / "skill.py") if f[1] != "EZ407"] == [
        ("skill.py", "EZ209", "warning")]


def test_the_note_on_several_launch_files_names_every_one(tmp_path: Path):
    files = {"pkg/skill.py": SKILL,
             **{f"launch/{n}.launch": LAUNCH.format(workspace="/nowhere", scene="x.turtle")
                for n in "abcdef"}}
    run = cli(".", cwd=repo(tmp_path, files))
    [note] = [line for line in run.stderr.splitlines() if "SkiROS2 launch files" in line]
    assert note.startswith("ezmigrate: 6 SkiROS2 launch files (")
    assert all(f"launch/{n}.launch" in note for n in "abcdef"), note


def test_an_empty_init_scene_is_no_missing_scene(tmp_path: Path):
    folder = repo(tmp_path, {"pkg/skill.py": SKILL,
                             "cell.launch": LAUNCH.format(workspace="/nowhere", scene="")})
    assert read_launch(folder / "cell.launch").scene() is None
    run = cli(".", cwd=folder)
    assert "init_scene" not in run.stderr.replace("init_scene=", ""), run.stderr
    named = repo(tmp_path / "b", {"pkg/skill.py": SKILL,
                                  "cell.launch": LAUNCH.format(workspace="/nowhere",
                                                               scene="gone.turtle")})
    assert "init_scene 'gone.turtle' is neither beside" in cli(".", cwd=named).stderr
