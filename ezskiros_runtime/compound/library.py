"""The skill index: which description types exist, what they declare, who implements them.

A compound skill names its children by description type and optional implementation label
(legacy-compound-skills.md §3). Checking a tree needs every type the skill manager could
load: the repository's own descriptions, the standard library's (bundled here as facts,
the list in the shared doc), and further libraries a project names
(``[tool.ezmigrate] skill-libraries``). Types resolve as SkiROS2 resolves them:
``re.match("^" + type + "$", name)`` over leaf description class names.
"""

from __future__ import annotations

import functools
import os
import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field, replace
from pathlib import PurePath

from .model import CompoundModel

SKIROS_PREFIX = "skiros:"


def type_name(stype: str) -> str:
    """A child type as SkiROS2 matches it: without the ``skiros:`` prefix it adds itself."""
    return stype[len(SKIROS_PREFIX):] if stype.startswith(SKIROS_PREFIX) else stype

ROBOT = "Robot"
ROBOT_TYPE = "sumo:Agent"
"""SkiROS2 gives every description an inferred ``Robot`` parameter (legacy-skiros2-api §8.1)."""


def _folders(path: str) -> tuple[str, ...]:
    """The folders of a file path made absolute, outermost first."""
    return _absolute_folders(path if os.path.isabs(path) else os.path.abspath(path))


@functools.lru_cache(maxsize=4096)
def _absolute_folders(path: str) -> tuple[str, ...]:
    """``_folders`` of an absolute path. Kept: ``nearest`` compares the same few files for
    every child of every tree, and normalising and splitting them was most of its cost."""
    return PurePath(os.path.normpath(path)).parent.parts


def _shared(here: tuple[str, ...], there: tuple[str, ...]) -> int:
    """How many leading folders two paths share."""
    count = 0
    for a, b in zip(here, there):
        if a != b:
            break
        count += 1
    return count


@dataclass(frozen=True)
class DescriptionInfo:
    """One description type: its parameters (key -> element type, ``None`` for values)."""

    name: str
    params: Mapping[str, str | None]
    origin: str = "repository"
    path: str = ""
    line: int = 0
    complete: bool = True
    """False for a description that exists but whose parameters could not be read (one
    ``rewrite`` keeps as legacy): its type resolves, its keys are not judged."""
    unset: frozenset[str] = frozenset()
    """Keys that must be given a value before the skill runs: Required parameters that
    are not Elements and are declared with a type instead of a value
    (``addParam("Relation", str, ParamTypes.Required)``). SkiROS2's
    ``NodeExecutor._autoParametrizeBB`` raises "Missing required parameter(s)" for any of
    them still without a value when the skill is grounded (issue #91; develop and ros2,
    master leaves them None). Inferred ones are left out: it raises for them too on those
    branches, but master does not, and labs declare outputs that way
    (``addParam("EndEffectorForce", float, ParamTypes.Inferred)``, set by the skill)."""

    def declared(self) -> set[str]:
        """Declared keys, the automatic ``Robot`` included."""
        return {*self.params, ROBOT}

    def element_type(self, key: str) -> str | None:
        if key == ROBOT and key not in self.params:
            return ROBOT_TYPE
        return self.params.get(key)


def _std(name: str, params: dict[str, str | None], *unset: str) -> DescriptionInfo:
    return DescriptionInfo(name, params, "skiros2_std_lib", unset=frozenset(unset))


STANDARD_LIBRARY: tuple[DescriptionInfo, ...] = (
    _std("Wait", {"Duration": None}),
    _std("WmSetRelation", {"Src": "sumo:Object", "Relation": None, "Dst": "sumo:Object",
                           "RelationState": None}, "Relation"),
    _std("WmSetProperties", {"Src": "sumo:Object", "Properties": None}, "Properties"),
    _std("WmMoveObject", {"StartLocation": "sumo:Object", "TargetLocation": "sumo:Object",
                          "Object": "sumo:Object", "Relation": None}),
    _std("Counter", {"CountTarget": None}, "CountTarget"),
    _std("TaskPlan", {"Goal": None}, "Goal"),
)
"""``skiros2_std_lib``'s descriptions (master), from legacy-compound-skills.md §3;
``unset``: the parameters declared with a type, not a value (``addParam("Relation", str,
ParamTypes.Required)`` in ``utility_primitives.py``, ``Goal`` in ``task_planner.py``)."""

