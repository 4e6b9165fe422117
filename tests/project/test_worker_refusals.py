"""``rewrite --no-verify``'s refusals (the runtime's early checks on each converted skill)
are worked out in the workers that migrated the file (issue 31): the main process takes
them from the result, and gives the verdicts it gave when it worked them out itself."""

from __future__ import annotations

from pathlib import Path

from ezmigrate.codemod.settings import Settings
from ezmigrate.files.discover import Candidate
from ezmigrate.project.refusals import static_rejections
from ezmigrate.project.runner import Extras, migrate_all
from ezmigrate.project.static_refusal import refuse_statically
from ezskiros_runtime.ontology.index import bundled_ontology_path
from ezskiros_runtime.ontology.load import load_index

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures"
INDEX = load_index([bundled_ontology_path(), FIXTURES / "ontology" / "paper_axioms.ttl"])
REJECTED = (FIXTURES / "rejected" / "type_errors.py").read_bytes()
FINE = (FIXTURES / "legacy" / "pick_and_place.py").read_bytes()


def _migrated(tmp_path: Path, jobs: int, refusals: bool):  # type: ignore[no-untyped-def]
    tmp_path.mkdir(parents=True, exist_ok=True)
    for name, data in (("a_rejected.py", REJECTED), ("b_fine.py", FINE)):
        (tmp_path / name).write_bytes(data)
    candidates = [Candidate(tmp_path / n, tmp_path) for n in ("a_rejected.py", "b_fine.py")]
    return migrate_all(candidates, INDEX, jobs, extras=Extras(refusals=refusals))


def test_the_workers_refusals_are_those_worked_out_here(tmp_path: Path) -> None:
    items = _migrated(tmp_path, 2, refusals=True)
    for item in items:
        assert item.result.refusals is not None
        assert item.result.refusals == {
            s.name: why for s in item.result.skills
            if (why := static_rejections(s, item.candidate.relative, INDEX))}
    assert set(items[0].result.refusals or {}) == {"HandOver", "CheckTool", "MountCamera"}
    assert items[1].result.refusals == {}


def test_holding_back_gives_the_same_verdicts_either_way(tmp_path: Path) -> None:
    carried = _migrated(tmp_path / "a", 2, refusals=True)
    worked_here = _migrated(tmp_path / "b", 2, refusals=False)
    assert all(m.result.refusals is None for m in worked_here)
    for items in (carried, worked_here):
        for item in items:
            item.settings = item.settings or Settings(index=INDEX)
        refuse_statically(items, INDEX)
    for one, other in zip(carried, worked_here, strict=True):
        assert [(s.name, s.status, s.reason) for s in one.result.skills] == \
            [(s.name, s.status, s.reason) for s in other.result.skills]
        assert one.result.new_source == other.result.new_source
    assert {s.status for s in carried[0].result.skills} == {"skipped"}
