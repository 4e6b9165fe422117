"""``bench/generate_repo.py`` as a module, for the tests that run on generated repositories.

The generator lives in ``bench/`` (a script, not a package); tests import it from its file,
once per session, under one module name (dataclasses look their module up in
``sys.modules`` while they decorate).
"""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path
from types import ModuleType

GENERATOR = Path(__file__).resolve().parents[1] / "bench" / "generate_repo.py"
NAME = "generate_repo_for_tests"


def generator() -> ModuleType:
    """The generator module (loaded on first use)."""
    if NAME not in sys.modules:
        spec = importlib.util.spec_from_file_location(NAME, GENERATOR)
        assert spec is not None and spec.loader is not None
        module = importlib.util.module_from_spec(spec)
        sys.modules[NAME] = module
        spec.loader.exec_module(module)
    return sys.modules[NAME]
