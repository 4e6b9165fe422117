"""``CodemodTest``-style helpers: before/after pairs, re-parsed, idempotent, meaning kept.

Every expected output is parsed again (libcst and ``compile``), migrated again (must not
change: idempotence), and its skills' static model is compared with the legacy source's.
"""

from __future__ import annotations

import functools
import re
import textwrap

import libcst as cst

from ezmigrate.codemod.migrate import Settings, migrate
from ezmigrate.report.results import FileResult
from ezskiros_runtime.ontology.load import load_index

HEADER = '''from skiros2_common.core.abstract_skill import SkillDescription, ParamOptions
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element
'''


@functools.cache
def settings() -> Settings:
    """The bundled default vocabulary, as a user without configuration gets it."""
    return Settings(index=load_index())


def _header_for(rest: str) -> str:
    """HEADER with only the names ``rest`` uses: the boilerplate every case shares.

    A real file's unused imports stay where they are after the migration (test_minimal_
    imports.py shows that); here each case reads as a file importing just what it uses, so
    its expected output shows only the imports the migration itself changed.
    """
    lines = []
    for line in HEADER.splitlines():
        module, _, names = line.partition(" import ")
        used = [n for n in names.split(", ") if re.search(rf"\b{n}\b", rest)]
        if used:
            lines.append(f"{module} import {', '.join(used)}\n")
    return "".join(lines)


def run(source: str, *, trim: bool = False) -> FileResult:
    """Migrate ``source``; ``trim``: first reduce a HEADER in it to the names used."""
    source = textwrap.dedent(source)
    if trim and HEADER in source:
        source = source.replace(HEADER, _header_for(source.replace(HEADER, "")), 1)
    return migrate(source, settings(), "case.py")


def assert_migrates(before: str, after: str) -> FileResult:
    """``before`` migrates to exactly ``after``; ``after`` is stable and valid Python."""
    result = run(before, trim=True)
    expected = textwrap.dedent(after)
    actual = result.new_source
    reasons = [(s.name, s.reason) for s in result.skills]
    assert isinstance(actual, str), f"nothing changed: {reasons}"
    assert actual == expected, "\n--- actual ---\n" + actual + "\n--- expected ---\n" + expected
    cst.parse_module(expected)
    compile(expected, "expected.py", "exec")
    again = migrate(expected, settings(), "case.py")
    assert again.new_source is None, "not idempotent"
    return result


def assert_unchanged(source: str) -> FileResult:
    """Nothing to do: the source comes back untouched (``new_source`` stays ``None``)."""
    result = run(source)
    assert result.new_source is None
    return result


def assert_skipped(source: str, *reason_parts: str) -> FileResult:
    """The only description is skipped, with a reason mentioning every ``reason_parts``."""
    result = run(source)
    assert result.new_source is None
    skipped = [s for s in result.skills if s.status == "skipped"]
    assert skipped, [s.status for s in result.skills]
    for part in reason_parts:
        assert part in (skipped[0].reason or ""), skipped[0].reason
    return result
