"""The hostile ontology file of issue 28, part 5, for the tests that write it to a folder.

About 1 KB of RDF/XML whose DTD nests entities ten deep (the "billion laughs": ``&lol9;``
expands to 10^9 copies of ``lol``) and declares one external entity. rdflib's reader does
not finish it (it only ever gives up on an expat recent enough to cap amplification, after
minutes); the runtime must refuse it before parsing. Text, not a file in ``fixtures/``:
every test writes its own copy to a temporary folder.
"""

from __future__ import annotations

_LAUGHS = "\n".join(
    f'  <!ENTITY lol{n} "' + f"&lol{n - 1};" * 10 + '">' for n in range(1, 10))

HOSTILE = f"""\
<?xml version="1.0"?>
<!DOCTYPE rdf:RDF [
  <!ENTITY owl "http://www.w3.org/2002/07/owl#">
  <!ENTITY lol0 "lol">
{_LAUGHS}
  <!ENTITY ext SYSTEM "file:///etc/hostname">
]>
<rdf:RDF xmlns:rdf="http://www.w3.org/1999/02/22-rdf-syntax-ns#"
         xmlns:rdfs="http://www.w3.org/2000/01/rdf-schema#">
  <rdf:Description rdf:about="http://example.org/x"><rdfs:label>&lol9;&ext;</rdfs:label>
  </rdf:Description>
</rdf:RDF>
"""

NESTED_LINE = 5
"""The line of ``<!ENTITY lol1 ...>``, the first entity that refers to another: the line a
refusal names."""

LAB = "http://lab.example.org/ontologies/lab.owl#"
FLAT = f"""\
<?xml version="1.0"?>
<!DOCTYPE rdf:RDF [
    <!ENTITY owl "http://www.w3.org/2002/07/owl#" >
    <!ENTITY lab '{LAB}' >
    <!-- a comment, and flat entities only: what OWL tools write -->
]>
<rdf:RDF xmlns:rdf="http://www.w3.org/1999/02/22-rdf-syntax-ns#"
         xmlns:rdfs="http://www.w3.org/2000/01/rdf-schema#">
  <rdf:Description rdf:about="&lab;Workstation">
    <rdf:type rdf:resource="&owl;Class"/>
    <rdfs:subClassOf rdf:resource="http://rvmi.aau.dk/ontologies/skiros.owl#Location"/>
  </rdf:Description>
</rdf:RDF>
"""
"""A lab ontology with a DTD as OWL tools write it (flat abbreviations): it must load."""

CHAIN = "http://example.org/chain#"


def chain_turtle(length: int, *, properties: bool = False) -> str:
    """A Turtle file of ``length`` ``rdfs:subClassOf`` triples in one chain (issue 41:
    10,000 of them took 3 GB when every class kept its ancestors), ``C1`` at the bottom;
    with ``properties``, the same chain of ``rdfs:subPropertyOf`` under a property with a
    domain, which every one of them inherits."""
    lines = [f"@prefix ex: <{CHAIN}> .",
             "@prefix rdfs: <http://www.w3.org/2000/01/rdf-schema#> .",
             "@prefix owl: <http://www.w3.org/2002/07/owl#> .",
             f"ex:C{length} a owl:Class ."]
    lines += [f"ex:C{n} rdfs:subClassOf ex:C{n + 1} ." for n in range(1, length)]
    if properties:
        lines.append(f"ex:p{length} a owl:ObjectProperty ; rdfs:domain ex:C{length} .")
        lines += [f"ex:p{n} a owl:ObjectProperty ; rdfs:subPropertyOf ex:p{n + 1} ."
                  for n in range(1, length)]
    return "\n".join(lines) + "\n"


def entity_owl(uses: int, length: int = 256) -> str:
    """RDF/XML with one flat entity of ``length`` characters used ``uses`` times in one
    literal: what the DTD guard let through before (issue 41: 80,000 uses in 240 KB kept
    rdflib busy for minutes, building the literal by quadratic concatenation)."""
    return f"""\
<?xml version="1.0"?>
<!DOCTYPE rdf:RDF [
  <!ENTITY owl "http://www.w3.org/2002/07/owl#">
  <!ENTITY big "{'x' * length}">
]>
<rdf:RDF xmlns:rdf="http://www.w3.org/1999/02/22-rdf-syntax-ns#"
         xmlns:rdfs="http://www.w3.org/2000/01/rdf-schema#">
  <rdf:Description rdf:about="http://example.org/x">
    <rdf:type rdf:resource="&owl;Class"/>
    <rdfs:comment>{'&big;' * uses}</rdfs:comment>
  </rdf:Description>
</rdf:RDF>
"""
