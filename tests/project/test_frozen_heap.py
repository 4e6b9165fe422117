"""``check`` reads a repository with the heap it started with frozen out of the collector's
reach (``gc.freeze``: full collections set off by the syntax trees it allocates need not
walk the imported modules again), and thaws it when the run ends, however it ends: a
process running many checks (these tests, an editor's server) must still collect what a
run left behind."""

from __future__ import annotations

import gc
from pathlib import Path

import pytest

from ezmigrate.checking import reading_pool
from ezmigrate.checking.pipeline import run_check
from ezmigrate.verify.pool import PoolConfig

LEGACY = """\
from skiros2_skill.core.skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


class Pick(SkillDescription):
    def createDescription(self):
        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)
"""


def _watch(monkeypatch: pytest.MonkeyPatch, seen: list[int], fail: bool = False) -> None:
    """Note the frozen count while the files are read (and fail there, if asked)."""
    real = reading_pool.ReadingPool.read_files

    def noted(self: reading_pool.ReadingPool, *args: object) -> object:
        seen.append(gc.get_freeze_count())
        if fail:
            raise RuntimeError("a bug of ours while reading")
        return real(self, *args)  # type: ignore[arg-type]

    monkeypatch.setattr(reading_pool.ReadingPool, "read_files", noted)


def test_the_heap_is_frozen_while_reading_and_thawed_after(tmp_path: Path, monkeypatch):
    (tmp_path / "pick.py").write_text(LEGACY, encoding="utf-8")
    gc.unfreeze()
    seen: list[int] = []
    _watch(monkeypatch, seen)
    outcome = run_check([tmp_path], None, PoolConfig(workers=1))
    assert outcome.skills == 1
    assert seen and seen[0] > 0
    assert gc.get_freeze_count() == 0


def test_a_run_that_fails_thaws_the_heap_too(tmp_path: Path, monkeypatch):
    (tmp_path / "pick.py").write_text(LEGACY, encoding="utf-8")
    gc.unfreeze()
    seen: list[int] = []
    _watch(monkeypatch, seen, fail=True)
    with pytest.raises(RuntimeError, match="a bug of ours"):
        run_check([tmp_path], None, PoolConfig(workers=1))
    assert seen and seen[0] > 0
    assert gc.get_freeze_count() == 0


def test_rewrite_workers_fork_from_a_frozen_heap_thawed_after(tmp_path: Path, monkeypatch):
    """``migrate_all`` freezes before its pool forks (the workers inherit the frozen heap)
    and thaws when the pool is gone."""
    from ezmigrate.files.discover import discover
    from ezmigrate.project import runner

    for name in ("a", "b", "c"):
        (tmp_path / f"{name}.py").write_text(LEGACY.replace("Pick", f"Pick{name}"),
                                             encoding="utf-8")
    gc.unfreeze()
    seen: list[int] = []
    real = runner._Workers._submit

    def noted(self: runner._Workers, *args: object) -> None:
        seen.append(gc.get_freeze_count())
        real(self, *args)  # type: ignore[arg-type]

    monkeypatch.setattr(runner._Workers, "_submit", noted)
    done = runner.migrate_all(discover([tmp_path])[0], None, jobs=2)
    assert sorted(s.name for m in done for s in m.result.skills) == ["Picka", "Pickb", "Pickc"]
    assert seen and all(count > 0 for count in seen)
    assert gc.get_freeze_count() == 0


def test_an_inner_freeze_leaves_the_outer_one_to_thaw():
    from ezmigrate.project.frozen_heap import frozen_heap

    gc.unfreeze()
    with frozen_heap():
        outer = gc.get_freeze_count()
        with frozen_heap():
            pass
        assert gc.get_freeze_count() >= outer > 0
    assert gc.get_freeze_count() == 0
