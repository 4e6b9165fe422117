"""Stage 8, keep: what the next run can take from this one. The whole outcome, by the
run's key (``outcome_cache``); the readings of each file and scene, by content
(``facts_cache``)."""

from __future__ import annotations

from .run import CheckRun


def run(run: CheckRun) -> None:
    """Keep the outcome and the readings, when the run is kept."""
    from ..cache.outcome_cache import OutcomeCache
    from .early_cutoff import remember

    outcome, cache_dir = run.outcome, run.settings.cache_dir
    outcome.files += len(run.world.scenes)
    if run.kept_key is not None and cache_dir is not None:
        OutcomeCache(cache_dir).put(run.kept_key, outcome.files, outcome.skills,
                                    outcome.notes, outcome.diagnostics, outcome.read)
    if run.facts_cache is not None:
        from ..cache.facts_cache import keep_scenes

        keep_scenes(run.facts_cache, run.world.scenes)
        run.facts_cache.save()
        remember(run)
