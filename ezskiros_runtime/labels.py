"""Conventional condition labels: the one place that says what label a condition gets by default.

SkiROS2 labels are free text. The conventional relation label is
``<Subject><Relation capitalised><Object>`` with a ``Not`` prefix for desired state False
(legacy-skiros2-api.md §4). The EzSkiROS runtime gives every condition without an explicit
``.named(...)`` its conventional label, and the migrator writes ``.named(...)`` exactly when
a legacy label differs from the convention, so both sides must use this module.
"""

from __future__ import annotations

OR_LABEL = "or"
"""``getOrCond`` conditions are always labelled ``"or"`` (legacy-skiros2-api.md §8.7)."""


def local_name(vocabulary: str) -> str:
    """``"skiros:contain"`` -> ``"contain"``; a string without a colon is its own local name."""
    return vocabulary.rsplit(":", 1)[-1]


def capitalised(name: str) -> str:
    """First letter upper-cased, the rest untouched (``robotPart`` -> ``RobotPart``)."""
    return name[:1].upper() + name[1:]


def _negated(label: str, desired: object) -> str:
    return label if desired is not False else "Not" + label


def conventional_label(
    kind: str,
    *,
    subject: str | None = None,
    vocabulary: str | None = None,
    object: str | None = None,
    desired_state: object = True,
) -> str:
    """The label the convention gives a condition of ``kind`` built from these parts.

    ``desired_state`` is the raw Python value: only ``False`` itself adds ``Not``, so a
    non-bool desired state (which SkiROS2 accepts) never gets a convention it did not have.
    """
    subj = subject or ""
    vocab = capitalised(local_name(vocabulary or ""))
    if kind in ("relation", "abstract_relation"):
        return _negated(f"{subj}{vocab}{object or ''}", desired_state)
    if kind == "property":
        return _negated(f"{subj}{vocab}", desired_state)
    if kind == "has_property":
        return _negated(f"{subj}Has{vocab}", desired_state)
    if kind == "is_specified":
        return _negated(f"{subj}Specified", desired_state)
    if kind == "generate":
        return _negated(f"{subj}Generated", desired_state)
    if kind == "on_type":
        return f"{subj}OfType"
    if kind == "or":
        return OR_LABEL
    raise ValueError(f"unknown condition kind {kind!r}")
