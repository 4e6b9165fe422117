"""Shared helpers of the DSL tests: the paper ontology fixture and model loading.

A plain module (not a conftest) so each test module says explicitly what it uses. The
ontology is real: ``fixtures/ontology/paper.ttl`` loaded through the index, activated with
``use_ontology`` and the previous index restored afterwards.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any, TypeVar

import pytest

from ezskiros_runtime.dsl.policy import collecting
from ezskiros_runtime.legacy.extract import model_of
from ezskiros_runtime.model import SkillModel
from ezskiros_runtime.ontology import active_index, use_ontology

ROOT = Path(__file__).resolve().parents[3]
PAPER = ROOT / "fixtures" / "ontology" / "paper.ttl"

T = TypeVar("T", bound=type)


@pytest.fixture
def paper() -> Iterator[Any]:
    """Activate paper.ttl for one test; restore the previous active index afterwards."""
    previous = active_index()
    try:
        yield use_ontology([PAPER])
    finally:
        use_ontology(previous)


def model(cls: type) -> SkillModel:
    """The normalized model of a freshly built instance of ``cls``."""
    return model_of(cls())


def quiet_model(cls: type) -> SkillModel:
    """Like ``model`` but without raising or warning on findings."""
    with collecting():
        return model_of(cls())


def named(name: str) -> Callable[[T], T]:
    """Rename a class, so an EzSkiROS class and its legacy twin get the same SkiROS2 type
    (``skiros:<ClassName>``) and can be compared as models."""

    def rename(cls: T) -> T:
        cls.__name__ = name
        cls.__qualname__ = name
        return cls

    return rename


def line_of(marker: str, path: str | Path) -> int:
    """The 1-based line of the first source line containing ``marker``."""
    for number, text in enumerate(Path(path).read_text().splitlines(), 1):
        if marker in text:
            return number
    raise AssertionError(f"{marker!r} not found in {path}")
