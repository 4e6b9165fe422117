"""Stage 2, read: every file of the run read once, each legacy description's declaration
taken without importing user code.

Plain descriptions are read with ``ast`` (``lint/plain_reader.py``); every other file goes
through the codemod's reader exactly as ``rewrite`` reads it (``settle``, without
verifying). What the later stages need of a file (the compound pass's ``TreeFacts``, the
implementation checks' ``ModuleFacts``) is taken in the same parse (``file_facts``), in
the reading pool's forked workers, and kept by content in the facts cache, so one changed
file is read again with what depends on it.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

from ..files.discover import Candidate
from ..project import holdpoint
from ..project.cross_file import RUNTIME_MARKER
from ..report.results import FileResult
from .run import CheckRun, text_of

if TYPE_CHECKING:
    from ezskiros_runtime.ontology.index import OntologyIndex

    from ..cache.facts_cache import FactsCache
    from .file_facts import FileFacts
    from .reading_pool import ReadingPool


@dataclass
class FileReadings:
    """Every file of a run as read (``read_facts``): its bytes (None: unreadable) and its
    parse's facts (None: never parsed, nothing to read in it), in the order given."""

    files: list[tuple[Candidate, bytes | None, FileFacts | None]] = field(default_factory=list)
    alone: dict[str, tuple[bytes, FileResult]] = field(default_factory=dict)
    """The codemod's readings, taken already (by the reading pool or from the cache)."""
    typed: set[str] = field(default_factory=set)
    """Files whose bytes are an overlay's (an editor's unsaved buffer), not the disk's."""
    keys: dict[str, str] = field(default_factory=dict)
    """The facts cache's key of each parsed file, by path (``facts_key``)."""
    shared: set[str] = field(default_factory=set)
    """Files whose bytes another file's reading took (``CheckRun.shared``)."""
    star_sources: set[str] = field(default_factory=set)
    """Files whose code another file's reading took (``CheckRun.star_sources``)."""


def read_facts(candidates: list[Candidate], compounds: bool, cache: FactsCache | None,
               reader: ReadingPool | None, overlay: Mapping[Path, bytes] | None = None,
               static_against: str | None = None) -> FileReadings:
    """Read and parse each candidate once; ``compounds``: parse files that may hold a
    compound skill too; ``overlay``: text standing for some files' bytes (by resolved
    path); ``static_against``: the fingerprint of the active ontology EzSkiROS files are
    read statically against (``FileFacts.loaded``; None: they are not, ``--trace`` loads
    them). Files without a description are read, never parsed."""
    from ..files.prefilter import by_text
    from .file_facts import FileFacts, file_facts, still_read

    readings = FileReadings()
    facts: dict[Path, FileFacts] = {}
    read: list[tuple[Candidate, bytes | None]] = []
    missing: list[tuple[Candidate, bytes, bool | None, str | None]] = []
    for candidate in candidates:
        data: bytes | None = overlay.get(candidate.path.resolve()) if overlay else None
        if data is not None:
            readings.typed.add(str(candidate.path))
        try:
            data = candidate.path.read_bytes() if data is None else data
        except OSError:
            data = None  # the codemod reports why it cannot be read
        read.append((candidate, data))
        verdict = None if data is None else by_text(data)
        if data is None or never_parsed(data, verdict, compounds):
            continue  # never parsed: nothing to read in it
        key = None if cache is None else facts_key(cache, candidate, data, compounds,
                                                    static_against)
        if key is not None:
            readings.keys[str(candidate.path)] = key
        found = None if cache is None or key is None else cache.get(key)
        if isinstance(found, FileFacts) and still_read(found):
            facts[candidate.path] = found
            if found.settled is not None:
                readings.alone[str(candidate.path)] = (data, found.settled)
        else:
            missing.append((candidate, data, verdict, key))
    items: list[tuple[Candidate, bytes, bool | None]] = [(c, d, v) for c, d, v, _ in missing]
    statically = static_against is not None
    made = reader.read_files(items, compounds, statically) if reader is not None \
        else [(file_facts(c, d, compounds, v, statically), None) for c, d, v in items]
    for (candidate, data, _, key), (found, own) in zip(missing, made, strict=True):
        facts[candidate.path] = found
        taken = own if own is not None else found.settled
        if taken is not None:
            readings.alone[str(candidate.path)] = (data, taken)
        if cache is not None and key is not None:
            cache.put(key, found)
    readings.files = [(c, data, facts.get(c.path)) for c, data in read]
    readings.star_sources = {path for found in facts.values() for path, _ in found.depends}
    return readings


