"""Recall of ``ezmigrate check`` by bug injection into real repositories (issue 42).

    python bench/bench_recall.py CHECKOUTS [--per-operator 40] [--seed 42] [--jobs 2]
                                 [--repos NAME ...] [--list] [--misses 12]

CHECKOUTS is a folder of git checkouts, one per repository, each named ``owner+name``
(the folder ``bench_precision.py`` reads). Nothing in it is modified: each worker process
copies a repository (without ``.git``) into a temporary folder once, and every mutant is
one edit of one literal of one file of that copy, undone after its run.

Mutation sites are found with ``ast`` (the exact line and byte column of a string literal
or a name), in the Python files that parse, outside the vendored SkiROS2 copies that
``check`` itself skips. The operators:

- ``class-typo``: the local name of ``Element("p:Class")`` (descriptions and implementations);
- ``relation-typo``: the relation of ``getRelationCond`` / ``getAbstractRelationCond``;
- ``property-typo``: the property of ``getPropCond`` / ``getHasPropCond``;
- ``condition-key-typo``: the subject or object key of a condition factory;
- ``params-key-typo``: ``self.params["Key"]`` in an implementation method (not
  ``createDescription``);
- ``child-type-typo``, ``child-label-typo``: ``self.skill("Type", "label", ...)``;
- ``specify-key-typo``, ``remap-key-typo``: the keys of the ``specify`` / ``remap`` dicts of
  ``self.skill(...)`` (not the key of an identity remap, ``{"Camera": "Camera"}``, whose
  typo SkiROS2 runs the same: ``HARMLESS_NOTE``);
- ``processor-typo``: the processor class of ``setProcessor(P())`` / ``self.skill(P())``;
- ``relation-domain``: the relation of a ``getRelationCond`` replaced with an object property
  of the bundled core ontology whose ``rdfs:domain`` no subclass of the subject's class
  (its ``addParam`` in the same class, or the automatic ``Robot``: ``sumo:Agent``) can
  satisfy (``OntologyIndex.can_satisfy`` is False).

A typo is one edit of a letter of the (local) name: drop it, swap it with the next one, or
double it, picked with a fixed seed. A mutant whose new name exists anyway (a class or
property of the core ontology, a local name in the repository's ontology or scene files,
a string literal, a class or a name of the repository's Python code, a standard library
description or an upstream processor) is dropped and counted, as is one whose text does
not parse. Up to ``--per-operator`` mutants per operator are kept, taken from the
repositories in turn so that they spread across them.

Counting rule. ``check --no-cache --output-format json --exit-zero .`` runs at the root of
the copy (``--cache-dir`` in the temporary folder, timeout 300 s) once unmutated (the
baseline) and once per mutant. A finding is *new* when its ``(path, line, code, message)``
is not among the baseline's (as a multiset; a mutant edits inside one line, so no line
moves). A mutant is *found* when a new finding with severity ``warning`` or ``error`` lies
on the lines of the innermost statement holding the mutated literal (for a compound tree
written as one ``skill(...)`` call, that call's lines). *Collateral* counts the mutants
with a new warning or error anywhere else. A run that times out or fails counts as not
found, and is reported.

``--at REV`` runs the ``ezmigrate`` of a commit instead of the working tree (``git archive``
of ``ezmigrate`` and ``ezskiros_runtime`` into the temporary folder, first on
``PYTHONPATH``): the figures then belong to that commit while the tree is being edited.
"""

from __future__ import annotations

import argparse
import ast
import datetime
import json
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
from collections import Counter, defaultdict
from collections.abc import Iterator, Sequence
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path

from ezskiros_runtime.ontology.index import OntologyIndex, bundled_ontology_path
from ezskiros_runtime.ontology.load import load_index

