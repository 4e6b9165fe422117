"""Stage 6, the world model (EZ4xx): post-conditions against the single-valued relations,
every ``*.turtle`` scene of the repository and the launch file's ``init_scene`` against
the ontology and the descriptions (``lint/world_model.py``)."""

from __future__ import annotations

from .run import CheckRun


def run(run: CheckRun) -> None:
    """The world model's findings, on the scenes the reading pool parsed."""
    from ezskiros_runtime.model import SkillModel

    from ..lint.world_model import world_diagnostics

    if run.reader is not None:
        run.reader.seed_scenes()
    run.diagnostics.extend(world_diagnostics(
        run.world, [(str(c.path), r) for c, r in run.results],
        [(str(c.path), [SkillModel.from_json(m) for m in o.models], run.post_lines.get(c.path))
         for c, o in zip(run.loadable, run.loads, strict=True) if o.loaded], run.index,
        run.outcome.sources))
