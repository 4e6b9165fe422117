"""EzSkiROS: ontology-typed SkiROS2 skill descriptions with early checks.

The public names are loaded lazily (module ``__getattr__``): ``import ezskiros_runtime``
costs nothing, ``ezmigrate`` can import the model without choosing a backend, and neither
rdflib nor the ontology is touched until a namespace attribute or a check needs them.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

__version__ = "0.1.0"
"""Also part of the ontology cache key: a new release never reads an old release's cache."""

if TYPE_CHECKING:
    from .compound import CompoundSkillError, check_compound
    from .diagnostics import (
        DescriptionError,
        EzSkirosWarning,
        Finding,
        SkillTypeError,
        UnknownVocabularyError,
    )
    from .dsl.checking import check
    from .dsl.conditions import abstract, any_of
    from .dsl.markers import (
        DESC,
        ELEMENT,
        INFERRED,
        KEY,
        LIST,
        OPTIONAL,
        REQUIRED,
        Annotated,
        Consume,
        Lock,
        Output,
        RespectType,
        Unspecify,
    )
    from .dsl.policy import collecting, is_strict, set_severity, strict
    from .dsl.skill import SkillDescription

_EXPORTS: dict[str, str] = {
    "SkillDescription": "dsl.skill",
    **dict.fromkeys(("INFERRED", "OPTIONAL", "REQUIRED", "ELEMENT", "KEY", "DESC", "LIST",
                     "Annotated", "Lock", "Consume", "Unspecify", "RespectType", "Output"),
                    "dsl.markers"),
    "abstract": "dsl.conditions",
    "any_of": "dsl.conditions",
    "check": "dsl.checking",
    "strict": "dsl.policy",
    "check_compound": "compound",
    "CompoundSkillError": "compound",
    "is_strict": "dsl.policy",
    "collecting": "dsl.policy",
    "set_severity": "dsl.policy",
    **dict.fromkeys(("Finding", "SkillTypeError", "DescriptionError", "EzSkirosWarning",
                     "UnknownVocabularyError"), "diagnostics"),
}


def __getattr__(name: str) -> Any:
    """A public name, imported from its submodule on first use.

    When importing that submodule fails (an import error inside SkiROS2 on the robot, a
    missing rdflib), the error says so and chains the original: Python would otherwise
    report only ``cannot import name 'SkillDescription' from 'ezskiros_runtime'`` when the
    failure is an ``AttributeError``, and the cause would be lost."""
    module = _EXPORTS.get(name)
    if module is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    try:
        loaded = importlib.import_module(f"{__name__}.{module}")
    except Exception as error:
        raise ImportError(f"cannot import name {name!r} from {__name__!r}: importing "
                          f"{__name__}.{module} raised {type(error).__name__}: {error}",
                          name=__name__) from error
    value = getattr(loaded, name)
    globals()[name] = value  # later lookups skip this function
    return value


def __dir__() -> list[str]:
    return sorted({*globals(), *_EXPORTS})


__all__ = [
    "DESC",
    "ELEMENT",
    "INFERRED",
    "KEY",
    "LIST",
    "OPTIONAL",
    "REQUIRED",
    "Annotated",
    "CompoundSkillError",
    "Consume",
    "DescriptionError",
    "EzSkirosWarning",
    "Finding",
    "Lock",
    "Output",
    "RespectType",
    "SkillDescription",
    "SkillTypeError",
    "UnknownVocabularyError",
    "Unspecify",
    "abstract",
    "any_of",
    "check",
    "check_compound",
    "collecting",
    "is_strict",
    "set_severity",
    "strict",
]