TIMEOUT = 300
OPERATORS = (
    "class-typo", "relation-typo", "property-typo", "condition-key-typo", "params-key-typo",
    "child-type-typo", "child-label-typo", "specify-key-typo", "remap-key-typo",
    "processor-typo", "relation-domain",
)
PROCESSORS = frozenset({
    "NoProcessor", "Serial", "SerialStar", "Sequential", "Selector", "SelectorStar",
    "ParallelFf", "ParallelFs", "NoFail", "RetryOnFail", "Loop", "InferInvalid",
})
STD_LIB_SKILLS = frozenset({"Wait", "WmSetRelation", "WmSetProperties", "WmMoveObject",
                            "Counter", "TaskPlan"})
RELATION_FACTORIES = frozenset({"getRelationCond", "getAbstractRelationCond"})
PROPERTY_FACTORIES = frozenset({"getPropCond", "getHasPropCond"})
# factory -> positions of its parameter keys (after the label)
KEY_POSITIONS = {
    "getRelationCond": (2, 3), "getAbstractRelationCond": (2, 3), "getPropCond": (2,),
    "getHasPropCond": (2,), "getIsSpecifiedCond": (1,), "getGenerateCond": (1,),
    "getOnTypeCond": (1,),
}
ONTOLOGY_SUFFIXES = (".owl", ".ttl", ".turtle", ".rdf")
SKIP_DIRS = frozenset({".git", "__pycache__", "build", "devel", "install"})
VENDORED = re.compile(r"^ezmigrate: (.+?): a vendored copy of .* skipped", re.MULTILINE)
SKILLS = re.compile(r"^ezmigrate: \d+ files? checked, (\d+) skills?", re.MULTILINE)
# a method that makes its class a skill (description or implementation)
SKILL_METHODS = frozenset({"createDescription", "modifyDescription", "expand", "execute",
                           "onStart", "onInit", "onPreempt", "onEnd", "run"})
Finding = dict[str, object]
FindingKey = tuple[str, int, str, str]


@dataclass(frozen=True)
class Mutant:
    """One edit of one literal: ``old`` at byte ``start`` of ``line`` becomes ``new``."""

    operator: str
    repo: str
    path: str
    line: int
    start: int
    old: str
    new: str
    first: int
    last: int

    def label(self) -> str:
        """``repo path:line: 'old' -> 'new'`` for listings."""
        return f"{self.repo} {self.path}:{self.line}: {self.old!r} -> {self.new!r}"


@dataclass
class Outcome:
    """What one mutant's run gave."""

    mutant: Mutant
    status: str  # "ok", "timeout" or "failed: ..."
    found_codes: list[str] = field(default_factory=list)
    collateral: list[str] = field(default_factory=list)


@dataclass
class Site:
    """A place where an operator can edit: a literal (or name) and its statement's lines."""

    operator: str
    path: str
    node: ast.expr
    value: str
    first: int
    last: int
    replacement: str | None = None  # fixed replacement (relation-domain), else a typo


# ---------------------------------------------------------------- repository walking

def python_files(root: Path) -> Iterator[Path]:
    """The repository's ``.py`` files, sorted, outside build and VCS folders."""
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames[:] = sorted(d for d in dirnames if d not in SKIP_DIRS)
        for name in sorted(filenames):
            if name.endswith(".py"):
                yield Path(dirpath) / name


def parse(path: Path) -> ast.Module | None:
    """The module of a UTF-8 file that Python 3 parses, else None."""
    try:
        return ast.parse(path.read_bytes().decode("utf-8"))
    except (SyntaxError, UnicodeDecodeError, ValueError):
        return None


def repository_names(root: Path, modules: dict[str, ast.Module]) -> set[str]:
    """Every name a typo could collide with in this repository.

    String literals (and their local names after ``:``), class, function and variable
    names of the Python code, and local names written in ontology and scene files.
    """
    names: set[str] = set()
    for module in modules.values():
        for node in ast.walk(module):
            if isinstance(node, ast.Constant) and isinstance(node.value, str):
                names.add(node.value)
                names.add(node.value.rsplit(":", 1)[-1])
            elif isinstance(node, ast.ClassDef | ast.FunctionDef):
                names.add(node.name)
            elif isinstance(node, ast.Name):
                names.add(node.id)
            elif isinstance(node, ast.alias):
                names.add(node.asname or node.name.rsplit(".", 1)[-1])
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames[:] = [d for d in dirnames if d not in SKIP_DIRS]
        for name in filenames:
            if name.endswith(ONTOLOGY_SUFFIXES):
                text = (Path(dirpath) / name).read_text(encoding="utf-8", errors="replace")
                names.update(re.findall(r"[#:]([A-Za-z_][\w.-]*)", text))
    return names


