"""``ezmigrate check``: the linter a SkiROS2 repository keeps in CI, before and after migrating.

Legacy descriptions are checked statically: ``read_statically`` extracts what each
``createDescription`` declares (no user code runs; plain ones with ``ast``, the rest with
the codemod's reader) and the runtime's early checks run on it, plus the checks only
legacy code needs (``lint/legacy.py``). EzSkiROS files are loaded
in an isolated child, exactly as ``verify`` does, and report the runtime's own findings.
Every finding gets its catalogue code (``ezskiros_runtime.codes``); selection and
suppression happen afterwards (``lint/select.py``), so this module reports everything.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator, Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING

from ezskiros_runtime.codes import code_for

from ..files.discover import Candidate, Discovery, library_candidates, start_discovery
from ..lint.diagnostic import Diagnostic, Positions, diagnostic
from ..lint.scene_search import SCENE_SUFFIX, WorldRun, scene_files
from ..report.results import FileResult
from . import holdpoint
from .implementation_code import IMPLEMENTATION
from .launch import Launch, with_init_scene
from .outcome_cache import OutcomeCache, read_all, run_key
from .uninferable import UNINFERABLE, UNKNOWN

if TYPE_CHECKING:
    from ezskiros_runtime.compound.library import SkillIndex
    from ezskiros_runtime.compound.model import CompoundModel
    from ezskiros_runtime.diagnostics import ClassError
    from ezskiros_runtime.ontology.index import OntologyIndex

    from ..compound.analysis import CompoundRun, Trees
    from ..verify.pool_config import PoolConfig
    from ..verify.protocol import LoadOutcome
    from .facts_cache import FactsCache
    from .file_facts import FileFacts
    from .implementation_code import ModuleFacts
    from .reading_pool import ReadingPool

UNRESOLVED_LOAD = {"timeout": "info", "memory": "info", "crashed": "info"}
"""Loads that failed on the sandbox's limits, not on the module: nothing is known of it."""
KEPT_FROM_CODEMOD = frozenset({"description-in-options", "options-ignored"})
"""Codemod findings ``check`` keeps; the others are found again by the runtime's checks."""


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


def _text(data: bytes) -> str:
    return data.decode("utf-8", errors="replace")


def _legacy(path: str, result: FileResult, positions: Positions,
            index: OntologyIndex | None) -> list[Diagnostic]:
    from ..lint.legacy import legacy_hits  # a run its cache answers needs none of this

    found: list[Diagnostic] = []
    if result.error:
        found.append(diagnostic(path, positions, result.error_kind, result.error_line or 0,
                                result.error.splitlines()[0]))
    for skill in result.skills:
        if skill.status == "converted":
            found.append(diagnostic(path, positions, "not-migrated", skill.line,
                                    "legacy description not migrated yet (run `ezmigrate "
                                    "rewrite`)", skill.name))
            for f in skill.findings:
                if f.kind in KEPT_FROM_CODEMOD:
                    found.append(diagnostic(path, positions, f.kind, f.line or skill.line,
                                            f.message, skill.name))
            if skill.static is not None:
                for hit in legacy_hits(skill.name, path, skill.static, index):
                    found.append(diagnostic(path, positions, hit.kind, hit.line or skill.line,
                                            hit.message, skill.name, hit.fix, param=hit.param,
                                            term=hit.term, term_is_class=hit.term_is_class))
        elif skill.status == "skipped":
            reason = (skill.reason or "").splitlines()[0] if skill.reason else ""
            found.append(diagnostic(path, positions, "kept-legacy", skill.line,
                                    f"legacy description kept, not checked: {reason}",
                                    skill.name))
    return found


