"""Our re-implementation of the legacy SkiROS2 description API (used when SkiROS2 is absent).

The bottom layer of ``ezskiros_runtime``: it imports neither the DSL nor rdflib, so loading it
stays cheap. Modules (legacy-skiros2-api.md is the spec):

- ``params``, ``world_element``, ``conditions``, ``abstract_skill``: the description API
  (``SkillDescription`` is the base of legacy *and* EzSkiROS classes);
- ``primitive``, ``skill``, ``processors``: implementation-side names, enough to import files;
- ``stand_ins.legacy_imports``: serves ``skiros2_common``/``skiros2_skill`` (and stubs);
- ``extract.model_of``: a constructed description -> ``model.SkillModel``;
- ``loader.load_file``: import a file, load every description class defined in it.
"""

from __future__ import annotations

from .abstract_skill import ParamOptions, SkillDescription
from .conditions import (
    AbstractConditionRelation,
    ConditionFunction,
    ConditionGenerate,
    ConditionHasProperty,
    ConditionIsSpecified,
    ConditionOnType,
    ConditionOr,
    ConditionProperty,
    ConditionRelation,
)
from .errors import (
    LegacyError,
    ModuleLoadError,
    NotDeclarativeError,
    NotUpstreamAPIError,
    ParamValueError,
    UnsupportedConstructError,
)
from .extract import model_of
from .loader import FileLoad, load_file, load_source
from .params import Param, ParamHandler, ParamTypes
from .stand_ins import legacy_imports
from .world_element import Element

__all__ = [
    "AbstractConditionRelation",
    "ConditionFunction",
    "ConditionGenerate",
    "ConditionHasProperty",
    "ConditionIsSpecified",
    "ConditionOnType",
    "ConditionOr",
    "ConditionProperty",
    "ConditionRelation",
    "Element",
    "FileLoad",
    "LegacyError",
    "ModuleLoadError",
    "NotDeclarativeError",
    "NotUpstreamAPIError",
    "Param",
    "ParamHandler",
    "ParamOptions",
    "ParamTypes",
    "ParamValueError",
    "SkillDescription",
    "UnsupportedConstructError",
    "legacy_imports",
    "load_file",
    "load_source",
    "model_of",
]
