"""Compound skills as Mermaid diagrams, for the Markdown review report.

Reviewers read a tree faster than the ``expand`` that builds it: each compound skill is a
flowchart with its root and processors as nodes, children left to right in order, remaps
(``Target→Shelf``) and specifies (``Duration=0.5``) on the edges, and the nodes a finding
points at highlighted, the findings listed below with their codes.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from ezskiros_runtime.codes import rule_for
from ezskiros_runtime.compound.model import (
    CallProblem,
    Child,
    CompoundModel,
    ProcessorNode,
    SkillNode,
)
from ezskiros_runtime.compound.trace import Unanalysable
from ezskiros_runtime.diagnostics import Finding

STYLES = ("    classDef error fill:#fde0e0,stroke:#c62828,stroke-width:2px",
          "    classDef warning fill:#fff4d6,stroke:#b7791f",
          "    classDef info fill:#e3f0fb,stroke:#2b6cb0")
_RANK = {"error": 0, "warning": 1, "info": 2}


def _text(value: object) -> str:
    """Mermaid label text: quotes and angle brackets as entities, one line."""
    return (str(value).replace("&", "&amp;").replace('"', "#quot;").replace("<", "&lt;")
            .replace(">", "&gt;").replace("\n", " "))


def _value(value: object) -> str:
    if isinstance(value, dict) and "param" in value:
        return f"params[{value['param']}]"
    return repr(value)


def _edge(index: int, node: Child) -> str:
    parts = [str(index)]
    if isinstance(node, (SkillNode, ProcessorNode)):
        parts += [f"{k}→{v}" for k, v in node.remap]
        parts += [f"{k}={_value(v)}" for k, v in node.specify]
    return _text(" · ".join(parts))


def mermaid(model: CompoundModel, findings: Sequence[Finding] = ()) -> str:
    """The flowchart of one tree (a fenced ``mermaid`` block)."""
    worst: dict[int, str] = {}
    for finding in findings:
        severity = rule_for(finding.kind).severity
        line = finding.line or 0
        if _RANK[severity] < _RANK.get(worst.get(line, "info"), 3):
            worst[line] = severity
    lines = ["```mermaid", "flowchart TD",
             f'    n0{{{{"{_text(model.implementation)}<br/>{_text(model.processor)}"}}}}']
    counter = [0]

    def add(parent: str, nodes: Sequence[Child]) -> None:
        for position, node in enumerate(nodes, 1):
            counter[0] += 1
            name = f"n{counter[0]}"
            if isinstance(node, ProcessorNode):
                lines.append(f'    {name}{{{{"{_text(node.processor)}"}}}}')
            elif isinstance(node, SkillNode):
                label = f"<br/><i>{_text(node.label)}</i>" if node.label else ""
                lines.append(f'    {name}["{_text(node.type)}{label}"]')
            else:
                lines.append(f'    {name}>"{_text(node.message[:60])}"]')
            lines.append(f'    {parent} -->|"{_edge(position, node)}"| {name}')
            severity = worst.get(node.line) if node.line else None
            if severity is not None or isinstance(node, CallProblem):
                lines.append(f"    class {name} {severity or 'error'}")
            if isinstance(node, (ProcessorNode, SkillNode)):
                add(name, node.children)

    add("n0", model.children)
    return "\n".join([*lines, *STYLES, "```"])


def markdown_section(models: Sequence[tuple[str, CompoundModel | Unanalysable]],
                     findings: Sequence[tuple[str, Finding]]) -> list[str]:
    """``## Compound skills``: a diagram and the findings of each, or ``[]`` for none."""
    if not models:
        return []
    out = ["## Compound skills", ""]
    for path, model in models:
        own = [f for p, f in findings if p == path and f.skill == model.implementation]
        name = Path(path).name
        if isinstance(model, Unanalysable):
            out += [f"### `{model.implementation}` ({name}, line {model.line})", "",
                    f"Not analysed: {model.reason}.", ""]
            continue
        how = "read statically" if model.obtained == "static" else "traced by running expand"
        out += [f"### `{model.implementation}` ({name}, line {model.line})", "",
                f"Implements {model.description or 'an unknown description'}"
                f" as `{model.label}`; tree {how}.", "", mermaid(model, own), ""]
        out += [f"- **{rule_for(f.kind).code}** line {f.line}: {f.message}" for f in own]
        if own:
            out.append("")
    return out
