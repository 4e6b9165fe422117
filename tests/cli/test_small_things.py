"""Small things a user notices (issue 22, item 12), each through the real command line."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures"


def ezmigrate(cwd: Path, *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "ezmigrate", *args], cwd=cwd,
                          capture_output=True, text=True, stdin=subprocess.DEVNULL,
                          timeout=300, check=False)


def test_a_gitignored_file_named_explicitly_is_skipped_with_a_word(tmp_path: Path):
    subprocess.run(["git", "init", "-q", str(tmp_path)], check=True)
    (tmp_path / "pkg").mkdir()
    legacy = (FIXTURES / "legacy" / "pick_and_place.py").read_bytes()
    (tmp_path / "pkg" / "generated.py").write_bytes(legacy)
    (tmp_path / ".gitignore").write_text("pkg/generated.py\n", encoding="utf-8")
    for command in (("rewrite", "--no-verify"), ("check",)):
        run = ezmigrate(tmp_path, *command, "pkg/generated.py")
        assert run.returncode == 0, run.stderr
        assert "ezmigrate: pkg/generated.py: skipped, git ignores it (.gitignore)\n" \
            in run.stderr, command
    assert (tmp_path / "pkg" / "generated.py").read_bytes() == legacy