STANDARD_IMPLEMENTATIONS: dict[str, str] = {
    "wait": "Wait", "wm_set_relation": "WmSetRelation", "wm_set_properties": "WmSetProperties",
    "wm_move_object": "WmMoveObject", "wm_move_and_transform_object": "WmMoveObject",
    "counter": "Counter", "task_plan": "TaskPlan"}
"""``skiros2_std_lib``'s implementations: label (the class name) -> description type."""

STANDARD_LIBRARY_ROS2: dict[str, DescriptionInfo] = {
    "WmSetRelation": _std("WmSetRelation", {
        "Src": "sumo:Object", "Relation": None, "Dst": "sumo:Object", "RelationState": None,
        "OldDstToRemove": "sumo:Object", "OldSrcToRemove": "sumo:Object"}, "Relation"),
}
"""Where the standard library's ``ros2`` branch (the ROS 2 port) differs from master: its
``WmSetRelation`` adds two optional Element parameters (legacy-compound-skills.md §3)."""


@dataclass
class SkillIndex:
    """Descriptions by type name, implementation labels, and the compound trees known.

    ``implementations`` maps a label to the description type its implementation sets;
    ``compounds`` the type to the trees of its compound implementations (a remap on a
    compound child reaches their nodes). ``unknown_compounds`` names types with a compound
    implementation whose tree could not be read: what reaches below them is unknown.
    """

    descriptions: dict[str, DescriptionInfo] = field(default_factory=dict)
    implementations: dict[str, str] = field(default_factory=dict)
    compounds: dict[str, list[CompoundModel]] = field(default_factory=dict)
    unknown_compounds: set[str] = field(default_factory=set)
    unknown_labels: set[str] = field(default_factory=set)
    """Labels and class names of the compound implementations whose tree is not known: a
    node with another label of the type does not run them."""
    bases: set[str] = field(default_factory=set)
    """Descriptions other descriptions derive from: the skill manager loads only leaves."""
    definitions: dict[str, list[DescriptionInfo]] = field(default_factory=dict)
    """Every file of the repository defining a type, when more than one does: packages of
    one repository reuse names, and a compound's child is read from the nearest one."""
    self_added: dict[str, set[str]] = field(default_factory=dict)
    """Keys implementations add to themselves in ``modifyDescription`` (not to the wrapper
    the tree holds), by description type: a ``specify`` of them is dropped."""
    ros2_paths: set[str] = field(default_factory=set)
    """Files of ROS 2 packages: their standard-library children are the ros2 branch's."""
    launched: frozenset[str] | None = None
    """The skills the launch file's ``skill_list`` loads (None: not known)."""
    launched_libraries: frozenset[str] = frozenset()
    """The launch file's ``libraries_list``: only a compound of one of these packages is
    judged against its ``skill_list`` (another launch file may start the others)."""
    package_names: dict[str, str] = field(default_factory=dict)
    """File -> the name of the ROS package it belongs to."""
    unread: list[str] = field(default_factory=list)
    """Files of the repository whose classes could not be read at all: a type not found may
    be defined there, so "unknown child type" is then at most informational."""
    context_writes: dict[str, frozenset[str] | None] = field(default_factory=dict)
    """Memo of ``compound.checks``: by description type, the blackboard keys the known
    trees around a compound of that type may write (None: not all of them are known)."""
    modified_by: dict[str, dict[str, set[str]]] = field(default_factory=dict)
    """``{description: {key: labels}}`` for keys only some implementations add to the
    wrapper in ``modifyDescription``: a node holds them only when one of those runs
    (``SkillWrapper.setInstance``), so the node's label decides."""

    @classmethod
    def with_standard_library(cls) -> SkillIndex:
        return cls({d.name: d for d in STANDARD_LIBRARY}, dict(STANDARD_IMPLEMENTATIONS))

    def add_description(self, info: DescriptionInfo) -> None:
        """A repository's own description wins over a library's of the same name; two
        files of the repository defining one name are both kept (``nearest``). The same
        file read twice (scanned, then checked) keeps the later reading."""
        known = self.descriptions.get(info.name)
        if known is not None and known.path and info.path and known.path != info.path \
                and known.origin.startswith("repository") \
                and info.origin.startswith("repository"):
            others = self.definitions.setdefault(info.name, [known])
            others[:] = [d for d in others if d.path != info.path] + [info]
        elif info.name in self.definitions:
            others = self.definitions[info.name]
            others[:] = [d for d in others if d.path != info.path] + [info]
        self.descriptions[info.name] = info

    def nearest(self, info: DescriptionInfo, path: str) -> list[DescriptionInfo]:
        """The definitions of ``info``'s type a compound skill in ``path`` may use: the only
        one, else those whose folder shares most of ``path`` (its own package first).
        Several when they are equally near: which one the skill manager loads is unknown,
        and only what holds for each of them is certain."""
        if info.origin == "skiros2_std_lib" and path in self.ros2_paths:
            return [STANDARD_LIBRARY_ROS2.get(info.name, info)]
        others = self.definitions.get(info.name)
        if not others:
            return [info]
        if not path:
            return list(others)
        here = _folders(path)
        shared = [_shared(here, _folders(o.path)) for o in others]
        best = max(shared)
        return [o for o, count in zip(others, shared) if count == best]

    def add_modified(self, description: str, key: str, element: str | None,
                     on_wrapper: bool, label: str = "") -> None:
        """A parameter the implementation ``label`` of ``description`` adds in
        ``modifyDescription``: to the wrapper (``skill.addParam``: declared like the
        description's own, but only on nodes that implementation runs: ``modified_by``),
        or to itself (``self.addParam``: not on the wrapper)."""
        if not on_wrapper:
            self.self_added.setdefault(description, set()).add(key)
            return
        info = self.descriptions.get(description)
        added = self.modified_by.setdefault(description, {})
        if info is not None and (key not in info.params or key in added):
            added.setdefault(key, set()).add(label)
            self.descriptions[description] = replace(info, params={**info.params,
                                                                   key: element})

    def held_by(self, description: str, key: str, label: str) -> bool | None:
        """Whether a node of ``description`` labelled ``label`` holds ``key`` that some
        implementation adds in ``modifyDescription``: True or False when the label decides,
        None when it is empty (the skill manager picks an implementation at run time)."""
        labels = self.modified_by.get(description, {}).get(key)
        if labels is None:
            return True
        if not label:
            return None
        return label in labels

    def launched_implementations(self, description: str, path: str) -> list[str] | None:
        """The labels implementing ``description``, when none is in the launch file's
        ``skill_list`` and the launch file loads the library of ``path`` (None when one
        is, or nothing is known)."""
        if self.launched is None \
                or self.package_names.get(path) not in self.launched_libraries:
            return None
        labels = sorted(label for label, described in self.implementations.items()
                        if described == description)
        return labels if labels and not self.launched.intersection(labels) else None

    def add_implementation(self, label: str, description: str | None) -> None:
        if description is not None:
            self.implementations.setdefault(label, description)

    def add_compound(self, model: CompoundModel) -> None:
        if model.description is not None:
            self.compounds.setdefault(model.description, []).append(model)
        self.add_implementation(model.label, model.description)

    def resolve(self, stype: str) -> tuple[list[DescriptionInfo], bool]:
        """(matching descriptions, whether the match is literal) for a child's type.

        SkiROS2 adds a ``skiros:`` prefix and matches the rest as a regular expression
        anchored at both ends; a type that is no valid expression matches nothing.
        """
        name = type_name(stype)
        if name in self.descriptions and name not in self.bases:
            return [self.descriptions[name]], True
        try:
            pattern = re.compile("^" + name + "$")
        except re.error:
            return [], False
        return [d for n, d in sorted(self.descriptions.items())
                if n not in self.bases and pattern.match(n)], False

    def names(self) -> Iterable[str]:
        """The loadable (leaf) description names."""
        return [n for n in self.descriptions if n not in self.bases]
