"""Files of the same bytes are read once (``ReadingPool.read_files``, issue 31): a lab's
workspace keeps a fork beside its upstream, or a vendored copy of a package, and the copy's
facts are the first file's moved to its path (``FileFacts.moved``).

That moving is exact is checked on every Python file of the fixtures, read at two places
of different names: the facts read there are, field for field (``repr`` shows the
``CompoundModel.path`` that equality leaves out), the first place's moved. That a run
reads each content once is observed in every process (``process_log``), and its findings
are those of a run where the copies differ (a comment appended to each), which reads
them all.
"""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest
from bench_generator import generator
from process_log import log_calls, logged

from ezmigrate.checking import reading_pool
from ezmigrate.checking.file_facts import file_facts
from ezmigrate.checking.pipeline import run_check
from ezmigrate.compound.analysis import TreeFacts
from ezmigrate.files.discover import Candidate
from ezmigrate.files.prefilter import by_text
from ezmigrate.lint.plain_reader import Declined
from ezmigrate.report.results import FileResult
from ezmigrate.verify.pool import PoolConfig
from ezskiros_runtime.compound.model import CompoundModel
from ezskiros_runtime.ontology.index import bundled_ontology_path
from ezskiros_runtime.ontology.load import load_index

ROOT = Path(__file__).resolve().parents[2]
FIXTURES = sorted(p for p in (ROOT / "fixtures").rglob("*.py") if p.is_file())
INDEX = load_index([bundled_ontology_path()])


def _placed(data: bytes, root: Path, relative: str) -> Candidate:
    path = root / relative
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(data)
    return Candidate(path, root)


def test_a_copy_reads_as_the_first_file_moved(tmp_path: Path) -> None:
    moved_trees = moved_results = 0
    for fixture in FIXTURES:
        data = fixture.read_bytes()
        first = _placed(data, tmp_path / "upstream", "src/skills/module.py")
        copy = _placed(data, tmp_path / "fork", "pkg/src/other_name.py")
        verdict = by_text(data)
        read = file_facts(first, data, True, verdict)
        assert repr(file_facts(copy, data, True, verdict)) == repr(read.moved(copy)), fixture
        moved_trees += isinstance(read.trees, TreeFacts) and any(
            isinstance(f, CompoundModel) for f in read.trees.found)
        moved_results += isinstance(read.static, FileResult) and bool(read.static.skills)
    assert len(FIXTURES) > 50 and moved_trees >= 5 and moved_results >= 20


def _with_a_tree(root: Path) -> tuple[bytes, Candidate]:
    """A fixture with a compound tree its syntax gives, and a description, at ``root``."""
    for fixture in FIXTURES:
        data = fixture.read_bytes()
        first = _placed(data, root, "x.py")
        read = file_facts(first, data, True, by_text(data))
        if isinstance(read.static, FileResult) and read.static.skills and read.trees \
                and any(isinstance(f, CompoundModel) for f in read.trees.found):
            return data, first
    raise AssertionError("no fixture has both a description and a tree read statically")


def test_moving_changes_the_paths_and_nothing_else(tmp_path: Path) -> None:
    data, first = _with_a_tree(tmp_path / "a")
    copy = _placed(data, tmp_path / "b", "y/z.py")
    read = file_facts(first, data, True, by_text(data))
    moved = read.moved(copy)
    assert isinstance(moved.static, FileResult) and moved.static.path == "y/z.py"
    assert isinstance(read.static, FileResult) and read.static.path == "x.py"
    assert moved.trees is not None
    models = [f for f in moved.trees.found if isinstance(f, CompoundModel)]
    assert models and all(m.path == str(copy.path) for m in models)
    assert repr(moved.moved(first)) == repr(read)  # moved back: the very facts read


@pytest.fixture
def workspace(tmp_path: Path) -> Path:
    """A lab's workspace: its packages (the compound skills fixture, and a generated
    repository large enough for the reading pool's workers), and a fork of them beside."""
    root = tmp_path / "ws"
    shutil.copytree(ROOT / "fixtures" / "compound_repo", root / "upstream" / "compound")
    generator().generate(root / "upstream" / "generated", 40, skill_share=1.0, seed=5,
                         messy_share=0.3)
    shutil.copytree(root / "upstream", root / "fork")
    subprocess.run(["git", "init", "-q", str(root)], check=True)
    return root


def _findings(paths: list[Path], workers: int) -> list[str]:
    return [str(d) for d in run_check(paths, INDEX, PoolConfig(workers=workers)).diagnostics]


@pytest.mark.parametrize("workers", [1, 2])
def test_a_workspace_reads_each_content_once(workspace: Path, tmp_path: Path,
                                             monkeypatch: pytest.MonkeyPatch,
                                             workers: int) -> None:
    log = tmp_path / "read.log"
    log_calls(monkeypatch, reading_pool, "file_facts", log,
              lambda candidate, *_: candidate.relative)
    both = _findings([workspace], workers)
    read = logged(log)
    assert len(read) >= reading_pool.SHARED_FROM and len(read) == len(set(read))
    again = [name for name in read if name.startswith("upstream/")]
    assert len(read) - 2 * len(again) >= 20  # the fork's files read, less those read again:
    for name in again:  # each content read once but for the codemod's, which are not moved
        data = (workspace / name).read_bytes()
        facts = file_facts(Candidate(workspace / name, workspace), data, True, by_text(data))
        assert isinstance(facts.static, Declined)
    for copy in (workspace / "fork").rglob("*.py"):  # the fork's own bytes: all read
        copy.write_bytes(copy.read_bytes() + b"\n# the fork's\n")
    log.unlink()
    apart = _findings([workspace], workers)
    assert len(logged(log)) == 2 * (len(read) - len(again))
    assert both == apart and sum("/fork/" in line for line in both) >= 5
