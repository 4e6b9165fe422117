"""The one object a ``check`` passes through its stages (``pipeline.STAGES``).

Why one object: every stage reads what earlier stages found and adds its own, so the
stages take the run and nothing else; nothing is threaded through as a parameter or a
callback, and a new stage is a module with one ``run(run)`` function. ``CheckSettings``
is what the caller decides; ``CheckOutcome`` is what the caller gets back.
"""

from __future__ import annotations

import sys
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

from ..files.discover import Candidate, Discovery
from ..lint.diagnostic import Diagnostic
from ..lint.scene_search import WorldRun

if TYPE_CHECKING:
    from ezskiros_runtime.compound.library import SkillIndex
    from ezskiros_runtime.compound.model import CompoundModel
    from ezskiros_runtime.ontology.config import SettledSource
    from ezskiros_runtime.ontology.index import OntologyIndex

    from ..cache.facts_cache import FactsCache
    from ..checking.launch import Launch
    from ..checking.reading_pool import ReadingPool
    from ..compound.analysis import CompoundRun, Trees
    from ..compound.repository import RepositoryScan
    from ..report.results import FileResult
    from ..verify.pool_config import PoolConfig
    from ..verify.protocol import LoadOutcome
    from .implementation_code import ModuleFacts


@dataclass
class Memo:
    """What a caller that checks again and again (the editor's server) keeps between runs:
    the repository around a named file, scanned once until the caller says a file was
    saved (``clear``). ``check`` runs once and keeps none."""

    repository: dict[tuple[str, ...], RepositoryScan] = field(default_factory=dict)

    def clear(self) -> None:
        self.repository.clear()


@dataclass(frozen=True)
class CheckSettings:
    """How a run is set up, beyond its paths, ontology and workers."""

    exclude: tuple[str, ...] = ()
    include_vendored: bool = False
    skill_libraries: tuple[Path, ...] = ()
    """``[tool.ezmigrate] skill-libraries``: their descriptions join the skill index."""
    compounds: bool = True
    """False when no selected code needs the trees (``pipeline.needs_trees``)."""
    trace: bool = False
    """``--trace``: load EzSkiROS files and trace trees in the sandbox; else no user code
    runs."""
    cache_dir: Path | None = None
    """The project's cache folder (``cache.cache_folder``); None: ``--no-cache``."""
    world: WorldRun | None = None
    """The world-model settings; None: the defaults and the scenes under the paths."""
    launch: Launch | None = None
    progress: bool = False
    """Say on stderr what the run is doing (``CheckRun.say``): for a terminal's user."""
    discovered: Discovery | None = None
    """The paths' files, already being discovered (``pipeline.checked_files``)."""
    memo: Memo | None = None
    overlay: Mapping[Path, bytes] = field(default_factory=dict)
    """Text that stands for a file's bytes on disk, by resolved path: an editor's unsaved
    buffer, checked as typed and never written. A run with one is never kept."""
    ontology: SettledSource | None = None
    """The ontology of a run given none loaded: its index is loaded when the run must read
    (``CheckRun.ontology_index``), so a run the cache answers decodes none."""


@dataclass
class CheckOutcome:
    """Every finding of a run (before selection), and the source of each file read."""

    files: int = 0
    skills: int = 0
    diagnostics: list[Diagnostic] = field(default_factory=list)
    sources: dict[str, str] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)
    """What discovery passed over and why (vendored SkiROS2 code, symlink loops), for
    stderr."""
    read: list[str] = field(default_factory=list)
    """Files the loads of ``--trace`` opened besides the run's own (``LoadOutcome.read``):
    a kept run depends on their bytes too."""


@dataclass
class CompoundFound:
    """What the compound stage found: the trees and the skill index they were checked
    against (the judgements read both)."""

    models: list[CompoundModel] = field(default_factory=list)
    skills: SkillIndex | None = None


