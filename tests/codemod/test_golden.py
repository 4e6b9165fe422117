"""Golden files: every ``fixtures/legacy`` file migrates to its ``fixtures/migrated`` twin.

Byte for byte (encodings, line endings, tabs, missing final newlines included), and the
migrated files are fixed points: migrating them again changes nothing.
"""

from __future__ import annotations

from pathlib import Path

import libcst as cst
import pytest
from codemod_case import settings

from ezmigrate.codemod.migrate import migrate

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures"
LEGACY = sorted((FIXTURES / "legacy").glob("*.py"))


def test_every_legacy_fixture_has_a_golden_twin():
    migrated = {p.name for p in (FIXTURES / "migrated").glob("*.py")}
    assert {p.name for p in LEGACY} == migrated
    assert len(LEGACY) >= 15


@pytest.mark.parametrize("legacy", LEGACY, ids=lambda p: p.name)
def test_golden_output_byte_for_byte(legacy: Path):
    expected = (FIXTURES / "migrated" / legacy.name).read_bytes()
    result = migrate(legacy.read_bytes(), settings(), legacy.name)
    actual = result.new_source if result.new_source is not None else legacy.read_bytes()
    assert actual == expected, f"{legacy.name}: regenerate with tests/codemod/regen_golden.py"


@pytest.mark.parametrize("legacy", LEGACY, ids=lambda p: p.name)
def test_golden_output_is_a_fixed_point_and_parses(legacy: Path):
    expected = (FIXTURES / "migrated" / legacy.name).read_bytes()
    cst.parse_module(expected)
    assert migrate(expected, settings(), legacy.name).new_source is None


def test_files_with_nothing_to_do_are_identical():
    for name in ("nothing_to_do.py", "implementations_only.py", "already_migrated.py"):
        assert (FIXTURES / "legacy" / name).read_bytes() == \
            (FIXTURES / "migrated" / name).read_bytes()
