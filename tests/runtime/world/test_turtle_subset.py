"""``turtle_subset``: the plain Turtle SkiROS2 saves scenes in, read without rdflib's parser.

Its one promise: whenever it reads a text, rdflib reads the same set of triples from it.
Held on every scene this project has, on each construct on both sides of the subset's
edge, and on thousands of texts put together at random from pieces near that edge. Runs
under each robot's Python and rdflib too (no ezmigrate import here)."""

from __future__ import annotations

import logging
import random
import warnings
from pathlib import Path

import pytest
from rdflib import Graph, Literal, URIRef

from ezskiros_runtime.ontology.naming import XSD
from ezskiros_runtime.world.scene import Scene, read_scene
from ezskiros_runtime.world.terms import Term, from_rdflib, plain_literal
from ezskiros_runtime.world.turtle_subset import read_triples

ROOT = Path(__file__).resolve().parents[3]
SCENES = sorted(p for folder in ("fixtures", "tests") for p in (ROOT / folder).rglob("*.turtle"))
HEAD = ("@prefix ex: <http://example.org/ex#> .\n"
        "@prefix xsd: <http://www.w3.org/2001/XMLSchema#> .\n")


def _rdflib(text: str) -> set[object] | None:
    """The triples rdflib reads, as ``terms`` (kind, text as rdflib keeps it, datatype,
    language, and the Python value rdflib gives)."""
    graph = Graph()
    try:
        graph.parse(data=text, format="turtle")
    except Exception:  # any refusal: the subset must refuse too
        return None
    return {tuple(_term(t) for t in triple) for triple in graph}


def _term(term: object) -> tuple[object, ...]:
    """A term as all it says (equal terms with different values would pass ``==``), the
    language's case aside, as rdflib compares it (rdflib 4.2.2's parser even hands back
    the first spelling it met)."""
    made = from_rdflib(term) if not isinstance(term, Term) else term
    return (made.kind, made.text, made.datatype, (made.language or "").lower(),
            repr(made.value))


def _ours(text: str) -> set[object] | None:
    found = read_triples(text)
    return None if found is None else {tuple(_term(t) for t in triple) for triple in found}


def _agrees(text: str) -> bool:
    """The subset reads nothing or exactly what rdflib reads."""
    ours = _ours(text)
    return ours is None or ours == _rdflib(text)


@pytest.mark.parametrize("path", SCENES, ids=lambda p: p.name)
def test_every_scene_of_the_project_reads_as_rdflib_reads_it(path: Path):
    assert _agrees(path.read_text(encoding="utf-8"))


def test_the_saved_scenes_are_in_the_subset():
    """Else the fast path would be dead code: SkiROS2's saved form is read by it."""
    saved = [p for p in SCENES if "broken" not in p.name]
    assert saved and all(read_triples(p.read_text(encoding="utf-8")) for p in saved)


READ = {
    "a type and a label": 'ex:s a ex:C ; ex:label "x" .',
    "lists of objects and predicates": "ex:s ex:p ex:a, ex:b ;\n    ex:q ex:c .",
    "integers and booleans": "ex:s ex:n 0, 12, -3 ; ex:b true, false .",
    "a datatype by name and by IRI": 'ex:s ex:v "1.5"^^xsd:float, '
                                     '"2"^^<http://www.w3.org/2001/XMLSchema#double> .',
    "a language tag": 'ex:s ex:label "chat"@fr, "cat"@en-GB .',
    "a value that does not fit its datatype": 'ex:s ex:v "0,35"^^xsd:float, "yes"^^xsd:boolean .',
    "comments and CRLF": "# saved\r\nex:s ex:p ex:o . # end\r\n",
    "a name ending in a hyphen, then the full stop": "ex:s ex:p ex:Door-10.",
    "the empty prefix and an empty local name": "@prefix : <http://x.org/#> .\n:s :p ex: .",
    "a prefix defined again": "ex:s ex:p ex:o .\n@prefix ex: <http://other.org/#> .\n"
                              "ex:s ex:p ex:o .",
    "a repeated triple": "ex:s ex:p ex:o . ex:s ex:p ex:o .",
    "text beyond ASCII in a string": 'ex:s ex:label "Kaffebryggare ☕" .',
    "an empty string": 'ex:s ex:label "" .',
    "prefixes saved as <> and never used": "@prefix : <> .\n@prefix default1: <> .\n"
                                            "ex:s ex:p ex:o .",
}