def ontology_names(index: OntologyIndex) -> set[str]:
    """Compact and local names of the core ontology's classes and properties."""
    names: set[str] = set()
    for iri in [*index.classes, *index.properties]:
        compact = index.compact(iri)
        names.update({compact, compact.rsplit(":", 1)[-1]})
    return names


# ---------------------------------------------------------------- finding sites

def walk(node: ast.AST, stmt: ast.stmt | None, cls: ast.ClassDef | None,
         func: str | None) -> Iterator[tuple[ast.AST, ast.stmt | None, ast.ClassDef | None,
                                             str | None]]:
    """Every node with its innermost statement, enclosing class and enclosing function."""
    yield node, stmt, cls, func
    if isinstance(node, ast.stmt):
        stmt = node
    if isinstance(node, ast.ClassDef):
        cls = node
    if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
        func = node.name
    for child in ast.iter_child_nodes(node):
        yield from walk(child, stmt, cls, func)


def call_name(call: ast.Call) -> str | None:
    """``f`` of ``f(...)`` or ``x.f(...)``."""
    if isinstance(call.func, ast.Name):
        return call.func.id
    if isinstance(call.func, ast.Attribute):
        return call.func.attr
    return None


def string(node: ast.expr | None) -> str | None:
    """The value of a string literal, else None."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value
    return None


def argument(call: ast.Call, position: int, keyword: str) -> ast.expr | None:
    """The argument at ``position`` or passed as ``keyword``."""
    if position < len(call.args):
        return call.args[position]
    return next((k.value for k in call.keywords if k.arg == keyword), None)


def is_self_skill(call: ast.Call) -> bool:
    """``self.skill(...)``."""
    return (isinstance(call.func, ast.Attribute) and call.func.attr == "skill"
            and isinstance(call.func.value, ast.Name) and call.func.value.id == "self")


def element_classes(cls: ast.ClassDef) -> dict[str, str]:
    """``{key: class}`` of ``addParam("Key", Element("p:Class"), ...)`` in a class body."""
    declared: dict[str, str] = {}
    for node in ast.walk(cls):
        if isinstance(node, ast.Call) and call_name(node) == "addParam" and len(node.args) >= 2:
            key, value = string(node.args[0]), node.args[1]
            if (key is not None and isinstance(value, ast.Call)
                    and call_name(value) == "Element" and value.args):
                element = string(value.args[0])
                if element is not None:
                    declared[key] = element
    declared.setdefault("Robot", "sumo:Agent")
    return declared


def is_skill_class(cls: ast.ClassDef) -> bool:
    """A class with a skill's methods (SkiROS2's framework classes are not in the
    repositories ``check`` counts skills in: those are skipped as a whole)."""
    return any(isinstance(n, ast.FunctionDef) and n.name in SKILL_METHODS for n in cls.body)


def processor_names(node: ast.expr | None) -> Iterator[ast.Name]:
    """The processor class names of ``P()`` / ``NoFail(P())``."""
    while isinstance(node, ast.Call) and isinstance(node.func, ast.Name):
        yield node.func
        node = node.args[0] if node.args else None


def call_sites(call: ast.Call, path: str, lines: tuple[int, int], cls: ast.ClassDef | None,
               func: str | None) -> Iterator[Site]:
    """The sites of one call, for every operator but ``relation-domain``."""
    name = call_name(call)

    def site(operator: str, node: ast.expr | None) -> Iterator[Site]:
        value = node.id if isinstance(node, ast.Name) else string(node)
        if node is not None and value:
            yield Site(operator, path, node, value, *lines)

    if name == "Element" and call.args:
        yield from site("class-typo", call.args[0])
    if name in RELATION_FACTORIES:
        yield from site("relation-typo", argument(call, 1, "relation"))
    if name in PROPERTY_FACTORIES:
        yield from site("property-typo", argument(call, 1, "property"))
    for position in KEY_POSITIONS.get(name or "", ()):
        if position < len(call.args):
            yield from site("condition-key-typo", call.args[position])
    if name == "setProcessor" and call.args:
        for processor in processor_names(call.args[0]):
            yield from site("processor-typo", processor)
    if is_self_skill(call) and call.args:
        if string(call.args[0]) is None:
            for processor in processor_names(call.args[0]):
                yield from site("processor-typo", processor)
            return
        yield from site("child-type-typo", call.args[0])
        yield from site("child-label-typo", argument(call, 1, "slabel"))
        for operator, position, keyword in (("remap-key-typo", 2, "remap"),
                                            ("specify-key-typo", 3, "specify")):
            mapping = argument(call, position, keyword)
            if isinstance(mapping, ast.Dict):
                for key, value in zip(mapping.keys, mapping.values, strict=True):
                    if operator == "remap-key-typo" and key is not None \
                            and string(key) is not None and string(key) == string(value):
                        continue  # an identity remap: its typo is harmless (HARMLESS_NOTE)
                    yield from site(operator, key)


def domain_site(call: ast.Call, path: str, lines: tuple[int, int], cls: ast.ClassDef,
                index: OntologyIndex, rng: random.Random) -> Site | None:
    """A ``relation-domain`` site: a real relation whose domain excludes the subject."""
    relation = argument(call, 1, "relation")
    subject = string(argument(call, 2, "subject_key"))
    old = string(relation)
    if relation is None or subject is None or old is None:
        return None
    subject_class = element_classes(cls).get(subject)
    subject_iri = index.expand(subject_class) if subject_class else None
    if subject_iri is None or subject_iri not in index.classes:
        return None
    candidates = sorted(
        index.compact(iri) for iri, info in index.properties.items()
        if info.kind == "object" and info.domains
        and any(index.can_satisfy(subject_iri, d) is False for d in info.domains))
    candidates = [c for c in candidates if c != old]
    if not candidates:
        return None
    return Site("relation-domain", path, relation, old, *lines, replacement=rng.choice(candidates))


def module_sites(module: ast.Module, path: str, index: OntologyIndex,
                 rng: random.Random) -> Iterator[Site]:
    """Every mutation site of one module."""
    for node, stmt, cls, func in walk(module, None, None, None):
        if stmt is None or cls is None or not is_skill_class(cls):
            continue
        lines = (stmt.lineno, stmt.end_lineno or stmt.lineno)
        if isinstance(node, ast.Call):
            yield from call_sites(node, path, lines, cls, func)
            if call_name(node) == "getRelationCond":
                found = domain_site(node, path, lines, cls, index, rng)
                if found is not None:
                    yield found
        elif (isinstance(node, ast.Subscript) and func not in (None, "createDescription")
              and isinstance(node.value, ast.Attribute) and node.value.attr == "params"
              and isinstance(node.value.value, ast.Name) and node.value.value.id == "self"):
            value = string(node.slice)
            if value:
                yield Site("params-key-typo", path, node.slice, value, *lines)


# ---------------------------------------------------------------- making mutants

def typos(name: str) -> list[str]:
    """Every one-edit typo of ``name``'s letters: drop, swap with the next, double."""
    out: set[str] = set()
    for i, char in enumerate(name):
        if not char.isalpha():
            continue
        out.add(name[:i] + name[i + 1:])
        out.add(name[:i] + char + name[i:])
        if i + 1 < len(name):
            out.add(name[:i] + name[i + 1] + char + name[i + 2:])
    out.discard(name)
    out.discard("")
    return sorted(out)


