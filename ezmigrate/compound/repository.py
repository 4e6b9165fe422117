"""The repository around the named files: every description, implementation and base in it.

pre-commit passes only the staged files; a compound skill in one of them names children
whose descriptions live in unstaged sibling files (or other packages of the repository).
Judging the tree against the named files alone gives false "unknown child type" errors,
so the skill index always covers the whole repository: the git top level of each named
file, else its ROS package (the folder of the nearest ``package.xml``), else its folder.
A named *directory* is its own scope (``check DIR`` asks about DIR).

Files not named are read here with ``ast`` only (no codemod, no tracing): plain legacy
descriptions with their keys, every other description class as a type whose keys are not
judged, implementation labels, description bases, and literal trees. A file ``ast`` cannot
parse (Python 2, a syntax error) still gives its class names, recovered by a tolerant
``tokenize`` scan, so that its descriptions are never reported as unknown child types; and
a description class of it that parses on its own (the Python 2 syntax elsewhere: a
``print x`` in an implementation, an ``except X, e:``) is read with the module's imports
like a plain one, its keys known (``read_classes``): a Python 2 module is loaded by a
Python 2 skill manager, so its descriptions are real.
"""

from __future__ import annotations

import ast
import io
import os
import re
import tokenize
from collections.abc import Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ezskiros_runtime.compound.library import DescriptionInfo
from ezskiros_runtime.compound.model import CompoundModel
from ezskiros_runtime.model import SkillModel

from ..files.discover import Candidate, discover, repository_root
from .markers import SCAN_WHEN
from .static import (
    NeedsTrace,
    class_bases,
    implementation_classes,
    implementations,
    modified_params,
    read_compounds,
)

UNPARSED = "in a file Python 3 cannot parse"
TOP_CLASS = "class@0"
_LINES = re.compile(r"[^\r\n]*(?:\r\n|\r|\n)|[^\r\n]+\Z")
_LAYOUT = frozenset({tokenize.NL, tokenize.NEWLINE, tokenize.COMMENT, tokenize.INDENT,
                     tokenize.DEDENT})


@dataclass
class RepositoryScan:
    """What the files of the repository that were not named hold."""

    descriptions: list[DescriptionInfo] = field(default_factory=list)
    labels: list[tuple[str, str | None]] = field(default_factory=list)
    bases: list[tuple[str, str]] = field(default_factory=list)
    modified: list[tuple[str, str, str | None, bool, str]] = field(default_factory=list)
    compounds: list[CompoundModel] = field(default_factory=list)
    untraced: set[str] = field(default_factory=set)
    """Description types whose compound implementation needs tracing (not done here)."""
    untraced_labels: set[str] = field(default_factory=set)
    """Their implementations' labels and class names."""
    unread: list[str] = field(default_factory=list)
    """Files whose class names not even ``tokenize`` could recover."""


def description_of(name: str, model: dict[str, Any] | None, origin: str, path: str,
                   line: int) -> DescriptionInfo:
    """A description type from its static model (``SkillResult.model``/a loaded model);
    without one (a description kept as legacy) the type exists, its keys are unknown."""
    if model is None:
        return DescriptionInfo(name, {}, origin, path, line, complete=False)
    params = SkillModel.from_json(model).params
    return DescriptionInfo(name, {p.key: p.element_type for p in params}, origin, path, line,
                           unset=frozenset(p.key for p in params if p.kind == "Required"
                                           and p.data_type != "Element" and not p.values))


Recovered = list[tuple[str, int, str | None]] | None
"""What ``recover_classes`` makes of a module ``ast`` cannot parse."""


def scan_repository(named: Sequence[Path], exclude: Sequence[str] = (),
                    skip: Iterable[str] = (),
                    read: Sequence[tuple[Candidate, bytes]] = (),
                    recovered: Mapping[str, Recovered] | None = None) -> RepositoryScan:
    """Descriptions, implementations, bases and literal trees of the repository around
    ``named``. ``read``: the run's own files with their bytes (never read again); ``skip``:
    the paths among them whose syntax tree the caller already read; ``recovered``: by path,
    files of ``read`` that ``ast`` cannot parse, recovered already where the run read
    them (``file_facts``). Only a named *file* widens the scope to its repository; the
    files of a named folder are all in ``read``."""
    scan = RepositoryScan()
    skipped = set(skip)
    for candidate, data in read:  # the run reads these itself, unless ast cannot parse them
        path = str(candidate.path)
        if recovered is not None and path in recovered:
            _add_recovered(candidate, recovered[path], scan, data)
        elif path not in skipped and any(m in data for m in SCAN_WHEN):
            _scan_file(candidate, data, scan, unparsable_only=True)
    items: list[tuple[Candidate, bytes]] = []
    roots = sorted({root.resolve() for p in named if p.exists() and not p.is_dir()
                    for root in [repository_root(p)] if root is not None})
    roots = [r for r in roots if not any(o != r and o in r.parents for o in roots)]
    if roots:
        known = {os.path.realpath(c.path) for c, _ in read}
        found, _ = discover(roots, exclude)
        for candidate in found:
            if os.path.realpath(candidate.path) in known:
                continue
            try:
                items.append((candidate, candidate.path.read_bytes()))
            except OSError:
                continue
    for candidate, data in items:
        if any(marker in data for marker in SCAN_WHEN):
            _scan_file(candidate, data, scan)
    return scan