@pytest.mark.parametrize("body", READ.values(), ids=READ.keys())
def test_each_construct_of_the_subset_reads_as_rdflib_reads_it(body: str):
    text = HEAD + body
    ours = _ours(text)
    assert ours is not None and ours == _rdflib(text)


def test_terms_are_rdflibs_terms_as_data():
    ours = read_triples(HEAD + 'ex:s ex:n 7 ; ex:label "x"@en .')
    assert ours == {
        tuple(from_rdflib(t) for t in triple) for triple in (
            (URIRef("http://example.org/ex#s"), URIRef("http://example.org/ex#n"),
             Literal("7", datatype=URIRef(XSD + "integer"))),
            (URIRef("http://example.org/ex#s"), URIRef("http://example.org/ex#label"),
             Literal("x", lang="en")))}
    assert {o.value for _, _, o in ours} == {7, "x"}


def _lexical(chance: random.Random) -> str:
    """A literal's text near the edge of ``plain_literal``: numbers of every shape, words,
    and now and then something else."""
    digits = "".join(chance.choice("0123456789") for _ in range(chance.randint(1, 20)))
    shapes = [digits, "-" + digits, "+" + digits, "0" + digits,
              digits[:8] + "." + digits[8:], "." + digits, digits + ".", digits + "e3",
              digits[:3] + "E-2", digits[:1] + "." + digits[1:] + "e-07",
              "-" + digits[:1] + "." + digits[1:] + "e+12", digits[:2] + "e-99",
              "true", "false", "TRUE", "1", "0", "yes", "", " 7", "7 ",
              "1_000", "nan", "inf", "-0", "-0.0", "0,35", "x", "Ä"]
    return chance.choice(shapes)


def test_plain_literals_are_read_as_rdflib_reads_them():
    """``plain_literal`` against rdflib's ``Literal`` (whichever rdflib runs the tests): the
    same text kept, datatype, language and value, or None; made here for most of what
    SkiROS2 saves."""
    chance = random.Random(7)
    datatypes = ["", *(XSD + t for t in ("string", "integer", "int", "float", "double",
                                          "boolean", "decimal", "long"))]
    made = 0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        logging.getLogger("rdflib.term").setLevel(logging.CRITICAL)
        for _ in range(6000):
            lexical, datatype = _lexical(chance), chance.choice(datatypes)
            language = chance.choice(["", "en", "sv", "EN"]) if not datatype else ""
            ours = plain_literal(lexical, language, datatype)
            if ours is None:
                continue
            made += 1
            theirs = Literal(lexical, lang=language or None,
                             datatype=URIRef(datatype) if datatype else None)
            assert _term(ours) == _term(theirs), (lexical, language, datatype)
    assert made > 1500


LEFT_TO_RDFLIB = {
    "a blank node": "ex:s ex:p [ ex:q ex:o ] .",
    "a labelled blank node": "_:b ex:p ex:o .",
    "a collection": "ex:s ex:p ( ex:a ex:b ) .",
    "an escape in a string": 'ex:s ex:label "a\\"b" .',
    "a long string": 'ex:s ex:label """two\nlines""" .',
    "a single-quoted string": "ex:s ex:label 'x' .",
    "a decimal": "ex:s ex:v 1.50 .",
    "a double": "ex:s ex:v 1e3 .",
    "an integer with a sign": "ex:s ex:v +5 .",
    "an integer with a leading zero": "ex:s ex:v 007 .",
    "a base": "@base <http://example.org/> .\nex:s ex:p ex:o .",
    "a relative IRI": "ex:s ex:p <o> .",
    "a name of a prefix saved as <>": "@prefix d: <> .\nex:s ex:p d:o .",
    "the empty prefix saved as <>": "@prefix : <> .\n:s ex:p ex:o .",
    "an empty IRI": "ex:s ex:p <> .",
    "SPARQL's PREFIX": "PREFIX ex2: <http://x.org/#>\nex2:s ex2:p ex2:o .",
    "a local name with a full stop inside": "ex:s ex:p ex:a.b .",
    "a local name with a colon": "ex:s ex:p ex:a:b .",
    "a local name starting with a digit": "ex:s ex:p ex:1a .",
    "an empty local name against the full stop": "ex:s ex:p ex:.",
    "a comment against a name": "ex:s ex:p ex:o# note\n.",
    "an unknown prefix": "ex:s ex:p nope:o .",
    "a trailing semicolon": "ex:s ex:p ex:o ; .",
    "a language tag apart from its string": 'ex:s ex:label "x" @en .',
    "a datatype apart from its string": 'ex:s ex:v "1" ^^xsd:integer .',
    "a missing full stop": "ex:s ex:p ex:o",
    "a literal subject": '"x" ex:p ex:o .',
    "a keyword as object": "ex:s ex:p a .",
    "a byte-order mark": "\ufeffex:s ex:p ex:o .",
    "an IRI beyond ASCII": "ex:s ex:p <http://example.org/caf\u00e9> .",
}


