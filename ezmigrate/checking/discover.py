"""Stage 1, discover: the run's files and scenes, the launch file's start scene, and
whether the outcome cache answers the run whole.

Then the run is set up for reading: the compound pass's ``Trees`` (when an EZ3 code is
selected), the facts cache and the reading pool, whose worker starts on the scenes at once.
"""

from __future__ import annotations

import os
from pathlib import Path

from ezskiros_runtime.ontology.vendored import PACKAGE_XML

from ..cache.outcome_cache import OutcomeCache, content_digest, read_all, run_key
from ..files.discover import Candidate, Discovery, library_candidates, start_discovery
from ..lint.scene_search import SCENE_SUFFIX, WorldRun, scene_files
from .launch import with_init_scene
from .run import CheckOutcome, CheckRun, text_of


def checked_files(paths: list[Path], exclude: tuple[str, ...] = (),
                  include_vendored: bool = False) -> Discovery:
    """The files ``check`` reads under ``paths`` (scenes named there are scenes), being
    discovered: the command starts this before it searches for the ontology, the launch
    file and the scenes, which it does while git says what it ignores."""
    return start_discovery([p for p in paths if p.suffix != SCENE_SUFFIX], exclude,
                           include_vendored=include_vendored)


def package_manifests(candidates: list[Candidate]) -> list[Path]:
    """The ``package.xml`` of each candidate's ROS package (the nearest above it): the
    compound stage reads a package's flavour (catkin or ament) and name from it
    (``ros_package_of``), so a kept run depends on its bytes too. Each folder is looked at
    once (a repository has a few folders for many files)."""
    found: dict[str, str | None] = {}

    def manifest(folder: str) -> str | None:
        if folder not in found:
            here, parent = os.path.join(folder, PACKAGE_XML), os.path.dirname(folder)
            found[folder] = here if os.path.isfile(here) else \
                manifest(parent) if parent != folder else None
        return found[folder]

    folders = {os.path.realpath(f) for f in {os.path.dirname(c.path) for c in candidates}}
    return sorted(Path(m) for m in {manifest(f) for f in folders} if m is not None)


def _kept(run: CheckRun) -> None:
    """Look the run up in the outcome cache (runs over folders with a cache only: a run
    over named files also reads the repository around them, which the key would have to
    read too); a hit answers the run."""
    settings, world, launch = run.settings, run.world, run.settings.launch
    if settings.cache_dir is None or settings.overlay or not run.paths \
            or not all(p.is_dir() for p in run.paths):
        return
    files = read_all([*(c.path for c in run.candidates), *world.scenes,
                      *([launch.path] if launch is not None else []),
                      *package_manifests(run.candidates)])
    if files is None:
        return
    files += [(str(c.path), data) for c, data in library_candidates(list(settings.skill_libraries))]
    inputs = {
        "ontology": run.fingerprint(),
        "interpreter": run.pool.python or "", "timeout": run.pool.timeout,
        "single_valued": list(world.single_valued) if world.single_valued is not None
        else None, "start_scene": str(world.start_scene or ""),
        "launch": sorted(launch.values.items()) if launch is not None else None,
        "compounds": settings.compounds, "trace": settings.trace,
        "paths": [str(p) for p in run.paths]}
    digests = {path: content_digest(data) for path, data in files}  # each file hashed once
    run.kept_key = run_key(digests.items(), inputs)
    python = {str(c.path) for c in run.candidates}  # the cutoff's key: all but their bytes
    run.cutoff_key = run_key([(p, "" if p in python else d) for p, d in digests.items()],
                             {**inputs, "early_cutoff": True})
    hit = OutcomeCache(settings.cache_dir).get(run.kept_key)
    if hit is None:  # (a run the cache answers whole never imports the cutoff's readers)
        from .early_cutoff import recall
    outcome = CheckOutcome(files=hit["files"], skills=hit["skills"],
                           diagnostics=hit["diagnostics"], notes=hit["notes"]) \
        if hit is not None else recall(run, dict(files), digests)
    if outcome is None:
        return
    read = python | {str(p) for p in world.scenes}
    outcome.sources = {path: text_of(data) for path, data in files if path in read}
    run.outcome = outcome
    run.done = True


def _prepare(run: CheckRun) -> None:
    """The compound pass's ``Trees``, the facts cache and the reading pool of a run the
    cache did not answer; the pool parses the scenes the facts cache lacks from now on."""
    from ..codemod.settings import Settings
    from ..compound.analysis import Trees
    from .reading_pool import ReadingPool

    settings, launch = run.settings, run.settings.launch
    run.ontology_index()  # the reading pool's worker inherits it
    run.say(f"checking {len(run.candidates)} files")
    if settings.compounds:
        listed = launch.listed("skill_list") if launch is not None else None
        run.trees = Trees(named=tuple(run.paths), exclude=settings.exclude,
                          launched=frozenset(listed) if listed is not None else None,
                          libraries=frozenset(launch.listed("libraries_list") or ())
                          if launch is not None else frozenset(), trace=settings.trace)
    if run.kept_key is not None and settings.cache_dir is not None:
        from ..cache.facts_cache import FactsCache, seed_scenes

        # the readings of each file by content: for runs over folders, as the whole run's
        # cache (a run over named files would keep only their entries and drop the others)
        if run.facts_cache is None:  # (``early_cutoff`` may have opened it)
            run.facts_cache = FactsCache.open(settings.cache_dir)
        if run.facts_cache is not None:
            run.scenes_cached = seed_scenes(run.facts_cache, run.world.scenes)
    run.reader = ReadingPool(run.pool.workers, Settings(index=run.index))
    run.reader.parse_scenes([s for s in run.world.scenes if s not in run.scenes_cached])


def run(run: CheckRun) -> None:
    """Discover the files and scenes; answer from the cache or set the run up to read."""
    settings = run.settings
    world = settings.world or WorldRun(scenes=tuple(scene_files(run.paths, settings.exclude)))
    run.world = with_init_scene(world, settings.launch)
    discovery = settings.discovered or checked_files(run.paths, settings.exclude,
                                                     settings.include_vendored)
    run.candidates, notes = discovery.result()
    run.outcome = CheckOutcome(files=len(run.candidates), notes=notes)
    _kept(run)
    if not run.done:
        _prepare(run)
