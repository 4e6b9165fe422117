""""Migrate this skill to EzSkiROS": the codemod's rewrite of the one description class
under the cursor, as ``rewrite --no-verify`` would write it.

The other classes of the module are held as they are (``Settings.held``), so the edit
touches that class and the imports it needs. A class the codemod keeps as legacy, or whose
migrated form the runtime's early checks refuse (``project/refusals.py``, as ``rewrite``
refuses it), gets the reason ``rewrite`` gives instead of an edit. The loaded equivalence
proof runs code, so it is ``ezmigrate rewrite``'s, never the editor's.
"""

from __future__ import annotations

import ast
from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ezskiros_runtime.ontology.index import OntologyIndex


@dataclass(frozen=True)
class Migration:
    """The class asked for and the module's new text, or why there is none."""

    name: str
    text: str | None
    refused: str | None = None


def class_at(text: str, line: int) -> str | None:
    """The top-level class whose lines hold the 0-based ``line``, when it has a
    ``createDescription``."""
    try:
        tree = ast.parse(text)
    except (SyntaxError, ValueError):
        return None
    for node in tree.body:
        if isinstance(node, ast.ClassDef) and \
                node.lineno - 1 <= line <= (node.end_lineno or node.lineno) - 1 and \
                any(isinstance(m, ast.FunctionDef) and m.name == "createDescription"
                    for m in node.body):
            return node.name
    return None


def migrate_class(text: str, name: str, path: str, index: OntologyIndex | None
                  ) -> Migration:
    """``text`` with class ``name`` migrated, or the reason it is not."""
    from ..codemod.migrate import migrate
    from ..codemod.settings import Settings
    from ..project.refusals import static_rejections
    from ..verify.verdicts import rejected

    result = migrate(text, Settings(index=index), path)
    others = {s.name: "another class than the one asked for" for s in result.skills
              if s.name != name}
    if others:
        result = migrate(text, Settings(index=index, held=others), path)
    skill = next((s for s in result.skills if s.name == name), None)
    if result.error or skill is None:
        return Migration(name, None, result.error or f"{name}: no legacy description here")
    if skill.status != "converted":
        return Migration(name, None, skill.reason or "kept as legacy")
    found = static_rejections(skill, path, index)
    if found:
        return Migration(name, None, rejected(skill, found).reason)
    new = result.new_source
    if new is None:
        return Migration(name, None, "nothing to change")
    return Migration(name, new if isinstance(new, str) else new.decode("utf-8"))
