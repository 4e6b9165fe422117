"""The README's two Markdown report examples ("Reviewing a migration") are the real output.

Both reports are generated again in temporary folders and compared, byte for byte, with
the fenced blocks of README.md: when the reports change, this test says the README must
change with them (the README is read here, never copied into the test).
"""

from __future__ import annotations

import re
from pathlib import Path

from verify_support import LEGACY, MIGRATED, ROOT, cli, edit, tree

SECTION = "## Reviewing a migration"
VERIFIER = re.compile(r"^Verified under Python \S+ \(\S+\), ontology read with rdflib \S+\.$",
                      re.M)
"""The one line that names this machine's interpreter and rdflib: compared by its form."""


def _same_report(real: str, shown: str) -> None:
    """``real`` is ``shown`` but for the versions in the verifier line, which must be there."""
    assert len(VERIFIER.findall(real)) == 1 and len(VERIFIER.findall(shown)) == 1
    assert VERIFIER.sub("V", real) == VERIFIER.sub("V", shown)


def _section() -> str:
    """The section's text, up to the next ``## `` heading outside a fenced block (the
    reports have ``## `` headings of their own)."""
    lines = (ROOT / "README.md").read_text(encoding="utf-8").splitlines(keepends=True)
    start = lines.index(SECTION + "\n")
    fence = ""  # the open fence: a report with fenced diagrams sits in a longer one
    for end in range(start + 1, len(lines)):
        ticks = re.match(r"`{3,}", lines[end])
        if ticks and not fence:
            fence = ticks.group(0)
        elif ticks and lines[end].rstrip() == fence:
            fence = ""
        if not fence and lines[end].startswith("## "):
            break
    else:
        end = len(lines)
    return "".join(lines[start:end])


def _examples() -> list[tuple[str, str]]:
    """(the prose before each ```markdown block, the block's content)."""
    section = _section()
    found = [(m.start(), m.group(2)) for m in
             re.finditer(r"^(`{3,})markdown\n(.*?)^\1$", section, re.M | re.S)]
    assert len(found) == 2, "the section should show a rewrite and a verify report"
    return [(section[:start], block) for start, block in found]


def test_the_rewrite_report_example_is_the_real_report(tmp_path):
    prose, block = _examples()[0]
    command = re.findall(r"`(ezmigrate rewrite [^`]*--report migration\.md)`", prose)[-1]
    args = command.split()[1:]
    for arg in args:  # the example files, copied: the command runs on them as the README says
        if arg.startswith("fixtures/"):
            tree((tmp_path / arg).parent, {Path(arg).name: ROOT / arg})
    run = cli(*args, cwd=tmp_path)
    assert run.returncode in (0, 1), run.stderr
    _same_report((tmp_path / "migration.md").read_text(encoding="utf-8"), block)


def test_the_verify_report_example_is_the_real_report(tmp_path):
    prose, block = _examples()[1]
    assert "`ezmigrate verify before after --report verify.md`" in prose
    assert "dropped the `~` of one condition in `pick_and_place.py`" in prose
    tree(tmp_path / "before", {"pick_and_place.py": LEGACY / "pick_and_place.py"})
    after = tree(tmp_path / "after", {"pick_and_place.py": MIGRATED / "pick_and_place.py"})
    edit(after / "pick_and_place.py", "self.pre_conditions += ~ Gripper.contain(Object)",
         "self.pre_conditions += Gripper.contain(Object)")
    run = cli("verify", "before", "after", "--report", "verify.md", cwd=tmp_path)
    assert run.returncode == 1, run.stderr
    _same_report((tmp_path / "verify.md").read_text(encoding="utf-8"), block)
