"""Read a constructed ``SkillDescription`` into the normalized ``model.SkillModel``.

Legacy classes and EzSkiROS classes share the base class (``abstract_skill``), so this one
function produces the model of both sides of a migration; it reads only the accessors listed
in ``abstract_skill``'s docstring (``_type``, ``params``, ``_pre/_hold/_post_conditions``).
"""

from __future__ import annotations

from typing import Any

from .. import model
from .abstract_skill import SkillDescription
from .conditions import condition_model
from .params import Param
from .world_element import Element

__all__ = ["model_of", "param_model"]


def _is_element_type(data_type: Any) -> bool:
    return isinstance(data_type, type) and issubclass(data_type, Element)


def param_model(param: Param) -> model.Param:
    """One ``Param`` as the model stores it.

    Element parameters keep the verbatim type string in ``element_type`` (``None`` when the
    ``Element`` class itself was given) and, like type objects, no values (§3). Only the rare
    element that carries a label or id, or a list of several elements, keeps its values
    (their deterministic ``repr``), so that such a difference is never lost.
    """
    if _is_element_type(param.dataType):
        elements = param.values
        element_type = elements[0].type if elements else None
        plain_single = len(elements) == 1 and elements[0].is_plain()
        values = () if not elements or plain_single else tuple(model.typed(e) for e in elements)
        return model.Param(
            key=param.key, kind=param.paramType.name, data_type="Element",
            element_type=element_type, values=values, description=param.description,
            options=param.options,
        )
    return model.Param(
        key=param.key, kind=param.paramType.name, data_type=param.dataType.__name__,
        values=tuple(model.typed(v) for v in param.values), description=param.description,
        options=param.options,
    )


def _conditions(conditions: list[Any], which: str) -> tuple[model.Condition, ...]:
    return tuple(condition_model(c, f"{which}-condition #{i}")
                 for i, c in enumerate(conditions, 1))


def model_of(description: SkillDescription) -> model.SkillModel:
    """The model of a constructed description: class name, ``_type``, params in order, and
    the three condition lists in call order. Raises ``NotDeclarativeError`` for a
    ``ConditionFunction`` (or any non-condition object) in a list."""
    return model.SkillModel(
        name=type(description).__name__,
        type=description._type,
        params=tuple(param_model(p) for p in description.params.values()),
        pre=_conditions(description._pre_conditions, "pre"),
        hold=_conditions(description._hold_conditions, "hold"),
        post=_conditions(description._post_conditions, "post"),
    )
