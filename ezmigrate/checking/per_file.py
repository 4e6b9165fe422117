"""Stage 3, per-file checks: what each file says on its own.

A legacy description gets the runtime's early checks on what the read stage found it to
declare, and the checks only legacy code needs (``lint/legacy.py``). An EzSkiROS file is
read from its syntax (``lint/ezskiros_static``: no code of the repository runs), or under
``--trace`` loaded in the sandbox (``verify``), and reports the runtime's own findings.
Every finding gets its catalogue code (``ezskiros_runtime.codes``); selection and
suppression come later (``lint/select.py``), so every stage reports everything.
"""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path
from typing import TYPE_CHECKING

from ..lint.diagnostic import Diagnostic, Positions, check_finding, from_finding
from ..report.results import FileResult
from .run import CheckRun

if TYPE_CHECKING:
    from ezskiros_runtime.ontology.index import OntologyIndex

    from ..cache.facts_cache import FactsCache
    from ..verify.protocol import LoadOutcome

UNRESOLVED_LOAD = frozenset({"timeout", "memory", "crashed"})
"""Loads that failed on the sandbox's limits, not on the module: nothing is known of it."""
KEPT_FROM_CODEMOD = frozenset({"description-in-options", "options-ignored"})
"""Codemod findings ``check`` keeps; the others are found again by the runtime's checks."""


def legacy_diagnostics(path: str, result: FileResult, positions: Positions,
                       index: OntologyIndex | None, libraries: Iterable[str] = ()
                       ) -> list[Diagnostic]:
    """The findings of one file's legacy descriptions, as the read stage found them
    (``libraries``: the launch file's ``libraries_list``)."""
    from ..lint.legacy import legacy_hits  # a run its cache answers needs none of this

    found: list[Diagnostic] = []
    if result.error:
        message, severity = result.error.splitlines()[0], None
        if result.error_kind == "unreadable":  # issue 42: EZ905 by where the file lives
            from ..lint.skill_library import unreadable_severity

            severity, message = unreadable_severity(path, message, result.python2,
                                                    libraries)
        found.append(from_finding(path, positions, check_finding(
            result.error_kind, result.error_line or 0, message, lowered=severity == "info")))
    for skill in result.skills:
        if skill.status == "converted":
            found.append(from_finding(path, positions, check_finding(
                "not-migrated", skill.line, "legacy description not migrated yet (run "
                "`ezmigrate rewrite`)", skill.name)))
            found += [from_finding(path, positions, f, f.line or skill.line)
                      for f in skill.findings if f.kind in KEPT_FROM_CODEMOD]
            if skill.static is not None:
                found += [from_finding(path, positions, hit, hit.line or skill.line,
                                       lowered=False)
                          for hit in legacy_hits(skill.name, path, skill.static, index)]
        elif skill.status == "skipped":
            reason = (skill.reason or "").splitlines()[0] if skill.reason else ""
            found.append(from_finding(path, positions, check_finding(
                "kept-legacy", skill.line, f"legacy description kept, not checked: {reason}",
                skill.name)))
    return found


def read_ezskiros(files: list[tuple[Path, bytes]], index: OntologyIndex | None,
                  cache: FactsCache | None = None) -> list[LoadOutcome]:
    """What loading each EzSkiROS file would give, read from its syntax against ``index``
    (``lint/ezskiros_static``): ``check`` runs no code of the repository unless told
    (``--trace``). ``cache`` keeps each reading by the ontology's fingerprint and the
    file's path and bytes (a reading depends on nothing else: no import is followed)."""
    from ezskiros_runtime.ontology import use_ontology

    from ..lint.ezskiros_static import read_ezskiros_statically
    from ..verify.protocol import LoadOutcome
    from .file_facts import parse, respelt

    if index is not None and files:
        use_ontology(index)  # the ontology the runtime's checks look names up in
    fingerprint = index.fingerprint if index is not None else ""
    outcomes = []
    for path, data in files:
        key = None if cache is None else cache.key("ezskiros", fingerprint, str(path), data)
        found = None if cache is None or key is None else cache.get(key)
        if isinstance(found, LoadOutcome):
            outcomes.append(found)
            continue
        tree = parse(data) or respelt(data)
        outcomes.append(LoadOutcome("ok") if tree is None  # the read stage said why
                        else read_ezskiros_statically(tree, str(path)).outcome())
        if cache is not None and key is not None:
            cache.put(key, outcomes[-1])
    return outcomes


