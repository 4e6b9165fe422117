"""Compound skills in ``check``: read every tree, build the skill index, run the checks.

Trees are read statically where ``expand`` is literal (``static.py``) and traced in the
verification sandbox otherwise (a child process per file, with its timeout and memory
limit; ``LoadJob.trace``). The index holds the descriptions ``check`` already read (legacy
ones statically, EzSkiROS ones loaded), the standard library's, and those of the project's
``skill-libraries``; implementations' labels come from each ``setDescription`` call.
"""

from __future__ import annotations

import ast
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ezskiros_runtime.compound.checks import check_model, compound_finding
from ezskiros_runtime.compound.library import SkillIndex
from ezskiros_runtime.compound.model import CompoundModel
from ezskiros_runtime.compound.trace import Unanalysable
from ezskiros_runtime.diagnostics import Finding
from ezskiros_runtime.ontology.discovery import package_root
from ezskiros_runtime.ontology.vendored import package_name

from ..files.discover import Candidate
from ..files.package_xml import ros_flavour
from ..report.once import once_per_cause
from ..report.results import FileResult
from ..verify.pool_config import PoolConfig
from ..verify.protocol import LoadOutcome
from .markers import READ_WHEN, ROS1_IMPORT, ROS2_IMPORT
from .repository import Recovered, RepositoryScan, description_of
from .static import (
    IMPLEMENTATION_BASES,
    NeedsTrace,
    class_bases,
    expand_findings,
    implementations,
    modified_params,
    read_compounds,
    undescribed,
)

if TYPE_CHECKING:
    from ezskiros_runtime.ontology.index import OntologyIndex

MARKER = READ_WHEN[0]
"""``expand``: a file that may build a compound skill's tree."""


@dataclass
class CompoundRun:
    """Every compound skill of a run (by file) and its findings."""

    models: list[tuple[str, CompoundModel | Unanalysable]] = field(default_factory=list)
    findings: list[tuple[str, Finding]] = field(default_factory=list)


@dataclass
class Trees:
    """What the static pass learnt of a run's compound skills: trees read, trees to trace,
    implementation labels. Filled file by file while the syntax tree is at hand (``add``):
    keeping a repository's syntax trees alive until later slows every garbage collection."""

    models: list[tuple[str, CompoundModel | Unanalysable]] = field(default_factory=list)
    traced: dict[str, tuple[Candidate, list[NeedsTrace]]] = field(default_factory=dict)
    labels: list[tuple[str, str | None]] = field(default_factory=list)
    bases: list[tuple[str, str]] = field(default_factory=list)
    """``(class, base)`` for every top-level class deriving from a named class."""
    modified: list[tuple[str, str, str | None, bool, str]] = field(default_factory=list)
    """Parameters implementations add in ``modifyDescription`` (``static.modified_params``)."""
    undescribed: list[tuple[str, str, int, tuple[str, ...]]] = field(default_factory=list)
    """``(path, class, line, bases)`` of classes whose ``createDescription`` never calls
    ``setDescription`` (``static.undescribed``)."""
    seen: set[str] = field(default_factory=set)
    syntax: dict[tuple[str, str], list[Finding]] = field(default_factory=dict)
    """``(path, class)`` -> mistakes its ``self.skill`` calls show in the syntax alone
    (``static.expand_findings``): reported when the tree can be neither read nor traced."""
    launched: frozenset[str] | None = None
    """The launch file's ``skill_list`` (None: no launch file, or no list in it)."""
    libraries: frozenset[str] = frozenset()
    """The launch file's ``libraries_list``."""
    named: tuple[Path, ...] = ()
    """The paths the run was given: the repository around them joins the skill index."""
    exclude: tuple[str, ...] = ()
    trace: bool = True
    """False (``check`` without ``--trace``): no user code is imported, so a tree the syntax
    cannot read stays unread, and says why."""
    prepared: dict[str, TreeFacts] = field(default_factory=dict)
    """Facts of files with no description, read with the run's files (``file_facts``):
    ``add`` takes them in its own order instead of parsing the file."""
    recovered: dict[str, Recovered] = field(default_factory=dict)
    """Files ``ast`` cannot parse, as ``recover_classes`` read them with the run's files:
    the repository scan takes them instead of reading them again."""
    parsed: set[str] = field(default_factory=set)
    """Files of the run ``ast`` read where the run read them (``FileFacts.parsed``): the
    repository scan need not parse them again to learn that they parse."""

    def wants(self, candidate: Candidate, data: bytes) -> bool:
        """Whether ``add`` would read this file: not yet seen, and holding a marker."""
        return str(candidate.path) not in self.seen and any(m in data for m in READ_WHEN)

    def add(self, candidate: Candidate, data: bytes, tree: ast.Module | None = None) -> None:
        """One file (``tree``: its syntax tree when the caller has parsed it already)."""
        if not self.wants(candidate, data):
            return
        prepared = self.prepared.pop(str(candidate.path), None)
        if prepared is not None:  # read already, where the run read its files
            self.take(candidate, prepared)
            return
        if tree is None:
            try:
                tree = ast.parse(data)
            except (SyntaxError, ValueError, UnicodeError, MemoryError, RecursionError):
                self.seen.add(str(candidate.path))
                return  # the static pass reports the file
        self.take(candidate, tree_facts(tree, str(candidate.path)))

    def take(self, candidate: Candidate, facts: TreeFacts) -> None:
        """One file's facts, read by ``tree_facts`` now or by an earlier run (cached)."""
        path = str(candidate.path)
        if path in self.seen:
            return
        self.seen.add(path)
        self.labels += facts.labels
        self.bases += facts.bases
        self.modified += facts.modified
        for cls, mistakes in facts.syntax:
            self.syntax[(path, cls)] = list(mistakes)
        self.models += [(path, found) for found in facts.found
                        if not isinstance(found, NeedsTrace)]
        self.undescribed += [(path, *found) for found in facts.undescribed]
        pending = facts.to_trace()
        if pending:
            self.traced[path] = (candidate, pending)


