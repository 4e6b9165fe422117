"""Imports after migration: ``ezskiros_runtime`` names added once, legacy ones removed when unused.

A legacy import name is removed only when the migration removed its last use: it was used
before and nothing left in the module uses it (implementation classes usually still need
``SkillBase`` or ``ParamTypes``). A use is a reference to the bound name (``name_counts``):
``wmi.Element(...)`` uses ``wmi``, not an imported ``Element``. An import that was already
unused stays byte for byte: removing it would put an unrelated line in the diff and could
drop an import-time side effect. Comments that stood above a removed import move to the
statement that takes its place, so banners like ``# SkiROS2 imports`` survive.

The new imports go where the first legacy import was, unless a star import follows it: a
helper module imported with ``*`` may re-export the legacy ``SkillDescription`` and would
rebind ours, so the new imports then go right after the last top-level star import.

What linters would newly count is marked where it cannot be avoided (issue 43), with the
code of the one rule, so nothing else is silenced:

- a new import whose place is past the top of the module as pycodestyle reads it (after a
  ``sys.path.append(...)`` that a star import of the lab's own module follows) is E402, as
  every import of the original there already is: it gets ``# noqa: E402``;
- a legacy import kept only because other modules of the package import its names from
  this one (``Settings.exported``) is unused here, F401: it gets ``# noqa: F401``, the
  usual mark of a re-export.
"""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Callable, Collection, Iterable, Sequence
from typing import Any

import libcst as cst

from .emit import LINE_LIMIT
from .legacy_names import dotted_name, is_legacy_module
from .tree_walk import walk

RUNTIME = "ezskiros_runtime"
ONTOLOGY = "ezskiros_runtime.ontology"
RUNTIME_ORDER = ("SkillDescription", "Annotated", "INFERRED", "OPTIONAL", "REQUIRED", "ELEMENT",
                 "KEY", "DESC", "abstract", "any_of", "Lock", "Consume", "Unspecify",
                 "RespectType", "Output")


def _as_name(node: cst.ExceptHandler | cst.ExceptStarHandler) -> cst.CSTNode | None:
    return node.name.name if node.name is not None else None


_NOT_REFERENCES: dict[type, Callable[[Any], cst.CSTNode | None]] = {
    # the ``Name`` child of these nodes spells a word without referring to a binding
    cst.Attribute: lambda node: node.attr,
    cst.Arg: lambda node: node.keyword,
    cst.Param: lambda node: node.name,
    cst.FunctionDef: lambda node: node.name,
    cst.ClassDef: lambda node: node.name,
    cst.ExceptHandler: _as_name,
    cst.ExceptStarHandler: _as_name,
    cst.MatchAs: lambda node: node.name,
    cst.MatchStar: lambda node: node.name,
    cst.MatchMapping: lambda node: node.rest,
    cst.MatchKeywordElement: lambda node: node.key,
    cst.TypeVar: lambda node: node.name,
    cst.TypeVarTuple: lambda node: node.name,
    cst.ParamSpec: lambda node: node.name,
}


def name_counts(node: cst.CSTNode) -> Counter[str]:
    """How often a subtree refers to each name outside imports: the ``Name`` nodes that
    stand for a variable, not an attribute's, a keyword's, a parameter's or a definition's
    own name. Only a reference uses an import (``wmi.Element`` leaves an imported
    ``Element`` unused). For a whole module, ``SyntaxFacts.names`` gives the same from one
    ``ast`` walk."""
    found = list(walk(node, (cst.Import, cst.ImportFrom)))
    spelled: set[int] = set()
    for item in found:
        child = _NOT_REFERENCES[type(item)](item) if type(item) in _NOT_REFERENCES else None
        if child is not None:
            spelled.add(id(child))
    return Counter(item.value for item in found
                   if type(item) is cst.Name and id(item) not in spelled)


def used_names(node: cst.CSTNode) -> set[str]:
    """The identifiers of ``name_counts``."""
    return set(name_counts(node))


def module_bindings(module: cst.Module) -> set[str]:
    """Names bound at module level by anything but an import (for conflict checks)."""
    bound: set[str] = set()
    for stmt in module.body:
        if isinstance(stmt, (cst.ClassDef, cst.FunctionDef)):
            bound.add(stmt.name.value)
        elif isinstance(stmt, cst.SimpleStatementLine):
            for small in stmt.body:
                targets: list[cst.BaseExpression] = []
                if isinstance(small, cst.Assign):
                    targets = [t.target for t in small.targets]
                elif isinstance(small, (cst.AnnAssign, cst.AugAssign)):
                    targets = [small.target]
                for target in targets:
                    if isinstance(target, cst.Name):
                        bound.add(target.value)
    return bound