def read_statically(candidates: list[Candidate], workers: int, index: OntologyIndex | None,
                    on_facts: Callable[[Candidate, bytes, FileFacts], None] | None = None,
                    cache: FactsCache | None = None, reader: ReadingPool | None = None
                    ) -> Iterator[tuple[Candidate, bytes, FileResult]]:
    """What every legacy description declares, without importing user code.

    Plain descriptions are read with ``ast`` (``lint/plain_reader.py``); every other file
    goes through the codemod's reader exactly as ``rewrite`` reads it. When a class may
    derive from a description of a sibling file, the plain files of its package are handed
    to the codemod's cross-file pass as read, not read again with libcst. Files without a
    description are read, never parsed. ``on_facts`` (when given) sees what the compound
    pass and the implementation checks read of each parsed file (``file_facts``); ``cache``
    keeps those readings, and the codemod's, by content (``facts_cache``); ``reader``
    parses the files the cache lacks in its workers (``reading_pool``). Files come out in
    the order given, the codemod's last.
    """
    from ..compound.repository import SCAN_WHEN
    from ..files.prefilter import by_text
    from ..lint.plain_reader import Declined
    from .file_facts import FileFacts, file_facts

    compounds = on_facts is not None
    read: list[tuple[Candidate, bytes | None]] = []
    facts: dict[Path, FileFacts] = {}
    alone: dict[str, tuple[bytes, FileResult]] = {}  # the codemod's readings, taken already
    missing: list[tuple[Candidate, bytes, bool | None, str | None]] = []
    for candidate in candidates:
        try:
            data: bytes | None = candidate.path.read_bytes()
        except OSError:
            data = None  # the codemod reports why it cannot be read
        read.append((candidate, data))
        verdict = None if data is None else by_text(data)
        if data is None or (verdict is False and not (
                compounds and any(marker in data for marker in SCAN_WHEN))):
            continue  # never parsed: nothing to read in it
        key = None if cache is None else cache.key(
            "file", str(candidate.path), candidate.relative, str(compounds), data)
        found = None if cache is None or key is None else cache.get(key)
        if isinstance(found, FileFacts):
            facts[candidate.path] = found
            if found.settled is not None:
                alone[str(candidate.path)] = (data, found.settled)
        else:
            missing.append((candidate, data, verdict, key))
    items: list[tuple[Candidate, bytes, bool | None]] = [(c, d, v) for c, d, v, _ in missing]
    made = reader.read_files(items, compounds) if reader is not None \
        else [(file_facts(c, d, compounds, v), None) for c, d, v in items]
    for (candidate, data, _, key), (found, own) in zip(missing, made, strict=True):
        facts[candidate.path] = found
        taken = own if own is not None else found.settled
        if taken is not None:
            alone[str(candidate.path)] = (data, taken)
        if cache is not None and key is not None:
            cache.put(key, found)
    plain: list[tuple[Candidate, bytes, FileResult]] = []
    declined: list[tuple[Candidate, bytes | None]] = []
    whole_package: set[Path] = set()
    for candidate, data in read:
        reading = facts.get(candidate.path)
        if data is None:
            declined.append((candidate, None))
        elif reading is None or not reading.described:
            if reading is not None and on_facts is not None:
                on_facts(candidate, data, reading)
            yield candidate, data, FileResult(path=candidate.relative)
        else:
            if on_facts is not None:
                on_facts(candidate, data, reading)
            if isinstance(reading.static, Declined):
                declined.append((candidate, data))
                if reading.static.cross_file:
                    whole_package.add(candidate.root)
            elif reading.static.foreign_bases:  # read, but its bases may be a sibling's:
                declined.append((candidate, data))  # the cross-file pass takes it as read
                whole_package.add(candidate.root)
                alone[str(candidate.path)] = (data, reading.static)
            else:
                plain.append((candidate, data, reading.static))
    yield from plain
    if declined:
        yield from _settled(declined, [(c, d, r) for c, d, r in plain if c.root in whole_package],
                            index, workers, cache, alone)


