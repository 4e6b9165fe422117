"""``check`` loads EzSkiROS files in batches, several one after the other in one child
(``run_batched``: a fork and a cold start per batch instead of per file). A batch must say
what each file's own child says: every migrated fixture, plus files that raise, print or
exit while loading, checked with batches and one file per child, give the same findings."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

from ezmigrate.checking.pipeline import run_check
from ezmigrate.checking.run import CheckSettings
from ezmigrate.verify import pool as pool_module
from ezmigrate.verify.pool import PoolConfig
from ezskiros_runtime.ontology.load import load_index

ROOT = Path(__file__).resolve().parents[2]
MIGRATED = ROOT / "fixtures" / "migrated"
TROUBLE = {
    "raises.py": "\nraise RuntimeError('the cell configuration is missing')\n",
    "prints.py": "\nprint('loading', flush=True)\nimport sys\nprint('oops', file=sys.stderr)\n",
    "exits.py": "\nimport sys\nsys.exit(3)\n",
}


@pytest.fixture
def repo(tmp_path: Path) -> Path:
    root = tmp_path / "repo"
    (root / "pkg").mkdir(parents=True)
    base = (MIGRATED / "pick_and_place.py").read_text(encoding="utf-8")
    for path in sorted(MIGRATED.glob("*.py")):
        (root / "pkg" / path.name).write_bytes(path.read_bytes())
    for name, tail in TROUBLE.items():
        (root / "pkg" / name).write_text(base + tail, encoding="utf-8")
    subprocess.run(["git", "init", "-q", str(root)], check=True)
    return root


def test_batches_find_what_one_child_per_file_finds(repo: Path,
                                                    monkeypatch: pytest.MonkeyPatch) -> None:
    index = load_index()
    batched = run_check([repo], index, PoolConfig(workers=2), CheckSettings(compounds=False))
    monkeypatch.setattr(pool_module, "BATCH", 1)  # every file in a child of its own
    alone = run_check([repo], index, PoolConfig(workers=2), CheckSettings(compounds=False))
    assert batched.diagnostics == alone.diagnostics
    assert batched.skills == alone.skills
    said = {(Path(d.path).name, d.code) for d in batched.diagnostics}
    assert {name for name, _ in said} >= set(TROUBLE)  # each troubled file has its verdict
    assert len(batched.diagnostics) > len(TROUBLE)
