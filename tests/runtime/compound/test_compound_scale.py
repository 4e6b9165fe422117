"""Compound checks scale with the tree, and speed changes no finding (issue 31).

A check used to ask the skill index again, for every node, about every other node of the
tree and everything below it: quadratic in a tree's width, exponential in its depth when
compound trees share children. Now each type is looked up once per tree and each type's
tree walked once. Counted here through a ``SkillIndex`` subclass that counts what it is
asked and a ``compounds`` mapping that counts the trees walked (no timing: speed figures
are in bench/RESULTS.md). Wide and deep trees must give the findings their small
equivalents give; the depth limit and cycles must stop a walk exactly where they did,
whichever walk reached a type first.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

import pytest

from ezskiros_runtime.compound.checks import check_model
from ezskiros_runtime.compound.library import DescriptionInfo, SkillIndex
from ezskiros_runtime.compound.model import CompoundModel, ProcessorNode, SkillNode
from ezskiros_runtime.diagnostics import Finding

LOCATION = "skiros:Location"


class CountingIndex(SkillIndex):
    """A real skill index that counts the questions a check asks it."""

    def __init__(self) -> None:
        super().__init__({})
        self.asked = {"resolve": 0, "nearest": 0}

    def resolve(self, stype: str) -> tuple[list[DescriptionInfo], bool]:
        self.asked["resolve"] += 1
        return super().resolve(stype)

    def nearest(self, info: DescriptionInfo, path: str) -> list[DescriptionInfo]:
        self.asked["nearest"] += 1
        return super().nearest(info, path)


class CountingTrees(dict):
    """``SkillIndex.compounds`` that counts how often a type's trees are looked up: once
    per walk below a node of that type."""

    looked_up = 0

    def get(self, key: Any, default: Any = None) -> Any:
        self.looked_up += 1
        return super().get(key, default)


def _steps(index: SkillIndex) -> None:
    """Three step types, each defined by two packages (``nearest`` picks one)."""
    for folder in ("/lab/cell_a/src/cell_a", "/lab/cell_b/src/cell_b"):
        for i in range(3):
            index.add_description(DescriptionInfo(
                f"Step{i}", {"Target": LOCATION, "Object": LOCATION, "Speed": None},
                path=f"{folder}/steps.py", line=i + 1))


def _wide(copies: int, index: SkillIndex) -> CompoundModel:
    """``copies`` times the same four children, every one remapped, then a dangling one."""
    index.add_description(DescriptionInfo("Task", {"Place": LOCATION, "Item": LOCATION},
                                          path="/lab/cell_a/src/cell_a/tasks.py"))
    index.add_description(DescriptionInfo("Fetch", {"Shelf": LOCATION},
                                          path="/lab/cell_a/src/cell_a/tasks.py"))
    index.add_compound(CompoundModel("fetch", "Fetch", "fetch", "Sequential",
                                     (SkillNode("Step0"),)))
    children: list[Any] = []
    for copy in range(copies):
        line = 10 * copy
        children += [
            SkillNode("Step0", "", (("Target", "Place"), ("Object", "Found")),
                      (("Sped", 0.1),), line=line + 1),  # a specify typo
            SkillNode("Step1", "", (("Targte", "Place"),), line=line + 2),  # a remap typo
            ProcessorNode("ParallelFs", (
                SkillNode("Step2", "", (("Object", "Found"), ("Target", "Item")),
                          line=line + 4),
                SkillNode("Fetch", "", (("Target", "Place"),), line=line + 5),  # below
            ), line=line + 3),
        ]
    children.append(SkillNode("Step2", "", (("Target", "Lost"),), line=9999))  # dangling
    return CompoundModel("task", "Task", "task", "Sequential", tuple(children),
                         "/lab/cell_a/src/cell_a/tasks.py", 1, 2)


def _check_wide(copies: int) -> tuple[list[Finding], dict[str, int]]:
    index = CountingIndex()
    _steps(index)
    model = _wide(copies, index)
    return check_model(model, index), index.asked


def test_a_wide_tree_has_its_small_equivalents_findings_repeated() -> None:
    small, _ = _check_wide(1)
    large, _ = _check_wide(100)
    assert [f.kind for f in small] == ["specify-key-unknown", "remap-key-unknown",
                                       "remap-key-descendant", "remap-dangling"]
    repeated = [replace(f, line=f.line + 10 * copy) for copy in range(100)
                for f in small[:-1]]
    assert large == [*repeated, small[-1]]


def test_the_index_is_asked_once_per_type_however_wide_the_tree() -> None:
    _, small = _check_wide(2)
    _, large = _check_wide(100)  # 401 skill nodes, each remapped
    assert large == small
    assert large["resolve"] <= 4 and large["nearest"] <= 4  # Step0-2 and Fetch


def _lattice(levels: int, width: int, index: SkillIndex) -> None:
    """``Level0`` .. ``Level{levels-1}``, each a compound of ``width`` nodes of the next
    (every path through them is a different path to the bottom); the last holds
    ``Bottom``, the only one declaring ``Deep``."""
    index.add_description(DescriptionInfo("Bottom", {"Deep": LOCATION}))
    for level in range(levels):
        index.add_description(DescriptionInfo(f"Level{level}", {"Where": LOCATION}))
        below = f"Level{level + 1}" if level + 1 < levels else "Bottom"
        index.add_compound(CompoundModel(
            f"level{level}", f"Level{level}", f"level{level}", "Sequential",
            tuple(SkillNode(below, "", (("Where", "Where"),)) for _ in range(width))))


def _check_deep(levels: int, width: int) -> tuple[list[Finding], int]:
    index = SkillIndex.with_standard_library()
    index.add_description(DescriptionInfo("Mission", {"Site": LOCATION}))
    _lattice(levels, width, index)
    trees = CountingTrees(index.compounds)
    index.compounds = trees
    model = CompoundModel("mission", "Mission", "mission", "Sequential", (
        SkillNode("Level0", "", (("Deep", "Site"), ("Where", "Site")), line=1),
        SkillNode("Level0", "", (("Nowhere", "Site"),), line=2),
        SkillNode("Level0", "", (("Where", "Site"), ("Deep", "Deep")), line=3),  # written
        SkillNode("Level0", "", (("Where", "Lost"),), line=4),  # dangling
    ))
    return check_model(model, index), trees.looked_up


def test_a_deep_tree_has_its_shallow_equivalents_findings() -> None:
    shallow, _ = _check_deep(1, 1)
    deep, _ = _check_deep(12, 3)
    assert [(f.kind, f.line) for f in shallow] == [
        ("remap-key-descendant", 1), ("remap-key-unknown", 2), ("remap-key-descendant", 3),
        ("remap-dangling", 4)]
    assert deep == shallow


def test_each_compound_tree_is_walked_once_however_many_paths_reach_it() -> None:
    _, walks = _check_deep(8, 3)  # 3 ** 8 paths from the top to the bottom
    assert walks <= 2 * 9  # two kinds of walk (keys below, remaps below), nine types


def _chain(levels: int, index: SkillIndex) -> None:
    """``Chain0`` .. ``Chain{levels-1}``, each a compound of one node of the next; the last
    declares ``Deep``."""
    for level in range(levels):
        last = level + 1 == levels
        index.add_description(DescriptionInfo(f"Chain{level}",
                                              {"Deep": LOCATION} if last else {}))
        if not last:
            index.add_compound(CompoundModel(f"chain{level}", f"Chain{level}",
                                             f"chain{level}", "Sequential",
                                             (SkillNode(f"Chain{level + 1}"),)))


@pytest.mark.parametrize("order", [(0, 14), (14, 0)])
def test_the_depth_limit_stops_a_walk_where_it_did_whichever_node_came_first(
        order: tuple[int, int]) -> None:
    """``Deep`` is 20 levels below ``Chain0``, beyond the walk's limit: not judged there;
    6 levels below ``Chain14``: found. The walk below ``Chain14`` is the same one in both,
    reached first from the top or first on its own."""
    index = SkillIndex.with_standard_library()
    index.add_description(DescriptionInfo("Mission", {"Site": LOCATION}))
    _chain(21, index)
    model = CompoundModel("mission", "Mission", "mission", "Sequential", tuple(
        SkillNode(f"Chain{level}", "", (("Deep", "Site"),), line=level) for level in order))
    assert [(f.kind, f.line) for f in check_model(model, index)] == [
        ("remap-key-descendant", 14)]


@pytest.mark.parametrize("order", [("Ping", "Pong"), ("Pong", "Ping")])
def test_a_cycle_stops_a_walk_where_it_did_whichever_node_came_first(
        order: tuple[str, str]) -> None:
    """``Ping``'s tree holds ``Pong``, whose tree holds ``Ping`` called with a child of its
    own, ``Leaf``. Below ``Ping`` the walk stops at the second ``Ping`` (already above)
    and never sees ``Leaf``; below ``Pong`` the ``Ping`` node is new and ``Leaf`` is
    reached."""
    index = SkillIndex.with_standard_library()
    for name, params in (("Mission", {"Site": LOCATION}), ("Ping", {}), ("Pong", {}),
                         ("Leaf", {"Deep": LOCATION})):
        index.add_description(DescriptionInfo(name, params))
    index.add_compound(CompoundModel("ping", "Ping", "ping", "Sequential",
                                     (SkillNode("Pong"),)))
    index.add_compound(CompoundModel("pong", "Pong", "pong", "Sequential",
                                     (SkillNode("Ping", children=(SkillNode("Leaf"),)),)))
    model = CompoundModel("mission", "Mission", "mission", "Sequential", tuple(
        SkillNode(name, "", (("Deep", "Site"),)) for name in order))
    found = [(f.kind, f.message) for f in check_model(model, index)]
    assert found == [("remap-key-descendant",
                      "remap key 'Deep' is declared not by Pong but below it; SkiROS2 "
                      "passes the remap down to it (tree read statically)")]
