"""The ontology: loading (rdflib), the index of classes and properties, and prefix namespaces.

``from ezskiros_runtime.ontology import skiros, cora`` gives the namespaces of the *active*
ontology's prefixes through the module ``__getattr__`` below; importing this package loads
nothing (no rdflib, no ontology) until such a name is actually asked for.

The helpers listed in ``_HELPERS`` (the public API) take precedence over prefixes. The
package's internal submodules do not: an ontology whose prefix is ``data``, ``cache`` or
``index`` must be usable (``from ezskiros_runtime.ontology import data``), so asking the
package for a submodule's name loads the active ontology and returns that prefix's namespace
when it defines one. Code that means the module imports from it
(``from ezskiros_runtime.ontology.cache import ...``), which never consults the package's
attributes. When the ontology cannot be loaded, the submodule is returned as before (the
load error surfaces at the first real use of the ontology).
"""

from __future__ import annotations

import importlib
import importlib.util
import sys
from pathlib import Path
from types import FrameType, ModuleType
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from .active import active_index, use_ontology
    from .index import OntologyIndex
    from .load import load_index
    from .namespaces import Namespace

_HELPERS: dict[str, str] = {
    "active_index": "active",
    "use_ontology": "active",
    "load_index": "load",
    "OntologyIndex": "index",
    "Namespace": "namespaces",
    "namespace": "namespaces",
}


_SUBMODULES = frozenset(
    path.stem for path in Path(__file__).resolve().parent.iterdir()
    if not path.name.startswith("_") and (path.suffix == ".py" or path.is_dir())
)
"""Names of the internal submodules (and the ``data`` folder): prefixes may shadow them."""

_resolving: list[bool] = [False]
"""True while `_prefix_namespace` loads the ontology: the loader's own module lookups must
reach the modules, not recurse."""


def _prefix_namespace(name: str) -> Any:
    """The namespace of prefix `name` in the active ontology, else None."""
    if _resolving[0]:
        return None
    _resolving[0] = True
    try:
        from .active import active_index
        from .errors import OntologyError

        _note_requester()
        try:
            index = active_index()
        except OntologyError:  # the submodule stays reachable; the error shows at real use
            return None
        if name not in index.prefixes:
            return None
        from .namespaces import namespace

        return namespace(name)
    finally:
        _resolving[0] = False


class _OntologyPackage(ModuleType):
    """This package's module type: a prefix named like a submodule wins over the module,
    even once the submodule is imported (the import system then binds it as an attribute,
    which the module-level ``__getattr__`` alone would never get past)."""

    def __getattribute__(self, name: str) -> Any:
        if name in _SUBMODULES:
            found = _prefix_namespace(name)
            if found is not None:
                return found
        return super().__getattribute__(name)


sys.modules[__name__].__class__ = _OntologyPackage


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

    _note_requester()
    try:
        return namespace(name)
    except UnknownVocabularyError as unknown:
        if not _asked_by_import_statement():
            raise  # an AttributeError: hasattr() and getattr(..., default) work as usual
        # Python replaces an AttributeError during `from ... import` by its own message
        raise UnknownPrefixError(str(unknown), name=name,
                                 suggestions=unknown.suggestions) from None


_IMPORT_SYSTEM = "importlib._bootstrap"


def _requesting_frame(skip: tuple[str, ...] = ()) -> FrameType | None:
    """The frame that asked this package for a name: the first one outside this module
    (``__getattribute__``, ``__getattr__`` and helpers) and the modules in ``skip``."""
    frame: FrameType | None = sys._getframe(1)
    while frame is not None and frame.f_globals.get("__name__") in (__name__, *skip):
        frame = frame.f_back
    return frame


def _asked_by_import_statement() -> bool:
    """Does the attribute lookup in progress come from ``from ezskiros_runtime.ontology
    import name``? The import system asks through ``importlib._bootstrap`` (its
    ``_handle_fromlist``); plain attribute access, ``hasattr`` and ``getattr`` come from
    user code."""
    frame = _requesting_frame()
    return frame is not None and frame.f_globals.get("__name__") == _IMPORT_SYSTEM


def _note_requester() -> None:
    """Tell the active-ontology resolver which file asks for vocabulary (see
    ``active.note_source_file``): the skill module, past the import system's frames."""
    from .active import note_source_file

    frame = _requesting_frame((_IMPORT_SYSTEM,))
    note_source_file(frame.f_globals.get("__file__") if frame is not None else None)


def __dir__() -> list[str]:
    return sorted({*globals(), *_HELPERS})


__all__ = ["Namespace", "OntologyIndex", "active_index", "load_index", "use_ontology"]
