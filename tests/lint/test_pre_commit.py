"""The hooks of ``.pre-commit-hooks.yaml``, run by real pre-commit (``try-repo``, as a lab's
``.pre-commit-config.yaml`` would run them) on real git repositories.

pre-commit builds the hooks' virtualenv from a git repository made of this checkout's
package files (so the test runs the same whether the checkout is a git clone, an export, or
has uncommitted changes) and installs ezmigrate into it from the package registry, once per
``try-repo`` call: each of those takes seconds.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
HOOK_REPOSITORY = (".pre-commit-hooks.yaml", "pyproject.toml", "README.md", "ezmigrate",
                   "ezskiros_runtime")

LEGACY_SKILL = textwrap.dedent('''\
    from skiros2_common.core.abstract_skill import SkillDescription
    from skiros2_common.core.params import ParamTypes
    from skiros2_common.core.world_element import Element


    class Pick(SkillDescription):
        def createDescription(self):
            self.addParam("Object", Element("skiros:product"), ParamTypes.Required)
            self.addParam("Linear", float, ParamTypes.Required, "Linear velocity")
    ''')
"""EZ213 (error: ``skiros:product`` for skiros:Product) on line 8, EZ101 (warning: the
description in the options slot) on line 9; ``rewrite`` converts it."""

BASE = textwrap.dedent('''\
    from skiros2_common.core.abstract_skill import SkillDescription
    from skiros2_common.core.params import ParamTypes
    from skiros2_common.core.world_element import Element


    class Navigate(SkillDescription):
        def createDescription(self):
            self.addParam("Target", Element("skiros:Location"), ParamTypes.Required)
    ''')

DERIVED = textwrap.dedent('''\
    from skiros2_common.core.params import ParamTypes
    from skiros2_common.core.world_element import Element
    from .descriptions import Navigate


    class NavigateWith(Navigate):
        def createDescription(self):
            Navigate.createDescription(self)
            self.addParam("Object", Element("skiros:product"), ParamTypes.Required)
    ''')
"""A description whose base is in a sibling file: checked (EZ213 on line 9) and converted
only when both files reach ezmigrate in the same run."""

LAB_REPOSITORY = {
    "skill.py": LEGACY_SKILL,
    "pkg/__init__.py": "",
    "pkg/descriptions.py": BASE,
    "pkg/impl.py": DERIVED,
    # more than four Python files: without require_serial, pre-commit would split them
    # over several processes, and pkg/impl.py would be checked without its base
    "pkg/constants.py": "SPEED = 0.1\n",
    "pkg/util.py": "def clamp(x):\n    return x\n",
    "scripts/run.py": 'print("demo")\n',
    "setup.py": "from setuptools import setup\n\nsetup()\n",
}

CLEAN_SKILL = textwrap.dedent('''\
    from ezskiros_runtime import SkillDescription, REQUIRED, DESC
    from ezskiros_runtime.ontology import skiros


    class Pick(SkillDescription):
        def description(self,
                        Object: skiros.Product,
                        Linear: REQUIRED[float, DESC("Linear velocity")]):
            pass
    ''')

_GIT_REPOSITORY_ENV = ("GIT_DIR", "GIT_WORK_TREE", "GIT_INDEX_FILE", "GIT_OBJECT_DIRECTORY",
                       "GIT_ALTERNATE_OBJECT_DIRECTORIES", "GIT_COMMON_DIR",
                       "GIT_CEILING_DIRECTORIES")


@pytest.fixture(scope="module")
def pre_commit_home(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """One PRE_COMMIT_HOME for the module: pre-commit's state never lands in ~/.cache."""
    if shutil.which("git") is None:
        pytest.fail("git is not on PATH: these tests run real git and pre-commit; install git")
    return tmp_path_factory.mktemp("pre-commit-home")


@pytest.fixture(scope="module")
def hooks(tmp_path_factory: pytest.TempPathFactory, pre_commit_home: Path
          ) -> tuple[Path, Path]:
    """(this checkout's package files committed to a git repository of their own, the
    pre-commit home)."""
    repository = tmp_path_factory.mktemp("hooks") / "ezmigrate"
    files: dict[str, str] = {}
    for name in HOOK_REPOSITORY:
        source = ROOT / name
        for path in ([source] if source.is_file() else sorted(source.rglob("*"))):
            if path.is_file() and "__pycache__" not in path.parts:
                files[path.relative_to(ROOT).as_posix()] = path.read_text(encoding="utf-8")
    repository.mkdir()
    return _repository(repository, files, pre_commit_home), pre_commit_home


def _env(home: Path) -> dict[str, str]:
    """This environment, minus what would point git at another repository (as when the
    tests run inside a git hook), with PRE_COMMIT_HOME set."""
    env = {k: v for k, v in os.environ.items() if k not in _GIT_REPOSITORY_ENV}
    env["PRE_COMMIT_HOME"] = str(home)
    return env


def _repository(path: Path, files: dict[str, str], home: Path) -> Path:
    """A git repository at ``path`` with ``files`` committed."""
    for name, text in files.items():
        (path / name).parent.mkdir(parents=True, exist_ok=True)
        (path / name).write_text(text, encoding="utf-8")
    for args in (["init", "-q"], ["config", "user.name", "Lab Member"],
                 ["config", "user.email", "member@lab.invalid"],
                 ["config", "commit.gpgsign", "false"], ["add", "-A"],
                 ["commit", "-q", "-m", "skills"]):
        run = subprocess.run(["git", *args], cwd=path, env=_env(home), capture_output=True,
                             text=True)
        assert run.returncode == 0, f"git {' '.join(args)}: {run.stderr}"
    return path