def _settled(declined: list[tuple[Candidate, bytes | None]],
             plain: list[tuple[Candidate, bytes, FileResult]], index: OntologyIndex | None,
             workers: int, cache: FactsCache | None,
             alone: Mapping[str, tuple[bytes, FileResult]] | None = None
             ) -> Iterator[tuple[Candidate, bytes, FileResult]]:
    """The codemod's readings of the files the plain reader declined (``settle``, without
    verification), beside the plain files of their packages (``plain``) that may define
    their bases.

    A class derives from a sibling's description only through an import naming the
    sibling's module, so a file can matter to another only when its module's name is a
    word of the other's imports (``import_scan``; a package's ``__init__`` always may).
    The cache keeps each reading by the ontology's fingerprint and the file's content, and
    for a file whose classes derive from imported bases, the content of every file that
    may define them: one changed file is read again with the files that depend on it.
    ``alone``: files already read alone as the codemod reads them, by the reading pool
    (``runner.own_reading``) or from their syntax (``ezskiros_reader``).
    """
    from .import_scan import import_words
    from .runner import Migrated
    from .settle import settle  # the codemod's readings: not in a run whose outcome is kept

    fingerprint = index.fingerprint if index is not None else ""
    everyone = {str(c.path): d for c, d in declined if d is not None}
    everyone.update((str(c.path), d) for c, d, _ in plain)
    words = {c.path: import_words(d) for c, d in declined if d is not None}
    definers = _Definers(everyone)
    wanted = definers.of(set().union(*words.values()) if words else set())
    siblings = [Migrated(c, d, None, r) for c, d, r in plain if str(c.path) in wanted]
    if cache is None:
        for item in settle([c for c, _ in declined], index, workers, read=siblings,
                           known=alone):
            yield item.candidate, item.original, item.result
        return

    def own_key(candidate: Candidate, data: bytes) -> str:
        return cache.key("settled", fingerprint, str(candidate.path), candidate.relative, data)

    def with_bases_key(candidate: Candidate, data: bytes) -> str:
        here = str(candidate.path)
        bases = definers.of(words.get(candidate.path, frozenset())) - {here}
        return cache.key("settled-with", fingerprint, here, candidate.relative, data,
                         *(part for path in sorted(bases) for part in (path, everyone[path])))

    found: dict[Path, FileResult] = {}
    for candidate, data in declined:
        if data is None:
            continue
        for keyed in (own_key, with_bases_key):
            hit = cache.get(keyed(candidate, data))
            if isinstance(hit, FileResult):
                found[candidate.path] = hit
                break
    missing = [c for c, _ in declined if c.path not in found]
    if missing:
        settled = [Migrated(c, d, None, found[c.path]) for c, d in declined
                   if c.path in found and d is not None and str(c.path) in wanted]
        for item in settle(missing, index, workers, read=[*siblings, *settled], known=alone):
            found[item.candidate.path] = item.result
            if item.candidate.path in words:
                keyed = own_key if not item.result.foreign_bases else with_bases_key
                cache.put(keyed(item.candidate, item.original), item.result)
    for candidate, data in declined:
        yield candidate, data or b"", found[candidate.path]


class _Definers:
    """The files that may define a base another file's imports name: those whose module
    name is a word of the imports, and every package's ``__init__`` (any import may run
    it). Indexed once by module name, asked once per declined file."""

    def __init__(self, paths: Iterable[str]) -> None:
        from .cross_file import module_name

        self.packages: set[str] = set()
        self.by_module: dict[bytes, set[str]] = {}
        for path in paths:
            if Path(path).name == "__init__.py":
                self.packages.add(path)
            else:
                self.by_module.setdefault(module_name(path).encode(), set()).add(path)

    def of(self, words: Iterable[bytes]) -> set[str]:
        """The paths that may define what imports spelling ``words`` name."""
        return self.packages.union(*(self.by_module.get(w, ()) for w in words))


def needs_trees(codes: Iterable[str]) -> bool:
    """Whether a selection needs the compound skills' trees and skill index: the EZ3xx
    checks, EZ105 and EZ209 (judged by what the trees pass to their children:
    ``uninferable``) and the checks inside implementations (``implementation_code``)."""
    return any(code.startswith("EZ3") or code in (UNINFERABLE, UNKNOWN, *IMPLEMENTATION)
               for code in codes)


def checked_files(paths: list[Path], exclude: tuple[str, ...] = (),
                  include_vendored: bool = False) -> Discovery:
    """The files ``check`` reads under ``paths`` (scenes named there are scenes), being
    discovered: the command starts this before it searches for the ontology, the launch
    file and the scenes, which it does while git says what it ignores."""
    return start_discovery([p for p in paths if p.suffix != SCENE_SUFFIX], exclude,
                           include_vendored=include_vendored)


