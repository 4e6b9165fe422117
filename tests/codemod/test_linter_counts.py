"""Migrated code passes the linters a lab already runs (issue 43).

Labs gate pull requests on ruff or flake8 with their default rules. A migration that adds
findings fails their CI, and the fixes those tools offer can change what a skill means:
ruff's unsafe E712 fix turns ``(X.Reachable == True)`` into ``X.Reachable``. So ruff with
its default rules and flake8 with its own (pycodestyle's E and W, pyflakes' F, mccabe's C90)
read every ``fixtures/legacy`` file and the codemod's output for it, and no rule may count
more afterwards. flake8 is the stricter reader of the two: pyflakes parses every string in
an annotation as a forward reference (F722), and pycodestyle lets no ``sys.path`` change
come before an import (E402).
"""

from __future__ import annotations

import json
import subprocess
import sys
from collections import Counter
from pathlib import Path

from codemod_case import settings

from ezmigrate.codemod.migrate import migrate

LEGACY = Path(__file__).resolve().parents[2] / "fixtures" / "legacy"
DEFAULT_RULES = "E4,E7,E9,F"
"""What ``ruff check`` selects when nothing is configured (ruff's documented default)."""


def ruff_counts(folder: Path) -> Counter[str]:
    """Findings per rule code of ruff with its default rules, ignoring any configuration
    around ``folder`` (``--isolated``: this repository's own ruff settings ignore E712)."""
    proc = subprocess.run(
        [sys.executable, "-m", "ruff", "check", "--isolated", "--no-cache", "--select",
         DEFAULT_RULES, "--output-format", "json", "--exit-zero", str(folder)],
        capture_output=True, text=True, check=False, timeout=300)
    assert proc.returncode == 0, proc.stderr
    return Counter(finding["code"] or "syntax-error" for finding in json.loads(proc.stdout))


def flake8_counts(folder: Path) -> Counter[str]:
    """Findings per code of flake8 with its defaults, ignoring any configuration around
    ``folder`` (``--isolated``)."""
    proc = subprocess.run(
        [sys.executable, "-m", "flake8", "--isolated", "--exit-zero", "--format", "%(code)s",
         str(folder)], capture_output=True, text=True, check=False, timeout=300)
    assert proc.returncode == 0, proc.stderr
    return Counter(proc.stdout.split())


def write_both(target: Path) -> tuple[Path, Path]:
    """Every legacy fixture under ``target/legacy`` and its migration under
    ``target/migrated`` (the file itself when the codemod leaves it alone)."""
    before, after = target / "legacy", target / "migrated"
    before.mkdir()
    after.mkdir()
    for path in sorted(LEGACY.glob("*.py")):
        source = path.read_bytes()
        result = migrate(source, settings(), path.name)
        assert result.error is None, f"{path.name}: {result.error}"
        migrated = result.new_source if result.new_source is not None else source
        assert isinstance(migrated, bytes)
        (before / path.name).write_bytes(source)
        (after / path.name).write_bytes(migrated)
    return before, after


def test_no_ruff_default_rule_counts_more_after_the_migration(tmp_path: Path) -> None:
    before, after = write_both(tmp_path)
    old, new = ruff_counts(before), ruff_counts(after)
    worse = {code: (old[code], new[code]) for code in new if new[code] > old[code]}
    assert worse == {}, f"rule: (before, after) = {worse}; before {dict(old)}, after {dict(new)}"


def test_no_flake8_default_code_counts_more_after_the_migration(tmp_path: Path) -> None:
    before, after = write_both(tmp_path)
    old, new = flake8_counts(before), flake8_counts(after)
    assert sum(old.values()) > 0
    worse = {code: (old[code], new[code]) for code in new if new[code] > old[code]}
    assert worse == {}, f"code: (before, after) = {worse}; before {dict(old)}, after {dict(new)}"


def test_the_comparison_reads_a_real_difference(tmp_path: Path) -> None:
    """The check can fail: the comparison form ``== True`` the codemod once wrote is E712,
    and an import left unused is F401."""
    (tmp_path / "skill.py").write_text(
        "from skiros2_common.core.world_element import Element\n\n"
        "def description(F):\n    return F.Open == True\n", encoding="utf-8")
    assert ruff_counts(tmp_path) == Counter({"E712": 1, "F401": 1})


def test_every_legacy_fixture_is_compared(tmp_path: Path) -> None:
    """The migrated side really differs from the legacy one: most fixtures migrate."""
    before, after = write_both(tmp_path)
    changed = [p.name for p in sorted(before.iterdir())
               if p.read_bytes() != (after / p.name).read_bytes()]
    assert len(changed) >= 15, changed


def test_flake8_reads_what_the_codemod_once_wrote(tmp_path: Path) -> None:
    """The flake8 check can fail: the string forms inside ``KIND[...]`` are F722 and F821,
    and an import after ``sys.path.append`` is E402 (ruff lets that one pass)."""
    (tmp_path / "skill.py").write_text(
        "import sys\n"
        "sys.path.append('/opt/lab')\n"
        "from ezskiros_runtime import SkillDescription, REQUIRED, ELEMENT, DESC\n\n\n"
        "class S(SkillDescription):\n"
        "    def description(self,\n"
        "                    T: ELEMENT('scalable:Workstation'),\n"
        "                    C: REQUIRED[str, DESC('compliant|joint_config')] = ''):\n"
        "        pass\n", encoding="utf-8")
    found = flake8_counts(tmp_path)
    assert {code: found[code] for code in ("E402", "F722", "F821")} == \
        {"E402": 1, "F722": 1, "F821": 2}
    assert ruff_counts(tmp_path) == Counter()
