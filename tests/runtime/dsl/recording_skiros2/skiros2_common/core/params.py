"""Recording stand-in for ``skiros2_common.core.params``: only ``ParamTypes``."""

from enum import Enum


class ParamTypes(Enum):
    """Same members and values as SkiROS2's."""

    Required = 0
    Optional = 1
    Inferred = 2
