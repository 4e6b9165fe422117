"""Suggestions ("did you mean ...?") for misspelt vocabulary names.

Typos in skill code are mostly in the local name (`GrASPingPose`, `conatin`) and sometimes in
the prefix (`skirso:Product`, `coraX:Robot`), so candidates are ranked by the similarity of
their local names, case-insensitively, with a small bonus for the prefix the user wrote.
difflib is imported lazily: suggestions are only needed on the error path.
"""

from __future__ import annotations

from collections.abc import Iterable

CUTOFF = 0.6
"""Minimum case-insensitive similarity of local names (difflib's own default)."""

PREFIX_BONUS = 0.05
"""Tie-breaker favouring candidates in the prefix the user wrote."""


def _split_compact(name: str) -> tuple[str | None, str]:
    prefix, colon, local = name.rpartition(":")
    if not colon:
        return None, name
    return prefix, local


def closest_names(name: str, candidates: Iterable[str], limit: int = 3) -> list[str]:
    """The `limit` candidates (compact names like `skiros:GraspingPose`) closest to `name`.

    `name` may be `prefix:Local`, `:Local` or `Local`. The candidate identical to `name` is
    never suggested: suggesting what the user already wrote helps nobody.
    """
    from difflib import SequenceMatcher

    if limit <= 0:
        return []
    wanted_prefix, wanted_local = _split_compact(name.strip())
    wanted_lower = wanted_local.lower()
    if not wanted_lower:
        return []
    exact_case = SequenceMatcher(autojunk=False)
    any_case = SequenceMatcher(autojunk=False)
    any_case.set_seq2(wanted_lower)
    exact_case.set_seq2(wanted_local)
    scored: list[tuple[float, float, str]] = []
    for candidate in set(candidates):
        if candidate == name:
            continue
        prefix, local = _split_compact(candidate)
        lower = local.lower()
        if lower == wanted_lower:
            score = 2.0  # same word, only the case (or the prefix) differs
        else:
            any_case.set_seq1(lower)
            if any_case.real_quick_ratio() < CUTOFF or any_case.quick_ratio() < CUTOFF:
                continue
            score = any_case.ratio()
            if score < CUTOFF:
                continue
        if wanted_prefix and prefix is not None and prefix.lower() == wanted_prefix.lower():
            score += PREFIX_BONUS
        exact_case.set_seq1(local)
        scored.append((score, exact_case.ratio(), candidate))
    scored.sort(key=lambda item: (-item[0], -item[1], item[2]))
    return [candidate for _score, _tie, candidate in scored[:limit]]


def one_edit_apart(a: str, b: str) -> bool:
    """Whether ``b`` is ``a`` with one letter dropped, added, changed, or two neighbours
    swapped (the typos a hand makes): what makes an unknown name almost certainly a
    misspelling of a known one."""
    if a == b or abs(len(a) - len(b)) > 1:
        return False
    if len(a) == len(b):
        diff = [i for i, (x, y) in enumerate(zip(a, b)) if x != y]
        return len(diff) == 1 or (len(diff) == 2 and diff[1] == diff[0] + 1
                                  and a[diff[0]] == b[diff[1]] and a[diff[1]] == b[diff[0]])
    short, long = (a, b) if len(a) < len(b) else (b, a)
    i = next((k for k, (x, y) in enumerate(zip(short, long)) if x != y), len(short))
    return short[i:] == long[i + 1:]


def misspelt_term(name: str, terms: Iterable[str]) -> str | None:
    """The known term (compact ``prefix:Local``: a class, a relation, a property) of the
    same prefix that ``name`` is one edit away from, or None."""
    prefix, local = _split_compact(name)
    for candidate in terms:
        other_prefix, other_local = _split_compact(candidate)
        if other_prefix == prefix and one_edit_apart(local, other_local):
            return candidate
    return None