def run_check(paths: list[Path], index: OntologyIndex | None, pool: PoolConfig,
              exclude: tuple[str, ...] = (),
              progress: Callable[[str], None] | None = None,
              skill_libraries: tuple[Path, ...] = (), compounds: bool = True,
              world: WorldRun | None = None,
              include_vendored: bool = False,
              cache_dir: Path | None = None, launch: Launch | None = None,
              trace: bool = False, discovered: Discovery | None = None) -> CheckOutcome:
    """Static pass over legacy descriptions, the runtime's checks of EzSkiROS files, then
    the compound skills' trees against every description found (unless ``compounds`` is
    False: no EZ3 code is selected, so their reading and tracing would be thrown away),
    then the world model (EZ4xx: ``world``, or the defaults and the scenes under ``paths``;
    scenes named in ``paths`` are scenes, not Python files). ``trace`` False
    (the default): no user code is imported, EzSkiROS files are read from their syntax
    (``lint/ezskiros_static``) and compound skills are not traced; True (``--trace``) loads
    and traces them in the sandbox.
    ``discovered``: the files of ``paths``, already being discovered (``checked_files``)."""
    world = world or WorldRun(scenes=tuple(scene_files(paths, exclude)))
    world = with_init_scene(world, launch)
    candidates, notes = (discovered or checked_files(paths, exclude, include_vendored)).result()
    outcome = CheckOutcome(files=len(candidates), notes=notes)
    kept = _kept_run(paths, candidates, world, launch, skill_libraries, index, pool,
                     compounds, trace, cache_dir)
    if kept is not None and kept[1] is not None:
        return kept[1]
    if progress is not None:
        progress(f"checking {len(candidates)} files")
    from ..codemod.settings import Settings
    from .facts_cache import FactsCache
    from .frozen_heap import frozen_heap

    trees = None
    if compounds:
        from ..compound.analysis import Trees

        listed = launch.listed("skill_list") if launch is not None else None
        trees = Trees(named=tuple(paths), exclude=exclude,
                      launched=frozenset(listed) if listed is not None else None,
                      libraries=frozenset(launch.listed("libraries_list") or ())
                      if launch is not None else frozenset(), trace=trace)
    # the readings of each file by content: for runs over folders, as the whole run's
    # cache (a run over named files would keep only their entries and drop the others)
    facts = FactsCache.open(kept[0][0]) if kept is not None else None
    from .reading_pool import ReadingPool  # not before: a kept run needs none of it

    # it forks when the files are read, before threads
    reader = ReadingPool(pool.workers, Settings(index=index), idle=_checks_after_reading)
    try:
        with frozen_heap():
            outcome = _run(candidates, outcome, index, pool, progress, skill_libraries, trees,
                           world, cache_dir, trace, facts, reader)
            outcome.files += len(world.scenes)
            from ..lint.robot_vocabulary import (
                as_the_robot_resolves,
                scene_classes,
                typing_scenes,
            )

            outcome.diagnostics = as_the_robot_resolves(
                outcome.diagnostics, scene_classes(typing_scenes(paths, world.scenes, exclude)),
                launch.workspace_unresolved if launch is not None else None,
                index.prefixes if index is not None else (), _misspelt_term(index))
            if kept is not None:
                OutcomeCache(kept[0][0]).put(kept[0][1], outcome.files, outcome.skills,
                                             outcome.notes, outcome.diagnostics,
                                             outcome.read)
            if facts is not None:
                facts.save()
            return outcome
    finally:
        reader.close()


def _checks_after_reading() -> None:
    """Import the checks that run once the files are read (legacy descriptions, the world
    model, the robot's vocabulary): 20 ms of a run's main process, spent while it waits for
    the reading workers' last chunks instead of after them."""
    from ..lint import legacy, robot_vocabulary, world_model  # noqa: F401


def _kept_run(paths: list[Path], candidates: list[Candidate], world: WorldRun,
              launch: Launch | None, libraries: tuple[Path, ...],
              index: OntologyIndex | None, pool: PoolConfig, compounds: bool, trace: bool,
              cache_dir: Path | None
              ) -> tuple[tuple[Path, str], CheckOutcome | None] | None:
    """``((cache folder, key), the kept outcome or None)`` for a run over folders with a
    cache (``outcome_cache``), None when the run is not kept (named files, ``--no-cache``,
    a file that cannot be read)."""
    if cache_dir is None or not paths or not all(p.is_dir() for p in paths):
        return None
    files = read_all([*(c.path for c in candidates), *world.scenes,
                      *([launch.path] if launch is not None else [])])
    if files is None:
        return None
    files += [(str(c.path), data) for c, data in library_candidates(list(libraries))]
    key = run_key(files, {
        "ontology": index.fingerprint if index is not None else "",
        "interpreter": pool.python or "", "timeout": pool.timeout,
        "single_valued": list(world.single_valued) if world.single_valued is not None
        else None, "start_scene": str(world.start_scene or ""),
        "launch": sorted(launch.values.items()) if launch is not None else None,
        "compounds": compounds, "trace": trace, "paths": [str(p) for p in paths]})
    hit = OutcomeCache(cache_dir).get(key)
    if hit is None:
        return (cache_dir, key), None
    read = {str(c.path) for c in candidates} | {str(p) for p in world.scenes}
    sources = {path: _text(data) for path, data in files if path in read}
    return (cache_dir, key), CheckOutcome(files=hit["files"], skills=hit["skills"],
                                          diagnostics=hit["diagnostics"], sources=sources,
                                          notes=hit["notes"])


