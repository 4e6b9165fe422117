"""IRI splitting and prefix derivation, the way SkiROS2 does it.

SkiROS2 never reads prefixes from the files: it derives one from each ontology namespace
(last path segment, extension dropped, lower-cased), so `.../coraX.owl#` is `corax`, not
the `coraX` the OWL file binds. Skill code is written against those derived prefixes, so
the index must derive them identically.
"""

from __future__ import annotations

SKIROS_NAMESPACE = "http://rvmi.aau.dk/ontologies/skiros.owl#"
"""SkiROS2's own namespace; always reachable as `skiros` because `:Name` means it."""

DEFAULT_PREFIX = "skiros"

WELL_KNOWN_PREFIXES: dict[str, str] = {
    "owl": "http://www.w3.org/2002/07/owl#",
    "rdf": "http://www.w3.org/1999/02/22-rdf-syntax-ns#",
    "rdfs": "http://www.w3.org/2000/01/rdf-schema#",
    "xsd": "http://www.w3.org/2001/XMLSchema#",
}
"""Added when no ontology namespace claims the prefix, so messages can say `xsd:float`."""

OWL = WELL_KNOWN_PREFIXES["owl"]
XSD = WELL_KNOWN_PREFIXES["xsd"]
RDF_TYPE = WELL_KNOWN_PREFIXES["rdf"] + "type"
"""The W3C terms the readers of scenes, ontologies and values name: spelt here once."""


def split_iri(iri: str) -> tuple[str, str]:
    """Split an IRI into (namespace, local name).

    The namespace runs up to and including the first `#`, else up to and including the last
    `/`. An IRI with neither has an empty namespace.
    """
    hash_at = iri.find("#")
    if hash_at >= 0:
        return iri[: hash_at + 1], iri[hash_at + 1 :]
    slash_at = iri.rfind("/")
    if slash_at >= 0:
        return iri[: slash_at + 1], iri[slash_at + 1 :]
    return "", iri


def local_name(iri: str) -> str:
    """The part of an IRI after its namespace (`...skiros.owl#Product` -> `Product`)."""
    return split_iri(iri)[1]


def derive_prefix(namespace: str) -> str | None:
    """SkiROS2's prefix for a namespace, or None when the namespace gives no usable one.

    `http://rvmi.aau.dk/ontologies/skiros.owl#` -> `skiros`; `.../coraX.owl#` -> `corax`.
    """
    stripped = namespace.rstrip("#/")
    segment = stripped.rsplit("/", 1)[-1]
    if ":" in segment:  # urn:a:b style namespaces have no path segments
        segment = segment.rsplit(":", 1)[-1]
    stem, dot, _extension = segment.rpartition(".")
    name = (stem if dot and stem else segment).lower()
    if not name or ":" in name or name in {"http", "https", "urn"}:
        return None
    return name


def looks_like_iri(text: str) -> bool:
    """True for absolute IRIs (`http://...`, `urn:...`), which need no prefix expansion."""
    return "://" in text or text.startswith("urn:")
