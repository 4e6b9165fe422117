"""Stand-in for ``skiros2_common.core.world_element.Element``.

Only what a skill *description* touches is reproduced: construction and the stored type,
label and id. The type string is kept verbatim (legacy-skiros2-api.md §8.6): ``":Location"``,
``"Location"`` and ``"skiros:Location"`` are three different descriptions in SkiROS2 (the world
model resolves them to one URI later, but the stored description differs), and ``Element()``
has the type ``"Unknown"``. Real SkiROS2's module imports ``rospy`` (§8.11); this one imports
nothing, which is why it can load legacy files without ROS.
"""

from __future__ import annotations

from typing import Any

__all__ = ["Element"]


class Element:
    """A world-model element as a skill description declares it: an OWL class string.

    ``Element(etype="Unknown", label="", eid="")`` mirrors SkiROS2's positional order so
    ``Element("skiros:Location", "kitchen")`` keeps meaning what it meant there.
    """

    def __init__(self, etype: str = "Unknown", label: str = "", eid: str = "") -> None:
        self._type = etype
        self._label = label
        self._id = eid
        self._properties: dict[str, Any] = {}
        self._relations: list[Any] = []

    @property
    def type(self) -> str:
        """The verbatim type string given at construction (§8.6)."""
        return self._type

    @type.setter
    def type(self, value: str) -> None:
        self._type = value

    @property
    def label(self) -> str:
        return self._label

    @label.setter
    def label(self, value: str) -> None:
        self._label = value

    @property
    def id(self) -> str:
        return self._id

    @id.setter
    def id(self, value: str) -> None:
        self._id = value

    def is_plain(self) -> bool:
        """True when only the type was given: the normalized model then needs no value (the
        form every real description uses, §7); otherwise label and id must be kept."""
        return not self._label and not self._id

    def __repr__(self) -> str:
        # Deterministic: the extractor keeps this text for the rare labelled element, so two
        # loads of the same description must print the same.
        args = [repr(self._type)]
        if not self.is_plain():
            args += [repr(self._label), repr(self._id)]
        return f"Element({', '.join(args)})"
