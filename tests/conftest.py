"""Test-session setup shared by every test package.

Tests use a private ontology cache and a private signing key for ``check``'s cache, so
that a run never reads or writes the user's real ``~/.cache/ezskiros`` or
``~/.cache/ezmigrate`` (and so that a stale cache can never make a test pass).
"""

from __future__ import annotations

import ast
import atexit
import os
import shutil
import sys
import tempfile
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any, List

import pytest

_CACHE = tempfile.mkdtemp(prefix="ezskiros-test-cache-")
os.environ.setdefault("EZSKIROS_CACHE_DIR", _CACHE)
# ``check``'s cache and its signing key, made by every run with a cache: here, not in the
# user's ``~/.cache/ezmigrate`` (children inherit it; pip's cache stays where it is)
_CHECK_CACHE = tempfile.mkdtemp(prefix="ezmigrate-test-cache-")
os.environ.setdefault("EZMIGRATE_CACHE_DIR", _CHECK_CACHE)
for _folder in (_CACHE, _CHECK_CACHE):  # nothing of the session is left in /tmp
    atexit.register(shutil.rmtree, _folder, True)


_SUMMARY = pytest.StashKey[List[str]]()


@pytest.fixture
def core_ontology() -> Iterator[None]:
    """The bundled SkiROS2 core as the runtime's active ontology for one test, the one
    before it restored after (tests that read EzSkiROS code as the runtime would)."""
    from ezskiros_runtime.ontology import active_index, use_ontology
    from ezskiros_runtime.ontology.index import bundled_ontology_path
    from ezskiros_runtime.ontology.load import load_index

    previous = active_index()
    use_ontology(load_index([bundled_ontology_path()]))
    try:
        yield
    finally:
        use_ontology(previous)


@pytest.fixture
def summary_line(request: pytest.FixtureRequest) -> Callable[[str], None]:
    """Adds a line to the end of pytest's output, shown even under ``-q`` (unlike print): the
    figures a proof test measured (mutants caught, examples run) belong in CI's log."""
    return request.config.stash.setdefault(_SUMMARY, []).append


def pytest_terminal_summary(terminalreporter: Any, exitstatus: int,
                            config: pytest.Config) -> None:
    for line in config.stash.get(_SUMMARY, []):
        terminalreporter.write_line(line)


COMMAND_PYTHON = (3, 10)
"""The ``ezmigrate`` command needs this Python; ``ezskiros_runtime`` runs from 3.8 (the robot)."""


def pytest_ignore_collect(collection_path: Path, config: pytest.Config) -> bool | None:
    """Under the robot's Python, leave out the test modules that import the command.

    CI runs the runtime's tests a second time under Python 3.8 with rdflib 4.2.2 (ROS
    Noetic). Which modules need the command is read from their imports (and a run of
    ``python -m ezmigrate``), not from a list,
    so a new runtime test is never left out by mistake; the run fails if nothing is left.
    """
    if sys.version_info >= COMMAND_PYTHON or collection_path.suffix != ".py":
        return None
    if not collection_path.name.startswith("test_"):
        return None
    tree = ast.parse(collection_path.read_bytes())
    for node in ast.walk(tree):
        if isinstance(node, ast.Constant) and node.value == "ezmigrate":  # `-m ezmigrate`
            return True
        if isinstance(node, ast.Import):
            names = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.level == 0:
            names = [node.module or ""]
        else:
            continue
        if any(name == "ezmigrate" or name.startswith("ezmigrate.") for name in names):
            return True
    return None