def _try_repo(repo: Path, hooks: tuple[Path, Path], *ids: str
              ) -> subprocess.CompletedProcess[str]:
    """``pre-commit try-repo HOOKS [ID] --all-files`` in ``repo``; stderr into stdout."""
    source, home = hooks
    return subprocess.run(
        [sys.executable, "-m", "pre_commit", "try-repo", str(source), *ids, "--all-files",
         "--color", "never"],
        cwd=repo, env=_env(home), stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
        timeout=280)


def test_check_fails_on_errors_and_rewrite_converts_the_files(tmp_path: Path,
                                                              hooks: tuple[Path, Path]):
    repo = _repository(tmp_path / "lab", LAB_REPOSITORY, hooks[1])

    check = _try_repo(repo, hooks, "ezmigrate-check")

    assert check.returncode == 1, check.stdout
    assert "ezmigrate check" in check.stdout and "Failed" in check.stdout, check.stdout
    assert "skill.py:8:9: EZ213 [error] Pick:" in check.stdout, check.stdout
    assert "skill.py:9:9: EZ101 [warning] Pick:" in check.stdout, check.stdout
    # the base in the sibling file was seen: the derived description is checked, not kept
    assert "pkg/impl.py:9:9: EZ213 [error] NavigateWith:" in check.stdout, check.stdout
    assert "EZ902" not in check.stdout, check.stdout

    rewrite = _try_repo(repo, hooks, "ezmigrate-rewrite")

    assert rewrite.returncode != 0, rewrite.stdout
    assert "files were modified by this hook" in rewrite.stdout, rewrite.stdout
    summary = "3 converted, 0 skipped, 0 failed, 0 unchanged; 3 files changed"
    assert summary in rewrite.stdout, rewrite.stdout
    for name in ("skill.py", "pkg/descriptions.py", "pkg/impl.py"):
        migrated = (repo / name).read_text(encoding="utf-8")
        assert "ezskiros_runtime" in migrated and "addParam" not in migrated, (name, migrated)
    after = {name: (repo / name).read_bytes() for name in LAB_REPOSITORY}

    again = _try_repo(repo, hooks, "ezmigrate-rewrite")

    assert again.returncode == 0, again.stdout
    assert "ezmigrate rewrite" in again.stdout and "Passed" in again.stdout, again.stdout
    assert {name: (repo / name).read_bytes() for name in LAB_REPOSITORY} == after


def test_both_hooks_pass_on_a_clean_repository(tmp_path: Path, hooks: tuple[Path, Path]):
    repo = _repository(tmp_path / "lab", {"skills/pick.py": CLEAN_SKILL}, hooks[1])

    run = _try_repo(repo, hooks)  # every hook of the manifest

    assert run.returncode == 0, run.stdout
    passed = [line for line in run.stdout.splitlines() if line.endswith("Passed")]
    assert [line.split(".")[0] for line in passed] == ["ezmigrate check",
                                                       "ezmigrate rewrite"], run.stdout
    assert (repo / "skills/pick.py").read_text(encoding="utf-8") == CLEAN_SKILL


COMPOUND_TASK = textwrap.dedent('''\
    from skiros2_common.core.abstract_skill import SkillDescription
    from skiros2_common.core.params import ParamTypes
    from skiros2_common.core.world_element import Element
    from skiros2_skill.core.skill import SkillBase


    class Patrol(SkillDescription):
        def createDescription(self):
            self.addParam("Route", Element("skiros:Location"), ParamTypes.Required)


    class patrol(SkillBase):
        def createDescription(self):
            self.setDescription(Patrol(), self.__class__.__name__)

        def expand(self, skill):
            skill(self.skill("{child}", "", remap={{"Target": "Route"}}))
    ''')


def test_check_on_staged_files_knows_the_children_of_unstaged_siblings(
        tmp_path: Path, hooks: tuple[Path, Path]):
    """pre-commit names only the staged files: a compound skill whose child is described
    in a sibling file that is not part of the commit gets what a run on the repository
    gives it (issue 21, pattern 7), here nothing; a child defined nowhere is still EZ301."""
    files = {"pkg/__init__.py": "", "pkg/descriptions.py": BASE,
             "pkg/tasks.py": COMPOUND_TASK.format(child="Navigate")}
    repo = _repository(tmp_path / "lab", files, hooks[1])
    source, home = hooks

    def staged(*names: str) -> subprocess.CompletedProcess[str]:
        return subprocess.run(
            [sys.executable, "-m", "pre_commit", "try-repo", str(source), "ezmigrate-check",
             "--files", *names, "--color", "never"], cwd=repo, env=_env(home),
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=280)

    run = staged("pkg/tasks.py")
    assert run.returncode == 0 and "Passed" in run.stdout, run.stdout
    (repo / "pkg" / "tasks.py").write_text(COMPOUND_TASK.format(child="NavigateTo"),
                                           encoding="utf-8")
    run = staged("pkg/tasks.py")
    assert run.returncode == 1 and "pkg/tasks.py:17:9: EZ301" in run.stdout, run.stdout
