"""Orchestration of ``rewrite``: discover, migrate, verify, write. No printing happens here.

The CLI turns options into a ``RewriteOptions``, calls ``run_rewrite`` and prints what the
returned outcome says, so every decision (what is written, what is refused) is testable
without a terminal.

Writing is the only phase that touches the user's files, one ``atomic_write`` at a time,
each inside an ``interrupt.deferred`` section: a signal lets the current write finish, then
stops the run before the next one (``Interrupted`` carries what was written and what was
not). Nothing is written before every file has been migrated and verified, so a run stopped
earlier changed nothing.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING

from ..files.discover import Candidate, discover
from ..files.package_xml import ManifestRefused, packages_of, with_runtime_depend
from ..files.writing import WriteRefused, atomic_write, digest, remove_stale_temporary
from ..report.reports import Summary
from ..verify.pool_config import default_jobs
from ..verify.verdicts import Comparison
from . import holdpoint, interrupt
from .exit_codes import EXIT_ATTENTION, EXIT_OK
from .progress import Progress
from .runner import Extras, Migrated
from .settle import Checks, Settling, settle

if TYPE_CHECKING:
    from ezskiros_runtime.ontology.index import OntologyIndex

    from ..verify.pool import PoolConfig


@dataclass
class RewriteOptions:
    """Everything ``rewrite`` was asked to do."""

    paths: list[Path]
    dry_run: bool = False
    check: bool = False
    exclude: tuple[str, ...] = ()
    jobs: int = field(default_factory=default_jobs)
    output_dir: Path | None = None
    verify: bool = True
    pool: PoolConfig | None = None
    """How verification loads files: the one pool the command resolved (workers, timeout,
    the ontology files, the robot's interpreter), shared with the report's tracing; None:
    the defaults with ``jobs`` workers."""
    ignore_order: bool = False
    ignore_labels: bool = False
    project: Path | None = None
    """The folder of the ``pyproject.toml`` in use: excludes also match relative to it."""
    target: tuple[int, int] | None = None
    """The Python the migrated code must run on (``project.target``; None: the default)."""
    include_vendored: bool = False
    """Go into vendored copies of SkiROS2's own packages too (``discover``)."""
    package_xml: bool = True
    """Declare the runtime in the package.xml of each package migrated (``package_xml``)."""

    @property
    def writes(self) -> bool:
        return not (self.dry_run or self.check)

    @property
    def verification(self) -> Checks | None:
        """How ``settle`` verifies (None: ``--no-verify``)."""
        if not self.verify:
            return None
        from ..verify.pool import PoolConfig

        return Checks(self.pool or PoolConfig(workers=self.jobs),
                      Comparison(self.ignore_order, self.ignore_labels))


@dataclass
class RewriteOutcome:
    """What happened: per-file results, files written, and messages for the user."""

    migrated: list[Migrated]
    notes: list[str] = field(default_factory=list)
    written: list[str] = field(default_factory=list)
    refused: list[str] = field(default_factory=list)
    manifests: list[Manifest] = field(default_factory=list)
    """package.xml files that gain a dependency on the runtime (``<run_depend>`` or
    ``<exec_depend>``, as their format allows; written when the run writes; otherwise what
    a write would do)."""


@dataclass(frozen=True)
class Manifest:
    """A package.xml before and after the runtime is declared in it."""

    path: Path
    old: bytes
    new: bytes


def run_rewrite(options: RewriteOptions, index: OntologyIndex | None,
                on_written: Callable[[str], None] | None = None) -> RewriteOutcome:
    """Discover; settle the project (migrate, verify); write files whose skills all verified.

    Raises ``interrupt.Interrupted`` when a signal stops the run (see the module doc).
    """
    stale: list[Path] = []
    candidates, notes = discover(options.paths, options.exclude, stale=stale,
                                 include_vendored=options.include_vendored,
                                 project=options.project)
    notes += _stale_notes(stale, options.writes)
    holdpoint.reach("discovered")
    with Progress.for_stream(len(candidates)) as progress:  # gone before anything is said
        migrated = settle(candidates, index, options.jobs, Settling(
            options.verification, options.target, refuse_unloadable=True,
            extras=Extras(written_lines=True, diffs=options.dry_run)), progress)
    outcome = RewriteOutcome(migrated, notes)
    if not options.writes:
        outcome.manifests = _manifests(outcome, options)
        return outcome
    interrupt.track(outcome.written, [i.candidate.relative for i in migrated
                                      if i.result.changed])
    copies: dict[Path, Path] = {}  # --output-dir: target -> the source written there
    for item in migrated:
        content = _content(item, options.output_dir)  # a copy is read only now
        if content is None:
            continue
        target = _target(item.candidate, options.output_dir)
        if target is not None:
            first = copies.setdefault(target, item.candidate.path)
            if first != item.candidate.path:
                _refuse(item, outcome, f"{item.candidate.path}: its copy {target} would "
                        f"overwrite the copy of {first} (both are {item.candidate.relative} "
                        "under the paths given), not written; give each its own "
                        "--output-dir")
                continue
        interrupt.check()
        with interrupt.deferred():
            holdpoint.reach(f"writing:{len(outcome.written) + 1}")
            _write(item, content, options, outcome, on_written)
        holdpoint.reach(f"written:{len(outcome.written)}")
    for manifest in _manifests(outcome, options):
        interrupt.check()
        with interrupt.deferred():
            try:
                atomic_write(manifest.path, manifest.new, digest(manifest.old),
                             roots=[manifest.path.parent])
            except (WriteRefused, OSError) as error:
                outcome.refused.append(f"{manifest.path}: not written ({error})")
                continue
        outcome.manifests.append(manifest)
    return outcome


def _manifests(outcome: RewriteOutcome, options: RewriteOptions) -> list[Manifest]:
    """The package.xml of each ROS package whose files were written (or, without writing,
    would be) that does not declare the runtime yet, with the line added; one with no safe
    place for the line is named in ``outcome.refused``. Not for ``--output-dir``, whose
    copies belong to no package."""
    if not options.package_xml or options.output_dir is not None:
        return []
    written = set(outcome.written)
    files = [item.candidate.path for item in outcome.migrated if item.result.changed
             and (not options.writes or item.candidate.relative in written)]
    found = []
    for path in packages_of(files):
        old = path.read_bytes()
        try:
            new = with_runtime_depend(old)
        except ManifestRefused as error:  # said, and the file is left as it was
            outcome.refused.append(f"{path}: the runtime's dependency not added, {error}; "
                                   "left as it was")
            continue
        if new is not None:
            found.append(Manifest(path, old, new))
    return found


def _content(item: Migrated, output_dir: Path | None) -> bytes | None:
    """What to write for ``item``: the new source, or (with an output folder) a copy."""
    data = item.result.new_source if item.result.changed else None
    if output_dir is None:
        return data if isinstance(data, bytes) else None
    if item.result.error is not None and item.original == b"":
        return None  # unreadable: nothing to copy
    return data if isinstance(data, bytes) else item.original


def _stale_notes(stale: list[Path], writes: bool) -> list[str]:
    """Say what became of temporary files a killed run left; remove them only when writing.

    Removing one loses nothing (see ``writing.remove_stale_temporary``), but ``--dry-run``
    and ``--check`` promise to write nothing, so there they are only listed.
    """
    notes = []
    for path in stale:
        if not writes:
            notes.append(f"{path}: temporary file left by an interrupted run (its original "
                         "is whole); a run that writes removes it")
        elif remove_stale_temporary(path):
            notes.append(f"{path}: removed, a temporary file left by an interrupted run "
                         "(its original is whole)")
        else:
            notes.append(f"{path}: temporary file in use by another running ezmigrate, "
                         "left alone")
    return notes


def _target(candidate: Candidate, output_dir: Path | None) -> Path | None:
    return None if output_dir is None else output_dir / candidate.relative


def _write(item: Migrated, data: bytes, options: RewriteOptions, outcome: RewriteOutcome,
           on_written: Callable[[str], None] | None) -> None:
    """Write one file; a refusal becomes a message, never an exception."""
    path = item.candidate.path
    try:
        target = _target(item.candidate, options.output_dir)
        if target is None:
            atomic_write(path, data, item.digest, roots=[item.candidate.root])
        else:
            target.parent.mkdir(parents=True, exist_ok=True)
            mode = _mode_of(path)
            atomic_write(target, data, None, roots=[options.output_dir or target.parent],
                         create=True, mode=mode)
    except WriteRefused as refused:
        _refuse(item, outcome, str(refused))
        return
    except OSError as error:  # e.g. the output folder cannot be made
        _refuse(item, outcome, f"{path}: not written ({error.strerror or error}), left as it "
                               "was")
        return
    if item.result.changed:
        outcome.written.append(item.candidate.relative)
        if on_written is not None:
            on_written(item.candidate.relative)


def _refuse(item: Migrated, outcome: RewriteOutcome, message: str) -> None:
    """The file keeps its content: say why, and report its skills as not migrated.

    A skill proven equivalent but left unwritten is still a legacy skill on disk: the report
    and the exit code must say so, not "converted".
    """
    outcome.refused.append(message)
    result = item.result
    skills = [replace(s, status="failed", reason=f"not written: {message}")
              if result.changed and s.status == "converted" else s for s in result.skills]
    item.result = replace(result, notes=[*result.notes, message], skills=skills,
                          new_source=None)


def _mode_of(path: Path) -> int | None:
    try:
        return path.stat().st_mode & 0o7777
    except OSError:
        return None


def exit_code(summary: Summary, check: bool, strict: bool, refused: Sequence[str]) -> int:
    """The exit code every ``rewrite`` ends with, as black's: 1 when ``--check`` found
    changes, a verification failed, a file could not be processed or written (with
    ``--strict`` also a skipped skill), else 0. Pure: the command line only exits with it."""
    would_change = summary.changed_files > 0 and check
    return EXIT_ATTENTION if would_change or summary.needs_attention(strict) or refused \
        else EXIT_OK
