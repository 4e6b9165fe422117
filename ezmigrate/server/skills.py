"""Child skills at a cursor: ``self.skill("Type", "label", ...)`` read from the line, and
what the skill index of the last check knows of them (their parameters, where their
description is, which implementations carry which label).

The index is ``check``'s own (``checking/skill_index.py``): the workspace's descriptions,
the standard library's and the configured skill libraries'.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ezskiros_runtime.compound.library import DescriptionInfo, SkillIndex
    from ezskiros_runtime.model import SkillModel

_CALL = re.compile(r"""\.skill\(\s*(["'])([^"']*)\1(?:\s*,\s*(["'])([^"']*)\3?)?""")
_KEY = re.compile(r"""(?:specify|remap)\s*=\s*\{[^}]*?(["'])([^"']*)$""")


@dataclass(frozen=True)
class ChildAt:
    """A ``self.skill`` call under the cursor: its type, its label, and which of the two
    (or a ``specify``/``remap`` key) the cursor is in, with the span of that string."""

    kind: str
    """"type", "label" or "key"."""
    type: str
    label: str | None
    typed: str
    """What is written in the string up to the cursor."""
    start: int
    end: int


def child_at(text: str, line: int, character: int) -> ChildAt | None:
    """The child-skill string the cursor is in, if any."""
    lines = text.splitlines()
    if not 0 <= line < len(lines):
        return None
    row = lines[line]
    for match in _CALL.finditer(row):
        if match.start(2) <= character <= match.end(2):
            return ChildAt("type", match.group(2), match.group(4), row[match.start(2):character],
                           match.start(2), match.end(2))
        if match.group(4) is not None and match.start(4) <= character <= match.end(4):
            return ChildAt("label", match.group(2), match.group(4),
                           row[match.start(4):character], match.start(4), match.end(4))
        key = _KEY.search(row[:character])
        if key is not None and key.start() > match.start():
            return ChildAt("key", match.group(2), match.group(4), key.group(2),
                           key.start(2), character)
    return None


def hover_text(skills: SkillIndex, child: ChildAt) -> str | None:
    """Markdown: the child's description, its parameters, its conditions (when its file
    reads from its syntax) and where it is declared; for a label, the description its
    implementation sets."""
    info = skills.descriptions.get(child.type)
    if child.kind == "label" and child.label:
        implements = skills.implementations.get(child.label)
        if implements is None:
            return f"**{child.label}**: no implementation the check knows has this label"
        return f"**{child.label}**: implements {implements}"
    if info is None:
        return None
    return _described(info)


def _described(info: DescriptionInfo) -> str:
    rows = [f"**{info.name}** ({info.origin})"]
    if info.params:
        rows.append("\n".join(f"- `{key}`: {kind or 'value'}"
                              for key, kind in info.params.items()))
    elif not info.complete:
        rows.append("parameters not known (the description could not be read)")
    model = model_of(info)
    if model is not None:
        from ezskiros_runtime.notation import render_condition

        for which, title in (("pre", "pre-conditions"), ("hold", "hold-conditions"),
                             ("post", "post-conditions")):
            listed = model.conditions(which)
            if listed:
                rows.append(f"{title}:\n" + "\n".join(f"- `{render_condition(c)}`"
                                                       for c in listed))
    if info.path:
        rows.append(f"declared at {info.path}:{info.line}")
    return "\n\n".join(rows)


def completions(skills: SkillIndex, child: ChildAt) -> list[tuple[str, str]]:
    """``(label, detail)``: description types, the labels of a type's implementations, or
    the parameter keys of the child's description."""
    if child.kind == "type":
        return [(name, info.origin) for name, info in sorted(skills.descriptions.items())
                if name.startswith(child.typed)]
    if child.kind == "label":
        return [(label, f"implements {described}")
                for label, described in sorted(skills.implementations.items())
                if described == child.type and label.startswith(child.typed)]
    info = skills.descriptions.get(child.type)
    if info is None:
        return []
    return [(key, kind or "value") for key, kind in info.params.items()
            if key.startswith(child.typed)]


def definition(skills: SkillIndex, child: ChildAt, root: Path) -> tuple[str, int] | None:
    """``(path, 1-based line)`` of the child's description class, or of the
    implementation class a label names (the class of that name in the workspace: SkiROS2
    labels an implementation by its class name unless it says otherwise)."""
    if child.kind == "label" and child.label:
        return _class_in(root, child.label)
    info = skills.descriptions.get(child.type)
    if info is None or not info.path or child.kind != "type":
        return None
    return info.path, info.line


def _class_in(root: Path, name: str) -> tuple[str, int] | None:
    """The first ``class NAME`` of the workspace's Python files."""
    from ..files.discover import discover

    pattern = re.compile(rf"^class\s+{re.escape(name)}\b", re.MULTILINE)
    found, _ = discover([root])
    for candidate in found:
        try:
            text = candidate.path.read_text(encoding="utf-8", errors="replace")
        except OSError:
            continue
        match = pattern.search(text)
        if match is not None:
            return str(candidate.path), text.count("\n", 0, match.start()) + 1
    return None


def model_of(info: DescriptionInfo) -> SkillModel | None:
    """The description's whole model (its conditions too), read from its file's syntax as
    ``check`` reads it: a plain legacy description, or an EzSkiROS one read statically.
    None when the file does not read so (the hover then shows the parameters alone)."""
    import ast

    from ezskiros_runtime.model import SkillModel

    from ..lint.plain_reader import Declined, read_plain

    try:
        data = Path(info.path).read_bytes()
        tree = ast.parse(data)
    except (OSError, SyntaxError, ValueError):
        return None
    if b"ezskiros_runtime" in data:
        from ..lint.ezskiros_static import read_ezskiros_statically

        models = read_ezskiros_statically(tree, info.path).outcome().models
        found = [m for m in models if m.get("name") == info.name]
        return SkillModel.from_json(found[0]) if found else None
    read = read_plain(data, info.path, tree)
    if isinstance(read, Declined):
        return None
    for skill in read.skills:
        if skill.name == info.name and skill.model is not None:
            return SkillModel.from_json(skill.model)
    return None