def static_against(run: CheckRun) -> str | None:
    """The fingerprint of the ontology the run reads EzSkiROS files statically against
    (``read_facts``; None under ``--trace``, which loads them), made the active ontology
    in this process: the static reading checks names against the active one, so a file
    read before this (a changed file early cutoff reads) would be read against another."""
    if run.settings.trace:
        return None
    index = run.ontology_index()
    if index is None:
        return ""
    from ezskiros_runtime.ontology import use_ontology

    use_ontology(index)
    return index.fingerprint


def never_parsed(data: bytes, verdict: bool | None, compounds: bool) -> bool:
    """Whether the read stage leaves a file unparsed: the prefilter rules it out
    (``verdict``: ``by_text``), and it has nothing the compound pass reads."""
    from ..compound.markers import SCAN_WHEN

    return verdict is False and not (compounds and any(m in data for m in SCAN_WHEN))


def facts_key(cache: FactsCache, candidate: Candidate, data: bytes, compounds: bool,
              static_against: str | None) -> str:
    """The key of a file's facts in the cache (``read_facts``): its path and bytes, whether
    the compound pass reads it, and for an EzSkiROS file read statically, the ontology."""
    ontology = ("static", static_against) \
        if static_against is not None and RUNTIME_MARKER in data else ()
    return cache.key("file", str(candidate.path), candidate.relative, str(compounds), data,
                     *ontology)


def declarations(readings: FileReadings, index: OntologyIndex | None, workers: int,
                 cache: FactsCache | None) -> Iterator[tuple[Candidate, bytes, FileResult]]:
    """What every legacy description of ``readings`` declares: the files without one
    first, then the plain reader's, then the codemod's readings of the files the plain
    reader declined. When a class may derive from a description of a sibling file, the
    plain files of its package are handed to the codemod's cross-file pass as read, not
    read again with libcst."""
    from ..lint.plain_reader import Declined

    plain: list[tuple[Candidate, bytes, FileResult]] = []
    declined: list[tuple[Candidate, bytes | None]] = []
    whole_package: set[Path] = set()
    for candidate, data, reading in readings.files:
        if data is None:
            declined.append((candidate, None))
        elif reading is None or not reading.described:
            yield candidate, data, FileResult(path=candidate.relative)
        elif isinstance(reading.static, Declined):
            declined.append((candidate, data))
            if reading.static.cross_file:
                whole_package.add(candidate.root)
        elif reading.static.foreign_bases:  # read, but its bases may be a sibling's:
            declined.append((candidate, data))  # the cross-file pass takes it as read
            whole_package.add(candidate.root)
            readings.alone[str(candidate.path)] = (data, reading.static)
        else:
            plain.append((candidate, data, reading.static))
    yield from plain
    for candidate, data in [(c, d) for c, d in declined if str(c.path) in readings.typed
                            and str(c.path) in readings.alone]:
        # an unsaved buffer the codemod read alone: ``settle`` would read the disk's bytes
        declined.remove((candidate, data))
        yield candidate, data or b"", readings.alone[str(candidate.path)][1]
    if declined:
        yield from _settled(declined, [(c, d, r) for c, d, r in plain if c.root in whole_package],
                            index, workers, cache, readings)


def read_statically(candidates: list[Candidate], workers: int, index: OntologyIndex | None
                    ) -> Iterator[tuple[Candidate, bytes, FileResult]]:
    """What every legacy description of ``candidates`` declares, read without a cache (the
    skill libraries' files)."""
    return declarations(read_facts(candidates, False, None, None), index, workers, None)


