"""A scene's spatial tree as a Mermaid flowchart: what a person would rather look at than
500 lines of Turtle.

Each element of the world is a node (its label, its class, its name in the file), each
spatial relation (``contain``, ``hasA``, any sub-property of ``spatiallyRelated``) an edge
from parent to child. Elements a finding is about are highlighted, an object defined
nowhere is drawn dashed. What SkiROS2 saves about itself (skills, parameters) is left out:
it is not part of the world. ``ezmigrate scene FILE`` prints it; the Markdown report of
``rewrite`` draws every scene of the repository.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from ezskiros_runtime.diagnostics import Finding
from ezskiros_runtime.world.scene import Relation, Scene, individuals_of
from ezskiros_runtime.world.scene_checks import bookkeeping
from ezskiros_runtime.world.vocabulary import spatial_properties

from .world_model import read_scenes

if TYPE_CHECKING:
    from ezskiros_runtime.ontology.index import OntologyIndex


def _text(value: str) -> str:
    """Text safe inside a quoted Mermaid label."""
    return (value.replace("&", "&amp;").replace('"', "#quot;").replace("<", "&lt;")
            .replace(">", "&gt;"))


def mermaid(scene: Scene, findings: Iterable[Finding],
            index: OntologyIndex | None) -> str:
    """The flowchart (Mermaid source, no fence)."""
    own = bookkeeping(scene, index)
    spatial = spatial_properties(index)
    flagged = {f.subject for f in findings}
    edges = [r for r in scene.relations if r.property in spatial and r.subject not in own]
    shown = _tree_order(sorted((iri for iri in scene.elements if iri not in own),
                               key=lambda iri: scene.elements[iri].line), edges)
    elsewhere = individuals_of(index) if index is not None else {}
    ids = {iri: f"n{i}" for i, iri in enumerate(shown)}
    out = ["flowchart TD"]
    for iri in shown:
        element = scene.elements.get(iri)
        name = scene.compact(iri)
        if element is None:
            where = "in the ontology" if iri in elsewhere else "nowhere"
            out.append(f'    {ids[iri]}["{_text(name)}<br/><i>defined {where}</i>"]')
            continue
        classes = ", ".join((index.compact(t) if index is not None else scene.compact(t))
                            for t in element.types) or "no class"
        title = f"{_text(element.label)}<br/>" if element.label else ""
        out.append(f'    {ids[iri]}["{title}<i>{_text(classes)}</i><br/>{_text(name)}"]')
    for r in sorted(edges, key=lambda r: (r.line, ids[r.object])):
        relation = scene.compact(r.property).rpartition(":")[2]
        out.append(f"    {ids[r.subject]} -->|{_text(relation)}| {ids[r.object]}")
    missing = [ids[iri] for iri in shown if iri not in scene.elements
               and iri not in elsewhere]
    marked = [ids[iri] for iri in shown if iri in flagged]
    if marked:
        out += ["    classDef finding fill:#fdd,stroke:#c00,stroke-width:2px",
                f"    class {','.join(marked)} finding"]
    if missing:
        out += ["    classDef missing stroke-dasharray: 5 5",
                f"    class {','.join(missing)} missing"]
    return "\n".join(out) + "\n"


def _tree_order(elements: list[str], edges: list[Relation]) -> list[str]:
    """Roots first, each followed by its subtree (depth first, in file order): the order
    a reader expects; elements no edge reaches come as further roots."""
    children: dict[str, list[str]] = {}
    for r in sorted(edges, key=lambda r: r.line):
        children.setdefault(r.subject, []).append(r.object)
    has_parent = {r.object for r in edges}
    every = list(dict.fromkeys([*elements, *(i for r in edges for i in (r.subject, r.object))]))
    ordered: list[str] = []
    for root in [e for e in every if e not in has_parent] + every:
        todo = [root]
        while todo:
            iri = todo.pop()
            if iri not in ordered:
                ordered.append(iri)
                todo += reversed(children.get(iri, []))
    return ordered


def markdown_section(paths: Sequence[Path], index: OntologyIndex | None,
                     root: Path | None = None) -> list[str]:
    """The report's "Scenes" section: per scene its findings and its tree ([] when the
    repository has no scene)."""
    if not paths:
        return []
    out = ["## Scenes", ""]
    for read in read_scenes(paths, index):
        shown = read.path.relative_to(root) if root is not None and read.path.is_relative_to(
            root) else read.path
        out += [f"### `{shown}`", ""]
        for f in read.findings:
            out.append(f"- line {f.line}: **{f.code}** {f.message}")
        if read.findings:
            out.append("")
        if read.scene is not None:
            out += ["```mermaid", mermaid(read.scene, read.findings, index).rstrip(), "```",
                    ""]
    return out


__all__ = ["markdown_section", "mermaid"]
