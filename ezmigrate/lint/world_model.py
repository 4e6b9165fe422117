"""``check``'s world-model pass (EZ4xx): post-conditions that leave two parents or two
places, the scenes of the repository, and (``--scene``) which skills cannot start there.

The checks themselves are the runtime's (``ezskiros_runtime.world``), so a lab's test and
the linter judge alike; this module finds the scenes, gives each finding its source line
and its fix in the file's own form, and makes diagnostics of them.
"""

from __future__ import annotations

import ast
from collections.abc import Iterable
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING

from ezskiros_runtime.diagnostics import Finding
from ezskiros_runtime.model import SkillModel
from ezskiros_runtime.ontology.consistency import ontology_findings, unknown_predicates
from ezskiros_runtime.ontology.errors import OntologyLoadError
from ezskiros_runtime.ontology.index import bundled_ontology_path
from ezskiros_runtime.world.findings import finding
from ezskiros_runtime.world.grounding import can_start
from ezskiros_runtime.world.postconditions import (
    RelationUse,
    double_places,
    past_typos,
    uses_of,
)
from ezskiros_runtime.world.scene import Scene, SceneError, read_scene
from ezskiros_runtime.world.scene_checks import check_scene, unreadable
from ezskiros_runtime.world.vocabulary import SingleValued, single_valued

from ..codemod.core.ast_walk import walk
from ..report.once import once_per_cause
from ..report.results import FileResult
from ..report.static_facts import StaticDescription
from .diagnostic import Diagnostic, Positions, from_finding
from .scene_search import WorldRun

if TYPE_CHECKING:
    from ezskiros_runtime.ontology.index import OntologyIndex

@dataclass
class SceneRead:
    """A scene file as the run read it: its text, the scene (None when it does not parse)
    and its findings."""

    path: Path
    text: str
    scene: Scene | None
    findings: list[Finding]


def read_scenes(paths: Iterable[Path], index: OntologyIndex | None) -> list[SceneRead]:
    """Each scene read and checked; one that cannot be read is one finding."""
    out = []
    for path in paths:
        try:
            text = path.read_text(encoding="utf-8")
            scene = read_scene(path, text)
        except (OSError, UnicodeError) as error:
            out.append(SceneRead(path, "", None, [unreadable(SceneError(
                str(path), 0, f"cannot be read: {error}"))]))
            continue
        except SceneError as error:
            out.append(SceneRead(path, text, None, [unreadable(error)]))
            continue
        found = check_scene(scene, index)
        if index is not None:
            found += unknown_predicates(scene, index)
        out.append(SceneRead(path, text, scene, found))
    return out


def ontology_diagnostics(index: OntologyIndex | None, sources: dict[str, str]
                         ) -> list[Diagnostic]:
    """EZ410 and EZ412 on the ontology files this run loaded besides the bundled core (the
    repository's ``owl/`` folders, ``--ontology``); their texts go to ``sources`` so that a
    suppression comment works there too. A file that does not parse was refused when the
    index was built and is left alone here."""
    if index is None:
        return []
    bundled = str(bundled_ontology_path())
    files = [Path(s) for s in index.sources if s != bundled]
    if not files:
        return []
    try:
        found = ontology_findings(files, index, [Path(s) for s in index.sources])
    except OntologyLoadError:
        return []
    out: list[Diagnostic] = []
    for f in found:
        path = f.file or ""
        text = sources.setdefault(path, _read(Path(path)))
        out += diagnostics_of([f], text)
    return out


def _read(path: Path) -> str:
    try:
        return path.read_text(encoding="utf-8", errors="replace")
    except OSError:
        return ""


def readable_scenes(paths: Iterable[Path]) -> list[Scene]:
    """The scenes of ``paths`` that parse (each read once per run: ``read_scene`` keeps
    them); one that does not is left out here, since ``read_scenes`` reports it (EZ402)."""
    found = []
    for path in paths:
        try:
            found.append(read_scene(path))
        except (SceneError, OSError, UnicodeError):
            continue
    return found


