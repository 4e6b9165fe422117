"""The early checks of a compound skill's tree against the skill index and the ontology.

Every mistake here is silent in SkiROS2: at best a log line when the compound skill runs
(legacy-compound-skills.md §2). Each check is one finding kind with a code in
``ezskiros_runtime.codes`` (EZ3xx). A check reports only what it can prove: a remap whose
child type is unknown, or whose tree below is unknown, is not judged; the blackboard
idioms of the shared doc (a utility remapped to several keys in turn, a value written by a
sibling, a key declared only by a grandchild) stay silent or informational.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable
from dataclasses import dataclass
from typing import TYPE_CHECKING

from .library import ROBOT, DescriptionInfo, SkillIndex, type_name
from .model import CallProblem, CompoundModel, Node, ProcessorNode, SkillNode
from .trace import PARAMETER_OBJECT, Unanalysable, parameter_object_message

if TYPE_CHECKING:
    from ..ontology.index import OntologyIndex

UPSTREAM_PROCESSORS = frozenset({"NoProcessor", "Serial", "SerialStar", "Sequential",
                                 "Selector", "SelectorStar", "ParallelFf", "ParallelFs",
                                 "NoFail"})
ELSEWHERE = {"RetryOnFail": "the upstream branch ros2_roscon24_workshop (the ROSCon 2024 "
                            "workshop's, which the public pyrobosim skill library targets)"}
"""Where a processor that upstream's other branches lack does exist (shared doc §3)."""
_MAX_DEPTH = 16
OBTAINED = {"static": "tree read statically", "traced": "tree traced by running expand"}
"""How the tree a finding is about was obtained, as every finding says it."""


def _did_you_mean(key: str, candidates: set[str]) -> str | None:
    """The closest spelling; else the one parameter left that is not ``Robot`` (``Wait``
    given ``Time``: ``Duration`` is all it has)."""
    close = difflib.get_close_matches(key, sorted(candidates), 1, 0.6)
    if close:
        return f"Did you mean {close[0]!r}?"
    left = sorted(candidates - {ROBOT})
    return f"Did you mean {left[0]!r}?" if len(left) == 1 else None


@dataclass(frozen=True)
class CompoundFinding:
    """One finding: its kind (a catalogue key), line, the compound class and the child."""

    kind: str
    line: int
    message: str
    implementation: str
    child: str = ""
    suggestion: str | None = None
    severity: str | None = None
    """Lower than the code's own when the finding rests on something not resolved."""


def check_model(model: CompoundModel | Unanalysable, index: SkillIndex,
                ontology: OntologyIndex | None = None) -> list[CompoundFinding]:
    """Every finding of one compound skill, in tree order."""
    if isinstance(model, Unanalysable):
        return [CompoundFinding("compound-unanalysable", model.line,
                                f"the tree of {model.implementation} could not be read "
                                f"statically nor traced ({model.reason}); it is not checked",
                                model.implementation)]
    return _Checker(model, index, ontology).run()


