"""Stage 5, compound skills: every tree of the run read (or traced under ``--trace``) and
checked against the skill index (EZ3xx), as the journal version of EzSkiROS checks the
trees built in ``expand``."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from ..lint.diagnostic import Diagnostic, Positions, from_finding
from .run import CheckRun, CheckSettings, CompoundFound

if TYPE_CHECKING:
    from ezskiros_runtime.ontology.index import OntologyIndex

    from ..files.discover import Candidate
    from ..report.results import FileResult
    from ..verify.pool_config import PoolConfig


def run(run: CheckRun) -> None:
    """Analyse the trees against the index; one finding per mistake (a traced loop adds
    the same mistake once a turn)."""
    if run.trees is None or run.skill_index is None:
        return
    from ezskiros_runtime.compound.model import CompoundModel

    from ..compound.analysis import analyse

    run.compound_run = analyse(run.read, run.skill_index, run.index, run.pool, run.library,
                               run.trees, run.around)
    found: dict[tuple[str, int, str, str], Diagnostic] = {}
    for path, finding in run.compound_run.findings:
        where = Positions(run.outcome.sources.get(path, ""))
        item = from_finding(path, where, finding)
        found.setdefault((path, item.line, item.code, item.message), item)
    run.diagnostics.extend(found.values())
    run.compound = CompoundFound([m for _, m in run.compound_run.models
                                  if isinstance(m, CompoundModel)], run.skill_index)


def compound_report(items: list[tuple[Candidate, bytes, FileResult]],
                    index: OntologyIndex | None, pool: PoolConfig,
                    settings: CheckSettings, paths: tuple[Path, ...]) -> list[str]:
    """The Markdown report's "Compound skills" section for the files of a ``rewrite``: the
    index and compound stages over them, as ``check`` runs them on the same repository."""
    from ..compound.analysis import Trees
    from ..compound.diagram import markdown_section
    from . import skill_index

    if not any(b"expand" in data for _, data, _ in items):
        return []
    report = CheckRun(list(paths), index, pool, settings)
    report.trees = Trees(named=paths, exclude=settings.exclude)
    report.read = [(c, d) for c, d, _ in items]
    report.results = [(c, r) for c, _, r in items]
    skill_index.run(report)
    run(report)
    done = report.compound_run
    return markdown_section(done.models, done.findings) if done is not None else []