@dataclass(frozen=True)
class TreeFacts:
    """What ``Trees`` keeps of one file's syntax tree: its implementations' labels, class
    bases, parameters added in ``modifyDescription``, the mistakes its ``self.skill`` calls
    show, and its compound trees (read, or to trace). Made of the file alone (its path and
    bytes), so ``check`` keeps it by content from one run to the next."""

    labels: tuple[tuple[str, str | None], ...] = ()
    bases: tuple[tuple[str, str], ...] = ()
    modified: tuple[tuple[str, str, str | None, bool, str], ...] = ()
    syntax: tuple[tuple[str, tuple[Finding, ...]], ...] = ()
    found: tuple[CompoundModel | Unanalysable | NeedsTrace, ...] = ()
    undescribed: tuple[tuple[str, int, tuple[str, ...]], ...] = ()
    """Classes whose ``createDescription`` never calls ``setDescription``
    (``static.undescribed``)."""

    def to_trace(self) -> list[NeedsTrace]:
        """The classes of the file whose trees only tracing reads."""
        return [found for found in self.found if isinstance(found, NeedsTrace)]


def tree_facts(tree: ast.Module, path: str) -> TreeFacts:
    """``TreeFacts`` of the module at ``path``."""
    return TreeFacts(tuple(implementations(tree)), tuple(class_bases(tree)),
                     tuple(modified_params(tree)),
                     tuple((cls, tuple(m)) for cls, m in expand_findings(tree).items()),
                     tuple(read_compounds(tree, path)), tuple(undescribed(tree)))


def _read(items: Iterable[tuple[Candidate, bytes]], trees: Trees | None = None) -> Trees:
    trees = trees or Trees()
    for candidate, data in items:
        trees.add(candidate, data)
    return trees


def _trace(trees: Trees, pool: PoolConfig) -> None:
    """Trace every class the syntax could not read, in sandboxed children
    (``tracing.trace_all``); without ``trees.trace``, take what the syntax gives of it."""
    if not trees.traced:
        return
    if not trees.trace:
        for candidate, pending in trees.traced.values():
            for unread in pending:
                trees.models.append((str(candidate.path), unread.partial or Unanalysable(
                    unread.implementation, f"{unread.reason}, and check runs no repository "
                    "code to trace it (check --trace does, in the sandbox)", unread.line)))
        return
    from .tracing import trace_all, trace_job  # --trace only: the sandboxed pool

    order = list(trees.traced.values())
    outcomes = trace_all([trace_job(c, pending) for c, pending in order], pool)
    for (candidate, pending), found in zip(order, outcomes, strict=True):
        _record(trees, str(candidate.path), pending, found)