def literal_start(line: bytes, node: ast.expr, value: str) -> int | None:
    """Byte offset of ``value`` inside the literal or name ``node`` on ``line``."""
    if node.end_lineno != node.lineno or node.end_col_offset is None:
        return None
    token = line[node.col_offset:node.end_col_offset]
    encoded = value.encode("utf-8")
    if isinstance(node, ast.Name):
        return node.col_offset if token == encoded else None
    quote = token[-1:]
    if quote not in (b'"', b"'") or not token.endswith(encoded + quote):
        return None  # escapes, implicit concatenation, triple quotes: not edited
    start = len(token) - len(encoded) - 1
    head = token[:start]  # string prefix and opening quote: r", u', "
    if not head.endswith(quote) or not (head[:-1] == b"" or head[:-1].isalpha()):
        return None
    return node.col_offset + start


def propose(site: Site, rng: random.Random) -> str | None:
    """The new text of a site: its fixed replacement, or a typo of its (local) name."""
    if site.replacement is not None:
        return site.replacement
    local_ops = ("class-typo", "relation-typo", "property-typo", "child-type-typo")
    prefix, local = "", site.value
    if site.operator in local_ops and ":" in site.value:
        prefix, local = site.value.rsplit(":", 1)
        prefix += ":"
    options = typos(local)
    return prefix + rng.choice(options) if options else None


