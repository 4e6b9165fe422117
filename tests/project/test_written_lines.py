"""The report's lines as the written file has them, worked out where the file was migrated
(issue 31: the main process no longer diffs and parses every migrated file after the
workers). A map made for one new source is never used for another."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

from ezmigrate.codemod.migrate import Settings, migrate
from ezmigrate.files.discover import Candidate
from ezmigrate.project.runner import migrate_all
from ezmigrate.report.written_lines import as_written, with_written_lines

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures"
SOURCE = (FIXTURES / "legacy" / "pick_and_place.py").read_bytes()


def test_the_map_from_the_worker_gives_the_lines_a_fresh_one_gives() -> None:
    result = migrate(SOURCE, Settings(), "pick_and_place.py")
    assert result.changed and result.written is None
    carried = with_written_lines(result, SOURCE)
    assert carried.written is not None
    fresh = as_written(result, SOURCE)
    assert as_written(carried, SOURCE) == replace(fresh, written=carried.written)
    moved = [s for s in fresh.skills if s.legacy_line is not None and s.line != s.legacy_line]
    assert moved  # the migration moved lines: the map is not the identity


def test_a_map_made_for_another_source_is_not_used() -> None:
    result = with_written_lines(migrate(SOURCE, Settings(), "pick_and_place.py"), SOURCE)
    assert isinstance(result.new_source, bytes)
    shifted = replace(result, new_source=b"# one more line\n" + result.new_source)
    lines = [s.line for s in as_written(shifted, SOURCE).skills]
    assert lines == [s.line + 1 for s in as_written(result, SOURCE).skills]


def test_the_workers_hand_back_results_with_their_map(tmp_path: Path) -> None:
    for name in ("a.py", "b.py"):
        (tmp_path / name).write_bytes(SOURCE)
    candidates = [Candidate(tmp_path / n, tmp_path) for n in ("a.py", "b.py")]
    items = migrate_all(candidates, None, 2, written_lines=True)
    assert all(m.result.written is not None for m in items)
    assert all(m.result.written is None for m in migrate_all(candidates, None, 2))  # check