def _scan_file(candidate: Candidate, data: bytes, scan: RepositoryScan,
               unparsable_only: bool = False) -> None:
    path = str(candidate.path)
    try:
        tree = ast.parse(data)
        if unparsable_only:
            return
    except (SyntaxError, ValueError, UnicodeError, MemoryError, RecursionError):
        _add_recovered(candidate, recover_classes(data), scan, data)
        return
    scan.labels += implementations(tree)
    scan.bases += class_bases(tree)
    scan.modified += modified_params(tree)
    implemented = implementation_classes(tree)
    from ..lint.plain_reader import Declined, read_plain  # libcst: only a scan that reads

    verdict = read_plain(data, candidate.relative, tree)
    read = {} if isinstance(verdict, Declined) else {s.name: s for s in verdict.skills}
    for node in tree.body:
        if not isinstance(node, ast.ClassDef) or node.name in implemented:
            continue
        if node.name in read:
            skill = read[node.name]
            scan.descriptions.append(description_of(node.name, skill.model, "repository",
                                                    path, node.lineno))
        elif _looks_described(node):
            scan.descriptions.append(DescriptionInfo(node.name, {}, "repository", path,
                                                     node.lineno, complete=False))
    for found in read_compounds(tree, path):
        if isinstance(found, NeedsTrace):
            scan.untraced.add(found.description or found.implementation)
            scan.untraced_labels |= {found.label, found.implementation}
        else:
            scan.compounds.append(found)


def _add_recovered(candidate: Candidate, recovered: Recovered, scan: RepositoryScan,
                   data: bytes) -> None:
    """What a module ``ast`` cannot parse adds to the scan (``recover_classes``): its
    description classes with their keys where they read on their own (``read_classes``),
    else as types whose keys are unknown."""
    if recovered is None:
        scan.unread.append(candidate.relative)
        return
    models = read_classes(data, candidate.relative) \
        if any(described is None for _, _, described in recovered) else {}
    for name, line, described in recovered:
        if described is None:
            scan.descriptions.append(description_of(name, models.get((name, line)),
                                                    f"repository ({UNPARSED})",
                                                    str(candidate.path), line))
        else:
            scan.labels.append((name, described))


def read_classes(data: bytes, path: str) -> dict[tuple[str, int], dict[str, Any]]:
    """``(class, line)`` -> model of the plain descriptions of a module ``ast`` cannot
    parse, read class by class: each top-level class that parses on its own, with the
    module's top-level imports that do (every other line blanked, so lines stay where they
    are), is read by ``read_plain`` as in a parsable file. A class that does not parse on
    its own (Python 2 syntax in it), or that ``read_plain`` declines or keeps, is left
    out: its keys stay unknown."""
    split = _statements(data)
    if split is None:
        return {}
    lines, statements = split
    imports: list[tuple[int, int]] = []
    classes: list[tuple[int, int]] = []
    for start, end in statements:
        tree = _parse_lines(lines, [(start, end)])
        if tree is None or not tree.body:
            continue
        if all(isinstance(node, (ast.Import, ast.ImportFrom)) for node in tree.body):
            imports.append((start, end))
        elif len(tree.body) == 1 and isinstance(tree.body[0], ast.ClassDef):
            classes.append((start, end))
    from ..lint.plain_reader import Declined, read_plain  # libcst: only a scan that reads

    models: dict[tuple[str, int], dict[str, Any]] = {}
    for start, end in classes:
        kept = [*imports, (start, end)]
        tree = _parse_lines(lines, kept)
        if tree is None:
            continue
        verdict = read_plain(_blanked(lines, kept).encode("utf-8"), path, tree)
        if isinstance(verdict, Declined):
            continue
        for skill in verdict.skills:
            if skill.status == "converted" and skill.model is not None:
                models[(skill.name, skill.line)] = skill.model
    return models


def _statements(data: bytes) -> tuple[list[str], list[tuple[int, int]]] | None:
    """The module's lines and the ``(first, last)`` lines (1-based) of its top-level
    statements, by ``tokenize`` (a decorated statement with its decorators). A statement
    the tokens stop in (an error) is left out; None when the text cannot be decoded."""
    try:
        encoding, _ = tokenize.detect_encoding(io.BytesIO(data).readline)
        text = data.decode(encoding)
    except (SyntaxError, UnicodeError, LookupError):
        return None
    if text.startswith("\ufeff"):
        text = text[1:]
    lines = _LINES.findall(text)  # not ``splitlines``: Python ends a line at these alone
    starts: list[int] = []
    fresh, decorated = True, False
    try:
        for token in tokenize.generate_tokens(iter([*lines, ""]).__next__):
            if token.type == tokenize.NEWLINE:
                fresh = True
            elif token.type in _LAYOUT or token.type == tokenize.ENDMARKER or not fresh:
                continue
            else:
                fresh = False
                if token.start[1] == 0 and not decorated:
                    starts.append(token.start[0])
                decorated = token.start[1] == 0 and token.string == "@"
        ends = [*(s - 1 for s in starts[1:]), len(lines)]
    except (tokenize.TokenError, SyntaxError):
        ends = [s - 1 for s in starts[1:]]  # the last statement never closed
    return lines, list(zip(starts, ends, strict=False))  # ends: one short after an error


