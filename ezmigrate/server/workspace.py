"""A workspace as ``check`` understands a repository, and its findings for one buffer.

The settings, the ontology (the workspace's ``owl/`` folders or what is configured), the
selection and suppressions are resolved once, when the editor opens the workspace, by
the same rules as ``check`` (the command line builds the ``Workspace``). A buffer is
checked through ``check``'s own pipeline with its text standing for the file's bytes
(``CheckSettings.overlay``): never written, no code of the repository run.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING

from ..checking.discover import checked_files
from ..checking.pipeline import check_run
from ..checking.run import CheckSettings, Memo
from ..lint.diagnostic import Diagnostic
from ..lint.select import Selection, apply

if TYPE_CHECKING:
    from ezskiros_runtime.compound.library import SkillIndex
    from ezskiros_runtime.ontology.index import OntologyIndex

    from ..files.discover import Discovery
    from ..verify.pool_config import PoolConfig


@dataclass
class Workspace:
    """What every request of one editor session shares."""

    root: Path
    index: OntologyIndex | None
    pool: PoolConfig
    settings: CheckSettings
    """``check``'s settings for the workspace (no cache: a buffer is not a file)."""
    selection: Selection
    skills: SkillIndex | None = None
    """The skill index of the last check (every description a tree may name): hover,
    completion and definition of child skills read it."""
    memo: Memo = field(default_factory=Memo)
    """The repository around each checked file, scanned once until a save (``saved``)."""
    discovered: dict[Path, Discovery] = field(default_factory=dict)
    """Each checked path's discovery (is it excluded, ignored by git, vendored?), made once
    per session: asking git costs a process per keystroke otherwise."""

    def saved(self) -> None:
        """A file was saved: what crosses files (the skill index's repository, scenes
        against descriptions) is read again on the next check."""
        self.memo.clear()

    def diagnose(self, path: Path, text: str) -> list[Diagnostic]:
        """``check``'s findings for ``path`` with ``text`` as its content, selected and
        suppressed as ``check`` would (``# ezskiros: ignore[...]``)."""
        data = text.encode("utf-8")
        if path not in self.discovered:
            self.discovered[path] = checked_files([path], self.settings.exclude,
                                                  self.settings.include_vendored)
        settings = replace(self.settings, overlay={path.resolve(): data},
                           discovered=self.discovered[path], memo=self.memo)
        run = check_run([path], self.index, self.pool, settings)
        outcome = run.outcome
        if run.skill_index is not None:
            self.skills = run.skill_index
        sources = {**outcome.sources, str(path): text}
        return [d for d in apply(outcome.diagnostics, sources, self.selection)
                if Path(d.path).resolve() == path.resolve()]
