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
from collections import Counter
from collections.abc import Callable, Collection, Iterable, Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import TYPE_CHECKING, Any, Generic, TypeVar

from ..codes import rule_for
from ..diagnostics import Finding
from .library import ROBOT, DescriptionInfo, SkillIndex, type_name
from .model import COMPUTED, CallProblem, CompoundModel, Node, ProcessorNode, SkillNode
from .trace import PARAMETER_OBJECT, Unanalysable, parameter_object_message

if TYPE_CHECKING:
    from ..ontology.index import OntologyIndex

UPSTREAM_PROCESSORS = frozenset({"NoProcessor", "Serial", "SerialStar", "Sequential",
                                 "Selector", "SelectorStar", "ParallelFf", "ParallelFs",
                                 "NoFail"})
ELSEWHERE = {"RetryOnFail": "the upstream branch ros2_roscon24_workshop (the ROSCon 2024 "
                            "workshop's, which the public pyrobosim skill library targets)",
             **dict.fromkeys(("Loop", "InferInvalid"), "forks of SkiROS2 only")}
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


def compound_finding(kind: str, line: int, message: str, implementation: str,
                     child: str = "", suggestion: str | None = None,
                     severity: str | None = None) -> Finding:
    """One finding of a compound skill, as the runtime's one ``Finding`` type: its kind (a
    catalogue key), line, the compound class (``skill``) and the child (``subject``);
    ``severity`` lower than the code's own when the finding rests on something not
    resolved."""
    return Finding(kind, severity or rule_for(kind).severity, message, None, line,
                   implementation, subject=child, fix=suggestion)


def check_model(model: CompoundModel | Unanalysable, index: SkillIndex,
                ontology: OntologyIndex | None = None) -> list[Finding]:
    """Every finding of one compound skill, in tree order."""
    if isinstance(model, Unanalysable):
        return [compound_finding("compound-unanalysable", model.line,
                                f"the tree of {model.implementation} could not be read "
                                f"statically nor traced ({model.reason}); it is not checked",
                                model.implementation)]
    unread = [compound_finding("compound-unanalysable", model.gaps[0][0],
                              f"part of the tree of {model.implementation} is not read: "
                              f"{'; '.join(why for _, why in model.gaps)}, which only "
                              "running expand gives (check --trace runs it in the sandbox); "
                              "the other statements' nodes are checked",
                              model.implementation)] if model.gaps else []
    return unread + _Checker(model, index, ontology).run()


T = TypeVar("T")
NOTHING_TAKEN: Mapping[str, str] = MappingProxyType({})


class _View:
    """The skill index as one compound skill's file sees it, each question asked once.

    A tree names the same few types again and again, and what lies below a node is asked
    for every other node of the tree: asking the index each time made a tree's check
    quadratic in its size, each answer comparing file paths (issue 31). Nothing changes the
    index while a tree is checked and the file is fixed, so each answer here depends on the
    type alone and is kept by it. Answers are shared: callers must not change them.
    """

    def __init__(self, index: SkillIndex, path: str) -> None:
        self.index = index
        self.path = path
        self._resolved: dict[str, tuple[list[DescriptionInfo], bool]] = {}
        self._nearest: dict[str, list[DescriptionInfo]] = {}
        self._one: dict[str, DescriptionInfo | None] = {}
        self._launched: dict[str, list[str] | None] = {}

    def resolve(self, stype: str) -> tuple[list[DescriptionInfo], bool]:
        """``SkillIndex.resolve`` of a child's type."""
        if stype not in self._resolved:
            self._resolved[stype] = self.index.resolve(stype)
        return self._resolved[stype]

    def nearest(self, info: DescriptionInfo) -> list[DescriptionInfo]:
        """``SkillIndex.nearest`` from this file. By name: ``info`` is always the index's
        own description of that name (``resolve`` returns nothing else)."""
        if info.name not in self._nearest:
            self._nearest[info.name] = self.index.nearest(info, self.path)
        return self._nearest[info.name]

    def one(self, stype: str) -> DescriptionInfo | None:
        """The one description a child type names, seen from this file (None when several
        match, or several files of the repository define it equally near with different
        parameters)."""
        if stype not in self._one:
            self._one[stype] = self._only(self.resolve(stype)[0])
        return self._one[stype]

    def _only(self, matches: list[DescriptionInfo]) -> DescriptionInfo | None:
        if len(matches) != 1:
            return None
        found = self.nearest(matches[0])
        if any(f.params != found[0].params or f.complete != found[0].complete
               for f in found[1:]):
            return None
        return found[0]

    def launched_implementations(self, description: str) -> list[str] | None:
        """``SkillIndex.launched_implementations`` for this file."""
        if description not in self._launched:
            self._launched[description] = self.index.launched_implementations(description,
                                                                               self.path)
        return self._launched[description]


