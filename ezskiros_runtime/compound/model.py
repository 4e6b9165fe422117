"""The model of a compound skill: the behaviour tree its ``expand`` builds, as data.

The counterpart of ``ezskiros_runtime.model.SkillModel`` for implementations: which class,
which description type it implements under which label, the root's processor, and the
ordered tree of processor nodes and skill nodes (type, label, remap, specify,
preconditions), each with its source line. Equality and the canonical JSON ignore source
positions and how the tree was obtained, so that a tree read statically, a tree traced by
running ``expand``, and one day a tree migrated to an EzSkiROS form compare equal exactly
when they mean the same composition.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from typing import Any, Literal, Union

Obtained = Literal["static", "traced"]


@dataclass(frozen=True)
class SkillNode:
    """``self.skill("Type", "label", remap={...}, specify={...}, preconditions=[...])``.

    ``remap`` and ``specify`` keep the call's order (SkiROS2 applies them in that order);
    values of ``specify`` are JSON-ready: a literal, or ``{"param": "X"}`` for a value read
    from the compound's own parameters at run time (``self.params["X"].value``).
    """

    type: str
    label: str = ""
    remap: tuple[tuple[str, str], ...] = ()
    specify: tuple[tuple[str, Any], ...] = ()
    preconditions: tuple[str, ...] = ()
    children: tuple[Child, ...] = ()
    """Nodes added by calling this one (``self.skill("X")(...)``): SkiROS2 accepts it."""
    line: int = field(default=0, compare=False)

    def to_json(self, positions: bool = True) -> dict[str, Any]:
        data: dict[str, Any] = {"node": "skill", "type": self.type, "label": self.label,
                                "remap": [list(p) for p in self.remap],
                                "specify": [[k, v] for k, v in self.specify],
                                "preconditions": list(self.preconditions),
                                "children": [c.to_json(positions) for c in self.children]}
        if positions:
            data["line"] = self.line
        return data


@dataclass(frozen=True)
class ProcessorNode:
    """``self.skill(ParallelFs())(...children)``: a processor with ordered children.

    ``processor`` is the class name (``NoFail(Sequential())`` is ``"NoFail(Sequential)"``);
    ``remap``/``specify`` are those passed with it, which SkiROS2 hands to its children.
    """

    processor: str
    children: tuple[Child, ...] = ()
    remap: tuple[tuple[str, str], ...] = ()
    specify: tuple[tuple[str, Any], ...] = ()
    line: int = field(default=0, compare=False)

    def to_json(self, positions: bool = True) -> dict[str, Any]:
        data: dict[str, Any] = {"node": "processor", "processor": self.processor,
                                "remap": [list(p) for p in self.remap],
                                "specify": [[k, v] for k, v in self.specify],
                                "children": [c.to_json(positions) for c in self.children]}
        if positions:
            data["line"] = self.line
        return data


Node = Union[SkillNode, ProcessorNode]


COMPUTED = "(computed at run time)"
"""A remap target, or the key of a ``specify`` value, that only running ``expand`` gives:
a node read where the tree around it cannot be (``CompoundModel.gaps``) keeps its known
parts, and the checks pass such a target by."""


@dataclass(frozen=True)
class CallProblem:
    """A call SkiROS2 cannot use (``self.skill(self.skill(...))``, a number as the type):
    kept in the tree's place so that checks can point at it."""

    message: str
    line: int = field(default=0, compare=False)
    kind: str = "compound-call-shape"
    """The catalogue key of its finding (``processor-undefined`` for a processor class the
    module neither defines nor imports)."""
    subject: str = ""
    """The name it is about (the undefined processor's), for the checks of the same name."""

    def to_json(self, positions: bool = True) -> dict[str, Any]:
        data: dict[str, Any] = {"node": "problem", "message": self.message}
        if self.kind != "compound-call-shape":
            data.update(kind=self.kind, subject=self.subject)
        if positions:
            data["line"] = self.line
        return data


Child = Union[SkillNode, ProcessorNode, CallProblem]


@dataclass(frozen=True)
class CompoundModel:
    """One compound skill implementation and the tree its ``expand`` builds."""

    implementation: str
    description: str | None
    """The description class passed to ``setDescription`` (None when not found)."""
    label: str
    processor: str = "Sequential"
    children: tuple[Child, ...] = ()
    path: str = field(default="", compare=False)
    line: int = field(default=0, compare=False)
    expand_line: int = field(default=0, compare=False)
    obtained: Obtained = field(default="static", compare=False)
    gaps: tuple[tuple[int, str], ...] = field(default=(), compare=False)
    """The statements of ``expand`` the syntax could not give (line, why), when the tree
    was read in part: ``children`` are the nodes of the others, in order."""

    def to_json(self, positions: bool = True) -> dict[str, Any]:
        data: dict[str, Any] = {
            "implementation": self.implementation, "description": self.description,
            "label": self.label, "processor": self.processor,
            "children": [c.to_json(positions) for c in self.children]}
        if positions:
            data.update(path=self.path, line=self.line, expand_line=self.expand_line,
                        obtained=self.obtained)
            if self.gaps:
                data["gaps"] = [list(gap) for gap in self.gaps]
        return data

    def canonical_json(self) -> str:
        """The meaning alone (no positions, not how it was obtained), byte-stable."""
        return json.dumps(self.to_json(positions=False), sort_keys=True,
                          separators=(",", ":"), ensure_ascii=False)

    def walk(self) -> list[tuple[Node | CallProblem, tuple[ProcessorNode, ...]]]:
        """Every node in tree order, with the processor nodes above it."""
        found: list[tuple[Node | CallProblem, tuple[ProcessorNode, ...]]] = []

        def visit(nodes: tuple[Any, ...], above: tuple[ProcessorNode, ...]) -> None:
            for node in nodes:
                found.append((node, above))
                if isinstance(node, ProcessorNode):
                    visit(node.children, (*above, node))
                elif isinstance(node, SkillNode):
                    visit(node.children, above)

        visit(self.children, ())
        return found


def node_from_json(data: dict[str, Any]) -> Node | CallProblem:
    """Rebuild a node from ``to_json`` (the child process sends trees this way)."""
    kind = data["node"]
    if kind == "problem":
        return CallProblem(data["message"], data.get("line", 0),
                           data.get("kind", "compound-call-shape"), data.get("subject", ""))
    children = tuple(node_from_json(c) for c in data.get("children", ()))
    remap = tuple((str(k), str(v)) for k, v in data.get("remap", ()))
    specify = tuple((str(k), v) for k, v in data.get("specify", ()))
    if kind == "processor":
        return ProcessorNode(data["processor"], children, remap, specify, data.get("line", 0))
    return SkillNode(data["type"], data.get("label", ""), remap, specify,
                     tuple(data.get("preconditions", ())), children, data.get("line", 0))


def model_from_json(data: dict[str, Any]) -> CompoundModel:
    """Rebuild a ``CompoundModel`` from ``to_json()``."""
    return CompoundModel(
        data["implementation"], data.get("description"), data.get("label", ""),
        data.get("processor", "Sequential"),
        tuple(node_from_json(c) for c in data.get("children", ())),
        data.get("path", ""), data.get("line", 0), data.get("expand_line", 0),
        data.get("obtained", "static"),
        tuple((int(line), str(why)) for line, why in data.get("gaps", ())))
