"""Which scenes a ``check`` run reads, and its world-model settings: found before the run
knows whether its outcome is kept, so this module imports none of the world model's
checks (``world_model`` has them)."""

from __future__ import annotations

import os
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from ezskiros_runtime.ontology.listing import walk
from ezskiros_runtime.ontology.vendored import vendored_skip

from ..files.discover import ALWAYS_EXCLUDED, excluded_under

SCENE_SUFFIX = ".turtle"


def scene_files(paths: Sequence[Path], exclude: Sequence[str] = ()) -> list[Path]:
    """The scenes a run checks: ``*.turtle`` files named on the command line, and every
    one under the folders named (SkiROS2 saves its scenes as ``.turtle``; labs keep them in
    ``owl/``, beside a launch file or beside the code), less ``exclude``, hidden and build
    folders and vendored SkiROS2 packages (whose scenes are upstream's demos)."""
    found: dict[str, Path] = {}
    for given in paths:
        if given.is_file():
            if given.suffix == SCENE_SUFFIX:
                found.setdefault(str(given.resolve()), given)
            continue
        if not given.is_dir():
            continue
        skip = excluded_under(given, exclude)
        vendored = vendored_skip(given)
        for folder, dirs, names in walk(given):
            dirs[:] = sorted(d for d in dirs if d not in ALWAYS_EXCLUDED
                             and not d.startswith(".") and not skip(Path(folder, d))
                             and not vendored(os.path.join(folder, d)))
            for name in sorted(n for n in names if n.endswith(SCENE_SUFFIX)):
                scene = Path(folder, name)
                if not skip(scene):
                    found.setdefault(str(scene.resolve()), scene)
    return sorted(found.values())


@dataclass
class WorldRun:
    """What ``check``'s world-model pass needs besides the files: the single-valued
    relations (None: the default list), the scene files, and ``--scene`` (or None)."""

    single_valued: tuple[str, ...] | None = None
    scenes: tuple[Path, ...] = ()
    start_scene: Path | None = None