def _run(candidates: list[Candidate], outcome: CheckOutcome, index: OntologyIndex | None,
         pool: PoolConfig, progress: Callable[[str], None] | None,
         skill_libraries: tuple[Path, ...], trees: Trees | None, world: WorldRun,
         cache_dir: Path | None = None, trace: bool = False,
         facts_cache: FactsCache | None = None,
         reader: ReadingPool | None = None) -> CheckOutcome:
    """``run_check`` once its compound pass (``trees``) is set up, with the heap it started
    with frozen (``frozen_heap``)."""
    from ezskiros_runtime.model import SkillModel

    from ..verify.pool import BATCH, job_for, run_batched
    from .cross_file import RUNTIME_MARKER
    from .facts_cache import keep_scenes, seed_scenes
    from .load_cache import LoadCache, cached_loads
    from .progress import Progress

    loadable: list[Candidate] = []
    read: list[tuple[Candidate, bytes]] = []
    results: list[tuple[Candidate, FileResult]] = []
    line = Progress.for_stream(len(candidates), skills_label="skills found") \
        if progress is not None else Progress(len(candidates), active=False)
    cached = seed_scenes(facts_cache, world.scenes) if facts_cache is not None else set()
    if reader is not None:
        reader.parse_scenes([scene for scene in world.scenes if scene not in cached])
    facts: dict[Path, ModuleFacts | None] = {}  # None: ``ast`` cannot read the file

    def at_hand(candidate: Candidate, data: bytes, found: FileFacts) -> None:
        """What the compound pass and the implementation checks read of a file (of a
        file with no description, kept for the compound pass to take in its own turn)."""
        if trees is not None and found.trees is not None:
            if found.described:
                trees.take(candidate, found.trees)
            else:
                trees.prepared[str(candidate.path)] = found.trees
        if trees is not None and found.unparsed is not None:
            trees.recovered[str(candidate.path)] = found.unparsed[0]
        if trees is not None and found.parsed:
            trees.parsed.add(str(candidate.path))
        if found.implementation is not None:
            facts[candidate.path] = found.implementation
        elif found.described and not found.parsed:  # parsing it again would fail again
            facts[candidate.path] = None

    with line:  # erased before the next message
        for candidate, data, result in read_statically(
                candidates, pool.workers, index, at_hand if trees is not None else None,
                facts_cache, reader):
            path = str(candidate.path)
            read.append((candidate, data))
            results.append((candidate, result))
            outcome.sources[path] = _text(data)
            skills = sum(1 for s in result.skills if s.status != "unchanged")
            outcome.skills += skills
            line.advance(1, skills)
            if line.files == 1:
                holdpoint.reach("checking")
            if result.error or result.skills:
                outcome.diagnostics += _legacy(path, result,
                                               Positions(outcome.sources[path]), index)
            if RUNTIME_MARKER in data:
                loadable.append(candidate)
    data_of = {c.path: data for c, data in read}
    if not trace:
        outcomes = _read_ezskiros([(c.path, data_of[c.path]) for c in loadable], index)
    else:
        if loadable and progress is not None:
            progress(f"loading {len(loadable)} EzSkiROS files")
        cache = None if cache_dir is None else LoadCache.for_run(
            cache_dir, [(str(c.path), data) for c, data in read],
            index.fingerprint if index is not None else "", pool.python)
        outcomes = cached_loads([job_for(c.path, None, c.root) for c in loadable],
                                [data_of[c.path] for c in loadable],
                                lambda jobs: run_batched(jobs, pool, BATCH,
                                                         alone=lambda found: not found.loaded),
                                cache)
    outcome.read = sorted({path for loaded in outcomes for path in loaded.read})
    compound = _Compound()
    if trees is not None:
        compound = _compound(read, results, list(zip(loadable, outcomes, strict=True)),
                             index, pool, skill_libraries, outcome.sources, trees)
        outcome.diagnostics += compound.diagnostics
    # a legacy class the static pass kept (EZ902) in a file that is loaded because another
    # class in it was migrated: its findings are the static pass's, as before the migration
    kept = {(str(c.path), s.name) for c, r in results for s in r.skills
            if s.status == "skipped"}
    for candidate, loaded in zip(loadable, outcomes, strict=True):
        path = str(candidate.path)
        where = Positions(outcome.sources[path])
        if not loaded.loaded:
            outcome.diagnostics.append(diagnostic(
                path, where, "unloadable", loaded.line or 0,
                f"{loaded.status}: {loaded.message}", severity=UNRESOLVED_LOAD.get(
                    loaded.status)))
            continue
        outcome.skills += len(loaded.models)
        outcome.diagnostics += [
            diagnostic(path, where, "not-read-statically", line,
                       f"description not read without running the module: {shape}; it is "
                       "not checked (check --trace loads it in the sandbox)", name)
            for name, line, shape in loaded.unread if shape]
        for error in loaded.errors:
            if (path, error.name) not in kept:
                outcome.diagnostics.append(_class_error(path, where, error))
        for found in loaded.findings:
            outcome.diagnostics.append(diagnostic(
                path, where, found.kind, found.line or 0, found.message, found.skill,
                f"Did you mean {found.suggestions[0]}?" if found.suggestions else None,
                found.severity if found.severity == "info" else None, found.param,
                found.actual, found.actual is not None and found.relation is None))
    if reader is not None:
        reader.seed_scenes()
    from ..lint.world_model import world_diagnostics

    outcome.diagnostics += world_diagnostics(
        world, [(str(c.path), r) for c, r in results],
        [(str(c.path), [SkillModel.from_json(m) for m in o.models])
         for c, o in zip(loadable, outcomes, strict=True) if o.loaded], index,
        outcome.sources)
    # the implementation classes, read once for both passes below (while the static pass
    # had their syntax trees at hand, else parsed now), and only when one of them has
    # work: the checks inside them, or an EZ105/EZ209 to judge
    judging = any(d.code in (UNINFERABLE, UNKNOWN) for d in outcome.diagnostics)
    implementing = [(c, found) for c, data in read if b"setDescription" in data
                    for found in (facts[c.path] if c.path in facts else _facts_of(data),)
                    if found is not None] \
        if compound.skills is not None or judging else []
    if compound.skills is not None:
        outcome.diagnostics += _implementations(implementing, compound.skills, index, world,
                                                outcome.sources)
    outcome.diagnostics = _judge_uninferable(outcome.diagnostics, implementing, compound,
                                             world, index)
    outcome.diagnostics.sort(key=lambda d: (d.path, d.line, d.column, d.code))
    if facts_cache is not None:
        keep_scenes(facts_cache, world.scenes)
    return outcome