def _settled(declined: list[tuple[Candidate, bytes | None]],
             plain: list[tuple[Candidate, bytes, FileResult]], index: OntologyIndex | None,
             workers: int, cache: FactsCache | None, readings: FileReadings
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
    ``readings.alone``: files already read alone as the codemod reads them, by the reading
    pool (``runner.own_reading``) or from their syntax (``ezskiros_reader``); the files that
    may define a base go to ``readings.shared``.
    """
    from ..project.import_scan import import_words
    from ..project.runner import Migrated
    from ..project.settle import settle  # the codemod's readings: not in a kept run

    fingerprint = index.fingerprint if index is not None else ""
    everyone = {str(c.path): d for c, d in declined if d is not None}
    everyone.update((str(c.path), d) for c, d, _ in plain)
    words = {c.path: import_words(d) for c, d in declined if d is not None}
    definers = _Definers(everyone)
    wanted = definers.of(set().union(*words.values()) if words else set())
    alone = readings.alone
    readings.shared |= definers.of(set().union(*(  # the siblings a reading may take
        _sibling_words(c, words[c.path], alone.get(str(c.path))) for c, _ in declined
        if c.path in words)))
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


def _sibling_words(candidate: Candidate, words: frozenset[bytes],
                   alone: tuple[bytes, FileResult] | None) -> frozenset[bytes]:
    """The module names of the siblings whose bytes the codemod's reading of a declined
    file may take (``cross_file.resolve_cross_file``). With a reading of its own that
    leaves the file as it is (``alone``), the modules its foreign bases come from: the
    cross-file pass reads only the files whose module name is the last part of a base's
    module, and none for a file without such bases (an EzSkiROS file deriving from
    ``ezskiros_runtime``'s ``SkillDescription`` reads no sibling). Otherwise every word of
    its imports (``words``): it has no reading yet, or the pass may migrate it again."""
    from ..project.cross_file import target_module

    if alone is None or alone[1].changed:
        return words
    return frozenset(target_module(candidate.relative, source).rpartition(".")[2].encode()
                     for _, source in alone[1].foreign_bases)


class _Definers:
    """The files that may define a base another file's imports name: those whose module
    name is a word of the imports, and every package's ``__init__`` (any import may run
    it). Indexed once by module name, asked once per declined file."""

    def __init__(self, paths: Iterable[str]) -> None:
        from ..project.cross_file import module_name

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


def _take(run: CheckRun, candidate: Candidate, found: FileFacts) -> None:
    """What the compound pass and the implementation checks read of a file (of a file with
    no description, kept for the compound pass to take in its own turn)."""
    trees = run.trees
    assert trees is not None
    if found.trees is not None:
        if found.described:
            trees.take(candidate, found.trees)
        else:
            trees.prepared[str(candidate.path)] = found.trees
    if found.unparsed is not None:
        trees.recovered[str(candidate.path)] = found.unparsed[0]
    if found.parsed:
        trees.parsed.add(str(candidate.path))
    if found.implementation is not None:
        run.module_facts[candidate.path] = found.implementation
    elif found.described and not found.parsed:  # parsing it again would fail again
        run.module_facts[candidate.path] = None


def run(run: CheckRun) -> None:
    """Read the run's files: their bytes, sources, declarations and facts; which are
    EzSkiROS files (``run.loadable``)."""
    from ..project.progress import Progress

    line = Progress.for_stream(len(run.candidates), skills_label="skills found") \
        if run.settings.progress else Progress(len(run.candidates), active=False)
    readings = read_facts(run.candidates, run.trees is not None, run.facts_cache, run.reader,
                          run.settings.overlay, static_against(run))
    run.fact_keys, run.star_sources = readings.keys, readings.star_sources
    run.shared = readings.shared  # (the declarations below add to it)
    for candidate, data, found in readings.files:
        if found is None or data is None:
            continue
        if found.loaded is not None:
            run.static_loads[candidate.path] = found.loaded
        if found.posts is not None:
            run.post_lines[candidate.path] = found.posts
        if run.trees is not None:
            _take(run, candidate, found)
    with line:  # erased before the next message
        for candidate, data, result in declarations(readings, run.index, run.pool.workers,
                                                    run.facts_cache):
            run.read.append((candidate, data))
            run.results.append((candidate, result))
            run.outcome.sources[str(candidate.path)] = text_of(data)
            skills = sum(1 for s in result.skills if s.status != "unchanged")
            run.outcome.skills += skills
            line.advance(1, skills)
            if line.files == 1:
                holdpoint.reach("checking")
            if RUNTIME_MARKER in data:
                run.loadable.append(candidate)