def collides(site: Site, new: str, known: set[str]) -> bool:
    """Does the new name exist anyway (then the mutant need not be a bug)?"""
    if site.operator == "relation-domain":
        return False
    return new in known or new.rsplit(":", 1)[-1] in known


def apply(data: bytes, mutant: Mutant) -> bytes:
    """The file's bytes with the mutant's edit."""
    lines = data.splitlines(keepends=True)
    line = lines[mutant.line - 1]
    old = mutant.old.encode("utf-8")
    assert line[mutant.start:mutant.start + len(old)] == old, mutant.label()
    lines[mutant.line - 1] = line[:mutant.start] + mutant.new.encode("utf-8") + \
        line[mutant.start + len(old):]
    return b"".join(lines)


def repository_mutants(root: Path, repo: str, skipped: Sequence[str], index: OntologyIndex,
                       core_names: set[str], seed: int, dropped: Counter[str]
                       ) -> dict[str, list[Mutant]]:
    """Every mutant of one repository, per operator, in a seeded random order."""
    modules: dict[str, ast.Module] = {}
    for path in python_files(root):
        relative = path.relative_to(root).as_posix()
        if any(relative == s or relative.startswith(s.rstrip("/") + "/") for s in skipped):
            continue
        module = parse(path)
        if module is not None:
            modules[relative] = module
    known = repository_names(root, modules) | core_names | PROCESSORS | STD_LIB_SKILLS
    rng = random.Random(f"{seed}:{repo}")
    out: dict[str, list[Mutant]] = defaultdict(list)
    seen: set[tuple[str, str, int, int]] = set()
    for relative, module in modules.items():
        data = (root / relative).read_bytes()
        lines = data.splitlines(keepends=True)
        for site in module_sites(module, relative, index, rng):
            start = literal_start(lines[site.node.lineno - 1], site.node, site.value)
            new = propose(site, rng)
            where = (site.operator, relative, site.node.lineno, start or -1)
            if start is None or new is None or where in seen:
                continue
            seen.add(where)
            if collides(site, new, known):
                dropped[site.operator] += 1
                continue
            mutant = Mutant(site.operator, repo, relative, site.node.lineno, start,
                            site.value, new, site.first, site.last)
            try:
                ast.parse(apply(data, mutant).decode("utf-8"))
            except SyntaxError:
                dropped[site.operator] += 1
                continue
            out[site.operator].append(mutant)
    for mutants in out.values():
        rng.shuffle(mutants)
    return out


def spread(per_repo: dict[str, dict[str, list[Mutant]]], operator: str, limit: int
           ) -> list[Mutant]:
    """Up to ``limit`` mutants of ``operator``, taken from the repositories in turn."""
    queues = [list(ops.get(operator, [])) for _, ops in sorted(per_repo.items())]
    chosen: list[Mutant] = []
    while len(chosen) < limit and any(queues):
        for queue in queues:
            if queue and len(chosen) < limit:
                chosen.append(queue.pop(0))
    return chosen