@dataclass(frozen=True)
class _Expansion(Generic[T]):
    """What a walk below one node found, and what that answer rests on.

    A walk stops where a type repeats (a tree containing itself) or beyond ``_MAX_DEPTH``
    levels, so its answer depends on the types above it (``seen``). ``names`` are the types
    the walk tested against ``seen``, ``depth`` the deepest level below its start that it
    tested: a walk done with nothing above gives the same answer under any ``seen`` that
    shares none of ``names`` and keeps every tested level within the limit.
    """

    value: T
    names: frozenset[str]
    depth: int

    def holds_under(self, seen: frozenset[str]) -> bool:
        """Whether this answer, found with nothing above, is also the answer under ``seen``."""
        return not seen or (self.names.isdisjoint(seen)
                            and len(seen) + self.depth <= _MAX_DEPTH)


class _Trail:
    """The names and depth of a walk being done (see ``_Expansion``)."""

    def __init__(self, name: str) -> None:
        self.names = {name}
        self.depth = 0

    def add(self, below: _Expansion[Any]) -> None:
        """A walk one level further down, done or answered from the memo."""
        self.names |= below.names
        self.depth = max(self.depth, below.depth + 1)

    def done(self, value: T) -> _Expansion[T]:
        return _Expansion(value, frozenset(self.names), self.depth)


class _Walks(Generic[T]):
    """One kind of walk below nodes, each kept by (the node's children, the child's type).

    Every walk is first done with nothing above (``fresh``) and reused wherever
    ``holds_under`` proves it gives the same answer; only where it does not (near a cycle
    or the depth limit) is it done again for that ``seen`` and kept for it (``exact``). So
    each type's tree is walked once per checked tree, not once per path that reaches it.
    Nodes without children of their own (nearly all) share their type's walk; those with
    children are told apart by the children's identity, alive in the model while it is
    checked.
    """

    def __init__(self, walk: Callable[[SkillNode, DescriptionInfo, frozenset[str]],
                                      _Expansion[T]], stopped: T) -> None:
        self.walk = walk
        self.stopped = stopped
        self.fresh: dict[tuple[int, str], _Expansion[T]] = {}
        self.exact: dict[tuple[int, str, frozenset[str]], _Expansion[T]] = {}
        self.open: list[tuple[int, str] | None] = []
        """The walks in progress, innermost last: a fresh one's key, None for an exact one."""

    def below(self, node: SkillNode, child: DescriptionInfo,
              seen: frozenset[str] = frozenset()) -> _Expansion[T]:
        """The walk below ``node`` (whose type is ``child``) under the types ``seen``."""
        if child.name in seen or len(seen) > _MAX_DEPTH or not child.complete:
            return _Expansion(self.stopped, frozenset({child.name}), 0)
        key = (id(node.children) if node.children else 0, f"{child.name}\0{node.label}")
        fresh = self.fresh.get(key)
        if fresh is None and self._may_start(key):
            fresh = self.fresh[key] = self._run(key, node, child, frozenset())
        if fresh is not None and fresh.holds_under(seen):
            return fresh
        exact = self.exact.get((key[0], key[1], seen))
        if exact is None:
            exact = self.exact[(key[0], key[1], seen)] = self._run(None, node, child, seen)
        return exact

    def _may_start(self, key: tuple[int, str]) -> bool:
        """A fresh walk starts at the top or right below another fresh one, never inside
        itself, and at most ``_MAX_DEPTH`` deep: the stack stays as shallow as the walks
        it replaces (one redone for its ``seen`` starts none, and goes where they went)."""
        if not self.open:
            return True
        return self.open[-1] is not None and key not in self.open \
            and len(self.open) <= _MAX_DEPTH

    def _run(self, key: tuple[int, str] | None, node: SkillNode, child: DescriptionInfo,
             seen: frozenset[str]) -> _Expansion[T]:
        self.open.append(key)
        try:
            return self.walk(node, child, seen)
        finally:
            self.open.pop()


