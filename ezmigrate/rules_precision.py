"""Measured precision of rule groups, rendered into docs/rules.md by ``rules_doc``.

The figures are what ``tests/world/test_world_check.py`` measures on the fixture
repositories with every finding labelled by hand; the test fails when a run reports other
figures than these, so the document cannot claim what the tool does not do.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Row:
    """One code: findings reported, how many of them a person judged real, and its
    severity (info rows count apart: they claim no mistake)."""

    code: str
    severity: str
    reported: int
    real: int


WORLD_MODEL_PATHS = ("fixtures/legacy", "fixtures/migrated", "fixtures/compound_repo",
                     "fixtures/ros_repo", "fixtures/world_repo", "fixtures/rejected")
WORLD_MODEL_SCENE = "fixtures/world_repo/owl/scenes/cell.turtle"
WORLD_MODEL: tuple[Row, ...] = (
    Row("EZ401", "warning", 17, 17),
    Row("EZ402", "error", 0, 0),
    Row("EZ403", "error", 1, 1),
    Row("EZ404", "warning", 1, 1),
    Row("EZ405", "error", 1, 1),
    Row("EZ406", "error", 2, 2),
    Row("EZ407", "info", 1, 1),
    Row("EZ408", "info", 1, 1),
    Row("EZ409", "info", 8, 8),
)


def _share(real: int, reported: int) -> str:
    return f"{real / reported:.0%}" if reported else "-"


def precision_section() -> list[str]:
    """The "Precision" part of docs/rules.md."""
    flagged = [r for r in WORLD_MODEL if r.severity != "info"]
    reported, real = sum(r.reported for r in flagged), sum(r.real for r in flagged)
    out = [
        "## Precision of EZ4xx (world model)",
        "",
        f"Measured with `ezmigrate check {' '.join(WORLD_MODEL_PATHS)} --select EZ4` (each "
        f"finding labelled by hand in `tests/world/test_world_check.py`), EZ409 with "
        f"`--scene {WORLD_MODEL_SCENE}` on `fixtures/world_repo`. `fixtures/world_repo` is a "
        "lab repository with scenes written for this measurement (one saved by SkiROS2, one "
        "edited by hand); the legacy and migrated corpora were written before these checks "
        "existed. The goal is at least 9 real warnings or errors in 10.",
        "",
        "| code | severity | reported | real | precision |",
        "|---|---|---:|---:|---:|",
    ]
    for r in WORLD_MODEL:
        out.append(f"| {r.code} | {r.severity} | {r.reported} | {r.real} | "
                   f"{_share(r.real, r.reported)} |")
    out += [f"| **warnings and errors** | | **{reported}** | **{real}** | "
            f"**{_share(real, reported)}** |", ""]
    return out


__all__ = ["WORLD_MODEL", "WORLD_MODEL_PATHS", "WORLD_MODEL_SCENE", "Row", "precision_section"]
