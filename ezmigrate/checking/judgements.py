"""Stage 7, judgements: what needs every finding and every reading of the run.

The checks inside implementation classes (``implementation_code``: EZ109, EZ214, EZ215),
EZ105/EZ209 kept a warning only where grounding by type can pick the wrong element
(``uninferable``), and vocabulary as the robot resolves it (``lint/robot_vocabulary.py``:
scenes and the launch file's ``workspace_dir``). Then the findings are put in order.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from typing import TYPE_CHECKING

from ezskiros_runtime.codes import code_for

from ..lint.diagnostic import Diagnostic, Positions, from_finding
from .run import CheckRun
from .uninferable import UNINFERABLE, UNKNOWN

if TYPE_CHECKING:
    from ezskiros_runtime.compound.library import SkillIndex
    from ezskiros_runtime.ontology.index import OntologyIndex

    from ..files.discover import Candidate
    from .implementation_code import ModuleFacts


def _facts_of(data: bytes) -> ModuleFacts | None:
    """The implementation facts of a file the read stage did not read for them."""
    from .file_facts import parse
    from .implementation_code import module_facts

    tree = parse(data)
    return None if tree is None else module_facts(tree, data)


def _implementing(run: CheckRun) -> list[tuple[Candidate, ModuleFacts]]:
    """The implementation classes, read once for the two judgements below (while the read
    stage had their syntax trees at hand, else parsed now), and only when one of them has
    work: the checks inside them, or an EZ105/EZ209 to judge."""
    judging = any(d.code in (UNINFERABLE, UNKNOWN) for d in run.diagnostics)
    if run.compound.skills is None and not judging:
        return []
    facts = run.module_facts
    return [(c, found) for c, data in run.read if b"setDescription" in data
            for found in (facts[c.path] if c.path in facts else _facts_of(data),)
            if found is not None]


def misspelt_term(index: OntologyIndex | None) -> Callable[[str], bool]:
    """Whether a term (class, relation, property) is one edit from a term of its prefix the
    ontology defines: a typo (``skiros:Lcoation``)."""
    from ezskiros_runtime.ontology.suggest import misspelt_term as one_edit

    if index is None:
        return lambda _term: False
    terms = [index.compact(c) for c in (*index.classes, *index.properties)]
    return lambda term: one_edit(term, terms) is not None


def _implementations(run: CheckRun, implementing: list[tuple[Candidate, ModuleFacts]],
                     skills: SkillIndex) -> list[Diagnostic]:
    """EZ109, EZ214 and EZ215 in the implementation classes of the run
    (``implementation_code``): classes are known when the ontology or a scene of the run
    types an element with them, properties when the ontology declares them, a scene holds
    them or the code sets them."""
    from ezskiros_runtime.dsl.vocabulary import to_iri

    from ..lint.robot_vocabulary import scene_classes
    from ..lint.world_model import readable_scenes
    from ..report.once import once_per_cause
    from .implementation_code import implementation_findings

    index = run.index
    typed = scene_classes(run.world.scenes)
    classes = {*(index.compact(c) for c in index.classes), *typed} if index else set(typed)
    made = set().union(*(facts.sets for _, facts in implementing))
    for scene in readable_scenes(run.world.scenes):
        made |= {scene.compact(p) for p in {v.property for v in scene.values}}

    def known(name: str) -> bool:
        iri = to_iri(index, name) if index is not None else None
        return name in typed or (iri is not None and index is not None
                                 and index.is_class(iri))

    def property_known(name: str) -> bool:
        iri = to_iri(index, name) if index is not None else None
        return name in made or index is None or (iri is not None
                                                 and index.property(iri) is not None)

    found: list[Diagnostic] = []
    for candidate, facts in implementing:
        path = str(candidate.path)
        where = Positions(run.outcome.sources.get(path, ""))
        # the key, class or property a finding is about is its subject: the term below
        found += [replace(from_finding(path, where, f), term=f.subject)
                  for f in implementation_findings(facts, path, skills, known, classes,
                                                   property_known)]
    unknown_property = code_for("implementation-unknown-property")
    return once_per_cause(  # an unknown property: once per project
        found, lambda d: d.term if d.code == unknown_property else None,
        lambda d, name, uses: replace(d, message=f"{d.message} ({uses} reads of {name} in "
                                                 "the project, reported once)"))


def _scene_counter(run: CheckRun) -> Callable[[str], int | None]:
    """How many elements of a class (or below it) the run's scenes hold together; None
    without a scene that reads."""
    from ezskiros_runtime.dsl.vocabulary import to_iri

    from ..lint.world_model import readable_scenes

    index = run.index
    types = [(e.types, {scene.compact(t) for t in e.types})  # IRIs, and as written
             for scene in readable_scenes(run.world.scenes) for e in scene.elements.values()]

    def count(cls: str) -> int | None:
        if not types:
            return None
        iri = to_iri(index, cls) if index is not None else None
        if iri is None or index is None:  # a lab class the ontology lacks: by its name
            return sum(1 for _, written in types if cls in written)
        return sum(1 for kinds, _ in types if any(index.is_subclass(k, iri) for k in kinds))
    return count


def _judge_uninferable(run: CheckRun, implementing: list[tuple[Candidate, ModuleFacts]],
                       misspelt: Callable[[str], bool]) -> list[Diagnostic]:
    """EZ105 kept a warning only where grounding by type can pick the wrong element
    (``uninferable``): implementations read, parents' trees, the scenes' elements."""
    from .uninferable import judge, keys_passed, keys_read

    if not any(d.code in (UNINFERABLE, UNKNOWN) for d in run.diagnostics):
        return run.diagnostics
    compound = run.compound
    passed = keys_passed(compound.models, compound.skills) \
        if compound.skills is not None else {}
    return judge(run.diagnostics, keys_read(facts for _, facts in implementing), passed,
                 _scene_counter(run), misspelt)


def run(run: CheckRun) -> None:
    """Judge the findings with everything the run read, then put them in order."""
    from ..lint.robot_vocabulary import as_the_robot_resolves, scene_classes, typing_scenes

    implementing = _implementing(run)
    if run.compound.skills is not None:
        run.diagnostics.extend(_implementations(run, implementing, run.compound.skills))
    misspelt = misspelt_term(run.index)
    found = _judge_uninferable(run, implementing, misspelt)
    found.sort(key=lambda d: (d.path, d.line, d.column, d.code))
    launch = run.settings.launch
    run.outcome.diagnostics = as_the_robot_resolves(
        found, scene_classes(typing_scenes(run.paths, run.world.scenes, run.settings.exclude)),
        launch.workspace_unresolved if launch is not None else None,
        run.index.prefixes if run.index is not None else (), misspelt)
