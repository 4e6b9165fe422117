"""Which triples of an ontology file declare an individual of the world: a robot
description in ``owl/robot.owl`` names the robot and its parts, and the world model loads
them with the ontology, so a scene may relate to them without defining them.

One rule for the two places that read them: the index's build, which keeps them with the
index (so that a cached index answers without rdflib), and ``world.scene`` for an index
that does not hold them. Runs on the robot's Python 3.8 with rdflib 4.2.2 as well.
"""

from __future__ import annotations

from typing import Any

from .naming import OWL, RDF_TYPE

NOT_CLASSES = frozenset({OWL + "NamedIndividual", OWL + "Thing"})
"""Types every saved individual carries that say nothing about what it is."""


def add_individuals(graph: Any, found: dict[str, list[str]]) -> None:
    """Add to ``found`` (``{iri: [classes]}``, in the order met) the individuals one
    parsed file (an rdflib graph) declares: subjects typed with anything but OWL's and the
    W3C's own vocabulary, ``owl:NamedIndividual`` aside."""
    from rdflib import URIRef

    for s, _, o in graph.triples((None, URIRef(RDF_TYPE), None)):
        iri, cls = str(s), str(o)
        if cls.startswith(OWL) and cls != OWL + "NamedIndividual":
            continue  # a class, a property, the ontology itself
        if cls.startswith("http://www.w3.org/"):
            continue
        types = found.setdefault(iri, [])
        if cls not in NOT_CLASSES and cls not in types:
            types.append(cls)