@pytest.mark.parametrize("body", LEFT_TO_RDFLIB.values(), ids=LEFT_TO_RDFLIB.keys())
def test_what_lies_outside_the_subset_is_left_to_rdflib(body: str):
    assert read_triples(HEAD + body) is None


SUBJECTS = (["ex:s", "ex:o", "ex:Door-10", "ex:_x", ":x", "ex:", "<http://example.org/i>"],
            ["ex:a.b", "ex:a:b", "ex:1a", "<rel>", "nope:o", "_:b", "a", '"v"'])
PREDICATES = (["a", "ex:p", "ex:q", "<http://example.org/p>"], ["true", "ex:p.x", "ex:p;"])
OBJECTS = ([*SUBJECTS[0], "true", "false", "0", "-0", "-3", "12", '"v"', '"v"@en', '"v"@EN',
            '"TRUE"^^xsd:boolean', '"01"^^xsd:integer', '"v"^^xsd:int',
            '"v"^^<http://example.org/t>', '"7"^^xsd:integer', '""', '"0,35"^^xsd:float'],
           [*SUBJECTS[1], "007", "+5", "1.5", "1e3", '"v" @en', '"a\\"b"', "'v'",
            "[ ex:p ex:o ]", "( ex:o )", "ex:o#c"])
SPACES = ([" ", "", "\n", "\t", " # c\n"], ["\u00a0", "\ufeff"])
ENDS = ([" .\n", ".\n", " .", "."], [" ;.\n", "\n", " ,.\n"])


def _texts(seed: int, count: int) -> list[str]:
    """Texts near the subset's edge: statements whose terms, lists, spacing and ends are
    drawn at random, each once in twenty from Turtle outside the subset or nonsense."""
    chance = random.Random(seed)

    def pick(inside_outside: tuple[list[str], list[str]]) -> str:
        return chance.choice(inside_outside[chance.random() < 1 / 20])

    texts = []
    for _ in range(count):
        out = [HEAD]
        for _ in range(chance.randint(1, 3)):
            if chance.random() < 0.1:
                out.append("@prefix ex: <http://example.org/again#> .\n")
            if chance.random() < 0.05:  # as SkiROS2 saves it: the names ``:x`` then use it
                out.append("@prefix : <> .\n")
            out.append(pick(SUBJECTS))
            for number in range(chance.randint(1, 3)):
                out.append((pick(SPACES) + ";" if number else "") + " " + pick(PREDICATES))
                for each in range(chance.randint(1, 3)):
                    out.append(pick(SPACES) + "," + pick(SPACES) if each else " ")
                    out.append(pick(OBJECTS))
            out.append(pick(ENDS))
        texts.append("".join(out))
    return texts


def test_texts_at_random_near_the_edge_read_as_rdflib_reads_them():
    texts = _texts(31, 4000)
    read = [t for t in texts if read_triples(t) is not None]
    assert 500 < len(read) < len(texts) - 500  # the edge is crossed both ways
    assert [t for t in texts if not _agrees(t)] == []


def test_a_scene_read_by_the_subset_is_the_scene_rdflib_gives(tmp_path: Path):
    """The same ``Scene`` (elements, lines, values) whichever reader read the triples: a
    ``@base`` line at the end sends the copy to rdflib without adding a triple."""
    compared = 0
    for path in SCENES:
        text = path.read_text(encoding="utf-8")
        if read_triples(text) is None:
            continue
        sent = text + "\n@base <http://example.org/> .\n"
        assert read_triples(sent) is None
        subset, whole = (read_scene(tmp_path / "a.turtle", t) for t in (text, sent))
        assert _seen(subset) == _seen(whole)
        compared += 1
    assert compared >= 3


def _seen(scene: Scene) -> tuple[object, ...]:
    return ([(e.iri, e.line, e.types, e.label) for e in scene.elements.values()],
            scene.relations,
            [(v.subject, v.property, v.lexical, v.datatype, repr(v.value), v.line)
             for v in scene.values])
