"""The ontology: loading (rdflib), the index of classes and properties, and prefix namespaces.

``from ezskiros_runtime.ontology import skiros, cora`` gives the namespaces of the *active*
ontology's prefixes through the module ``__getattr__`` below; importing this package loads
nothing (no rdflib, no ontology) until such a name is actually asked for. Submodules and the
helpers listed in ``_HELPERS`` take precedence over prefixes.
"""

from __future__ import annotations

import importlib
import importlib.util
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from .active import active_index, use_ontology
    from .index import OntologyIndex, load_index
    from .namespaces import Namespace

_HELPERS: dict[str, str] = {
    "active_index": "active",
    "use_ontology": "active",
    "load_index": "index",
    "OntologyIndex": "index",
    "Namespace": "namespaces",
    "namespace": "namespaces",
}


def __getattr__(name: str) -> Any:
    """A helper, a submodule, or the namespace of an ontology prefix."""
    if name.startswith("_"):
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    module_name = _HELPERS.get(name)
    if module_name is not None:
        return getattr(importlib.import_module(f"{__name__}.{module_name}"), name)
    if importlib.util.find_spec(f"{__name__}.{name}") is not None:
        return importlib.import_module(f"{__name__}.{name}")
    from ..diagnostics import UnknownPrefixError, UnknownVocabularyError
    from .namespaces import namespace

    try:
        return namespace(name)
    except UnknownVocabularyError as unknown:  # keep the "did you mean" through the import
        raise UnknownPrefixError(str(unknown), name=name,
                                 suggestions=unknown.suggestions) from None


def __dir__() -> list[str]:
    return sorted({*globals(), *_HELPERS})


__all__ = ["Namespace", "OntologyIndex", "active_index", "load_index", "use_ontology"]