def _blanked(lines: list[str], kept: list[tuple[int, int]]) -> str:
    """The module's text with only the ``kept`` lines, the others left empty."""
    keep = {n for start, end in kept for n in range(start, end + 1)}
    return "".join(line if n in keep else "\n" for n, line in enumerate(lines, 1))


def _parse_lines(lines: list[str], kept: list[tuple[int, int]]) -> ast.Module | None:
    """``ast`` of the ``kept`` lines alone (``_blanked``), or None."""
    try:
        return ast.parse(_blanked(lines, kept))
    except (SyntaxError, ValueError, UnicodeError, MemoryError, RecursionError):
        return None


def _looks_described(node: ast.ClassDef) -> bool:
    """A description class by its shape: a ``createDescription`` of its own (an
    implementation's calls ``setDescription`` and is listed apart), or a base named
    ``SkillDescription`` (an EzSkiROS description, or an empty legacy one)."""
    if any(isinstance(m, ast.FunctionDef) and m.name == "createDescription"
           for m in node.body):
        return True
    return any((isinstance(b, ast.Name) and b.id == "SkillDescription")
               or (isinstance(b, ast.Attribute) and b.attr == "SkillDescription")
               for b in node.bases)


def recover_classes(data: bytes) -> Recovered:
    """``(class, line, described type or None)`` of a module's top-level classes, read with
    ``tokenize`` where ``ast`` fails (``print x``, ``except E, e:``): a class whose body
    calls ``setDescription(Type(), ...)`` is an implementation of ``Type``, one with
    ``createDescription`` and no such call a description (None); other classes are left
    out. None when not even the tokens can be read."""
    classes: list[_Recovered] = []
    current: _Recovered | None = None
    previous: list[str] = ["", ""]
    try:
        for string, kind, line, column in _tokens(data):
            if kind == tokenize.NAME and previous[-1] == TOP_CLASS:
                current = _Recovered(string, line)
                classes.append(current)
            elif kind == tokenize.NAME and column == 0:
                current = None  # a top-level statement ends the class before it
            elif current is not None and kind == tokenize.NAME:
                if string == "createDescription":
                    current.creates = True
                elif current.described is None:
                    _described_by(current, previous, string)
            if kind not in _LAYOUT:
                top = string == "class" and column == 0
                previous = [previous[-1], TOP_CLASS if top else string]
    except (tokenize.TokenError, SyntaxError, UnicodeError, LookupError):
        if not classes:
            return None
    return [(c.name, c.line, c.described) for c in classes if c.described or c.creates]


_KEYWORDS = ("description", "label")
"""The names of ``setDescription``'s parameters, which a call may pass by keyword."""


def _described_by(current: _Recovered, previous: list[str], string: str) -> None:
    """Note the type a class's ``setDescription`` call passes, from the name token
    ``string`` after the two ``previous`` tokens, whether it is passed by position
    (``setDescription(Pick(), ...)``) or by keyword (``setDescription(label="p",
    description=Pick())``), as the ``ast`` reading of ``compound.static`` takes both."""
    if previous == ["setDescription", "("]:
        if string in _KEYWORDS:
            current.keyword = True
        else:
            current.described = string
    elif current.keyword and previous == ["description", "="]:
        current.described = string


Token = tuple[str, int, int, int]
"""``(string, type, line, column)`` of one token."""


def _tokens(data: bytes) -> Iterable[Token]:
    """The module's tokens as ``tokenize`` gives them, but for its layout (newlines and
    comments, which ``recover_classes`` passes over) and its first, the encoding."""
    return python_tokens(data)


def _code(line: str) -> bool:
    """Whether a line (or its end) holds more than spaces and a comment."""
    stripped = line.strip()
    return bool(stripped) and not stripped.startswith("#")


def python_tokens(data: bytes) -> Iterator[Token]:
    """``_tokens`` by ``tokenize``: it raises where the module cannot be read on, after
    the tokens before."""
    return ((t.string, t.type, t.start[0], t.start[1])
            for t in tokenize.tokenize(io.BytesIO(data).readline))


@dataclass
class _Recovered:
    """One class seen by ``recover_classes``."""

    name: str
    line: int
    creates: bool = False
    described: str | None = None
    keyword: bool = False
    """Its ``setDescription`` call passes its arguments by keyword."""
