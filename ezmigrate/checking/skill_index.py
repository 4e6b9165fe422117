"""Stage 4, the cross-file index: every description a compound skill of the run may name.

The index holds this run's descriptions (as read, or as loaded under ``--trace``), the
repository's around the run's paths (``compound/repository.py``), SkiROS2's standard
library's and the ``skill-libraries``' (read like the run's own files; the run's own
descriptions win over theirs). ``check`` and the review report of ``rewrite --report``
build it the same way, so they judge the same trees the same way.
"""

from __future__ import annotations

from dataclasses import fields
from typing import TYPE_CHECKING

from ..files.discover import library_candidates
from .read_files import read_statically
from .run import CheckRun

if TYPE_CHECKING:
    from ..compound.repository import RepositoryScan


def _around(run: CheckRun) -> RepositoryScan:
    """The repository around the run's paths (``scan_repository``): the run's own files
    that only the scan reads (those ``ast`` cannot parse), then the others. With a memo,
    the others are scanned once until a save clears it."""
    from ..compound.repository import scan_repository

    trees, memo = run.trees, run.settings.memo
    assert trees is not None
    skip = trees.seen | set(trees.prepared) | trees.parsed
    if memo is None:
        return scan_repository(trees.named, trees.exclude, skip, run.read, trees.recovered)
    own = scan_repository((), trees.exclude, skip, run.read, trees.recovered)
    key = tuple(str(p) for p in trees.named)
    rest = memo.repository.get(key)
    if rest is None:
        rest = memo.repository[key] = scan_repository(
            trees.named, trees.exclude, (), [(c, b"") for c, _ in run.read], None)
    for part in fields(own):  # the run's own files first, as one scan gives them
        mine, theirs = getattr(own, part.name), getattr(rest, part.name)
        setattr(own, part.name, mine | theirs if isinstance(mine, set) else mine + theirs)
    return own


def run(run: CheckRun) -> None:
    """The skill index, when the run reads trees and a file defines a compound skill or
    implements a description."""
    if run.trees is None or not (run.trees.undescribed  # issue 42: EZ110 needs the index
                                 or any(b"expand" in data or b"setDescription" in data
                                        for _, data in run.read)):
        return
    from ezskiros_runtime.compound.library import SkillIndex

    from ..compound.analysis import add_descriptions
    from ..compound.repository import description_of

    skills = SkillIndex.with_standard_library()
    run.library = library_candidates(list(run.settings.skill_libraries))
    if run.library:
        statics = [(c, r) for c, _, r in read_statically([c for c, _ in run.library],
                                                         run.pool.workers, run.index)]
        add_descriptions(skills, statics, [], "skill library")
    run.around = _around(run)
    for info in run.around.descriptions:  # the files not named; the named ones' win
        skills.add_description(info)
    loaded = [(c, o) for c, o in zip(run.loadable, run.loads, strict=True) if o.loaded]
    add_descriptions(skills, run.results, [(c, o.models) for c, o in loaded], "repository")
    for candidate, outcome in loaded:  # read in part from its syntax: the type exists,
        for name, line, _ in outcome.unread:  # its keys are not known
            if name not in skills.descriptions:
                skills.add_description(description_of(name, None, "repository",
                                                      str(candidate.path), line))
    run.skill_index = skills