def once_per_project(per_scene: list[list[Finding]]) -> list[list[Finding]]:
    """The scenes' findings with each declaration-caused EZ403 (a property the ontology
    makes spatial, the finding's subject) kept at its first scene only, counting the
    others: one cause, one finding."""
    kept = once_per_cause(
        [(number, f) for number, found in enumerate(per_scene) for f in found],
        lambda item: item[1].subject if item[1].kind == "scene-spatial-declaration" else None,
        lambda item, _subject, uses: (item[0], replace(
            item[1], message=f"{item[1].message}; the same in {uses - 1} other scene(s), "
                             "reported once")))
    return [[f for number, f in kept if number == scene] for scene in range(len(per_scene))]


def diagnostics_of(found: Iterable[Finding], text: str) -> list[Diagnostic]:
    """World findings of one file as diagnostics (columns from ``text``); an unknown
    predicate's term is its subject."""
    where = Positions(text)
    out = []
    for f in found:
        made = from_finding(f.file or "", where, f)
        out.append(replace(made, term=f.subject) if f.kind == UNKNOWN_PREDICATE else made)
    return out


UNKNOWN_PREDICATE = "scene-unknown-predicate"
"""Its term (the predicate, as the scene writes it) is judged as the robot resolves
vocabulary (``robot_vocabulary``), like an unknown name in the code."""


def legacy_double_places(path: str, skill: str, facts: StaticDescription,
                         index: OntologyIndex | None, entries: list[SingleValued]
                         ) -> list[Finding]:
    """EZ401 for a legacy description read statically (lines from the source);
    ``entries``: the single-valued relations (``single_valued``)."""
    uses = [RelationUse(which, c.vocabulary, c.subject, c.object, bool(c.desired), c.line,
                        str(c.label or ""))
            for which, c in facts.conditions
            if c.kind == "relation" and c.vocabulary and c.subject and c.object]
    uses = past_typos(uses, (p.key for p in facts.params))
    return [replace(finding("double-place", path, d.second.line, d.message(),
                            fix=d.fix("legacy")), skill=skill)
            for d in double_places(uses, entries, index)]


def ezskiros_double_places(path: str, source: str, models: Iterable[SkillModel],
                           index: OntologyIndex | None, entries: list[SingleValued],
                           posts: PostLines | None = None) -> list[Finding]:
    """EZ401 for loaded EzSkiROS descriptions; the line is that of the post-condition's
    ``+=`` in the class, found in the source (``posts``, when the read stage took them
    from its parse; else parsed only for a finding: on a migrated repository, parsing every
    file for its lines was a third of ``check``)."""
    lines: PostLines | None = posts
    found = []
    for model in models:
        for d in double_places(past_typos(uses_of(model), (p.key for p in model.params)),
                               entries, index):
            if lines is None:
                lines = _post_lines(source)
            line = _line_of(lines.get(model.name, []), d.second) or model.line or 0
            found.append(replace(finding("double-place", path, line, d.message(),
                                         fix=d.fix("ezskiros")), skill=model.name))
    return found


PostLines = dict[str, list[tuple[int, str]]]
"""``{class: [(line, text of the added condition)]}`` of a module (``post_lines``)."""


def _post_lines(source: str) -> PostLines:
    """``post_lines`` of a module's source."""
    if "post_conditions" not in source:
        return {}
    try:
        tree = ast.parse(source)
    except (SyntaxError, ValueError):
        return {}
    return post_lines(tree, source)


def post_lines(tree: ast.Module, source: str) -> PostLines:
    """``{class: [(line, text of the added condition)]}`` for every
    ``self.post_conditions += ...`` in a module (``tree``, parsed from ``source``)."""
    if "post_conditions" not in source:
        return {}
    lines = source.splitlines()
    naming = [n for n, text in enumerate(lines, start=1) if "post_conditions" in text]
    found: PostLines = {}  # (a class or statement spanning no line naming it adds none)
    for node in walk(tree, naming):
        if not isinstance(node, ast.ClassDef):
            continue
        for stmt in walk(node, naming):
            if isinstance(stmt, ast.AugAssign) and isinstance(stmt.target, ast.Attribute) \
                    and stmt.target.attr == "post_conditions":
                found.setdefault(node.name, []).append((stmt.lineno,
                                                        _text_from(lines, stmt.value)))
    return found