@dataclass
class CheckRun:
    """A run on its way through the stages: what it was asked, then what each stage left."""

    paths: list[Path]
    index: OntologyIndex | None
    pool: PoolConfig
    settings: CheckSettings
    world: WorldRun = field(default_factory=WorldRun)
    outcome: CheckOutcome = field(default_factory=CheckOutcome)
    done: bool = False
    """Answered whole (by the outcome cache): the stages after the one that set it are
    skipped."""
    candidates: list[Candidate] = field(default_factory=list)
    kept_key: str | None = None
    """The run's key in the outcome cache, when the run is kept there."""
    cutoff_key: str | None = None
    """The key of what the next run needs to cut off early (``early_cutoff``): the run's
    inputs but its Python files' bytes."""
    fact_keys: dict[str, str] = field(default_factory=dict)
    """The facts cache's key of each parsed file, by path (``read_files.facts_key``)."""
    shared: set[str] = field(default_factory=set)
    """Files whose bytes another file's reading took (a possible base of a file the codemod
    read): never cut off early (``early_cutoff``)."""
    star_sources: set[str] = field(default_factory=set)
    """Files whose code another file's reading took (a star import's module,
    ``FileFacts.depends``): cut off early only when their code is as it was."""
    facts_cache: FactsCache | None = None
    scenes_cached: set[Path] = field(default_factory=set)
    """Scenes whose parse the facts cache held (the reading pool parses the others)."""
    reader: ReadingPool | None = None
    trees: Trees | None = None
    """The compound pass's readings, filled while the files are read (None: no EZ3
    code is selected)."""
    read: list[tuple[Candidate, bytes]] = field(default_factory=list)
    """Every Python file of the run with its bytes, in order."""
    results: list[tuple[Candidate, FileResult]] = field(default_factory=list)
    """What the legacy descriptions of each file declare (``read_files``)."""
    module_facts: dict[Path, ModuleFacts | None] = field(default_factory=dict)
    """What the implementation checks read of each file (None: ``ast`` cannot read it)."""
    loadable: list[Candidate] = field(default_factory=list)
    """The EzSkiROS files."""
    static_loads: dict[Path, LoadOutcome] = field(default_factory=dict)
    """What the read stage read of each EzSkiROS file from its syntax (``FileFacts.loaded``),
    by path."""
    post_lines: dict[Path, dict[str, list[tuple[int, str]]]] = field(default_factory=dict)
    """The post-conditions' lines the read stage took of each EzSkiROS file
    (``FileFacts.posts``), by path, for the world stage."""
    loads: list[LoadOutcome] = field(default_factory=list)
    """What reading (or, under ``--trace``, loading) each EzSkiROS file gave."""
    skill_index: SkillIndex | None = None
    around: RepositoryScan | None = None
    library: list[tuple[Candidate, bytes]] = field(default_factory=list)
    """The skill libraries' files: their compound skills join the index, unreported."""
    compound_run: CompoundRun | None = None
    compound: CompoundFound = field(default_factory=CompoundFound)

    @property
    def diagnostics(self) -> list[Diagnostic]:
        return self.outcome.diagnostics

    def say(self, line: str) -> None:
        """A progress message on stderr, when the run shows progress (our own words: no
        file name or text of the repository is in them)."""
        if self.settings.progress:
            sys.stderr.write(f"ezmigrate: {line}\n")
            sys.stderr.flush()

    def fingerprint(self) -> str:
        """The fingerprint of the run's ontology ("" without one), without loading it."""
        if self.index is not None:
            return self.index.fingerprint
        return self.settings.ontology.fingerprint if self.settings.ontology is not None \
            else ""

    def ontology_index(self) -> OntologyIndex | None:
        """The run's index, loaded (``CheckSettings.ontology``) when the run first needs
        it: a run that reads."""
        if self.index is None and self.settings.ontology is not None:
            self.index = self.settings.ontology.index()
        return self.index

    def loadable_data(self) -> list[bytes]:
        """The bytes the run read of each EzSkiROS file, in ``loadable``'s order."""
        data = {c.path: d for c, d in self.read}
        return [data[c.path] for c in self.loadable]


def text_of(data: bytes) -> str:
    """A file's bytes as the findings quote it (undecodable bytes replaced)."""
    return data.decode("utf-8", errors="replace")
