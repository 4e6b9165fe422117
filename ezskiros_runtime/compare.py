"""Equivalence of two skill models, and a difference report people can read.

The comparison is order- and label-sensitive by default because SkiROS2 keeps declaration
order and shows labels; ``ignore_order`` and ``ignore_labels`` relax it for users who decide
those do not matter to them (and the report then says so).
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, replace
from difflib import SequenceMatcher

from .model import CONDITION_LISTS, Condition, SkillModel
from .notation import render_condition, render_param


@dataclass(frozen=True)
class Difference:
    """One way in which two models differ, both sides in legacy notation.

    ``where`` names the part (``"params"``, ``"pre"``, ``"hold"``, ``"post"``, ``"type"``);
    ``before``/``after`` are ``None`` when that side lacks the item.
    """

    where: str
    message: str
    before: str | None = None
    after: str | None = None

    def to_json(self) -> dict[str, str | None]:
        return {"where": self.where, "message": self.message, "before": self.before,
                "after": self.after}

    def __str__(self) -> str:
        lines = [f"{self.where}: {self.message}"]
        if self.before is not None:
            lines.append(f"  - {self.before}")
        if self.after is not None:
            lines.append(f"  + {self.after}")
        return "\n".join(lines)


def _unlabelled(c: Condition) -> Condition:
    return replace(c, label="", children=tuple(_unlabelled(x) for x in c.children))


def _relaxed(m: SkillModel, ignore_order: bool, ignore_labels: bool) -> SkillModel:
    """``m`` without what the flags say to ignore, for the final exact check: the flags relax
    order and labels only, never details the notation does not show (values of a labelled
    ``Element``, data types)."""
    lists = {which: m.conditions(which) for which in CONDITION_LISTS}
    if ignore_labels:
        lists = {which: tuple(_unlabelled(c) for c in cs) for which, cs in lists.items()}
    params = m.params
    if ignore_order:
        params = tuple(sorted(params, key=repr))
        lists = {which: tuple(sorted(cs, key=repr)) for which, cs in lists.items()}
    return replace(m, params=params, pre=lists["pre"], hold=lists["hold"], post=lists["post"])


def _sequence_diff(where: str, before: list[str], after: list[str], ignore_order: bool,
                   noun: str) -> list[Difference]:
    if ignore_order:
        missing = Counter(before) - Counter(after)
        extra = Counter(after) - Counter(before)
        return [Difference(where, f"{noun} missing after migration", before=b)
                for b in missing.elements()] + [
                Difference(where, f"{noun} added by migration", after=a)
                for a in extra.elements()]
    if before == after:
        return []
    if sorted(before) == sorted(after):
        return [Difference(where, f"same {noun}s in a different order",
                           before=" ; ".join(before), after=" ; ".join(after))]
    out: list[Difference] = []
    matcher = SequenceMatcher(a=before, b=after, autojunk=False)
    for tag, i1, i2, j1, j2 in matcher.get_opcodes():
        if tag == "equal":
            continue
        olds, news = before[i1:i2], after[j1:j2]
        for k in range(max(len(olds), len(news))):
            b = olds[k] if k < len(olds) else None
            a = news[k] if k < len(news) else None
            position = i1 + k + 1 if b is not None else j1 + k + 1
            if b is not None and a is not None:
                msg = f"{noun} #{position} differs"
            elif b is not None:
                msg = f"{noun} #{position} missing after migration"
            else:
                msg = f"{noun} #{position} added by migration"
            out.append(Difference(where, msg, before=b, after=a))
    return out


def compare(before: SkillModel, after: SkillModel, *, ignore_order: bool = False,
            ignore_labels: bool = False) -> list[Difference]:
    """Every difference between two models; an empty list means equivalent."""
    diffs: list[Difference] = []
    if before.type != after.type:
        diffs.append(Difference("type", "skill type differs", before.type, after.type))
    diffs += _sequence_diff("params", [render_param(p) for p in before.params],
                            [render_param(p) for p in after.params], ignore_order, "parameter")
    for which in CONDITION_LISTS:
        b_conds = before.conditions(which)
        a_conds = after.conditions(which)
        if ignore_labels:
            b_conds = tuple(_unlabelled(c) for c in b_conds)
            a_conds = tuple(_unlabelled(c) for c in a_conds)
        diffs += _sequence_diff(which, [render_condition(c) for c in b_conds],
                                [render_condition(c) for c in a_conds], ignore_order,
                                f"{which}-condition")
    if not diffs:
        b_json = _relaxed(replace(before, name=after.name), ignore_order,
                          ignore_labels).canonical_json()
        a_json = _relaxed(after, ignore_order, ignore_labels).canonical_json()
        if b_json != a_json:  # a detail the legacy notation does not show (e.g. data type)
            diffs.append(Difference("model", "models differ", before=b_json, after=a_json))
    return diffs


def equivalent(before: SkillModel, after: SkillModel, *, ignore_order: bool = False,
               ignore_labels: bool = False) -> bool:
    """True when ``compare`` finds nothing."""
    return not compare(before, after, ignore_order=ignore_order, ignore_labels=ignore_labels)

