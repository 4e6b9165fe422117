"""The README is a user's guide that holds up in any clone.

It opens with exactly the two set-up-included commands (the main job on the bundled example,
then the tests), names no file the clone lacks (no ``../shared``, no numbered sections of
documents a user does not have), and every relative link in it and in ``docs/`` resolves.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
DOCUMENTS = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
LINK = re.compile(r"\]\(([^)\s]+)\)")


def test_the_readme_opens_with_the_two_commands() -> None:
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    block = re.search(r"```bash\n(.*?)```", text, re.S)
    assert block is not None and text.index("```bash") < text.index("\n## ")
    lines = block.group(1).strip().splitlines()
    assert len(lines) == 2
    assert lines[0].endswith("ezmigrate rewrite --dry-run fixtures/legacy")
    assert lines[1].endswith("python -m pytest -q -p no:cacheprovider")
    assert (ROOT / ".ci" / "run").read_text(encoding="utf-8").rstrip().endswith(
        "python -m pytest -q -p no:cacheprovider")


@pytest.mark.parametrize("document", DOCUMENTS, ids=lambda p: p.name)
def test_every_relative_link_resolves(document: Path) -> None:
    text = document.read_text(encoding="utf-8")
    for target in LINK.findall(text):
        if re.match(r"[a-z]+:", target) or target.startswith("#"):
            continue
        path = (document.parent / target.split("#")[0]).resolve()
        assert path.exists(), f"{document.name} links {target}, which does not exist"


@pytest.mark.parametrize("document", DOCUMENTS, ids=lambda p: p.name)
def test_no_reference_to_what_a_clone_does_not_have(document: Path) -> None:
    text = document.read_text(encoding="utf-8")
    assert "../shared" not in text
    assert "§" not in text
    assert "<your-org>" not in text
