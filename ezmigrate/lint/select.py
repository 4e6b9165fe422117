"""Which findings a run reports: ruff's ``select``/``ignore``/``extend-select`` over codes
and group prefixes, then ``# ezskiros: ignore[...]`` comments on the finding's line.

As in ruff, the most specific selector wins: ``--select EZ2 --ignore EZ201`` reports EZ2xx
but EZ201, and ``--ignore EZ2 --extend-select EZ201`` reports EZ201 alone of the group.
A rule that is off by default (EZ901) runs only when a selector names it or its group.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

from ezskiros_runtime.codes import BY_CODE, RULES, matches, valid_selector

from .diagnostic import Diagnostic, Positions, check_finding, from_finding

SUPPRESSION = re.compile(r"#\s*ezskiros:\s*ignore\[([^\]]*)\]")
NOQA = re.compile(r"#\s*noqa:\s*([A-Za-z]+[0-9]+(?:\s*,?\s*[A-Za-z]+[0-9]+)*)", re.IGNORECASE)
"""ruff's and flake8's ``# noqa: EZ209`` (its ``EZ`` codes are ours; the others are the
lab's other linters', and a bare ``# noqa`` silences nothing of ours: a CI gate does not
lose an error to a comment written for another tool)."""
UNUSED = "EZ100"


class SelectorError(ValueError):
    """A selector that names no code (a usage error: exit 2)."""


def parse_selectors(values: Iterable[str], where: str) -> tuple[str, ...]:
    """Comma-separated or repeated selectors, each checked against the catalogue."""
    found = tuple(s.strip() for v in values for s in v.split(",") if s.strip())
    for selector in found:
        if not valid_selector(selector):
            raise SelectorError(f"{where}: {selector!r} is no finding code or group prefix "
                                "(see docs/rules.md)")
    return found


@dataclass(frozen=True)
class Selection:
    """The selectors of a run; ``select=None`` means the rules that are on by default."""

    select: tuple[str, ...] | None = None
    ignore: tuple[str, ...] = ()
    extend_select: tuple[str, ...] = ()

    def codes(self) -> frozenset[str]:
        """Every code this selection reports."""
        return frozenset(r.code for r in RULES if self._on(r.code))

    def _on(self, code: str) -> bool:
        chosen = (*(self.select or ()), *self.extend_select)
        best_on = max((len(s) for s in chosen if matches(code, s)), default=-1)
        if self.select is None and BY_CODE[code].enabled:
            best_on = max(best_on, 0)
        best_off = max((len(s) for s in self.ignore if matches(code, s)), default=-1)
        return best_on > best_off  # a tie (--select EZ201 --ignore EZ201): ignoring wins


def suppressions(source: str) -> dict[int, list[str]]:
    """``{line: [codes]}`` of the ``# ezskiros: ignore[...]`` and ``# noqa: EZ...``
    comments of a file."""
    found: dict[int, list[str]] = {}
    if "ezskiros:" not in source and "noqa" not in source.lower():
        return found
    for number, text in enumerate(source.splitlines(), start=1):
        codes: list[str] = []
        for match in SUPPRESSION.finditer(text):
            codes += [c.strip() for c in match.group(1).split(",") if c.strip()]
        for noqa in NOQA.finditer(text):
            codes += [c.upper() for c in re.split(r"[\s,]+", noqa.group(1))
                      if c.upper().startswith("EZ")]
        if codes:
            found[number] = list(dict.fromkeys(codes))
    return found


def apply(diagnostics: Sequence[Diagnostic], sources: dict[str, str],
          selection: Selection) -> list[Diagnostic]:
    """The selected findings that no comment suppresses, plus EZ100 for unused comments.

    A comment's code is unused when that code ran (it is selected) and found nothing on the
    line; a code that did not run cannot be judged, so it is not reported.
    """
    codes = selection.codes()
    kept = [d for d in diagnostics if d.code in codes]
    by_file: dict[str, list[Diagnostic]] = {}
    for d in kept:
        by_file.setdefault(d.path, []).append(d)
    out: list[Diagnostic] = [d for d in kept if d.path not in sources]
    for path, source in sources.items():
        comments = suppressions(source)
        used: set[tuple[int, str]] = set()
        for d in by_file.get(path, []):
            hit = next((c for c in comments.get(d.line, ()) if matches(d.code, c)), None)
            if hit is None:
                out.append(d)
            else:
                used.add((d.line, hit))
        if UNUSED not in codes or not comments:
            continue
        positions = Positions(source)
        for line, listed in comments.items():
            for code in listed:
                ran = code in codes or any(c.startswith(code) for c in codes)
                if (line, code) not in used and ran:
                    out.append(from_finding(path, positions, check_finding(
                        "unused-suppression", line,
                        f"unused suppression: no {code} finding on this line")))
    out.sort(key=lambda d: (d.path, d.line, d.column, d.code))
    return out
