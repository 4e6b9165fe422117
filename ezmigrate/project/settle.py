"""One owner for a migration: migrate, derive cross-file facts, verify, hold back, repeat.

Every command that migrates goes through ``settle``: ``rewrite PATH`` (then writes what
settled), ``rewrite -`` (a project of one file), and ``check`` for the legacy files its fast
reader declines (without verification). A round:

1. migrate every file that needs it, in parallel workers (``runner``);
2. derive the facts that cross files (``cross_file``): names sibling files import from a
   migrated one keep their legacy imports, bases defined in sibling files are inlined;
   files whose facts changed are migrated again, until the facts are stable;
3. verify the files that changed (both versions loaded in the sandbox, ``verify``);
4. hold back the classes that did not verify and migrate their files again without them,
   with every file whose classes derive from one of those; back to 3.

Rounds are bounded: a file still changing after the last one is not written.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

from ..codemod.settings import Settings
from ..files.discover import Candidate
from ..report.results import FileResult
from ..verify.verdicts import Comparison, apply_verdicts
from . import holdpoint
from .cross_file import imported_from, resolve_cross_file
from .holding import hold_back, not_written
from .progress import Progress
from .runner import NO_EXTRAS, Extras, Migrated, migrate_all
from .static_refusal import refuse_statically

if TYPE_CHECKING:
    from ezskiros_runtime.ontology.index import OntologyIndex

    from ..verify.pool import PoolConfig

VERIFY_ROUNDS = 3
"""Rounds of holding refused classes back and verifying the rest of their files again."""


@dataclass(frozen=True)
class Checks:
    """How the project verifies what it migrated: the sandbox's settings and how strictly
    models must agree."""

    pool: PoolConfig
    comparison: Comparison = field(default_factory=Comparison)


@dataclass(frozen=True)
class Settling:
    """How a command settles its project, beyond its files, ontology and workers: decided
    by the command in one place and passed to ``settle`` as one argument."""

    checks: Checks | None = None
    """How what changed is verified; None: not at all (``--no-verify``, ``check``)."""
    target: tuple[int, int] | None = None
    """The Python the migrated code must run on (None: the default, ``Settings.target``)."""
    refuse_unloadable: bool = False
    """Without verification, hold back what the runtime's early checks refuse
    (``static_refusal``; ``rewrite --no-verify`` writes, ``check`` only reads)."""
    extras: Extras = NO_EXTRAS
    """What the workers add to each result for the report and the output
    (``runner.Extras``; ``settle`` asks for the refusals itself, with
    ``refuse_unloadable``)."""


MIGRATE_ONLY = Settling()
"""Migrate for the default target, verify and refuse nothing, add nothing (``check``)."""


def settle(candidates: Sequence[Candidate], index: OntologyIndex | None, jobs: int,
           how: Settling = MIGRATE_ONLY, progress: Progress | None = None, *,
           read: Sequence[Migrated] = (),
           known: Mapping[str, tuple[bytes, FileResult]] | None = None) -> list[Migrated]:
    """Every candidate's settled result (see the module doc), settled as ``how`` says.

    ``read``: files of the same package already read by other means (``check``'s plain
    reader, or its cache), not migrated here and not returned: only the cross-file pass
    sees them, as files that define bases for the candidates. Their readings are final
    (``exported`` only decides the imports a rewrite keeps, which ``check`` never
    writes). ``known``: files already migrated alone (``migrate_all``)."""
    extras = how.extras
    if how.refuse_unloadable and how.checks is None:
        extras = replace(extras, refusals=True)
    migrated = migrate_all(candidates, index, jobs, progress, how.target, extras, known)
    base = Settings(index=index) if how.target is None else Settings(index=index,
                                                                     target=how.target)
    _settle_cross_file(migrated, base, read)
    if progress is not None:
        progress.close()  # the line is gone before verification says anything
    holdpoint.reach("migrated")
    if how.checks is not None:
        verify_changed(migrated, how.checks)
    elif how.refuse_unloadable:
        refuse_statically(migrated, index)
    return migrated


def _settle_cross_file(migrated: list[Migrated], base: Settings,
                       read: Sequence[Migrated] = ()) -> None:
    """Migrate again the files whose cross-file facts are not those they were migrated
    with: names other files import from them, and bases defined in sibling files. ``read``:
    files settled already, which the others may derive from (never migrated again)."""
    everything = [*migrated, *read] if read else migrated
    exported = imported_from(everything)
    for item in migrated:
        names = exported.get(item.candidate.relative)
        if names and item.result.changed:
            from ..codemod.migrate import migrate  # libcst: in the main process only now

            item.settings = replace(base, exported=names)
            item.result = migrate(item.original, item.settings, item.candidate.relative)
    if any(m.result.foreign_bases for m in migrated):
        resolve_cross_file(everything, base, exported, settled=read)


def verify_changed(migrated: list[Migrated], checks: Checks) -> None:
    """Verify every changed file; revert (in memory) what does not verify.

    A class that fails (or that the runtime would refuse to load) is held as it was and its
    file is migrated again without it, so the classes beside it that verified still land.
    Files whose descriptions derive from a file migrated again are verified again with it.
    """
    from ..verify.pool import BATCH, job_for, run_batched

    changed = [item for item in migrated if item.result.changed]
    if not changed:
        return
    by_relative = {item.candidate.relative: item for item in changed}
    pending = list(changed)
    for _ in range(VERIFY_ROUNDS):
        jobs = []
        for item in pending:
            assert isinstance(item.result.new_source, bytes)
            root = item.candidate.root
            jobs.append(job_for(item.candidate.path, item.original, root))
            after = job_for(item.candidate.path, item.result.new_source, root)
            after.overlays = _overlays(item, by_relative)
            jobs.append(after)
        outcomes = run_batched(jobs, checks.pool, BATCH, alone=lambda found: not found.loaded)
        again = []
        for number, item in enumerate(pending):
            item.result, culprits = apply_verdicts(item.result, outcomes[2 * number],
                                                   outcomes[2 * number + 1],
                                                   checks.comparison)
            if culprits and hold_back(item, culprits):
                again.append(item)
        redone = {item.candidate.relative for item in again}
        again += [item for item in changed if item not in again and item.result.changed
                  and redone & set(item.result.depends_on)]
        if not again:
            break
        pending = again
    else:  # still unsettled after the last round: write none of it
        for item in pending:
            item.result = not_written(item.result, "not verified: its file changed in "
                                       "every verification round")
    _hold_dependents(changed, by_relative)


def _overlays(item: Migrated, by_relative: dict[str, Migrated]) -> dict[str, bytes]:
    """Migrated bytes of the files whose descriptions ``item``'s classes derive from."""
    overlays = {}
    for relative in item.result.depends_on:
        base = by_relative.get(relative)
        if base is not None and isinstance(base.result.new_source, bytes):
            overlays[str(base.candidate.path.absolute())] = base.result.new_source
    return overlays


def _hold_dependents(migrated: list[Migrated], by_relative: dict[str, Migrated]) -> None:
    """A file deriving from a base file that will not be written is not written either."""
    changed = True
    while changed:
        changed = False
        for item in migrated:
            if item.result.new_source is None:
                continue
            held = [r for r in item.result.depends_on
                    if r in by_relative and by_relative[r].result.new_source is None]
            if held:
                item.result = not_written(item.result, "not written: it derives from a "
                                           f"description in {held[0]}, which is not being "
                                           "written")
                changed = True
