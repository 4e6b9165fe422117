"""The hooks of ``.pre-commit-hooks.yaml`` work under the real pre-commit.

pre-commit (installed from the package registry with the test extra) builds its own
environment from this project (``pre-commit try-repo``) and runs each hook in a real git
repository holding a legacy skill, exactly as a lab's commit would. The hook repository is
a git repository made from this checkout's package files, so the test runs the same
whether the checkout is a git clone, an export, or has uncommitted changes.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
HOOK_REPOSITORY = (".pre-commit-hooks.yaml", "pyproject.toml", "README.md", "ezmigrate",
                   "ezskiros_runtime")

pytestmark = pytest.mark.slow

HEADER = """\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


"""

CONTRADICTION = HEADER + textwrap.dedent("""\
    class Pick(SkillDescription):
        def createDescription(self):
            self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)
            self.addParam("Place", Element("skiros:Location"), ParamTypes.Required)
            self.addPreCondition(self.getRelationCond("In", "skiros:contain", "Place", "Object",
                                                      True))
            self.addPreCondition(self.getRelationCond("Out", "skiros:contain", "Place", "Object",
                                                      False))
    """)

PLAIN = HEADER + textwrap.dedent("""\
    class Place(SkillDescription):
        def createDescription(self):
            self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)
            self.addParam("Place", Element("skiros:Location"), ParamTypes.Required)
            self.addPostCondition(self.getRelationCond("In", "skiros:contain", "Place",
                                                       "Object", True))
    """)


@pytest.fixture(scope="module")
def hooks(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path]:
    """(the hook repository, one pre-commit cache): the hook environment is built once."""
    if shutil.which("git") is None:
        pytest.fail("git is needed to run pre-commit (it is present in CI)")
    repository = tmp_path_factory.mktemp("hooks") / "ezmigrate"
    repository.mkdir()
    for name in HOOK_REPOSITORY:
        source = ROOT / name
        if source.is_dir():
            shutil.copytree(source, repository / name,
                            ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
        else:
            shutil.copy2(source, repository / name)
    _commit(repository)
    return repository, tmp_path_factory.mktemp("pre-commit-home")


def _repository(folder: Path, files: dict[str, str]) -> Path:
    folder.mkdir()
    for name, text in files.items():
        (folder / name).write_text(text, encoding="utf-8")
    return _commit(folder)


def _commit(folder: Path) -> Path:
    for command in (["init", "-q"], ["config", "user.email", "lab@example.org"],
                    ["config", "user.name", "Lab"], ["add", "-A"],
                    ["commit", "-q", "-m", "skills"]):
        subprocess.run(["git", *command], cwd=folder, check=True)
    return folder


def _hook(repository: Path, hook: str, hooks: tuple[Path, Path]
          ) -> subprocess.CompletedProcess[str]:
    source, home = hooks
    env = {**os.environ, "PRE_COMMIT_HOME": str(home), "PRE_COMMIT_COLOR": "never"}
    return subprocess.run([sys.executable, "-m", "pre_commit", "try-repo", str(source), hook,
                           "--all-files"], cwd=repository, env=env, capture_output=True,
                          text=True, timeout=600)


def test_check_hook_fails_on_an_error_and_names_it(tmp_path: Path, hooks: tuple[Path, Path]):
    repository = _repository(tmp_path / "lab", {"pick.py": CONTRADICTION})
    run = _hook(repository, "ezmigrate-check", hooks)
    assert run.returncode == 1, run.stdout + run.stderr
    assert "pick.py:12:9: EZ107 Pick" in run.stdout, run.stdout


def test_rewrite_hook_fails_when_it_migrates_then_passes(tmp_path: Path,
                                                        hooks: tuple[Path, Path]):
    repository = _repository(tmp_path / "lab", {"place.py": PLAIN})
    checked = _hook(repository, "ezmigrate-check", hooks)
    assert checked.returncode == 0, checked.stdout + checked.stderr

    first = _hook(repository, "ezmigrate-rewrite", hooks)
    assert first.returncode == 1, first.stdout + first.stderr
    assert "files were modified by this hook" in first.stdout, first.stdout
    migrated = (repository / "place.py").read_text(encoding="utf-8")
    assert "from ezskiros_runtime import" in migrated and "addParam" not in migrated

    second = _hook(repository, "ezmigrate-rewrite", hooks)
    assert second.returncode == 0, second.stdout + second.stderr
    assert (repository / "place.py").read_text(encoding="utf-8") == migrated
    after = _hook(repository, "ezmigrate-check", hooks)
    assert after.returncode == 0, after.stdout + after.stderr
