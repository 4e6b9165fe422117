"""``lint/ezskiros_reader.py``: an EzSkiROS file without a legacy description read from
``ast``, as the codemod reads it with libcst. Its promise: whenever it answers, the answer
is ``migrate``'s; held on every such file of the project and on modules made at random
near its edge. And ``check`` then no longer parses those files with libcst."""

from __future__ import annotations

import ast
import random
import subprocess
from pathlib import Path

import pytest
from process_log import log_calls, logged

from ezmigrate.checking.pipeline import run_check
from ezmigrate.checking.run import CheckSettings
from ezmigrate.codemod.migrate import Settings, migrate
from ezmigrate.lint.ezskiros_reader import read_ezskiros
from ezmigrate.project import runner
from ezmigrate.verify.pool import PoolConfig
from ezskiros_runtime.ontology.load import load_index

ROOT = Path(__file__).resolve().parents[2]
SETTINGS = Settings()


def _runtime_files() -> list[Path]:
    return sorted(p for folder in ("fixtures", "tests") for p in (ROOT / folder).rglob("*.py")
                  if b"ezskiros_runtime" in p.read_bytes())


def _agrees(text: bytes, path: str = "m.py") -> bool | None:
    """None when the reader leaves the file to the codemod, else whether both agree."""
    try:
        tree = ast.parse(text)
    except SyntaxError:
        return None
    read = read_ezskiros(tree, path)
    return None if read is None else read == migrate(text, SETTINGS, path)


def test_every_ezskiros_file_of_the_project_reads_as_the_codemod_reads_it() -> None:
    verdicts = [_agrees(p.read_bytes(), p.name) for p in _runtime_files()]
    assert False not in verdicts
    assert verdicts.count(True) >= 20  # the migrated fixtures are read without libcst


LEGACY = "from skiros2_common.core.abstract_skill import SkillDescription as Legacy\n"
IMPORTS = [
    "from ezskiros_runtime import SkillDescription\n",
    "from ezskiros_runtime import SkillDescription as EzSkillDescription\n",
    "import ezskiros_runtime as ez\n",
    "from ezskiros_runtime.ontology import skiros\n",
    "from .base import Base\n",
    "from .base import Base as Other\n",
    "from ..pkg.mod import Helper, Mixin\n",
    "from . import sibling\n",
    "from lab.skills import Shared\n",
    "from skiros2_skill.core.skill import SkillBase\n",
    "from os.path import *\n",
    "import skiros2_common.core.params as params\n",
]
BASES = ["SkillDescription", "EzSkillDescription", "ez.SkillDescription", "Base", "Other",
         "Helper", "Mixin", "Shared", "SkillBase", "sibling.Thing", "Legacy", "object",
         "*Mixins", "metaclass=Meta", "First", "First.Inner"]
BODIES = ["    pass\n",
          "    def createDescription(self, Object: skiros.Product):\n        pass\n",
          "    def createDescription(self):\n        self.addParam('X', 1, 0)\n",
          "    def expand(self, skill):\n        pass\n"]


def _module(chance: random.Random) -> bytes:
    lines = [chance.choice(IMPORTS) for _ in range(chance.randint(1, 4))]
    if chance.random() < 0.15:
        lines.append(LEGACY)
    for number in range(chance.randint(1, 3)):
        name = "First" if number == 0 else f"Skill{number}"
        bases = ", ".join(chance.choice(BASES) for _ in range(chance.randint(0, 2)))
        lines.append(f"class {name}({bases}):\n{chance.choice(BODIES)}")
    return "".join(lines).encode()


def test_modules_at_random_read_as_the_codemod_reads_them() -> None:
    chance = random.Random(11)
    verdicts = [_agrees(_module(chance)) for _ in range(600)]
    assert False not in verdicts
    assert verdicts.count(True) > 150 and verdicts.count(None) > 100  # both sides met


def test_check_parses_no_such_file_with_libcst(tmp_path: Path, monkeypatch) -> None:
    """A migrated repository: every skill file uses ``ezskiros_runtime``; those the syntax
    settles never reach ``migrate_file`` (libcst), in a worker or here, and the findings
    are those of the codemod's reading (the same files, each migrated, give the same)."""
    repo = tmp_path / "repo"
    (repo / "pkg").mkdir(parents=True)
    for path in _runtime_files():
        if path.parent.name == "migrated" and _agrees(path.read_bytes(), path.name):
            (repo / "pkg" / path.name).write_bytes(path.read_bytes())
    subprocess.run(["git", "init", "-q", str(repo)], check=True)
    log = tmp_path / "migrated.log"
    log_calls(monkeypatch, runner, "migrate_file", log, lambda relative, *_: relative)
    index = load_index()
    outcome = run_check([repo], index, PoolConfig(workers=2), CheckSettings(trace=False))
    assert outcome.files >= 10 and logged(log) == []
    monkeypatch.setattr("ezmigrate.checking.file_facts.read_ezskiros", lambda *_: None)
    codemod = run_check([repo], index, PoolConfig(workers=2), CheckSettings(trace=False))
    assert len(logged(log)) >= 10 and codemod.diagnostics == outcome.diagnostics


@pytest.mark.parametrize("text", [
    b"from ezskiros_runtime import SkillDescription\n" + LEGACY.encode()
    + b"class A(Legacy):\n    def createDescription(self):\n        pass\n",
    b"from ezskiros_runtime import SkillDescription\nclass A(SkillDescription):\n    pass\n"
    b"class B(A):\n    def createDescription(self):\n        pass\n",
])
def test_a_legacy_import_or_a_local_base_is_left_to_the_codemod(text: bytes) -> None:
    assert read_ezskiros(ast.parse(text), "m.py") is None