def imported_names(module: cst.Module) -> dict[str, str]:
    """Local name -> module it is imported from, for every top-level ``from`` import."""
    found: dict[str, str] = {}
    for stmt in module.body:
        if not isinstance(stmt, cst.SimpleStatementLine):
            continue
        for small in stmt.body:
            if isinstance(small, cst.ImportFrom) and small.module is not None \
                    and not small.relative and not isinstance(small.names, cst.ImportStar):
                source = dotted_name(small.module) or ""
                for alias in small.names:
                    found[_local(alias)] = source
            elif isinstance(small, cst.Import):
                for alias in small.names:
                    found[_local(alias)] = dotted_name(alias.name) or ""
    return found


def _local(alias: cst.ImportAlias) -> str:
    if alias.asname is not None and isinstance(alias.asname.name, cst.Name):
        return alias.asname.name.value
    name = dotted_name(alias.name) or ""
    return name.split(".")[0]


def _prune(small: cst.BaseSmallStatement, used: set[str],
           used_before: set[str]) -> cst.BaseSmallStatement | None:
    """A legacy import without the names the migration left unused; ``None`` when nothing is
    left. A name that was unused before the migration is kept."""
    if isinstance(small, cst.ImportFrom):
        module = dotted_name(small.module) if small.module is not None else None
        if module is None or small.relative or not is_legacy_module(module) \
                or isinstance(small.names, cst.ImportStar):
            return small
        kept = [a for a in small.names if _local(a) in used or _local(a) not in used_before]
        if len(kept) == len(small.names):
            return small
        if not kept:
            return None
        kept[-1] = kept[-1].with_changes(comma=cst.MaybeSentinel.DEFAULT)
        return small.with_changes(names=kept, rpar=small.rpar if len(kept) > 1 else None,
                                  lpar=small.lpar if len(kept) > 1 else None)
    if isinstance(small, cst.Import):
        kept_plain = [a for a in small.names
                      if not is_legacy_module(dotted_name(a.name) or "") or _local(a) in used
                      or _local(a) not in used_before]
        if len(kept_plain) == len(small.names):
            return small
        if not kept_plain:
            return None
        kept_plain[-1] = kept_plain[-1].with_changes(comma=cst.MaybeSentinel.DEFAULT)
        return small.with_changes(names=kept_plain)
    return small


NOQA_E402 = "# noqa: E402"
NOQA_F401 = "# noqa: F401"


def _import_line(module: str, names: Sequence[tuple[str, str]],
                 config: cst.PartialParserConfig, noqa: str = "") -> cst.SimpleStatementLine:
    """``from module import names``, on one line when it fits, with ``noqa`` (a comment, or
    "") on its first line: where flake8 and ruff look for it."""
    items = [name if alias == name else f"{name} as {alias}" for name, alias in names]
    comment = f"  {noqa}" if noqa else ""
    text = f"from {module} import {', '.join(items)}{comment}"
    if len(text) > LINE_LIMIT:
        text = f"from {module} import ({comment}\n" + "".join(
            f"    {item},\n" for item in items) + ")"
    parsed = cst.parse_statement(text + "\n", config=config)
    assert isinstance(parsed, cst.SimpleStatementLine)
    return parsed