# ---------------------------------------------------------------- running check

_COPIES: dict[str, Path] = {}


def working_copy(checkouts: Path, repo: str, scratch: Path) -> Path:
    """This process's copy of a repository (made once, without ``.git``)."""
    if repo not in _COPIES:
        target = scratch / f"worker-{os.getpid()}" / repo
        shutil.copytree(checkouts / repo, target, symlinks=True,
                        ignore=shutil.ignore_patterns(".git"))
        _COPIES[repo] = target
    return _COPIES[repo]


def snapshot(rev: str, target: Path) -> str:
    """Extract ``ezmigrate`` and ``ezskiros_runtime`` of commit ``rev``; its full hash."""
    repo = Path(__file__).resolve().parents[1]
    target.mkdir(parents=True)
    archive = subprocess.run(["git", "archive", rev, "ezmigrate", "ezskiros_runtime"],
                             cwd=repo, capture_output=True, check=True).stdout
    subprocess.run(["tar", "-x", "-C", str(target)], input=archive, check=True)
    return subprocess.run(["git", "rev-parse", rev], cwd=repo, capture_output=True,
                          text=True, check=True).stdout.strip()


def run_check(root: Path, cache_dir: Path) -> tuple[str, list[Finding], str]:
    """``(status, findings, stderr)`` of ``check`` at ``root``."""
    command = [sys.executable, "-m", "ezmigrate", "check", "--no-cache", "--output-format",
               "json", "--exit-zero", "--cache-dir", str(cache_dir), "."]
    try:
        run = subprocess.run(command, cwd=root, capture_output=True, text=True,
                             stdin=subprocess.DEVNULL, check=False, timeout=TIMEOUT,
                             env=os.environ.copy())
    except subprocess.TimeoutExpired:
        return "timeout", [], ""
    if run.returncode != 0:
        return f"failed: exit {run.returncode}: {run.stderr[-300:]}", [], run.stderr
    try:
        return "ok", json.loads(run.stdout), run.stderr
    except json.JSONDecodeError as error:
        return f"failed: {error}", [], run.stderr


def evaluate(checkouts: Path, scratch: Path, repo: str, mutant: Mutant | None
             ) -> tuple[str, list[Finding], str]:
    """Run ``check`` on this process's copy of ``repo``, with ``mutant`` applied if given."""
    root = working_copy(checkouts, repo, scratch)
    cache_dir = scratch / f"cache-{os.getpid()}"
    if mutant is None:
        return run_check(root, cache_dir)
    target = root / mutant.path
    original = target.read_bytes()
    try:
        target.write_bytes(apply(original, mutant))
        return run_check(root, cache_dir)
    finally:
        target.write_bytes(original)


def key(finding: Finding) -> FindingKey:
    """What makes a finding the same in two runs."""
    return (str(finding["path"]), int(str(finding["line"])), str(finding["code"]),
            str(finding["message"]))


def judge(mutant: Mutant, status: str, findings: list[Finding], baseline: list[Finding]
          ) -> Outcome:
    """Found and collateral findings of one mutant against the baseline."""
    outcome = Outcome(mutant, status)
    before = Counter(key(f) for f in baseline)
    for finding in findings:
        k = key(finding)
        if before[k] > 0:
            before[k] -= 1
            continue
        if finding["severity"] == "info":
            continue
        if k[0] == mutant.path and mutant.first <= k[1] <= mutant.last:
            outcome.found_codes.append(k[2])
        else:
            outcome.collateral.append(f"{k[0]}:{k[1]} {k[2]}")
    return outcome


# ---------------------------------------------------------------- report