def _read_ezskiros(files: list[tuple[Path, bytes]], index: OntologyIndex | None
                   ) -> list[LoadOutcome]:
    """What loading each EzSkiROS file would give, read from its syntax against ``index``
    (``lint/ezskiros_static``): ``check`` runs no code of the repository unless told
    (``--trace``)."""
    from ezskiros_runtime.ontology import use_ontology

    from ..lint.ezskiros_static import read_ezskiros_statically
    from ..verify.protocol import LoadOutcome
    from .file_facts import parse, respelt

    if index is not None and files:
        use_ontology(index)  # the ontology the runtime's checks look names up in
    outcomes = []
    for path, data in files:
        tree = parse(data) or respelt(data)
        outcomes.append(LoadOutcome("ok") if tree is None  # the static pass said why
                        else read_ezskiros_statically(tree, str(path)).outcome())
    return outcomes


@dataclass
class _Compound:
    """What the compound pass found: its diagnostics, the trees and the skill index."""

    diagnostics: list[Diagnostic] = field(default_factory=list)
    models: list[CompoundModel] = field(default_factory=list)
    skills: SkillIndex | None = None


def _facts_of(data: bytes) -> ModuleFacts | None:
    """The implementation facts of a file the static pass did not read for them."""
    from .file_facts import parse
    from .implementation_code import module_facts

    tree = parse(data)
    return None if tree is None else module_facts(tree, data)