def _loaded(run: CheckRun) -> list[LoadOutcome]:
    """The EzSkiROS files loaded in the sandbox (``--trace``), each load kept by the file
    and every file it opened (``load_cache``)."""
    from ..cache.load_cache import LoadCache, cached_loads
    from ..verify.pool import BATCH, job_for, run_batched

    if run.loadable:
        run.say(f"loading {len(run.loadable)} EzSkiROS files")
    cache_dir, pool = run.settings.cache_dir, run.pool
    cache = None if cache_dir is None else LoadCache.for_run(
        cache_dir, [(str(c.path), data) for c, data in run.read],
        run.index.fingerprint if run.index is not None else "", pool.python)
    return cached_loads([job_for(c.path, None, c.root) for c in run.loadable],
                        run.loadable_data(),
                        lambda jobs: run_batched(jobs, pool, BATCH,
                                                 alone=lambda found: not found.loaded),
                        cache)


def _load_diagnostics(run: CheckRun) -> list[Diagnostic]:
    """The findings of the EzSkiROS files as read (or loaded)."""
    found: list[Diagnostic] = []
    # a legacy class the read stage kept (EZ902) in a file that is loaded because another
    # class in it was migrated: its findings are the read stage's, as before the migration
    kept = {(str(c.path), s.name) for c, r in run.results for s in r.skills
            if s.status == "skipped"}
    for candidate, loaded in zip(run.loadable, run.loads, strict=True):
        path = str(candidate.path)
        where = Positions(run.outcome.sources[path])
        if not loaded.loaded:
            found.append(from_finding(path, where, check_finding(
                "unloadable", loaded.line or 0, f"{loaded.status}: {loaded.message}",
                lowered=loaded.status in UNRESOLVED_LOAD)))
            continue
        run.outcome.skills += len(loaded.models)
        found += [from_finding(path, where, check_finding(
                      "not-read-statically", line, "description not read without running "
                      f"the module: {shape}; it is not checked (check --trace loads it in "
                      "the sandbox)", name))
                  for name, line, shape in loaded.unread if shape]
        found += [from_finding(path, where, error) for error in loaded.errors
                  if (path, error.skill) not in kept]
        found += [from_finding(path, where, f) for f in loaded.findings]
    return found


def run(run: CheckRun) -> None:
    """Each file's own findings: its legacy descriptions', then its EzSkiROS ones'."""
    launch = run.settings.launch  # issue 42: its libraries_list decides EZ905's severity
    libraries = (launch.listed("libraries_list") if launch is not None else None) or ()
    for candidate, result in run.results:
        if result.error or result.skills:
            path = str(candidate.path)
            run.diagnostics.extend(legacy_diagnostics(
                path, result, Positions(run.outcome.sources[path]), run.index, libraries))
    if run.settings.trace:
        run.loads = _loaded(run)
    else:
        unread = [(c.path, data) for c, data in zip(run.loadable, run.loadable_data(),
                                                     strict=True)
                  if c.path not in run.static_loads]  # a copy, or Python 3.12 syntax
        read = iter(read_ezskiros(unread, run.index, run.facts_cache))
        run.loads = [run.static_loads.get(c.path) or next(read) for c in run.loadable]
    run.outcome.read = sorted({path for loaded in run.loads for path in loaded.read})
    run.diagnostics.extend(_load_diagnostics(run))
