"""``check`` as one pipeline: the run object (``run.CheckRun``) passes through the stages in
order, each a module with one ``run(run)`` function.

discover → read → per-file checks → cross-file index → compound skills → world model →
judgements → keep. ``docs/architecture.md`` walks it. A stage that answers the run whole
(the outcome cache, in ``discover``) sets ``run.done`` and the rest are skipped.
"""

from __future__ import annotations

import importlib
from collections.abc import Iterable
from pathlib import Path
from types import ModuleType
from typing import TYPE_CHECKING

from .implementation_code import IMPLEMENTATION
from .run import CheckOutcome, CheckRun, CheckSettings
from .uninferable import UNINFERABLE, UNKNOWN

if TYPE_CHECKING:
    from ezskiros_runtime.ontology.index import OntologyIndex

    from ..verify.pool_config import PoolConfig

STAGES = ("discover", "read_files", "per_file", "skill_index", "compound", "world",
          "judgements", "keep")
"""The stages' modules, in the order a run passes through them: each imported when the
run reaches it (a run the cache answers ends after the first)."""


def stage(name: str) -> ModuleType:
    """The stage module ``name`` (of ``STAGES``)."""
    return importlib.import_module(f"{__package__}.{name}")


def run_check(paths: list[Path], index: OntologyIndex | None, pool: PoolConfig,
              settings: CheckSettings | None = None) -> CheckOutcome:
    """Every finding of ``paths`` against ``index`` (before selection and suppression)."""
    return check_run(paths, index, pool, settings).outcome


def check_run(paths: list[Path], index: OntologyIndex | None, pool: PoolConfig,
              settings: CheckSettings | None = None) -> CheckRun:
    """The run through every stage, with what each found (the editor's server reads the
    skill index of it), with the heap the run started with frozen (``frozen_heap``)."""
    from ..project.frozen_heap import frozen_heap

    run = CheckRun(list(paths), index, pool, settings or CheckSettings())
    try:
        with frozen_heap():
            for name in STAGES:
                stage(name).run(run)
                if run.done:
                    break
    finally:
        if run.reader is not None:
            run.reader.close()
    return run


def needs_trees(codes: Iterable[str]) -> bool:
    """Whether a selection needs the compound skills' trees and skill index: the EZ3xx
    checks, EZ105 and EZ209 (judged by what the trees pass to their children:
    ``uninferable``) and the checks inside implementations (``implementation_code``)."""
    return any(code.startswith("EZ3") or code in (UNINFERABLE, UNKNOWN, *IMPLEMENTATION)
               or code == "EZ110"  # issue 42: no-set-description, read with the trees
               for code in codes)


def scene_report(paths: tuple[Path, ...], exclude: tuple[str, ...],
                 index: OntologyIndex | None) -> list[str]:
    """The Markdown report's "Scenes" section: each scene of the run checked and drawn,
    found as ``check`` finds them (``scene_files``)."""
    from ..lint.scene_diagram import markdown_section
    from ..lint.scene_search import scene_files

    return markdown_section(scene_files(list(paths), exclude), index)