def _judge_uninferable(diagnostics: list[Diagnostic],
                       implementing: list[tuple[Candidate, ModuleFacts]],
                       compound: _Compound, world: WorldRun,
                       index: OntologyIndex | None) -> list[Diagnostic]:
    """EZ105 kept a warning only where grounding by type can pick the wrong element
    (``uninferable``): implementations read, parents' trees, the scenes' elements."""
    from .uninferable import judge, keys_passed, keys_read

    if not any(d.code in (UNINFERABLE, UNKNOWN) for d in diagnostics):
        return diagnostics
    passed = keys_passed(compound.models, compound.skills) \
        if compound.skills is not None else {}
    return judge(diagnostics, keys_read(facts for _, facts in implementing), passed,
                 _scene_counter(world, index), _misspelt_term(index))


def _misspelt_term(index: OntologyIndex | None) -> Callable[[str], bool]:
    """Whether a term (class, relation, property) is one edit from a term of its prefix the
    ontology defines: a typo (``skiros:Lcoation``)."""
    from ezskiros_runtime.ontology.suggest import misspelt_term

    if index is None:
        return lambda _term: False
    terms = [index.compact(c) for c in (*index.classes, *index.properties)]
    return lambda term: misspelt_term(term, terms) is not None


def _implementations(implementing: list[tuple[Candidate, ModuleFacts]], skills: SkillIndex,
                     index: OntologyIndex | None, world: WorldRun,
                     sources: dict[str, str]) -> list[Diagnostic]:
    """EZ109, EZ214 and EZ215 in the implementation classes of the run
    (``implementation_code``): classes are known when the ontology or a scene of the run
    types an element with them, properties when the ontology declares them, a scene holds
    them or the code sets them."""
    from ezskiros_runtime.dsl.vocabulary import to_iri

    from ..lint.robot_vocabulary import scene_classes
    from ..lint.world_model import readable_scenes
    from ..report.once import once_per_cause
    from .implementation_code import implementation_findings

    typed = scene_classes(world.scenes)
    classes = {*(index.compact(c) for c in index.classes), *typed} if index else set(typed)
    made = set().union(*(facts.sets for _, facts in implementing))
    for scene in readable_scenes(world.scenes):
        made |= {scene.compact(v.property) for v in scene.values}

    def known(name: str) -> bool:
        iri = to_iri(index, name) if index is not None else None
        return name in typed or (iri is not None and index is not None
                                 and index.is_class(iri))

    def property_known(name: str) -> bool:
        iri = to_iri(index, name) if index is not None else None
        return name in made or index is None or (iri is not None
                                                 and index.property(iri) is not None)

    found: list[Diagnostic] = []
    for candidate, facts in implementing:
        path = str(candidate.path)
        where = Positions(sources.get(path, ""))
        found += [diagnostic(path, where, kind, line, message, skill, fix, term=term)
                  for kind, line, message, skill, fix, term in implementation_findings(
                      facts, path, skills, known, classes, property_known)]
    unknown_property = code_for("implementation-unknown-property")
    return once_per_cause(  # an unknown property: once per project
        found, lambda d: d.term if d.code == unknown_property else None,
        lambda d, name, uses: replace(d, message=f"{d.message} ({uses} reads of {name} in "
                                                 "the project, reported once)"))


def _scene_counter(world: WorldRun, index: OntologyIndex | None
                   ) -> Callable[[str], int | None]:
    """How many elements of a class (or below it) the run's scenes hold together; None
    without a scene that reads."""
    from ezskiros_runtime.dsl.vocabulary import to_iri

    from ..lint.world_model import readable_scenes

    types = [(e.types, {scene.compact(t) for t in e.types})  # IRIs, and as written
             for scene in readable_scenes(world.scenes) for e in scene.elements.values()]

    def count(cls: str) -> int | None:
        if not types:
            return None
        iri = to_iri(index, cls) if index is not None else None
        if iri is None or index is None:  # a lab class the ontology lacks: by its name
            return sum(1 for _, written in types if cls in written)
        return sum(1 for kinds, _ in types if any(index.is_subclass(k, iri) for k in kinds))
    return count


