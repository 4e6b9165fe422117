"""``check --fix`` and ``check --diff`` (issue 22, item 2): EZ101's explicit fix.

A string passed 4th to ``addParam`` lands in the options slot, where SkiROS2 drops it; the
fix passes it as ``description=...``. ``--diff`` shows the change with headers relative to
the repository root (``git apply`` takes it there) and writes nothing; ``--fix`` writes it,
keeping the file's encoding and line endings, and leaves alone what is not explicit.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

HEAD = ("from skiros2_common.core.abstract_skill import SkillDescription\n"
        "from skiros2_common.core.params import ParamTypes\n\n\n"
        "class Drive(SkillDescription):\n"
        "    def createDescription(self):\n")
LEGACY = HEAD + (
    '        self.addParam("Linear", float, ParamTypes.Required, "Linear velocity")\n'
    '        self.addParam("Angular", 0.5, ParamTypes.Optional, options="rad/s")  # turn\n'
    '        self.addParam("Both", 0.5, ParamTypes.Optional, "x", description="y")\n')
FIXED = HEAD + (
    '        self.addParam("Linear", float, ParamTypes.Required, description="Linear velocity")\n'
    '        self.addParam("Angular", 0.5, ParamTypes.Optional, description="rad/s")  # turn\n'
    '        self.addParam("Both", 0.5, ParamTypes.Optional, "x", description="y")\n')


def ezmigrate(cwd: Path, *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "ezmigrate", *args], cwd=cwd,
                          capture_output=True, text=True, stdin=subprocess.DEVNULL,
                          timeout=300, check=False)


def repository(tmp_path: Path, data: bytes) -> Path:
    """A git repository with ``pkg/skills/drive.py`` holding ``data``."""
    subprocess.run(["git", "init", "-q", str(tmp_path)], check=True)
    folder = tmp_path / "pkg" / "skills"
    folder.mkdir(parents=True)
    (folder / "__init__.py").write_text("", encoding="utf-8")
    (folder / "drive.py").write_bytes(data)
    return folder / "drive.py"


def test_diff_shows_the_fix_and_applies_from_the_repository_root(tmp_path: Path):
    path = repository(tmp_path, LEGACY.encode())
    shown = ezmigrate(path.parent, "check", "--diff", "drive.py")  # run from deep inside
    assert shown.returncode == 1, shown.stderr
    assert shown.stdout.startswith("--- a/pkg/skills/drive.py\n+++ b/pkg/skills/drive.py\n")
    assert "would fix 2 findings in 1 file" in shown.stderr
    assert path.read_text(encoding="utf-8") == LEGACY  # --diff writes nothing
    (tmp_path / "fix.diff").write_text(shown.stdout, encoding="utf-8")
    subprocess.run(["git", "apply", "fix.diff"], cwd=tmp_path, check=True)
    assert path.read_text(encoding="utf-8") == FIXED


def test_fix_writes_the_fix_and_the_finding_is_gone(tmp_path: Path):
    path = repository(tmp_path, LEGACY.replace("\n", "\r\n").encode())
    fixed = ezmigrate(tmp_path, "check", "--fix", "pkg")
    assert fixed.returncode == 0, fixed.stderr
    assert "fixed 2 findings in 1 file" in fixed.stderr
    assert [line.split(": ")[0] for line in fixed.stdout.splitlines()] == [
        "pkg/skills/drive.py:9:9"]  # Both has a description already: not explicit, kept
    assert path.read_bytes() == FIXED.replace("\n", "\r\n").encode()  # CRLF kept
    assert not list(path.parent.glob(".*.ezmigrate"))  # atomic: no temporary file left
    again = ezmigrate(tmp_path, "check", "--diff", "pkg")  # nothing left to fix
    assert (again.returncode, again.stdout) == (0, ""), again.stderr


def test_fix_keeps_the_files_encoding(tmp_path: Path):
    text = "# -*- coding: latin-1 -*-\n" + LEGACY.replace("Linear velocity", "Geschw. in °/s")
    path = repository(tmp_path, text.encode("latin-1"))
    assert ezmigrate(tmp_path, "check", "--fix", "pkg").returncode == 0
    assert path.read_bytes() == ("# -*- coding: latin-1 -*-\n" + FIXED.replace(
        "Linear velocity", "Geschw. in °/s")).encode("latin-1")


def test_a_suppressed_finding_is_not_fixed(tmp_path: Path):
    text = LEGACY.replace('"Linear velocity")', '"Linear velocity")  # ezskiros: ignore[EZ101]')
    path = repository(tmp_path, text.encode())
    assert ezmigrate(tmp_path, "check", "--fix", "pkg").returncode == 0
    assert '"Linear velocity")  # ezskiros' in path.read_text(encoding="utf-8")
    assert 'description="rad/s"' in path.read_text(encoding="utf-8")