def _record(trees: Trees, path: str, pending: list[NeedsTrace],
            outcome: LoadOutcome) -> None:
    """The traced trees of one file (or why none could be read) into ``trees``."""
    needs = {n.implementation: n for n in pending}
    if not outcome.loaded:
        for unread in pending:
            trees.models.append((path, unread.partial or Unanalysable(
                unread.implementation, f"{unread.reason}, and the module could not be "
                f"loaded to trace it ({outcome.status}: {outcome.message})", unread.line)))
        return
    for found in outcome.compounds:
        need = needs.get(found.implementation)
        if need is None:
            continue
        if isinstance(found, Unanalysable) and need.partial is not None:
            (line, why), *rest = need.partial.gaps  # what the syntax gives all the same
            trees.models.append((path, replace(need.partial, gaps=(
                (line, f"{why} ({found.reason})"), *rest))))
        elif isinstance(found, Unanalysable):
            trees.models.append((path, replace(found, line=found.line or need.line)))
        else:
            trees.models.append((path, replace(found, path=path, line=need.line,
                                               description=need.description,
                                               label=need.label)))


def add_descriptions(index: SkillIndex, results: Iterable[tuple[Candidate, FileResult]],
                     loaded: Iterable[tuple[Candidate, Sequence[dict[str, Any]]]],
                     origin: str) -> None:
    """Every description read statically (``results``) or loaded, into ``index``."""
    for candidate, result in results:
        for skill in result.skills:
            index.add_description(description_of(skill.name, skill.model, origin,
                                                 str(candidate.path), skill.line))
    for candidate, models in loaded:
        for data in models:
            name = str(data.get("name", ""))
            if name:
                index.add_description(description_of(name, data, origin, str(candidate.path),
                                                     int(data.get("line") or 0)))


def analyse(items: Sequence[tuple[Candidate, bytes]], index: SkillIndex,
            ontology: OntologyIndex | None, pool: PoolConfig,
            library_items: Sequence[tuple[Candidate, bytes]] = (),
            read: Trees | None = None, around: RepositoryScan | None = None) -> CompoundRun:
    """Read, trace and check every compound skill of ``items`` against ``index``.

    Compound skills of ``library_items`` join the index (a remap reaches into their trees)
    but are not reported. ``read``: what the caller's own pass already read (its files are
    not parsed again); ``around``:
    the rest of the repository (``repository.py``), whose descriptions the caller already
    added to ``index``.
    """
    around = around or RepositoryScan()
    library = _read(library_items, Trees(trace=read.trace if read is not None else True))
    _trace(library, pool)
    trees = _read(items, read)
    _trace(trees, pool)
    for label, description in [*library.labels, *around.labels, *trees.labels]:
        index.add_implementation(label, description)
    index.bases |= {base for cls, base in [*library.bases, *around.bases, *trees.bases]
                    if cls in index.descriptions and base in index.descriptions}
    for description, key, element, on_wrapper, label in [*library.modified,
                                                         *around.modified, *trees.modified]:
        index.add_modified(description, key, element, on_wrapper, label)
    index.unread = list(around.unread)
    index.launched = read.launched if read is not None else None
    index.launched_libraries = read.libraries if read is not None else frozenset()
    index.unknown_compounds |= around.untraced
    index.unknown_labels |= around.untraced_labels
    for compound in around.compounds:
        index.add_compound(compound)
    pending = {n.implementation: n.label for found in (library, trees)
               for _, needs in found.traced.values() for n in needs}
    for _, model in [*library.models, *trees.models]:
        if isinstance(model, CompoundModel):
            index.add_compound(model)
        else:
            index.unknown_compounds.add(_described_type(model, trees, library))
            index.unknown_labels |= {model.implementation,
                                     pending.get(model.implementation, model.implementation)}
    for candidate, data in items:
        if MARKER in data:
            flavour, package = ros_package_of(candidate.path, data)
            if flavour == "ros2":
                index.ros2_paths.add(str(candidate.path))
            if package is not None:
                index.package_names[str(candidate.path)] = package
    run = CompoundRun(models=trees.models)
    for path, model in trees.models:
        found = check_model(model, index, ontology)
        run.findings += [(path, f) for f in found]
        # what the syntax shows of every self.skill call: a traced tree took one branch of
        # expand, so a mistake in another (a keyword typo behind an if) shows only here
        seen = {(f.kind, f.line) for f in found}
        run.findings += [(path, f) for f in trees.syntax.get((path, model.implementation), ())
                         if (f.kind, f.line) not in seen]
    run.findings += _undescribed(trees, [*library.bases, *around.bases, *trees.bases],
                                 index.launched)
    run.findings = once_per_project(run.findings)
    return run


