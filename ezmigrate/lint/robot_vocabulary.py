"""Unknown vocabulary (EZ209) judged as the robot resolves it.

Most "unknown class" findings on real repositories are classes the robot does know: the
world model loads the init scene, whose individuals are typed with the lab's classes, and
matches elements by exact type; or the ontology lives in a ``workspace_dir`` the launch
file names in another package, which this run cannot read. So:

- a class that a scene of the run types an individual with is known (no finding);
- with a launch file whose ``workspace_dir`` cannot be read, an unknown class or property
  is ``info``, and says which folder was not read;
- a prefix the ontology does not define is one ``info`` finding per project (at its
  first use), with its count of uses, instead of one per use: a lab prefix is usually
  defined by an ontology another package loads (issue 30), as the runtime says too.
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Iterable, Sequence
from dataclasses import replace
from pathlib import Path

from ezskiros_runtime.codes import code_for

from ..files.discover import repository_root
from ..report.once import once_per_cause
from .diagnostic import Diagnostic
from .scene_search import scene_files
from .world_model import readable_scenes

UNKNOWN = code_for("unknown-vocabulary")
PREDICATE = code_for("scene-unknown-predicate")
JUDGED = frozenset({UNKNOWN, PREDICATE})
"""The codes of a name the loaded ontology lacks, in code or in a scene."""


def scene_classes(scenes: Iterable[Path]) -> set[str]:
    """Classes the individuals of these scenes are typed with, as the scene writes them
    (``lab:Widget``) and as full IRIs."""
    found: set[str] = set()
    for scene in readable_scenes(scenes):
        kinds = {kind for element in scene.elements.values() for kind in element.types}
        found |= kinds | {scene.compact(kind) for kind in kinds}
    return found


def typing_scenes(paths: Sequence[Path], scenes: Sequence[Path],
                  exclude: Sequence[str] = ()) -> list[Path]:
    """The scenes whose types count as known: the run's, and those of the repository
    around each named file, so that pre-commit (staged files only) judges a class as a
    run on the repository does."""
    roots = sorted({root.resolve() for p in paths if p.is_file() and p.suffix == ".py"
                    for root in [repository_root(p)] if root is not None})
    return [*scenes, *scene_files(roots, exclude)] if roots else list(scenes)


def as_the_robot_resolves(diagnostics: Sequence[Diagnostic], typed: set[str],
                          unread_workspace: str | None,
                          prefixes: Collection[str] = (),
                          misspelt: Callable[[str], bool] = lambda _term: False
                          ) -> list[Diagnostic]:
    """``diagnostics`` with EZ209 and EZ411 judged as the module doc says, by the term each
    names (``Diagnostic.term``); ``prefixes``: those the loaded ontology defines;
    ``misspelt(term)``: the term is one edit from a term its loaded namespace defines, a
    typo, which a workspace this run cannot read would not define either."""
    def undefined(d: Diagnostic) -> str | None:
        """The prefix no loaded file defines that an EZ209 or EZ411 names, else None."""
        if d.code not in JUDGED or d.term is None or "://" in d.term:
            return None
        prefix, colon, _ = d.term.partition(":")
        return prefix if colon and prefix not in prefixes else None

    judged: list[Diagnostic] = []
    for d in diagnostics:
        if d.code in JUDGED and d.term is not None:
            if d.code == UNKNOWN and d.term_is_class and d.term in typed:
                continue  # the scene types individuals with it: the world model matches it
            if undefined(d) is not None:
                d = replace(d, severity="info")  # another package's ontology may define it
            if unread_workspace is not None and not misspelt(d.term or ""):
                d = replace(d, severity="info", message=(
                    f"{d.message} (the launch file's workspace_dir {unread_workspace} could "
                    "not be read by this run: it may define it)"))
        judged.append(d)
    return once_per_cause(judged, undefined, lambda d, name, uses: replace(d, message=(
        f"{d.message} ({uses} uses of prefix {name!r} in the project, reported once, "
        "here)")))