def _text_from(lines: list[str], node: ast.expr) -> str:
    """The source of ``node`` from its start to the end of its last line. Not
    ``ast.get_source_segment``, which splits the whole module again for every node (most
    of ``check``'s time on a migrated repository went there)."""
    first = lines[node.lineno - 1].encode()[node.col_offset:].decode(errors="replace")
    return "\n".join([first, *lines[node.lineno:node.end_lineno or node.lineno]])


def _line_of(lines: list[tuple[int, str]], use: RelationUse) -> int:
    """The line of the ``+=`` adding ``use``: it names the relation and both ends."""
    local = use.relation.rpartition(":")[2]
    for line, text in lines:
        if local in text and use.object in text and use.subject in text \
                and not text.lstrip().startswith("~"):
            return line
    return 0


def cannot_start(path: str, skill: str, line: int, model: SkillModel, scene: Scene,
                 index: OntologyIndex) -> Finding | None:
    """EZ409 when the skill cannot be grounded in ``scene``."""
    grounded = can_start(model, scene, index)
    if grounded.ok:
        return None
    return replace(finding("cannot-start", path, line, f"cannot start from scene "
                           f"{Path(scene.path).name}: {grounded.reason}"), skill=skill)




def world_diagnostics(run: WorldRun, legacy: Iterable[tuple[str, FileResult]],
                      loaded: Iterable[tuple[str, list[SkillModel], PostLines | None]],
                      index: OntologyIndex | None, sources: dict[str, str]
                      ) -> list[Diagnostic]:
    """Every EZ4xx diagnostic of a run; the scenes' texts are added to ``sources`` (so that
    ``# ezskiros: ignore[EZ403]`` works in a scene too)."""
    out: list[Diagnostic] = []
    entries = single_valued(index, run.single_valued)  # resolved once per run
    models: list[tuple[str, str, int, SkillModel]] = []
    for path, result in legacy:
        for skill in result.skills:
            if skill.static is not None and skill.status == "converted":
                out += diagnostics_of(legacy_double_places(path, skill.name, skill.static,
                                                           index, entries),
                                      sources.get(path, ""))
            if skill.model is not None and run.start_scene is not None:
                models.append((path, skill.name, skill.line, SkillModel.from_json(skill.model)))
    for path, found, posts in loaded:
        out += diagnostics_of(ezskiros_double_places(path, sources.get(path, ""), found, index,
                                                     entries, posts), sources.get(path, ""))
        models += [(path, m.name, m.line or 0, m) for m in found]
    out += ontology_diagnostics(index, sources)
    reads = read_scenes(run.scenes, index)
    for read, kept in zip(reads, once_per_project([r.findings for r in reads]), strict=True):
        sources[str(read.path)] = read.text
        out += diagnostics_of(kept, read.text)
    if run.start_scene is not None and index is not None:
        out += _start_diagnostics(run.start_scene, models, index, sources)
    return out


def _start_diagnostics(path: Path, models: list[tuple[str, str, int, SkillModel]],
                       index: OntologyIndex, sources: dict[str, str]) -> list[Diagnostic]:
    """EZ409 for every skill that cannot start from the ``--scene`` (which must parse)."""
    scene = read_scene(path)
    out = []
    for file, name, line, model in models:
        found = cannot_start(file, name, line, model, scene, index)
        if found is not None:
            out += diagnostics_of([found], sources.get(file, ""))
    return out


__all__ = ["SceneRead", "cannot_start", "diagnostics_of", "ezskiros_double_places",
           "legacy_double_places", "ontology_diagnostics", "read_scenes", "world_diagnostics"]
