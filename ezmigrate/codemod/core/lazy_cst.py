"""libcst, imported when the codemod first uses it rather than when its modules are imported.

``check`` reads most descriptions with ``ast`` (``lint.plain_reader``), through the
codemod's own IR and rules; importing libcst is the run's dearest import (0.1 s), and a
process whose files are all plain never needs it. The codemod's modules therefore bind
``cst`` to this stand-in at run time (mypy sees libcst itself, under ``TYPE_CHECKING``):
its first attribute looked up imports libcst, and each name is then kept on the stand-in,
so a later lookup costs what a module's attribute does.

A module of the codemod may use ``cst`` at import time only if the plain reader never
imports it (a ``CSTVisitor`` subclass, a tuple of node types): that import is libcst's.
``tests/codemod/test_lazy_cst.py`` holds that ``check``'s reading imports no libcst.
"""

from __future__ import annotations

import importlib
from typing import Any


class _LibCST:
    """Looks each name up in libcst on first use, importing it then."""

    def __getattr__(self, name: str) -> Any:
        value = getattr(importlib.import_module("libcst"), name)
        setattr(self, name, value)
        return value


cst: Any = _LibCST()