def _undescribed(trees: Trees, bases: list[tuple[str, str]],
                 launched: frozenset[str] | None) -> list[tuple[str, Finding]]:
    """An implementation (its bases reach SkiROS2's) that no class derives from, whose
    ``createDescription`` never calls ``setDescription``: its type stays SkillCore's
    empty one, and the skill manager cannot add it to the world model (issue #109). Info
    when the launch file's ``skill_list`` does not load it."""
    parents: dict[str, set[str]] = {}
    for cls, base in bases:
        parents.setdefault(cls, set()).add(base)
    derived = {base for _, base in bases}

    def implementation(name: str, seen: frozenset[str] = frozenset()) -> bool:
        if name in IMPLEMENTATION_BASES:
            return True
        return name not in seen and any(implementation(b, seen | {name})
                                        for b in parents.get(name, ()))

    found = []
    for path, cls, line, own in trees.undescribed:
        if cls in derived or cls in IMPLEMENTATION_BASES \
                or not any(implementation(b, frozenset({cls})) for b in own):
            continue
        unloaded = launched is not None and cls not in launched
        found.append((path, compound_finding(
            "no-set-description", line,
            f"{cls}'s createDescription never calls self.setDescription(Description(), "
            "label): the implementation keeps SkillCore's empty type and label, so when "
            "SkillManager.add_skill adds it, its world-model element has the type \"\" "
            "and WorldModel.add_element cannot store it (SkiROS2 issue #109); the skill is "
            "not loaded" + (" (info: the launch file's skill_list does not load it)"
                            if unloaded else ""),
            cls, "", "Call self.setDescription(TheDescription(), self.__class__.__name__) in "
            "createDescription.", "info" if unloaded else None)))
    return found


def once_per_project(findings: list[tuple[str, Finding]]
                     ) -> list[tuple[str, Finding]]:
    """A processor that upstream lacks is one finding per project (at its first use, with
    its count of uses), not one per tree that uses it."""
    return once_per_cause(
        findings,
        lambda item: item[1].subject if item[1].kind == "processor-not-upstream" else None,
        lambda item, name, uses: (item[0], replace(
            item[1], message=f"{item[1].message}; {uses} uses of {name} in the project, "
                             "reported once")))


def ros_package_of(path: Path, data: bytes) -> tuple[str | None, str | None]:
    """``(ros1/ros2, package name)`` of a file: its ROS package's ``package.xml`` (the
    buildtool, catkin or ament, and the name), else its own ``rospy``/``rclpy`` imports for
    the flavour; None for what neither says."""
    package = package_root(path.resolve())
    flavour, name = None, None
    if package is not None:
        flavour = ros_flavour(package / "package.xml")
        name = package_name(package / "package.xml")
    if flavour is None:
        if ROS2_IMPORT.search(data):
            flavour = "ros2"
        elif ROS1_IMPORT.search(data):
            flavour = "ros1"
    return flavour, name or None


def _described_type(model: Unanalysable, *trees: Trees) -> str:
    """The description an unreadable compound implements (its label's), for the index."""
    for found in trees:
        for label, description in found.labels:
            if label == model.implementation and description is not None:
                return description
    return model.implementation
