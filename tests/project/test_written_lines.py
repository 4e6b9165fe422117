"""The report's lines as the written file has them, worked out where the file was migrated
(issue 31: the main process no longer diffs and parses every migrated file after the
workers). A map made for one new source is never used for another."""

from __future__ import annotations

import difflib
import random
from dataclasses import replace
from pathlib import Path

from ezmigrate.codemod.migrate import Settings, migrate
from ezmigrate.files.discover import Candidate
from ezmigrate.project.runner import Extras, migrate_all
from ezmigrate.report.diffs import decode, unified_diff
from ezmigrate.report.written_lines import as_written, with_written_lines, written_diff

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
    items = migrate_all(candidates, None, 2, extras=Extras(written_lines=True))
    assert all(m.result.written is not None for m in items)
    assert all(m.result.written is None for m in migrate_all(candidates, None, 2))  # check


def test_the_diff_made_in_the_worker_is_the_diff_made_here(tmp_path: Path) -> None:
    (tmp_path / "a.py").write_bytes(SOURCE)
    [item] = migrate_all([Candidate(tmp_path / "a.py", tmp_path)], None, 1,
                         extras=Extras(written_lines=True, diffs=True))
    assert isinstance(item.result.new_source, bytes)
    carried = written_diff(item.result)
    assert carried is not None
    assert unified_diff("a.py", SOURCE, item.result.new_source, carried) == \
        unified_diff("a.py", SOURCE, item.result.new_source)
    other = replace(item.result, new_source=item.result.new_source + b"# more\n")
    assert written_diff(other) is None  # made for another source: not used


def test_a_diff_is_its_two_file_lines_and_its_hunks() -> None:
    """``unified_diff`` is ``difflib``'s, whatever the line endings; no change, no diff."""
    chance = random.Random(5)
    pieces = ["x\n", "y\n", "z", "\r\n", "w\r\n", "q"]
    for _ in range(2000):
        before = "".join(chance.choice(pieces) for _ in range(chance.randint(0, 12))).encode()
        after = "".join(chance.choice(pieces) for _ in range(chance.randint(0, 12))).encode()
        old = decode(before).splitlines(keepends=True)
        new = decode(after).splitlines(keepends=True)
        expected = "".join(
            line if line.endswith("\n") else line + "\n\\ No newline at end of file\n"
            for line in difflib.unified_diff(old, new, fromfile="a/p.py", tofile="b/p.py"))
        assert unified_diff("p.py", before, after) == expected


def test_the_classes_are_those_the_migrations_own_check_parsed(monkeypatch) -> None:
    """The written file's classes come from the parse that checked the migrated code
    (``FileResult.new_classes``), not from a second parse; they are the classes a fresh
    parse finds, on every legacy fixture; for another source they are not used."""
    from ezmigrate.report import written_lines

    compared = 0
    for path in sorted((FIXTURES / "legacy").glob("*.py")):
        original = path.read_bytes()
        result = migrate(original, Settings(), path.name)
        if not result.changed:
            continue
        assert isinstance(result.new_source, bytes) and result.new_classes is not None
        fresh = written_lines._class_lines(decode(result.new_source))
        assert result.new_classes.classes == fresh and fresh
        compared += 1
    assert compared >= 5

    parsed: list[str] = []
    real = written_lines._class_lines

    def counted(after: str) -> dict[str, int]:
        parsed.append(after)
        return real(after)

    monkeypatch.setattr(written_lines, "_class_lines", counted)
    result = migrate(SOURCE, Settings(), "pick_and_place.py")
    assert with_written_lines(result, SOURCE).written is not None and parsed == []
    assert isinstance(result.new_source, bytes)
    shifted = replace(result, new_source=b"# one more line\n" + result.new_source)
    with_written_lines(shifted, SOURCE)
    assert len(parsed) == 1  # made for another source: parsed again