class _Checker:
    def __init__(self, model: CompoundModel, index: SkillIndex,
                 ontology: OntologyIndex | None) -> None:
        self.model = model
        self.index = index
        self.ontology = ontology
        self.found: list[CompoundFinding] = []
        self.parent = index.descriptions.get(model.description or "")

    def add(self, kind: str, line: int, message: str, child: str = "",
            suggestion: str | None = None, severity: str | None = None) -> None:
        how = OBTAINED[self.model.obtained]
        self.found.append(CompoundFinding(kind, line or self.model.expand_line,
                                          f"{message} ({how})", self.model.implementation,
                                          child, suggestion, severity))

    def _one(self, matches: list[DescriptionInfo]) -> DescriptionInfo | None:
        """The one description a child type names, seen from this compound's file (None
        when several match, or several files of the repository define it equally near
        with different parameters)."""
        if len(matches) != 1:
            return None
        found = self.index.nearest(matches[0], self.model.path)
        if any(f.params != found[0].params or f.complete != found[0].complete
               for f in found[1:]):
            return None
        return found[0]

    def run(self) -> list[CompoundFinding]:
        self._processor(self.model.processor, self.model.expand_line)
        nodes = self.model.walk()
        for node, _ in nodes:
            if isinstance(node, CallProblem):
                self.add("compound-call-shape", node.line, node.message)
            elif isinstance(node, ProcessorNode):
                self._processor(node.processor, node.line)
            else:
                self._skill(node, [n for n, _ in nodes if n is not node])
        return self.found

    def _processor(self, name: str, line: int) -> None:
        for part in name.replace(")", "").split("("):
            if part and part not in UPSTREAM_PROCESSORS:
                where = ELSEWHERE.get(part, "forks of SkiROS2 only")
                self.add("processor-not-upstream", line,
                         f"processor {part} is not on SkiROS2's master and ros2 branches; it "
                         f"exists on {where}: the tree runs only where that is installed",
                         part)

    # -- one child ----------------------------------------------------------------------

    def _skill(self, node: SkillNode, others: list[Node | CallProblem]) -> None:
        matches, literal = self.index.resolve(node.type)
        if not matches:
            name = type_name(node.type)
            own = {self.model.description, self.model.implementation}
            close = difflib.get_close_matches(  # a description type, never this compound's
                name, [n for n in self.index.names() if n not in own], 1, 0.6)
            hint = f"Did you mean {close[0]!r}?" if close else None
            why = (f" ({name} is a base other descriptions derive from; the skill manager "
                   "loads only leaf descriptions)" if name in self.index.bases else "")
            unread = self.index.unread
            if unread:
                why += (f"; {len(unread)} file(s) of the repository could not be read "
                        f"({', '.join(unread[:3])}), so it may be defined there")
            self.add("unknown-child-type", node.line,
                     f"child type {node.type!r} matches no description the skill manager "
                     "could load (the repository, skiros2_std_lib, [tool.ezmigrate] "
                     f"skill-libraries){why}: the compound skill fails when it runs",
                     node.type, hint, "info" if unread else None)
            return
        if not literal:
            names = ", ".join(d.name for d in matches)
            self.add("regex-child-type", node.line,
                     f"child type {node.type!r} matches {names} only as a regular "
                     "expression (SkiROS2 matches types with re.match)", node.type,
                     f"Write the type name exactly: {matches[0].name!r}.")
        if len(matches) != 1:
            return
        definitions = self.index.nearest(matches[0], self.model.path)
        found = []
        for child in definitions:  # two packages define the type: what holds for both
            before, self.found = self.found, []
            self._judge(node, child, others)
            found.append(self.found)
            self.found = before
        self.found += [f for f in found[0] if all(
            any((g.kind, g.message) == (f.kind, f.message) for g in other)
            for other in found[1:])]

    def _judge(self, node: SkillNode, child: DescriptionInfo,
               others: list[Node | CallProblem]) -> None:
        self._label(node, child)
        unlaunched = self.index.launched_implementations(child.name, self.model.path)
        if unlaunched is not None and child.origin.startswith("repository"):
            self.add("child-not-launched", node.line,
                     f"child type {child.name} is implemented by {', '.join(unlaunched)}, "
                     "none of which the launch file's skill_list loads: the skill manager "
                     "would not find it", node.type)
        if not child.complete:
            return
        renamed = self._remaps(node, child)
        self._specify(node, child, renamed)
        self._dangling(node, others)

    def _label(self, node: SkillNode, child: DescriptionInfo) -> None:
        implements = self.index.implementations.get(node.label) if node.label else None
        if implements is not None and implements != child.name:
            self.add("label-other-type", node.line,
                     f"label {node.label!r} names an implementation of {implements}, not of "
                     f"{child.name}: SkiROS2 runs it anyway (upstream issue #80)", node.type)

    def _remaps(self, node: SkillNode, child: DescriptionInfo) -> dict[str, str]:
        """Check each remap; return the renames SkiROS2 applies (child key -> new key)."""
        declared = child.declared()
        renamed: dict[str, str] = {}
        for key, target in node.remap:
            if key in declared:
                if target in declared and target != key:
                    self.add("remap-onto-declared", node.line,
                             f"remap {key!r} -> {target!r}: {child.name} already declares "
                             f"{target!r}, so SkiROS2 rejects the remap and renames nothing",
                             node.type)
                    continue
                renamed[key] = target
                self._element_types(node, child, key, target)
                continue
            _, complete = self._descendant_keys(node, child)
            reached, taken = self._reach(node, child)
            if key in reached:
                self.add("remap-key-descendant", node.line,
                         f"remap key {key!r} is declared not by {child.name} but below it; "
                         "SkiROS2 passes the remap down to it", node.type)
            elif key in taken:
                self.add("remap-key-remapped-below", node.line,
                         f"remap key {key!r}: the node below {child.name} that declares it "
                         f"already remapped it ({taken[key]!r}), so SkiROS2 refuses this "
                         "second remap there (\"already remapped\") and the value never "
                         "reaches it", node.type,
                         f"Remap {taken[key]!r} instead, the name it has after the remap "
                         "below.")
            elif complete:
                self.add("remap-key-unknown", node.line,
                         f"remap key {key!r}: neither {child.name} nor anything below it "
                         "declares it, so the remap does nothing", node.type,
                         _did_you_mean(key, declared - {k for k, _ in node.remap}))
        return renamed

    def _specify(self, node: SkillNode, child: DescriptionInfo,
                 renamed: dict[str, str]) -> None:
        keys = {renamed.get(k, k) for k in child.declared()}
        specified = {k for k, _ in node.specify}
        for key, value in node.specify:
            if isinstance(value, dict) and PARAMETER_OBJECT in value:
                self.add("specify-parameter-object", node.line,
                         parameter_object_message(str(value[PARAMETER_OBJECT])), node.type,
                         f"Write self.params[{value[PARAMETER_OBJECT]!r}].value.")
            if key not in keys:
                why = f" (remapped, it is called {renamed[key]!r})" if key in renamed else ""
                if key in self.index.self_added.get(child.name, ()):
                    why = (" (an implementation adds it in modifyDescription to itself, "
                           "self.addParam, not to the wrapper the tree holds, skill.addParam)")
                self.add("specify-key-unknown", node.line,
                         f"specify key {key!r}: {child.name} has no such parameter after "
                         f"remapping{why}, so SkiROS2 drops the value", node.type,
                         f"Did you mean {renamed[key]!r}?" if key in renamed
                         else _did_you_mean(key, keys - specified))

    def _dangling(self, node: SkillNode, others: list[Node | CallProblem]) -> None:
        if not node.remap or self.parent is None or not self.parent.complete:
            return
        written, complete = self._written(others)
        if not complete:
            return
        for key, target in node.remap:
            if target not in self.parent.declared() and target not in written:
                close = difflib.get_close_matches(target, sorted(self.parent.declared()), 1, 0.6)
                self.add("remap-dangling", node.line,
                         f"remap {key!r} -> {target!r}: no parameter of "
                         f"{self.parent.name} and no other node of the tree declares "
                         f"{target!r}, so it connects to nothing", node.type,
                         f"Did you mean {close[0]!r}?" if close else None)

    def _element_types(self, node: SkillNode, child: DescriptionInfo, key: str,
                       target: str) -> None:
        if self.ontology is None or self.parent is None or not self.parent.complete:
            return
        mine, theirs = child.element_type(key), self.parent.element_type(target)
        if mine is None or theirs is None or target not in self.parent.declared():
            return
        onto = self.ontology
        sub, sup = onto.expand(theirs), onto.expand(mine)
        if sub is None or sup is None or not onto.is_class(sub) or not onto.is_class(sup):
            return
        from ..ontology.expressions import Named

        if onto.is_subclass(sub, sup):
            return
        if onto.can_satisfy(sub, Named(sup)) is False:
            self.add("remap-disjoint", node.line,
                     f"remap {key!r} -> {target!r}: {self.parent.name}'s {target} is "
                     f"{theirs} and {child.name}'s {key} is {mine}; no element can be both",
                     node.type)
        else:
            self.add("remap-narrower", node.line,
                     f"remap {key!r} -> {target!r}: {child.name}'s {key} wants {mine}, "
                     f"narrower than {self.parent.name}'s {target} ({theirs})", node.type)

    # -- what reaches where -------------------------------------------------------------

    def _descendant_keys(self, node: SkillNode, child: DescriptionInfo,
                         seen: frozenset[str] = frozenset()) -> tuple[set[str], bool]:
        """Keys declared below ``node``: its own children and its type's compound trees.

        Complete only when every type below resolves and every compound tree below is
        known; a type that contains itself (directly or further down) is not complete.
        """
        if child.name in seen or len(seen) > _MAX_DEPTH or not child.complete:
            return set(), False
        seen = seen | {child.name}
        keys: set[str] = set()
        complete = self._below(node.children, keys, seen)
        if child.name in self.index.unknown_compounds:
            complete = False
        for tree in self.index.compounds.get(child.name, ()):
            complete &= self._below(tree.children, keys, seen)
        return keys, complete

    def _reach(self, node: SkillNode, child: DescriptionInfo,
               seen: frozenset[str] = frozenset()) -> tuple[set[str], dict[str, str]]:
        """Keys below ``node`` that a remap passed down would still rename, and keys a node
        below already remapped (key -> its new name): SkiROS2 drops a second remap of a
        key at the node that remapped it first, and does not pass it further down."""
        reached: set[str] = set()
        taken: dict[str, str] = {}
        if child.name in seen or len(seen) > _MAX_DEPTH or not child.complete:
            return reached, taken
        seen = seen | {child.name}
        nodes: list[Node | CallProblem] = list(node.children)
        for tree in self.index.compounds.get(child.name, ()):
            nodes += tree.children
        for below in nodes:
            self._reach_node(below, reached, taken, seen)
        return reached, taken

    def _reach_node(self, node: Node | CallProblem, reached: set[str],
                    taken: dict[str, str], seen: frozenset[str]) -> None:
        if isinstance(node, CallProblem):
            return
        keys: set[str] = set()
        if isinstance(node, ProcessorNode):
            for inner in node.children:
                self._reach_node(inner, keys, taken, seen)
        else:
            matches, _ = self.index.resolve(node.type)
            child = self._one(matches)
            if child is None:
                return
            keys = child.declared()
            deeper, deeper_taken = self._reach(node, child, seen)
            keys |= deeper
            for key, target in deeper_taken.items():
                taken.setdefault(key, target)
        for key, target in node.remap:
            if key in keys:
                keys.discard(key)
                keys.add(target)
                taken.setdefault(key, target)
        reached |= keys

    def _below(self, nodes: Iterable[Node | CallProblem], keys: set[str],
               seen: frozenset[str]) -> bool:
        complete = True
        for node in nodes:
            if isinstance(node, CallProblem):
                continue
            if isinstance(node, ProcessorNode):
                complete &= self._below(node.children, keys, seen)
                continue
            matches, _ = self.index.resolve(node.type)
            child = self._one(matches)
            if child is None:
                complete = False
                continue
            keys.update(child.declared())
            below, whole = self._descendant_keys(node, child, seen)
            keys |= below
            complete &= whole
        return complete

    def _written(self, others: list[Node | CallProblem]) -> tuple[set[str], bool]:
        """Blackboard keys the other nodes declare or remap onto (and those below them)."""
        keys: set[str] = set()
        complete = True
        for node in others:
            if not isinstance(node, SkillNode):
                continue
            keys.update(target for _, target in node.remap)
            matches, _ = self.index.resolve(node.type)
            child = self._one(matches)
            if child is None or not child.complete:
                complete = False
                continue
            keys.update(child.declared())
            below, whole = self._descendant_keys(node, child)
            keys |= below
            complete &= whole
        return keys, complete