HARMLESS_NOTE = (
    "Mutants considered harmless, not made: a typo of the key of an identity remap "
    "(`remap={'Camera': 'Camera'}` -> `{'CCamera': 'Camera'}`): the remap did nothing "
    "before (ParamHandler.remap pops and puts back the same key) and does nothing after "
    "(the child declares no `CCamera`), and the child's `Camera` still reads the "
    "blackboard's `Camera`, so SkiROS2 runs the tree the same. "
    "Operators considered harmless: none. A typo'd class, relation or property is stored "
    "verbatim and matches nothing in the world model (grounding fails or the condition "
    "never holds); a typo'd condition key names no parameter (the condition is never "
    "grounded); a typo'd `self.params` key makes `ParamHandler.__getitem__` return None; a "
    "typo'd child type or label makes `PluginLoader`/`SkillInstanciator` fail (\"No plugin "
    "with name ...\"); a typo'd remap key renames nothing and a typo'd specify key is "
    "dropped by `specifyParamDefault` (harmless only where the specified value equals the "
    "child's default); a typo'd processor raises NameError when `expand` runs. "
    "`relation-domain` is a bug by the ontology, not by SkiROS2's code: SkiROS2 does not "
    "check domains, so the condition holds only if the world model stores a triple the "
    "ontology forbids; its recall is also given apart.")


def table(outcomes: list[Outcome], dropped: Counter[str]) -> list[str]:
    """The Markdown table per operator, with the totals."""
    rows = ["| operator | mutants | found | recall | codes that found them | sites dropped (name "
            "exists / no parse) | timeouts or failures |", "|---|---:|---:|---:|---|---:|---:|"]
    total = found_total = 0
    for operator in OPERATORS:
        mine = [o for o in outcomes if o.mutant.operator == operator]
        found = [o for o in mine if o.found_codes]
        codes = Counter(c for o in found for c in sorted(set(o.found_codes)))
        bad = sum(o.status != "ok" for o in mine)
        recall = f"{100 * len(found) / len(mine):.0f}%" if mine else "-"
        rows.append(f"| {operator} | {len(mine)} | {len(found)} | {recall} | "
                    f"{', '.join(f'{c} {n}' for c, n in codes.most_common())} | "
                    f"{dropped[operator]} | {bad} |")
        total += len(mine)
        found_total += len(found)
    overall = f"{100 * found_total / total:.0f}%" if total else "-"
    rows.append(f"| **all** | **{total}** | **{found_total}** | **{overall}** | | "
                f"{sum(dropped.values())} | {sum(o.status != 'ok' for o in outcomes)} |")
    typo = [o for o in outcomes if o.mutant.operator != "relation-domain"]
    if typo:
        hit = sum(bool(o.found_codes) for o in typo)
        rows.append(f"| all but relation-domain | {len(typo)} | {hit} | "
                    f"{100 * hit / len(typo):.0f}% | | | |")
    return rows


def report(outcomes: list[Outcome], dropped: Counter[str], misses: int) -> list[str]:
    """The whole Markdown report: table, collateral, misses, failures, harmless note."""
    out = table(outcomes, dropped)
    collateral = [o for o in outcomes if o.collateral]
    out += ["", f"Collateral: {len(collateral)} of {len(outcomes)} mutants gave a new warning "
            "or error outside the mutated statement."]
    for o in collateral[:8]:
        out.append(f"- {o.mutant.label()} [{o.mutant.operator}]: "
                   f"{'; '.join(o.collateral[:3])}")
    missed = [o for o in outcomes if not o.found_codes]
    if missed:
        out += ["", f"Misses ({len(missed)}; first {min(misses, len(missed))}, one per "
                "operator first):"]
        ordered = sorted(missed, key=lambda o: (OPERATORS.index(o.mutant.operator)))
        firsts = {o.mutant.operator: o for o in reversed(ordered)}
        picks = list(firsts.values()) + [o for o in ordered if o not in firsts.values()]
        for o in picks[:misses]:
            out.append(f"- [{o.mutant.operator}] {o.mutant.label()}"
                       + ("" if o.status == "ok" else f" ({o.status[:80]})"))
    failed = [o for o in outcomes if o.status != "ok"]
    if failed:
        out += ["", f"Runs that timed out or failed ({len(failed)}, counted as not found):"]
        out += [f"- {o.mutant.label()}: {o.status[:200]}" for o in failed[:10]]
    out += ["", HARMLESS_NOTE]
    return out


# ---------------------------------------------------------------- main