def update_imports(module: cst.Module, runtime: Iterable[tuple[str, str]],
                   prefixes: Iterable[tuple[str, str]],
                   exported: Collection[str] = (), *, used: set[str],
                   used_before: set[str] | None = None) -> cst.Module:
    """Add the runtime and namespace imports, drop legacy imports the migration left unused.

    ``runtime`` and ``prefixes`` hold ``(name, local alias)`` pairs. The new imports go where
    the first legacy import was, after the last top-level star import that follows it (or
    after the last top-level import, or after the docstring). ``exported`` names (``*``:
    all) are used by other modules importing them from this one. ``used_before``: the names
    the module used before the migration (``used_names`` of the original); only those can
    lose their last use. ``None``: every imported name counts as used before. ``used``: the
    names ``module`` uses outside imports (the caller knows them without a visit).
    """
    existing = imported_names(module)
    own_use = used
    used = used | set(exported)
    if "*" in exported:  # another module takes every name: no import is unused
        used |= _all_imported(module)
    before = _all_imported(module) if used_before is None else used_before
    star_after_legacy = _star_after_first_legacy(module)
    order = {name: i for i, name in enumerate(RUNTIME_ORDER)}
    wanted = sorted({pair for pair in runtime if existing.get(pair[1]) != RUNTIME},
                    key=lambda pair: order.get(pair[0], len(order)))
    spaces = sorted(pair for pair in set(prefixes) if existing.get(pair[1]) != ONTOLOGY)
    config = module.config_for_parsing

    def additions_at(noqa: str) -> list[cst.SimpleStatementLine]:
        return ([_import_line(RUNTIME, wanted, config, noqa)] if wanted else []) + (
            [_import_line(ONTOLOGY, spaces, config, noqa)] if spaces else [])

    additions = additions_at("")

    body: list[cst.BaseStatement] = []
    anchor: int | None = None
    carried: list[cst.EmptyLine] = []
    last_import: int | None = None
    for stmt in module.body:
        if isinstance(stmt, cst.SimpleStatementLine) and all(
                isinstance(s, (cst.Import, cst.ImportFrom)) for s in stmt.body):
            is_legacy = any(_is_legacy_import(s) for s in stmt.body)
            kept = [k for k in (_prune(s, used, before) for s in stmt.body) if k is not None]
            if any(_is_star(s) for s in stmt.body) and star_after_legacy:
                anchor = len(body) + 1  # after this star import (it is kept: not legacy)
            elif is_legacy and anchor is None:
                anchor = len(body) + (1 if kept else 0)
                if not kept and additions and not star_after_legacy:
                    # our import takes its place and its comments
                    additions[0] = additions[0].with_changes(leading_lines=stmt.leading_lines)
                    continue
            if not kept:
                carried += list(stmt.leading_lines)
                continue
            stmt = stmt.with_changes(body=_fix_semicolons(kept))
            if any(_kept_for_others(s, own_use, before) for s in kept):
                stmt = with_noqa(stmt, NOQA_F401)
            last_import = len(body)
        if carried:
            stmt = stmt.with_changes(leading_lines=carried + list(stmt.leading_lines))
            carried = []
        body.append(stmt)
    if not additions:
        return module.with_changes(body=body)
    if anchor is None:
        anchor = last_import + 1 if last_import is not None else _after_docstring(body)
    if past_import_zone(body[:anchor]):
        leading = additions[0].leading_lines
        additions = additions_at(NOQA_E402)
        additions[0] = additions[0].with_changes(leading_lines=leading)
    return module.with_changes(body=body[:anchor] + additions + body[anchor:])


_DUNDER = re.compile(r"__\S+__\Z")


def past_import_zone(statements: Sequence[cst.BaseStatement]) -> bool:
    """Whether an import after ``statements`` is E402 as pycodestyle (flake8) reads it:
    one of them is module code, anything but an import, the docstring (the first string
    statement), a ``__dunder__ = ...`` assignment, or an ``if``/``try``/``with`` block
    (pycodestyle lets imports be conditional). Ruff also lets ``sys.path`` and
    ``os.environ`` changes pass; pycodestyle does not."""
    seen_string = False
    for stmt in statements:
        if isinstance(stmt, (cst.If, cst.Try, cst.TryStar, cst.With)):
            continue
        if not isinstance(stmt, cst.SimpleStatementLine):
            return True
        for small in stmt.body:
            if isinstance(small, (cst.Import, cst.ImportFrom)):
                continue
            if isinstance(small, cst.Expr) and isinstance(
                    small.value, (cst.SimpleString, cst.ConcatenatedString)):
                if seen_string:
                    return True
                seen_string = True
                continue
            if isinstance(small, (cst.Assign, cst.AnnAssign)) and all(
                    isinstance(t, cst.Name) and _DUNDER.match(t.value) for t in (
                        [t.target for t in small.targets] if isinstance(small, cst.Assign)
                        else [small.target])):
                continue
            return True
    return False


