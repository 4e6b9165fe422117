"""Recording stand-in for ``skiros2_common.core.world_element``: only ``Element``."""


class Element:
    """Keeps the verbatim type string, as SkiROS2's Element does."""

    def __init__(self, etype="Unknown", label="", eid=""):
        self.type = etype
        self.label = label
        self.id = eid

    def __repr__(self):
        return f"Element({self.type!r})"
