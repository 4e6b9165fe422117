"""The codemod's reading of an EzSkiROS file that holds no legacy description, from ``ast``.

``check`` hands every file that uses ``ezskiros_runtime`` to the codemod (the plain reader
leaves them alone: a half-migrated file keeps legacy classes the codemod must judge), and
on a migrated repository that is every skill file: libcst parses each one to find that
nothing in it is legacy. When the syntax alone says so, the codemod's answer is known
without it: no skill, and the bases its classes import from user modules (``foreign_bases``,
for the cross-file pass). That holds when

- no class derives from the legacy ``SkillDescription`` (its names as the codemod reads
  the file's imports, ``SyntaxFacts.legacy``; an implementation's ``PrimitiveBase`` or
  ``SkillBase`` is no description);
- no class derives from a class of the same file: a description can then come only
  through a base of another file, which the cross-file pass decides as before;
- libcst would read the file too: Python accepts ``class A(metaclass=M, *bases)``,
  libcst does not, and its refusal is the codemod's answer.

Otherwise ``None``: the codemod reads the file. A test holds this reading equal to
``migrate``'s on every such file this project has and on modules made at random.
"""

from __future__ import annotations

import ast

from ..codemod.core.ast_names import ast_dotted_name
from ..codemod.core.classes import ast_foreign_bases, ast_positional_bases
from ..codemod.core.syntax_facts import legacy_names
from ..report.results import FileResult


def read_ezskiros(tree: ast.Module, path: str) -> FileResult | None:
    """``migrate``'s result for the module (see the module doc), or None."""
    legacy = legacy_names(tree)
    classes = [node for node in tree.body if isinstance(node, ast.ClassDef)]
    local = {node.name for node in classes}
    for node in classes:
        if node.keywords and any(isinstance(b, ast.Starred) for b in node.bases):
            return None  # ``(metaclass=M, *bases)``: Python reads it, libcst refuses it
        for base in ast_positional_bases(node):
            name = ast_dotted_name(base)
            if legacy.symbol_named(name) == "SkillDescription" or (
                    name is not None and (name in local or name.split(".")[0] in local)):
                return None
    return FileResult(path, foreign_bases=ast_foreign_bases(tree, classes))