def compound_pass(read: list[tuple[Candidate, bytes]],
                  results: list[tuple[Candidate, FileResult]],
                  loaded: list[tuple[Candidate, LoadOutcome]], index: OntologyIndex | None,
                  pool: PoolConfig, libraries: tuple[Path, ...], trees: Trees
                  ) -> tuple[CompoundRun, SkillIndex] | None:
    """The one compound pass (issue 29): every compound skill of the run read or traced and
    checked against the index of this run's descriptions, the repository's around them,
    the standard library's and ``libraries``'. ``check`` and the review report of
    ``rewrite --report`` both call it, so they judge the same trees the same way. None when
    no file defines a compound skill or implements a description."""
    if not any(b"expand" in data or b"setDescription" in data for _, data in read):
        return None
    from ezskiros_runtime.compound.library import SkillIndex

    from ..compound.analysis import add_descriptions, analyse
    from ..compound.repository import description_of, scan_repository

    skills = SkillIndex.with_standard_library()
    library = library_candidates(list(libraries))
    if library:  # read like the run's own files; the run's descriptions win over them
        statics = [(c, r) for c, _, r in read_statically([c for c, _ in library], pool.workers,
                                                         index)]
        add_descriptions(skills, statics, [], "skill library")
    around = scan_repository(trees.named, trees.exclude,
                             trees.seen | set(trees.prepared) | trees.parsed, read,
                             trees.recovered)
    for info in around.descriptions:  # the files not named; the named ones' readings win
        skills.add_description(info)
    add_descriptions(skills, results, [(c, o.models) for c, o in loaded if o.loaded],
                     "repository")
    for candidate, outcome in loaded:  # read in part from its syntax: the type exists,
        for name, line, _ in outcome.unread:  # its keys are not known
            if name not in skills.descriptions:
                skills.add_description(description_of(name, None, "repository",
                                                      str(candidate.path), line))
    return analyse(read, skills, index, pool, library, trees, around), skills


def compound_report(items: list[tuple[Candidate, bytes, FileResult]],
                    index: OntologyIndex | None, pool: PoolConfig,
                    libraries: tuple[Path, ...], paths: tuple[Path, ...],
                    exclude: tuple[str, ...]) -> list[str]:
    """The Markdown report's "Compound skills" section for the files of a ``rewrite``:
    ``compound_pass`` over them, as ``check`` runs it on the same repository."""
    from ..compound.analysis import Trees
    from ..compound.diagram import markdown_section

    if not any(b"expand" in data for _, data, _ in items):
        return []
    trees = Trees(named=paths, exclude=exclude)
    done = compound_pass([(c, d) for c, d, _ in items], [(c, r) for c, _, r in items], [],
                         index, pool, libraries, trees)
    return markdown_section(done[0].models, done[0].findings) if done is not None else []


def scene_report(paths: tuple[Path, ...], exclude: tuple[str, ...],
                 index: OntologyIndex | None) -> list[str]:
    """The Markdown report's "Scenes" section: each scene of the run checked and drawn,
    found as ``check`` finds them (``scene_files``)."""
    from ..lint.scene_diagram import markdown_section

    return markdown_section(scene_files(list(paths), exclude), index)


def _compound(read: list[tuple[Candidate, bytes]], results: list[tuple[Candidate, FileResult]],
              loaded: list[tuple[Candidate, LoadOutcome]], index: OntologyIndex | None,
              pool: PoolConfig, libraries: tuple[Path, ...],
              sources: dict[str, str], trees: Trees) -> _Compound:
    """``compound_pass`` as ``check``'s diagnostics (EZ3xx), with the trees and the index
    they were checked against."""
    done = compound_pass(read, results, loaded, index, pool, libraries, trees)
    if done is None:
        return _Compound()
    run, skills = done
    found: dict[tuple[str, int, str, str], Diagnostic] = {}
    for path, finding in run.findings:  # a traced loop adds the same mistake once a turn
        where = Positions(sources.get(path, ""))
        item = diagnostic(path, where, finding.kind, finding.line, finding.message,
                          finding.implementation, finding.suggestion, finding.severity)
        found.setdefault((path, item.line, item.code, item.message), item)
    from ezskiros_runtime.compound.model import CompoundModel

    return _Compound(list(found.values()),
                     [m for _, m in run.models if isinstance(m, CompoundModel)], skills)


def _class_error(path: str, where: Positions, error: ClassError) -> Diagnostic:
    return diagnostic(path, where, "description", error.line or 0, error.message, error.name)
