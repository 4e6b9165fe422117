"""The Markdown review report draws every compound skill as a Mermaid flowchart.

``rewrite --dry-run --report r.md`` on a copy of ``fixtures/compound_repo`` (real CLI, real
tracing child): a section per compound class, a diagram whose every line is a node, an edge
or a style, children in order with remaps and specifies on the edges, the nodes findings
point at highlighted, and the findings listed with their codes.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
LINE = re.compile(r'    (n\d+(\{\{"[^"]*"\}\}|\["[^"]*"\]|>"[^"]*"\])'
                  r'|n\d+ -->\|"[^"]*"\| n\d+|class n\d+ (error|warning|info)'
                  r'|classDef (error|warning|info) .*)')


def _report(tmp_path: Path) -> str:
    repo = tmp_path / "repo"
    shutil.copytree(ROOT / "fixtures" / "compound_repo", repo)
    run = subprocess.run([sys.executable, "-m", "ezmigrate", "rewrite", "--dry-run", str(repo),
                          "--report", str(tmp_path / "r.md")], capture_output=True, text=True,
                         timeout=300)
    assert run.returncode in (0, 1), run.stderr
    return (tmp_path / "r.md").read_text(encoding="utf-8")


def _diagram(report: str, implementation: str) -> list[str]:
    section = report.split(f"### `{implementation}`", 1)[1].split("\n### ", 1)[0]
    block = section.split("```mermaid\n", 1)[1].split("\n```", 1)[0]
    return block.splitlines()


def test_each_compound_skill_is_drawn_with_its_findings(tmp_path: Path) -> None:
    report = _report(tmp_path)
    section = report.split("## Compound skills", 1)[1]
    classes = re.findall(r"^class (\w+)\(SkillBase\)", "\n".join(
        p.read_text() for p in (ROOT / "fixtures" / "compound_repo").rglob("*.py")), re.M)
    assert len(classes) >= 15
    assert sorted(re.findall(r"^### `(\w+)`", section, re.M)) == sorted(classes)

    kit = _diagram(report, "kit_parts")
    assert kit[0] == "flowchart TD" and all(LINE.fullmatch(line) for line in kit[1:]), kit
    assert kit[1] == '    n0{{"kit_parts<br/>SerialStar"}}'
    edges = [line for line in kit if "-->" in line]
    assert edges[0] == '    n0 -->|"1 · Object→Found · Container→Shelf"| n1'
    assert edges[-1] == '    n0 -->|"7 · Duration=params[Pause]"| n7'
    assert not any(line.startswith("    class n") for line in kit)  # clean: nothing lit

    wrong = _diagram(report, "kit_wrong_specify")
    assert '    n0 -->|"1 · Time=2.0"| n1' in wrong and "    class n1 error" in wrong
    assert "- **EZ307** line 55: specify key 'Time'" in report

    fork = _diagram(report, "kit_fork_processor")
    assert '    n1{{"RetryOnFail(Sequential)"}}' in fork
    assert "    class n1 warning" not in fork  # EZ310 is info: the node is not coloured

    assert "tree traced by running expand" in report.split("### `kit_clear_all`")[1]
    from_world = report.split("### `kit_from_world`")[1].split("\n### ")[0]
    assert "running expand raised TypeError: expand queries the world model " \
        "(self.wmi.get_element)" in from_world  # why tracing could not read it all
    assert "```mermaid" in from_world  # and the nodes the syntax gives are drawn


def test_a_run_without_compound_skills_has_no_such_section(tmp_path: Path) -> None:
    (tmp_path / "pick.py").write_bytes((ROOT / "fixtures" / "legacy" / "conditions.py")
                                       .read_bytes())
    run = subprocess.run([sys.executable, "-m", "ezmigrate", "rewrite", "--dry-run",
                          str(tmp_path / "pick.py"), "--report", str(tmp_path / "r.md")],
                         capture_output=True, text=True, timeout=300)
    assert run.returncode in (0, 1), run.stderr
    assert "## Compound skills" not in (tmp_path / "r.md").read_text(encoding="utf-8")
