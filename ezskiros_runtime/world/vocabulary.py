"""Which relations the world model keeps single-valued, and which elements are SkiROS2's
own bookkeeping rather than part of the world.

SkiROS2 reads a scene as a tree through the sub-properties of ``skiros:spatiallyRelated``
(``contain``, ``hasA``): every element has one spatial parent, the subject of the relation.
``skiros:at`` gives a subject one place. Both are the default list of single-valued
relations; a project changes it with ``[tool.ezmigrate] single-valued``. An entry covers the
relation and its sub-properties; a spatial one (``spatiallyRelated`` or below) is one
*subject* per object (one parent), any other one *object* per subject (one place).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Iterable

if TYPE_CHECKING:
    from ..ontology.index import OntologyIndex

SKIROS = "http://rvmi.aau.dk/ontologies/skiros.owl#"
SPATIALLY_RELATED = SKIROS + "spatiallyRelated"
DEFAULT_SINGLE_VALUED: tuple[str, ...] = ("skiros:spatiallyRelated", "skiros:at")
BOOKKEEPING_CLASSES = tuple(SKIROS + c for c in ("Skill", "Parameter", "Condition",
                                                 "SkillManager", "Primitive"))
"""Classes of what SkiROS2 saves into a scene about itself (skills, their parameters and
conditions, skill managers): not objects of the world, never flagged as such."""
BOOKKEEPING_PROPERTIES = frozenset(SKIROS + p for p in (
    "hasSkill", "hasParam", "hasPreCondition", "hasHoldCondition", "hasPostCondition",
    "hasTemplate", "hasSkillManager", "hasSkillManagers"))


def sub_properties(index: OntologyIndex | None, iri: str) -> frozenset[str]:
    """``iri`` and every loaded property below it."""
    return frozenset((iri,)) if index is None else index.sub_properties(iri)


def spatial_properties(index: OntologyIndex | None) -> frozenset[str]:
    """``skiros:spatiallyRelated`` and its sub-properties; the core's two when the loaded
    ontology does not define them."""
    found = sub_properties(index, SPATIALLY_RELATED)
    return found if len(found) > 1 else frozenset(
        {SPATIALLY_RELATED, SKIROS + "contain", SKIROS + "hasA"})


@dataclass(frozen=True)
class SingleValued:
    """One entry of the list: its name, the relations it covers, and which end is unique
    (``"object"``: one subject per object, a parent; ``"subject"``: one object per subject,
    a place)."""

    name: str
    members: frozenset[str]
    per: str


def single_valued(index: OntologyIndex | None,
                  names: Iterable[str] | None = None) -> list[SingleValued]:
    """The configured entries (``DEFAULT_SINGLE_VALUED`` when ``names`` is None), resolved
    against the ontology; a name the ontology cannot expand is kept as written."""
    spatial = spatial_properties(index)
    found = []
    for name in DEFAULT_SINGLE_VALUED if names is None else names:
        iri = (index.expand(name) if index is not None else None) or _expand(name)
        members = spatial if iri == SPATIALLY_RELATED else sub_properties(index, iri)
        found.append(SingleValued(name, members, "object" if iri in spatial else "subject"))
    return found


def _expand(name: str) -> str:
    prefix, colon, local = name.partition(":")
    if colon and prefix in ("", "skiros"):
        return SKIROS + local
    return name


__all__ = ["BOOKKEEPING_CLASSES", "BOOKKEEPING_PROPERTIES", "DEFAULT_SINGLE_VALUED",
           "SPATIALLY_RELATED", "SingleValued", "single_valued", "spatial_properties",
           "sub_properties"]