class _Writes:
    """What the skill nodes of one tree write on the blackboard, counted once per tree.

    Each node's share (its remap targets, its type's keys and the keys below it) is
    counted over the tree, so that what the *other* nodes write is the count less the
    node's own share: it used to be the union over every other node, done again for every
    node. A node object may stand at several places of a tree: all of them are its own.
    """

    def __init__(self, shares: Iterable[tuple[SkillNode, frozenset[str], bool]]) -> None:
        self.counts: Counter[str] = Counter()
        self.unknown = 0
        """Places whose share is not completely known."""
        self.own: dict[int, tuple[frozenset[str], bool, int]] = {}
        for node, keys, whole in shares:
            self.counts.update(keys)
            self.unknown += not whole
            times = self.own[id(node)][2] if id(node) in self.own else 0
            self.own[id(node)] = (keys, whole, times + 1)

    def complete_without(self, node: SkillNode) -> bool:
        """Whether every other node's share is completely known."""
        _, whole, times = self.own[id(node)]
        return self.unknown == (0 if whole else times)

    def by_others(self, node: SkillNode, key: str) -> bool:
        """Whether a node other than ``node`` writes ``key``."""
        keys, _, times = self.own[id(node)]
        return self.counts[key] > (times if key in keys else 0)


class _Checker:
    """The checks of one tree. What the index says about a type, what lies below a node
    and what each node writes are each worked out once for the tree (``_View``, ``_Walks``,
    ``_Writes``) and then asked for freely: the cost follows the size of the tree."""

    def __init__(self, model: CompoundModel, index: SkillIndex,
                 ontology: OntologyIndex | None) -> None:
        self.model = model
        self.index = index
        self.ontology = ontology
        self.found: list[Finding] = []
        self.parent = index.descriptions.get(model.description or "")
        self.nodes = model.walk()
        self.view = _View(index, model.path)
        self.keys: _Walks[tuple[frozenset[str], bool]] = _Walks(self._keys_walk,
                                                                (frozenset(), False))
        self.reaches: _Walks[tuple[frozenset[str], Mapping[str, str]]] = _Walks(
            self._reach_walk, (frozenset(), NOTHING_TAKEN))
        self.writes: _Writes | None = None
        self.remapped_below: set[int] | None = None
        """Nodes some node above them in the tree remaps for (``_inherits_remap``)."""
        self.hints: dict[str, str | None] = {}
        self.undefined = frozenset(n.subject for n, _ in self.nodes if isinstance(n, CallProblem)
                                   and n.kind == "processor-undefined")
        """Processors the module defines nowhere (EZ317): not judged again as a fork's."""

    def add(self, kind: str, line: int, message: str, child: str = "",
            suggestion: str | None = None, severity: str | None = None) -> None:
        how = OBTAINED[self.model.obtained]
        self.found.append(compound_finding(kind, line or self.model.expand_line,
                                          f"{message} ({how})", self.model.implementation,
                                          child, suggestion, severity))

    def run(self) -> list[Finding]:
        self._processor(self.model.processor, self.model.expand_line)
        for node, _ in self.nodes:
            if isinstance(node, CallProblem):
                self.add(node.kind, node.line, node.message)
            elif isinstance(node, ProcessorNode):
                self._processor(node.processor, node.line)
            else:
                self._skill(node)
        return self.found

    def _processor(self, name: str, line: int) -> None:
        for part in name.replace(")", "").split("("):
            if part and part not in UPSTREAM_PROCESSORS and part not in self.undefined:
                where = ELSEWHERE.get(part)
                self.add("processor-not-upstream", line,
                         f"processor {part} is not on SkiROS2's master and ros2 branches; it "
                         f"exists on {where}: the tree runs only where that is installed"
                         if where is not None else
                         f"processor {part} is not one of SkiROS2's (master, ros2) nor of a "
                         "known fork's: the lab's own processor class, which this run does "
                         "not judge", part)

    # -- one child ----------------------------------------------------------------------

    def _skill(self, node: SkillNode) -> None:
        matches, literal = self.view.resolve(node.type)
        if not matches:
            self._unknown(node)
            return
        if not literal:
            names = ", ".join(d.name for d in matches)
            self.add("regex-child-type", node.line,
                     f"child type {node.type!r} matches {names} only as a regular "
                     "expression (SkiROS2 matches types with re.match)"
                     + (": SkillInstanciator.assign_instance looks for an instance under "
                        "the literal type, finds none, and the node has no label to load "
                        "one by, so the compound skill fails when it runs" if not node.label
                        else f"; the node's label {node.label!r} loads the implementation "
                        "all the same (SkillInstanciator.add_instance)"), node.type,
                     f"Write the type name exactly: {matches[0].name!r}.",
                     None if not node.label else "info")
        if len(matches) != 1:
            return
        definitions = self.view.nearest(matches[0])
        found = []
        for child in definitions:  # two packages define the type: what holds for both
            before, self.found = self.found, []
            self._judge(node, child)
            found.append(self.found)
            self.found = before
        self.found += [f for f in found[0] if all(
            any((g.kind, g.message) == (f.kind, f.message) for g in other)
            for other in found[1:])]

    def _unknown(self, node: SkillNode) -> None:
        name = type_name(node.type)
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
                 node.type, self._closest_type(name), "info" if unread else None)

    def _closest_type(self, name: str) -> str | None:
        """A description type spelt like ``name``, never this compound's own (once a name:
        it compares ``name`` with every type of the index)."""
        if name not in self.hints:
            own = {self.model.description, self.model.implementation}
            close = difflib.get_close_matches(
                name, [n for n in self.index.names() if n not in own], 1, 0.6)
            self.hints[name] = f"Did you mean {close[0]!r}?" if close else None
        return self.hints[name]

    def _judge(self, node: SkillNode, child: DescriptionInfo) -> None:
        self._label(node, child)
        unlaunched = self.view.launched_implementations(child.name)
        if unlaunched is not None and child.origin.startswith("repository"):
            self.add("child-not-launched", node.line,
                     f"child type {child.name} is implemented by {', '.join(unlaunched)}, "
                     "none of which the launch file's skill_list loads: the skill manager "
                     "would not find it", node.type)
        if not child.complete:
            return
        renamed = self._remaps(node, child)
        self._specify(node, child, renamed)
        self._dangling(node, self._unset(node, child, renamed))

    def _label(self, node: SkillNode, child: DescriptionInfo) -> None:
        if not node.label:
            return
        implements = self.index.implementations.get(node.label)
        if implements is not None and implements != child.name:
            self.add("label-other-type", node.line,
                     f"label {node.label!r} names an implementation of {implements}, not of "
                     f"{child.name}: SkiROS2 runs it anyway (upstream issue #80)", node.type)
        if implements is None:
            self._unknown_label(node, child)

    def _unknown_label(self, node: SkillNode, child: DescriptionInfo) -> None:
        """A label no implementation the run knows has: a warning when the run knows the
        type's implementations (most likely a typo of one), info when it knows none of them
        or could not read every file (another library may hold it)."""
        known = sorted(label for label, described in self.index.implementations.items()
                       if described == child.name)
        close = difflib.get_close_matches(node.label, known, 1, 0.6)
        unsure = not known or bool(self.index.unread)
        where = (f"the implementations of {child.name} the run knows are "
                 f"{', '.join(known[:4])}{', ...' if len(known) > 4 else ''}" if known else
                 f"the run knows no implementation of {child.name} (it may come from a "
                 "library this run does not read)")
        self.add("unknown-label", node.line,
                 f"label {node.label!r} names no implementation this run knows ({where}): "
                 "SkillInstanciator.add_instance asks PluginLoader.getPluginByName for it, "
                 "which raises when the compound skill expands", node.type,
                 f"Did you mean {close[0]!r}?" if close else None,
                 "info" if unsure else None)

    def _remaps(self, node: SkillNode, child: DescriptionInfo) -> dict[str, str]:
        """Check each remap; return the renames SkiROS2 applies (child key -> new key)."""
        declared = child.declared()
        renamed: dict[str, str] = {}
        for key, target in node.remap:
            if key in declared and target == COMPUTED:
                renamed[key] = target
                continue
            if key in declared:
                held = self.index.held_by(child.name, target, node.label) \
                    if target in declared and target != key else False
                if held is not False:  # None: modifyDescription of an unlabelled choice
                    self.add("remap-onto-declared", node.line,
                             f"remap {key!r} -> {target!r}: {child.name} already declares "
                             f"{target!r}, so SkiROS2 rejects the remap and renames nothing"
                             + ("" if held else " (when an implementation whose "
                                "modifyDescription adds it runs: the node has no label)"),
                             node.type, None, None if held else "info")
                    continue
                renamed[key] = target
                self._element_types(node, child, key, target)
                continue
            _, complete = self.keys.below(node, child).value
            reached, taken = self.reaches.below(node, child).value
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
            if key in keys and key in self.index.modified_by.get(child.name, {}):
                self.add("specify-modified-key", node.line,
                         f"specify key {key!r}: {child.name} declares it only in an "
                         "implementation's modifyDescription, which runs after specify is "
                         "applied (SkillWrapper.setInstance), so SkiROS2 drops the value",
                         node.type)
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

    def _unset(self, node: SkillNode, child: DescriptionInfo,
               renamed: dict[str, str]) -> set[str]:
        """Required non-Element parameters of the child that nothing gives a value
        (``required-unset``): not its declaration (a type, not a value), not a ``specify``,
        not the compound's own parameters nor anything another node of the tree writes on
        the blackboard, nor the trees around the compound. Judged only where all of that
        is known; returns the (renamed) keys reported."""
        if not child.unset or self.parent is None or not self.parent.complete \
                or child.name in self.index.modified_by or child.name in self.index.self_added:
            return set()
        declared = child.declared()
        if any(k not in declared for k, _ in node.remap) \
                or any(k not in {renamed.get(d, d) for d in declared} for k, _ in node.specify):
            return set()  # a remap or specify key the child lacks: reported as such already
        if self._inherits_remap(node):
            return set()
        writes = self._tree_writes()
        if not writes.complete_without(node):
            return set()
        specified = {k for k, _ in node.specify}
        own = self.parent.declared() | self.index.self_added.get(self.parent.name, set())
        missing = sorted(name for name in (renamed.get(k, k) for k in child.unset)
                         if name != COMPUTED and name not in specified and name not in own
                         and not writes.by_others(node, name))
        if not missing:
            return set()
        around = self._context(self.parent.name)
        if around is not None:
            missing = [k for k in missing if k not in around]
        if not missing:
            return set()
        unsure = self._unread_trees()
        why = ("" if around is not None and not unsure else
               " (info: " + (unsure if unsure else "a tree around "
                             f"{self.parent.name} is not known in full") +
               ", and may set it)")
        names = ", ".join(repr(k) for k in missing)
        self.add("required-unset", node.line,
                 f"{child.name}'s required parameter(s) {names} have no default value and "
                 f"nothing in the tree sets them (no parameter of {self.parent.name}, no "
                 "remap onto them, no specify, no other node that writes them): "
                 "NodeExecutor._autoParametrizeBB raises \"Missing required parameter(s): "
                 f"{missing}\" when the child is grounded (SkiROS2 issue #91; on master "
                 f"the child runs with the value None){why}", node.type,
                 f"Give it a value: specify={{{missing[0]!r}: ...}}, or declare "
                 f"{missing[0]!r} in {self.parent.name} so that its caller sets it.",
                 None if around is not None and not unsure else "info")
        return set(missing)

    def _inherits_remap(self, node: SkillNode) -> bool:
        """Whether a node of the tree above ``node`` remaps (SkillInterface.addChild copies
        its remaps onto the node: a key may be renamed on the way down)."""
        if self.remapped_below is None:
            below: set[int] = set()

            def visit(nodes: Iterable[Node | CallProblem], remapped: bool) -> None:
                for inner in nodes:
                    if isinstance(inner, CallProblem):
                        continue
                    if remapped:
                        below.add(id(inner))
                    visit(inner.children, remapped or bool(inner.remap))

            visit(self.model.children, False)
            self.remapped_below = below
        return id(node) in self.remapped_below

    def _unread_trees(self) -> str:
        """Why a tree of the repository that may hold this compound is not known (""
        when every tree is)."""
        if self.index.unknown_compounds:
            return (f"{len(self.index.unknown_compounds)} compound tree(s) of the run "
                    "could not be read")
        if any(m.gaps for models in self.index.compounds.values() for m in models):
            return "a compound tree of the run is read only in part"
        return ""

    def _context(self, description: str) -> frozenset[str] | None:
        """The blackboard keys the known trees holding a compound of ``description`` may
        write (their compounds' parameters, every key their nodes declare or remap onto,
        and so on up); None when one of them is not known in full, or passes a remap down
        to it. Kept on the index: the answer is the same for every tree of the run."""
        memo = self.index.context_writes
        if description in memo:
            return memo[description]
        memo[description] = None  # a cycle of trees: not known
        keys: set[str] = set()
        for models in list(self.index.compounds.values()):
            for model in models:
                if model is self.model:
                    continue
                uses = [n for n, _ in model.walk() if isinstance(n, SkillNode)
                        and any(d.name == description for d in self.view.resolve(n.type)[0])]
                if not uses:
                    continue
                outer = self.index.descriptions.get(model.description or "")
                if model.gaps or outer is None or not outer.complete:
                    return None
                checker = _Checker(model, self.index, None)
                if any(n.remap or checker._inherits_remap(n) for n in uses):
                    return None
                used = {id(n) for n in uses}
                for other, _ in model.walk():  # what the other nodes write (not this tree)
                    if isinstance(other, SkillNode) and id(other) not in used:
                        share, whole = checker._share(other)
                        if not whole:
                            return None
                        keys |= share
                above = self._context(outer.name)
                if above is None:
                    return None
                keys |= outer.declared() | above
        memo[description] = frozenset(keys)
        return memo[description]

    def _dangling(self, node: SkillNode, reported: Collection[str] = ()) -> None:
        if not node.remap or self.parent is None or not self.parent.complete:
            return
        writes = self._tree_writes()
        unsure = "" if writes.complete_without(node) else (
            ", unless a node whose parameters this run could not read writes it")
        for key, target in node.remap:
            if target == COMPUTED:
                continue
            if target not in self.parent.declared() and not writes.by_others(node, target) \
                    and target not in reported:
                close = difflib.get_close_matches(target, sorted(self.parent.declared()), 1, 0.6)
                self.add("remap-dangling", node.line,
                         f"remap {key!r} -> {target!r}: no parameter of "
                         f"{self.parent.name} and no other node of the tree declares "
                         f"{target!r}, so it connects to nothing{unsure}", node.type,
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

    def _keys_walk(self, node: SkillNode, child: DescriptionInfo,
                   seen: frozenset[str]) -> _Expansion[tuple[frozenset[str], bool]]:
        """Keys declared below ``node``: its own children and its type's compound trees.

        Complete only when every type below resolves and every compound tree below is
        known; a type that contains itself (directly or further down) is not complete.
        """
        seen = seen | {child.name}
        trail = _Trail(child.name)
        keys: set[str] = set()
        complete = self._below(node.children, keys, seen, trail)
        trees, unknown = self._trees_of(child.name, node.label)
        if unknown:
            complete = False
        for tree in trees:
            complete &= self._below(tree.children, keys, seen, trail)
        return trail.done((frozenset(keys), complete))

    def _trees_of(self, description: str, label: str) -> tuple[list[CompoundModel], bool]:
        """The compound trees a node of ``description`` labelled ``label`` may expand, and
        whether one of them is not known. A label picks the implementation
        (SkillInstanciator.assign_instance takes the instance of that label): a label of a
        primitive the run knows has no tree below it, even where a compound implementation
        of the same type contains that type again. An empty or unknown label may be any."""
        trees = self.index.compounds.get(description, [])
        unknown = description in self.index.unknown_compounds
        if not label or self.index.implementations.get(label) != description:
            return trees, unknown
        return ([t for t in trees if label in (t.label, t.implementation)],
                unknown and label in self.index.unknown_labels)

    def _leaf(self, node: SkillNode, child: DescriptionInfo) -> bool:
        """Whether nothing is below ``node``: no children of its own, and its label picks
        an implementation with no tree (a primitive), even of a type whose compound
        implementation contains the type again (``jp_move_arm`` running
        ``JPMoveArm`` labelled ``jp_primitive_joint``)."""
        return not node.children and bool(node.label) and child.complete \
            and self._trees_of(child.name, node.label) == ([], False)

    def _below(self, nodes: Iterable[Node | CallProblem], keys: set[str],
               seen: frozenset[str], trail: _Trail) -> bool:
        complete = True
        for node in nodes:
            if isinstance(node, CallProblem):
                continue
            if isinstance(node, ProcessorNode):
                complete &= self._below(node.children, keys, seen, trail)
                continue
            child = self.view.one(node.type)
            if child is None:
                complete = False
                continue
            keys.update(child.declared())
            if self._leaf(node, child):
                continue
            below = self.keys.below(node, child, seen)
            trail.add(below)
            keys |= below.value[0]
            complete &= below.value[1]
        return complete

    def _reach_walk(self, node: SkillNode, child: DescriptionInfo, seen: frozenset[str]
                    ) -> _Expansion[tuple[frozenset[str], Mapping[str, str]]]:
        """Keys below ``node`` that a remap passed down would still rename, and keys a node
        below already remapped (key -> its new name): SkiROS2 drops a second remap of a
        key at the node that remapped it first, and does not pass it further down."""
        seen = seen | {child.name}
        trail = _Trail(child.name)
        reached: set[str] = set()
        taken: dict[str, str] = {}
        nodes: list[Node | CallProblem] = list(node.children)
        for tree in self._trees_of(child.name, node.label)[0]:
            nodes += tree.children
        for below in nodes:
            self._reach_node(below, reached, taken, seen, trail)
        return trail.done((frozenset(reached), taken))

    def _reach_node(self, node: Node | CallProblem, reached: set[str],
                    taken: dict[str, str], seen: frozenset[str], trail: _Trail) -> None:
        if isinstance(node, CallProblem):
            return
        keys: set[str] = set()
        if isinstance(node, ProcessorNode):
            for inner in node.children:
                self._reach_node(inner, keys, taken, seen, trail)
        else:
            child = self.view.one(node.type)
            if child is None:
                return
            keys = child.declared()
            below = self.reaches.below(node, child, seen) if not self._leaf(node, child) \
                else _Expansion((frozenset(), NOTHING_TAKEN), frozenset(), 0)
            trail.add(below)
            deeper, deeper_taken = below.value
            keys |= deeper
            for key, target in deeper_taken.items():
                taken.setdefault(key, target)
        for key, target in node.remap:
            if key in keys:
                keys.discard(key)
                keys.add(target)
                taken.setdefault(key, target)
        reached |= keys

    def _tree_writes(self) -> _Writes:
        """What each skill node of the tree writes, worked out once for the whole tree."""
        if self.writes is None:
            shares: dict[int, tuple[frozenset[str], bool]] = {}
            places = []
            for node, _ in self.nodes:
                if isinstance(node, SkillNode):
                    if id(node) not in shares:
                        shares[id(node)] = self._share(node)
                    places.append((node, *shares[id(node)]))
            self.writes = _Writes(places)
            self.writes.unknown += len(self.model.gaps)  # what the unread statements add
        return self.writes

    def _share(self, node: SkillNode) -> tuple[frozenset[str], bool]:
        """Blackboard keys one node declares or remaps onto (and those below it), and
        whether that is all of them."""
        keys = {target for _, target in node.remap}
        child = self.view.one(node.type)
        if child is None or not child.complete:
            return frozenset(keys), False
        keys |= child.declared()
        below, whole = self.keys.below(node, child).value
        return frozenset(keys | below), whole