def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n\n")[0])
    parser.add_argument("checkouts", type=Path)
    parser.add_argument("--per-operator", type=int, default=40)
    parser.add_argument("--seed", type=int, default=42)
    parser.add_argument("--repos", nargs="*", help="checkout folder names (owner+name)")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--list", action="store_true", help="print the mutants, run nothing")
    parser.add_argument("--misses", type=int, default=12, help="misses to list")
    parser.add_argument("--at", metavar="REV", help="run the ezmigrate of this commit")
    args = parser.parse_args(argv)
    checkouts = args.checkouts.resolve()
    repos = sorted(p.name for p in checkouts.iterdir() if (p / ".git").exists()
                   and (not args.repos or p.name in args.repos))
    index = load_index([bundled_ontology_path()], cache=False)
    head = subprocess.run(["git", "rev-parse", "HEAD"], cwd=Path(__file__).parent,
                          capture_output=True, text=True, check=False).stdout.strip()
    with tempfile.TemporaryDirectory(prefix="bench-recall-") as tmp:
        scratch = Path(tmp)
        if args.at:  # set before the pool's workers start, so that they inherit it
            head = snapshot(args.at, scratch / "ezmigrate-src")
            os.environ["PYTHONPATH"] = os.pathsep.join(
                filter(None, [str(scratch / "ezmigrate-src"), os.environ.get("PYTHONPATH")]))
        with ProcessPoolExecutor(max_workers=args.jobs) as pool:
            measured = measure(pool, args, checkouts, scratch, repos, index)
    if measured is None:
        return 0
    outcomes, dropped, used = measured
    source = f"commit {head[:12]}" if args.at else f"the working tree at {head[:12]}"
    print(f"`{' '.join(['python', 'bench/bench_recall.py', *sys.argv[1:]])}`, "
          f"{datetime.date.today().isoformat()}, ezmigrate of {source}, seed {args.seed}, "
          f"{len(used)} repositories: {', '.join(used)}\n")
    print("\n".join(report(outcomes, dropped, args.misses)))
    return 0


def measure(pool: ProcessPoolExecutor, args: argparse.Namespace, checkouts: Path,
            scratch: Path, repos: list[str], index: OntologyIndex
            ) -> tuple[list[Outcome], Counter[str], list[str]] | None:
    """Baselines, mutants and their runs: (outcomes, dropped per operator, repositories
    used); None under ``--list``, which prints the mutants instead."""
    core_names = ontology_names(index)
    baselines = {r: pool.submit(evaluate, checkouts, scratch, r, None) for r in repos}
    base: dict[str, list[Finding]] = {}
    per_repo: dict[str, dict[str, list[Mutant]]] = {}
    dropped: Counter[str] = Counter()
    for repo, future in baselines.items():
        status, findings, stderr = future.result()
        skills = SKILLS.search(stderr)
        if status != "ok" or (skills is not None and skills.group(1) == "0"):
            print(f"{repo}: skipped ({status if status != 'ok' else 'no skill checked'})",
                  file=sys.stderr)
            continue
        base[repo] = findings
        per_repo[repo] = repository_mutants(checkouts / repo, repo, VENDORED.findall(stderr),
                                            index, core_names, args.seed, dropped)
    mutants = [m for op in OPERATORS for m in spread(per_repo, op, args.per_operator)]
    if args.list:
        for m in mutants:
            print(f"[{m.operator}] {m.label()} (lines {m.first}-{m.last})")
        print(f"{len(mutants)} mutants", file=sys.stderr)
        return None
    futures = [pool.submit(evaluate, checkouts, scratch, m.repo, m) for m in mutants]
    outcomes: list[Outcome] = []
    for done, (mutant, future) in enumerate(zip(mutants, futures, strict=True), 1):
        status, findings, _ = future.result()
        outcomes.append(judge(mutant, status, findings, base[mutant.repo]))
        if done % 20 == 0:
            print(f"{done}/{len(mutants)}", file=sys.stderr)
    return outcomes, dropped, sorted(base)


if __name__ == "__main__":
    sys.exit(main())