def _kept_for_others(small: cst.BaseSmallStatement, own_use: set[str],
                     used_before: set[str]) -> bool:
    """Whether a kept legacy import holds a name this module used before the migration
    and no longer uses: it stays only because other modules import it from this one."""
    if isinstance(small, cst.ImportFrom):
        if small.module is None or small.relative or isinstance(small.names, cst.ImportStar) \
                or not is_legacy_module(dotted_name(small.module) or ""):
            return False
        aliases: Sequence[cst.ImportAlias] = small.names
    elif isinstance(small, cst.Import):
        aliases = [a for a in small.names if is_legacy_module(dotted_name(a.name) or "")]
    else:
        return False
    return any(_local(a) in used_before and _local(a) not in own_use for a in aliases)


def with_noqa(stmt: cst.SimpleStatementLine, noqa: str) -> cst.SimpleStatementLine:
    """``stmt`` with ``noqa`` on its first line, after any comment there; unchanged when
    that line already holds a ``noqa`` (or the statement's first line has no place for a
    comment: a line continued by a backslash)."""
    first = stmt.body[0]
    lpar = getattr(first, "lpar", None)
    if isinstance(first, cst.ImportFrom) and isinstance(lpar, cst.LeftParen) \
            and isinstance(lpar.whitespace_after, cst.ParenthesizedWhitespace):
        line = lpar.whitespace_after.first_line
        marked = _marked(line, noqa)
        return stmt if marked is line else stmt.with_changes(body=[first.with_changes(
            lpar=lpar.with_changes(whitespace_after=lpar.whitespace_after.with_changes(
                first_line=marked))), *stmt.body[1:]])
    if "\n" in cst.Module(body=[]).code_for_node(stmt.with_changes(
            leading_lines=(), trailing_whitespace=cst.TrailingWhitespace())).rstrip("\r\n"):
        return stmt  # the statement's first line ends inside it
    marked = _marked(stmt.trailing_whitespace, noqa)
    return stmt if marked is stmt.trailing_whitespace else stmt.with_changes(
        trailing_whitespace=marked)


def _marked(line: cst.TrailingWhitespace, noqa: str) -> cst.TrailingWhitespace:
    if line.comment is None:
        return line.with_changes(whitespace=cst.SimpleWhitespace("  "),
                                 comment=cst.Comment(noqa))
    if "noqa" in line.comment.value.lower():
        return line
    return line.with_changes(comment=cst.Comment(f"{line.comment.value}  {noqa}"))


def _all_imported(module: cst.Module) -> set[str]:
    """Every local name a top-level import statement binds."""
    found: set[str] = set()
    for stmt in module.body:
        for small in stmt.body if isinstance(stmt, cst.SimpleStatementLine) else ():
            if isinstance(small, (cst.Import, cst.ImportFrom)) \
                    and not isinstance(small.names, cst.ImportStar):
                found.update(_local(alias) for alias in small.names)
    return found


def _is_star(small: cst.BaseSmallStatement) -> bool:
    return isinstance(small, cst.ImportFrom) and isinstance(small.names, cst.ImportStar)


def _star_after_first_legacy(module: cst.Module) -> bool:
    """Whether a top-level star import comes after (or with) the first legacy import: the
    names it brings in could rebind ours."""
    seen_legacy = False
    for stmt in module.body:
        if not isinstance(stmt, cst.SimpleStatementLine):
            continue
        seen_legacy = seen_legacy or any(_is_legacy_import(s) for s in stmt.body)
        if seen_legacy and any(_is_star(s) for s in stmt.body):
            return True
    return False


def _fix_semicolons(kept: list[cst.BaseSmallStatement]) -> list[cst.BaseSmallStatement]:
    if kept:
        kept[-1] = kept[-1].with_changes(semicolon=cst.MaybeSentinel.DEFAULT)
    return kept


def _is_legacy_import(small: cst.BaseSmallStatement) -> bool:
    if isinstance(small, cst.ImportFrom) and small.module is not None and not small.relative:
        return is_legacy_module(dotted_name(small.module) or "")
    if isinstance(small, cst.Import):
        return any(is_legacy_module(dotted_name(a.name) or "") for a in small.names)
    return False


def _after_docstring(body: list[cst.BaseStatement]) -> int:
    index = 0
    if body and isinstance(body[0], cst.SimpleStatementLine) and isinstance(
            body[0].body[0], cst.Expr) and isinstance(body[0].body[0].value, cst.SimpleString):
        index = 1
    while index < len(body) and isinstance(body[index], cst.SimpleStatementLine) and any(
            isinstance(s, cst.ImportFrom) and s.module is not None
            and dotted_name(s.module) == "__future__"
            for s in body[index].body):  # type: ignore[attr-defined]
        index += 1
    return index
