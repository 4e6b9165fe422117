"""How much of an ontology file the loader reads: bytes, triples, seconds, entities.

Why: ontology files come from repositories nobody vetted (every ``owl/`` folder is
discovered), and rdflib has no bound of its own. A 35 MB Turtle file took 90 s and 3.5 GB
with no message; a long flat entity used 80,000 times made rdflib build one literal by
quadratic concatenation for minutes. Each limit below is checked before or while the file
is parsed, and a file over one is refused with an `OntologyLimitError` that names the file,
the limit and the environment variable that raises it. Like any load error, a refused
discovered file is skipped with one warning and the run goes on with the other files
(``config.load_source``); a file named explicitly stops the load, on the robot as in the
command, instead of a hang.

Memory follows the triples (rdflib keeps each in several indexes) and the bytes; the
class and property closures are linear in the triples (``closure.Hierarchy``), so no
separate memory limit is needed. Runs on the robot's Python 3.8.
"""

from __future__ import annotations

import os
import time
from collections.abc import Mapping
from typing import NamedTuple

from .errors import OntologyLimitError


class Limit(NamedTuple):
    """One bound: the environment variable that sets it, its default, and its unit."""

    variable: str
    default: float
    unit: str

    def value(self, environ: Mapping[str, str] | None = None) -> float:
        """The bound in force: the environment variable when it holds a positive number,
        else the default (a typo must not switch the protection off). A count is whole;
        seconds may be a fraction."""
        raw = (os.environ if environ is None else environ).get(self.variable, "").strip()
        try:
            number = float(raw.replace("_", ""))
        except ValueError:
            return self.default
        if not number > 0 or number == float("inf"):
            return self.default
        return number if isinstance(self.default, float) else int(number)


MAX_BYTES = Limit("EZSKIROS_ONTOLOGY_MAX_BYTES", 16 * 1024 * 1024, "bytes")
"""Size of one file, checked before it is read (the SkiROS2 core is about 50 KB)."""
MAX_TRIPLES = Limit("EZSKIROS_ONTOLOGY_MAX_TRIPLES", 200_000, "triples")
"""Triples one file may hold, counted while rdflib parses it (the bundled core has 478)."""
MAX_SECONDS = Limit("EZSKIROS_ONTOLOGY_MAX_SECONDS", 60.0, "seconds")
"""Time parsing one file may take, checked as its triples arrive."""
MAX_ENTITY_REFERENCES = Limit("EZSKIROS_ONTOLOGY_MAX_ENTITY_REFERENCES", 100_000,
                              "entity references")
"""References to the DTD's own entities in one RDF/XML file."""
MAX_ENTITY_EXPANSION = Limit("EZSKIROS_ONTOLOGY_MAX_ENTITY_EXPANSION", 2_000_000,
                             "characters")
"""Characters those references add to the file when expanded, all together."""

ALL = (MAX_BYTES, MAX_TRIPLES, MAX_SECONDS, MAX_ENTITY_REFERENCES, MAX_ENTITY_EXPANSION)


def stamp(environ: Mapping[str, str] | None = None) -> str:
    """The limits in force, for the key of a remembered refusal: raising a limit must
    load the file again, not repeat the old refusal."""
    return ",".join(f"{limit.variable}={limit.value(environ)}" for limit in ALL)


def shown(number: float) -> str:
    """``200,000`` for a count, ``0.5`` for seconds."""
    return f"{number:g}" if isinstance(number, float) else f"{number:,}"


def refuse(path: object, found: str, limit: Limit, line: int | None = None,
           environ: Mapping[str, str] | None = None) -> OntologyLimitError:
    """The error for a file over ``limit``: what was found, the limit, how to raise it."""
    bound = limit.value(environ)
    where = f"{path}:{line}" if line else str(path)
    return OntologyLimitError(
        f"{where}: refused: {found}, over the limit of {shown(bound)} {limit.unit} "
        f"(set {limit.variable} to a larger number, e.g. {limit.variable}={bound * 4:.0f}, "
        "to load it)",
        path=str(path), line=line, variable=limit.variable)


class ParseBudget:
    """Counts the triples of one file as rdflib adds them, and watches the clock.

    ``tick`` runs once per triple, so it does as little as it can: the clock is read every
    ``CLOCK_EVERY`` triples only."""

    CLOCK_EVERY = 512

    def __init__(self, path: object, environ: Mapping[str, str] | None = None) -> None:
        self.path = path
        self.environ = environ
        self.triples = 0
        self.max_triples = MAX_TRIPLES.value(environ)
        self.max_seconds = MAX_SECONDS.value(environ)
        self.started = time.monotonic()

    def tick(self) -> None:
        """One more triple; raises `OntologyLimitError` past a limit."""
        self.triples += 1
        if self.triples > self.max_triples:
            raise refuse(self.path, f"it holds more than {shown(self.max_triples)} triples",
                         MAX_TRIPLES, environ=self.environ)
        if self.triples % self.CLOCK_EVERY == 0:
            self.check_clock()

    def check_clock(self) -> None:
        """Raises `OntologyLimitError` when the parse has taken longer than allowed."""
        elapsed = time.monotonic() - self.started
        if elapsed > self.max_seconds:
            raise refuse(self.path, f"parsing it took more than {shown(self.max_seconds)} seconds "
                         f"({self.triples:,} triples read)", MAX_SECONDS,
                         environ=self.environ)
