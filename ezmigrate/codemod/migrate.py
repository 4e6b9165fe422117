"""The pure core: ``migrate(source, settings) -> FileResult``. No I/O, no user code runs.

For each legacy description class: extract its ``createDescription`` into IR (rules in
``ezmigrate/codemod/rules``), replay the IR through the legacy backend in legacy order and in the
order the EzSkiROS form lowers to (they must give the same model, or the skill is skipped),
write the ``description`` method, then fix the module's imports. A skill converts whole or
not at all; a class whose base description was not converted is not converted either.
"""

from __future__ import annotations

import ast
import re
import traceback
from collections import Counter
from collections.abc import Collection, Iterator, Mapping
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

import libcst as cst

from ..report.findings import skill_findings
from ..report.results import (
    ClassLines,
    FileResult,
    SkillResult,
    source_digest,
    unparsable,
)
from ..report.written_lines import classes_of
from .core.classes import DescriptionClass, description_classes, inert_classes
from .core.context import ExtractContext, StatementLines, module_constants, positions_of
from .core.cst_facts import facts_of
from .core.declared import static_description
from .core.emit import DSL_NAMES, EmitContext, quote_style
from .core.function import build_description, emitted_params
from .core.guard import encoding_of, lost_line, refuse
from .core.holes import Holes, stand_in
from .core.imports import (
    ONTOLOGY,
    RUNTIME,
    imported_names,
    module_bindings,
    name_counts,
    update_imports,
    used_names,
)
from .core.ir import (
    ExtractedSkill,
    KeptStatement,
    Literal,
    Operation,
    Unsupported,
)
from .core.legacy_names import LegacyNames, dotted_name, is_legacy_module
from .core.python2 import (
    EXCEPT_COMMA,
    comma_handler,
    except_comma,
    python2_refusal,
    python2_statement,
    python_parses,
)
from .core.reader import (
    class_bindings,
    find_create_description,
    read_operations,
    self_parameter,
)
from .core.replay import checked_model, replay
from .core.syntax_facts import ClassFacts, FunctionFacts, SyntaxFacts
from .core.tree_walk import walk
from .rules import CONSTRUCTS
from .settings import Settings

if TYPE_CHECKING:
    from ezskiros_runtime.ontology.index import OntologyIndex

DEFAULT_PREFIXES = ("skiros", "sumo", "cora", "corax", "rparts")


@dataclass
class _Plan:
    """Per-class outcome while a module is being migrated."""

    cls: DescriptionClass
    result: SkillResult
    operations: list[Operation] = field(default_factory=list)
    new_function: cst.FunctionDef | None = None
    old_function: cst.FunctionDef | None = None
    create: FunctionFacts | None = None
    """What ``SyntaxFacts`` knows of ``old_function`` (the names its replacement removes)."""
    runtime: set[str] = field(default_factory=set)
    prefixes: set[str] = field(default_factory=set)


@dataclass
class _ModulePlanning:
    """What planning each description class of one module shares: the module, its legacy
    names and constants, the run's settings, the aliases of the ontology's prefixes, and
    what the classes planned so far give the classes after them: each one's operations
    (``effective``; a class without ``createDescription`` inherits its base's) and which of
    them convert (``converted``). One object, not seven arguments, since every class reads
    the same ones."""

    module: cst.Module
    names: LegacyNames
    settings: Settings
    aliases: dict[str, str]
    constants: Mapping[str, Literal]
    effective: dict[str, list[Operation]]
    converted: set[str]


def migrate(source: bytes | str, settings: Settings | None = None,
            path: str = "<string>") -> FileResult:
    """Migrate one module's text. ``result.new_source`` is set only if something changed."""
    refused: FileResult | None = None
    for result, lost in guarded_readings(source, settings or Settings(), path):
        if lost is None:
            return result
        refused = refused or refuse(result, lost)  # the first reading's line is named
    assert refused is not None, "the whole source is the last reading; it gives a result"
    return refused


def guarded_readings(source: bytes | str, settings: Settings,
                     path: str = "<string>") -> Iterator[tuple[FileResult, int | None]]:
    """The migration of each reading (``_readings``) that gives a result, with the first
    line outside the migrated code it would change (``core/guard.py``; ``None``: none).
    ``migrate`` takes the first result the guard passes; ``bench/guard_triggers.py``
    counts the others."""
    tree, facts, refused = _python_reading(source, path)
    if refused is not None:  # Python 2: libcst's reading would change nothing
        yield refused, None
        return
    for text, holes, origin in _readings(source, tree, facts, settings):
        result = _migrate_text(text, origin, settings, path, facts, holes)
        if result is not None:
            if isinstance(source, bytes) and isinstance(result.new_source, str):
                encoded = result.new_source.encode(encoding_of(source))
                result = replace(result, new_source=encoded, new_classes=None
                                 if result.new_classes is None else replace(
                                     result.new_classes, digest=source_digest(encoded)))
            yield result, lost_line(source, result, tree)


def _migrate_text(text: bytes | str, source: bytes | str, settings: Settings, path: str,
                  facts: SyntaxFacts | None, holes: Holes | None) -> FileResult | None:
    """``migrate`` with libcst reading ``text`` (``source``, or it with ``holes``)."""
    try:
        module = cst.parse_module(text)
    except cst.ParserSyntaxError as error:
        if holes is not None:
            return None
        message, line, column = syntax_error_location(source, error)
        return replace(unparsable(path, message, line, column),
                       python2=python2_statement(message))
    except (UnicodeDecodeError, LookupError, SyntaxError) as error:
        if holes is not None:
            return None
        reason, at = decode_error_message(source, error)
        return FileResult(path, error=reason, error_line=at)
    try:
        return _migrate_module(module, source, settings, path, facts, holes)
    except RecursionError:
        deep = too_deep_line(module)
        where = f" (the statement at line {deep})" if deep is not None else ""
        return FileResult(path, error=(
            f"nested too deeply to migrate{where}: libcst walks the syntax tree recursively; "
            "split that expression into smaller ones, then migrate"), error_line=deep)


def _python_reading(source: bytes | str, path: str) -> tuple[
        ast.Module | None, SyntaxFacts | None, FileResult | None]:
    """The module as Python's own parser reads it, and its facts; ``None`` where it does
    not (Python 2 leftovers, syntax newer than this Python, bad bytes: libcst's reading
    decides), with the file's result when Python's error alone gives it
    (``python2_refusal``)."""
    try:
        tree = ast.parse(source)
    except SyntaxError as error:
        return None, None, python2_refusal(path, _raw(source), error)
    except (ValueError, MemoryError, RecursionError):
        return None, None, None
    return tree, SyntaxFacts.of(tree), None


def _readings(source: bytes | str, tree: ast.Module | None, facts: SyntaxFacts | None,
              settings: Settings) -> Iterator[tuple[bytes | str, Holes | None, bytes | str]]:
    """What libcst reads, in order, and the source that reading stands for: the source
    with the code the migration never reads stood in for (``core/holes.py``), if ``ast``
    read it; then the whole source, when that fails. A file in an encoding other than
    UTF-8 is stood in for in its decoded text, whose lines are the lines ``ast`` counts
    (a utf-7 ``+AAo-`` is a newline); its result is encoded back by the caller."""
    holes = None
    origin = _by_lines(source)
    if tree is not None and facts is not None and origin is not None:
        inert = inert_classes(tree, facts.legacy, {
            *settings.external, *settings.migrated_bases, *settings.unresolved_bases})
        holes = stand_in(_raw(origin), tree, inert)
    if holes is not None and origin is not None:
        yield _like(origin, holes.text), holes, origin
    yield source, None, source


def _by_lines(source: bytes | str) -> bytes | str | None:
    """``source`` as text whose line breaks are Python's: itself, unless its coding
    cookie names an encoding other than UTF-8 (then its decoded text; ``None`` if it does
    not decode)."""
    encoding = encoding_of(source)
    if not isinstance(source, bytes) or encoding in ("utf-8", "utf-8-sig"):
        return source
    try:
        return source.decode(encoding)
    except (LookupError, UnicodeDecodeError):
        return None


def _raw(source: bytes | str) -> bytes:
    """The bytes of a source given as text (a lone surrogate kept as the byte it stood
    for), or the source itself."""
    return source if isinstance(source, bytes) else source.encode("utf-8", "surrogateescape")


def _like(source: bytes | str, raw: bytes) -> bytes | str:
    """``raw`` in the type ``source`` came in: ``_raw`` undone for a text source."""
    return raw if isinstance(source, bytes) else raw.decode("utf-8", "surrogateescape")


def _migrate_module(module: cst.Module, source: bytes | str, settings: Settings, path: str,
                    known: SyntaxFacts | None, holes: Holes | None) -> FileResult | None:
    """``migrate`` once the source parsed; ``None`` when ``holes`` do not fill back.
    ``known``: the module's facts, when ``ast`` read it."""
    facts = known if known is not None else _syntax_facts(module, source)
    if isinstance(facts, FileResult):
        return replace(facts, path=path)
    names = facts.legacy
    found = FileResult(path, foreign_bases=foreign_bases(module, names))
    planned = _plan_module(module, facts, settings)
    if planned is None:
        return found
    plans, _, aliases = planned
    converted = [p for p in plans if p.result.status == "converted"]
    found = replace(found, skills=[p.result for p in plans], exports=[
        p.cls.name for p in plans if p.result.status in ("converted", "unchanged")])
    if not converted:
        return found
    used = _used_after(facts, converted)
    legacy = names.local_names_for("SkillDescription")
    still_used = bool(legacy & (used | settings.exported)) or bool(legacy and "*" in
                                                                   settings.exported)
    base_name = "EzSkillDescription" if still_used else "SkillDescription"
    runtime_pairs = {(n, aliases.get(n, n)) for p in converted for n in p.runtime}
    if any(p.cls.base is None for p in converted):
        runtime_pairs.add(("SkillDescription", base_name))
    new_module = update_imports(_rewrite(module, converted, base_name), runtime_pairs,
                                {(n, aliases.get(n, n)) for p in converted for n in p.prefixes},
                                settings.exported, used=used, used_before=set(facts.names))
    printed = new_module.code  # once: ``Module.bytes`` would print the tree again
    code: bytes | str = printed
    if holes is not None:
        raw = holes.fill(printed.encode(new_module.encoding) if isinstance(source, bytes)
                         else _raw(printed))
        if raw is None:
            return None
        code = _like(source, raw)
    try:  # the parser that read the original reads the result
        checked = ast.parse(code) if facts.python_parses else cst.parse_module(code)
    except (SyntaxError, ValueError, cst.ParserSyntaxError) as error:  # a bug of ours
        message = f"internal error: migrated code does not parse ({error})"
        return replace(found, error=message, skills=[
            replace(s, status="failed", reason=message) if s.status == "converted" else s
            for s in found.skills])
    if isinstance(source, bytes) and isinstance(code, str):
        code = code.encode(new_module.encoding)
    classes = ClassLines(source_digest(code) if isinstance(code, bytes) else None,
                         classes_of(checked)) if isinstance(checked, ast.Module) else None
    return replace(found, new_source=code, new_classes=classes)


def _syntax_facts(module: cst.Module, source: bytes | str) -> SyntaxFacts | FileResult:
    """The module's facts, from ``ast`` unless Python's own parser refuses the file; for
    Python 2's ``except X, e:`` (which libcst reads as Python 3.14's ``except A, B:``) the
    result that says so instead."""
    try:
        return SyntaxFacts.of(ast.parse(source))
    except (SyntaxError, ValueError, MemoryError):
        python2 = _python2_except(module, source)
        if python2 is None:  # syntax newer than this Python: libcst reads it all the same
            return facts_of(module)
        return except_comma("", *python2)


def _used_after(facts: SyntaxFacts, converted: list[_Plan]) -> set[str]:
    """The names the module uses once the converted classes are rewritten: the original's,
    less those of the replaced methods and bases, plus those of the new methods."""
    removed: Counter[str] = Counter()
    for plan in converted:
        if plan.new_function is not None and plan.create is not None:
            removed += plan.create.names
        if plan.cls.base is None:  # the legacy base is replaced: ``abstract_skill`` of
            # ``abstract_skill.SkillDescription`` is a reference, ``SkillDescription`` is not
            removed += name_counts(plan.cls.base_arg.value)
    used = set(facts.names - removed)
    for plan in converted:
        if plan.new_function is not None:
            used |= used_names(plan.new_function)
    return used


def _plan_module(module: cst.Module, facts: SyntaxFacts, settings: Settings) -> tuple[
        list[_Plan], dict[str, list[Operation]], dict[str, str]] | None:
    """Plan every description class of the module, bases before children."""
    names = facts.legacy
    classes = description_classes(module, names, settings.external.keys(),
                                  settings.migrated_bases, settings.unresolved_bases)
    if not classes:
        return None
    cst_classes = [stmt for stmt in module.body if isinstance(stmt, cst.ClassDef)]
    class_facts = dict(zip(map(id, cst_classes), facts.classes, strict=True))
    shared = _ModulePlanning(module, names, settings, _aliases(module, settings.index),
                             module_constants(module, facts.bindings),
                             dict(settings.external), set(settings.external))
    plans: list[_Plan] = []
    for cls in classes:
        plan = _plan(cls, class_facts[id(cls.node)], shared)
        plans.append(plan)
        if plan.result.status in ("converted", "unchanged"):
            shared.converted.add(cls.name)
    return plans, shared.effective, shared.aliases


def too_deep_line(module: cst.Module) -> int | None:
    """First line of the top-level statement too deeply nested for libcst to walk, if any.

    Generating the code of each statement alone finds it without a position pass (which
    is itself recursive); the lines before it are counted from the code of the ones before.
    """
    lines = "".join(module.code_for_node(line) for line in module.header).count("\n")
    for stmt in module.body:
        try:
            code = module.code_for_node(stmt)
        except RecursionError:
            return lines + len(stmt.leading_lines) + 1
        lines += code.count("\n")
    return None


def exported_operations(source: bytes | str, wanted: Collection[str],
                        settings: Settings) -> dict[str, list[Operation]]:
    """The operations of the ``wanted`` description classes of a module that convert.

    Another file deriving from one of them inlines these when it calls the base's
    ``createDescription`` (see ``ezmigrate.project.cross_file``).
    """
    tree, known, refused = _python_reading(source, "")
    if refused is not None:  # Python 2: nothing converts
        return {}
    for text, _, origin in _readings(source, tree, known, settings):  # nothing to fill back
        try:
            module = cst.parse_module(text)
        except (cst.ParserSyntaxError, UnicodeDecodeError, LookupError, SyntaxError):
            continue  # as ``migrate``: the next reading, the whole file, if any is left
        try:
            facts = known if known is not None else _syntax_facts(module, origin)
            planned = _plan_module(module, facts, settings) \
                if isinstance(facts, SyntaxFacts) else None
        except (RecursionError, MemoryError):  # its own migration reports the file
            return {}
        if planned is None:
            return {}
        plans, effective, _ = planned
        ok = {p.cls.name for p in plans if p.result.status in ("converted", "unchanged")}
        return {name: effective[name] for name in wanted if name in ok and name in effective}
    return {}


def foreign_bases(module: cst.Module, names: LegacyNames) -> list[tuple[str, str]]:
    """``(base, imported-from module)`` for class bases imported from user modules.

    Candidates for descriptions defined in another file of the same package; the module
    is written with its leading dots for relative imports (``".base"``). ``base`` is spelled
    as the import spells it: ``"Navigate"``, or ``"Navigate as Nav2"`` when the class derives
    from an alias (the sibling defines ``Navigate``; this module's classes name ``Nav2``).
    """
    imported: dict[str, tuple[str, str]] = {}
    for stmt in module.body:
        if not isinstance(stmt, cst.SimpleStatementLine):
            continue
        for small in stmt.body:
            if isinstance(small, cst.ImportFrom) and not isinstance(small.names, cst.ImportStar):
                source = "." * len(small.relative) + (
                    dotted_name(small.module) or "" if small.module is not None else "")
                if small.relative or not is_legacy_module(source):
                    for alias in small.names:
                        if not isinstance(alias.name, cst.Name):
                            continue
                        name = alias.name.value
                        local = alias.asname.name if alias.asname is not None else None
                        if isinstance(local, cst.Name) and local.value != name:
                            imported[local.value] = (f"{name} as {local.value}", source)
                        elif local is None or isinstance(local, cst.Name):
                            imported[name] = (name, source)
    found = []
    for stmt in module.body:
        if isinstance(stmt, cst.ClassDef):
            for arg in stmt.bases:
                if isinstance(arg.value, cst.Name) and arg.value.value in imported:
                    found.append(imported[arg.value.value])
    return found


def _plan(cls: DescriptionClass, facts: ClassFacts, shared: _ModulePlanning) -> _Plan:
    module, settings, effective = shared.module, shared.settings, shared.effective
    line_no = facts.line
    plan = _Plan(cls, SkillResult(cls.name, line_no, "skipped"))
    func = find_create_description(cls.node)
    plan.old_function, plan.create = func, facts.create
    class_lines = StatementLines(module, cls.node.body, facts.spans)
    try:
        if cls.name in settings.held:
            raise Unsupported(settings.held[cls.name])
        if cls.kept is not None:
            raise Unsupported(cls.kept)
        bindings = class_bindings(cls.node)
        _check_bindings(cls, bindings, class_lines)
        if cls.other_bases:
            raise Unsupported(f"{cls.name} derives from several classes; a migration could "
                              "change its method resolution order")
        if cls.base is not None and cls.base not in shared.converted \
                and not cls.migrated_base:
            raise Unsupported(f"its base class {cls.base} was not converted")
        if func is None:
            effective[cls.name] = effective.get(cls.base or "", []) if cls.base else []
            model = replay(cls.name, effective[cls.name])
            plan.result = replace(plan.result, model=model.to_json(),
                                  status="converted" if cls.base is None else "unchanged")
            return plan
        skill = ExtractedSkill(cls.name, line_no)
        create = plan.create
        assert create is not None  # both parsers see the same class body
        lines = StatementLines(module, func.body, create.spans)
        ctx = ExtractContext(module=module, names=shared.names, lines=lines, skill=skill,
                             rules=CONSTRUCTS, constants=shared.constants,
                             self_name=self_parameter(func), class_name=cls.name,
                             class_names=frozenset(n for n, _ in bindings),
                             base_names=[cls.base] if cls.base else [],
                             parent_operations=lambda base: _parent_operations(cls, base,
                                                                               effective))
        read_operations(func, create.bound, ctx)
        params = emitted_params(skill)
        model = checked_model(cls.name, skill.operations, params)
        emit = EmitContext(index=settings.index, rules=CONSTRUCTS, self_name=ctx.self_name,
                           aliases=shared.aliases,
                           reserved=_reserved(skill, settings.index, ctx.self_name),
                           column=create.column + 4, target=settings.target,
                           quotes=quote_style(cls.node))
        plan.new_function = build_description(func, skill, params, emit,
                                              module.config_for_parsing)
        effective[cls.name] = skill.operations
        plan.operations = skill.operations
        plan.result = replace(
            plan.result, status="converted", model=model.to_json(),
            static=static_description(skill),
            findings=skill.findings + skill_findings(model, settings.index,
                                                     skill.source_lines()))
        plan.runtime, plan.prefixes = emit.runtime_names, emit.prefixes
    except Unsupported as unsupported:
        plan.result = replace(plan.result, status="skipped", reason=unsupported.reason)
    except RecursionError:  # a problem with the file, not this skill: ``migrate`` says so
        raise
    except Exception as error:  # the legacy backend rejects what SkiROS2 rejects
        reason = f"SkiROS2 would reject this description: {error}"
        if not isinstance(error, (ValueError, TypeError, KeyError)):
            reason += "\n" + traceback.format_exc(limit=3)
        plan.result = replace(plan.result, status="skipped", reason=reason)
    return plan


def _parent_operations(cls: DescriptionClass, base: str,
                       effective: Mapping[str, list[Operation]]) -> list[Operation]:
    """What a call to ``base``'s ``createDescription`` declares, for inlining into ``cls``.

    A base that an earlier run already migrated has only its EzSkiROS form left, which
    ezmigrate does not read back: the child cannot be converted automatically.
    """
    if cls.migrated_base and base == cls.base:
        raise Unsupported(f"it calls createDescription of its base class {base}, which is "
                          "already an EzSkiROS description (migrated by an earlier run); "
                          "ezmigrate cannot inline a migrated description: migrate "
                          f"{cls.name} by hand")
    return effective[base]


def _reserved(skill: ExtractedSkill, index: OntologyIndex | None, self_name: str) -> set[str]:
    """Names a parameter must not take because the new body of ``description`` uses them."""
    used = {node.value for op in skill.operations if isinstance(op, KeptStatement)
            for node in walk(op.node) if type(node) is cst.Name}
    prefixes = set(index.prefixes) if index is not None else set(DEFAULT_PREFIXES)
    return used | prefixes | {self_name, "abstract", "any_of"}


def _aliases(module: cst.Module, index: OntologyIndex | None) -> dict[str, str]:
    """Local names for our imports that would clash with names the module already binds."""
    taken = module_bindings(module) | {
        local for local, source in imported_names(module).items()
        if source not in (RUNTIME, ONTOLOGY) and not is_legacy_module(source)}
    prefixes = set(index.prefixes) if index is not None else set(DEFAULT_PREFIXES)
    aliases = {}
    for name in (DSL_NAMES - {"SkillDescription"}) | prefixes:
        if name in taken:
            aliases[name] = f"Ez{name}" if name[:1].isupper() else f"{name}_ns"
    return aliases


def _rewrite(module: cst.Module, converted: list[_Plan], base_name: str) -> cst.Module:
    """Swap base and method of every converted class (top-level statements, by identity)."""
    by_class = {id(p.cls.node): p for p in converted}
    body: list[cst.BaseStatement] = []
    for stmt in module.body:
        plan = by_class.get(id(stmt))
        if plan is not None:
            assert isinstance(stmt, cst.ClassDef)
            stmt = _convert_class(stmt, plan, base_name)
        body.append(stmt)
    return module.with_changes(body=body)


def _convert_class(node: cst.ClassDef, plan: _Plan, base_name: str) -> cst.ClassDef:
    bases = [arg.with_changes(value=cst.Name(base_name))
             if arg is plan.cls.base_arg and plan.cls.base is None else arg
             for arg in node.bases]
    body = node.body
    if plan.new_function is not None and isinstance(body, cst.IndentedBlock):
        body = body.with_changes(body=[
            plan.new_function if stmt is plan.old_function else stmt for stmt in body.body])
    return node.with_changes(bases=bases, body=body)


def _check_bindings(cls: DescriptionClass, bindings: list[tuple[str, cst.CSTNode]],
                    lines: StatementLines) -> None:
    """Refuse classes whose own names (``class_bindings``) the migrated method would
    collide with."""
    line = lines.line
    own = [node for name, node in bindings if name == "description"]
    if own:
        raise Unsupported(f"{cls.name} already defines `description` (line {line(own[0])}); "
                          "the migrated method would replace it (rename it, then migrate)")
    creates = [node for name, node in bindings if name == "createDescription"]
    if len(creates) > 1:
        raise Unsupported(f"createDescription is bound {len(creates)} times in {cls.name} "
                          f"(lines {', '.join(str(line(n)) for n in creates)}); keep the one "
                          "Python uses, the last, then migrate")
    if creates and not isinstance(creates[0], cst.FunctionDef):
        raise Unsupported(f"createDescription is assigned, not defined, in {cls.name} (line "
                          f"{line(creates[0])}); define it with `def`, then migrate")


def syntax_error_location(source: bytes | str, error: cst.ParserSyntaxError) -> tuple[str, int,
                                                                                        int]:
    """Message, line and 1-based column of a syntax error, as Python itself words it.

    libcst's native parser reports the token after the error (often on the next line);
    ``ast.parse`` (parsing only, nothing runs) points where a user looks.
    """
    raw = _raw(source)
    if b"\0" in raw:
        at = raw.index(b"\0")
        return ("a NUL byte (binary data, not Python source)", raw.count(b"\n", 0, at) + 1,
                at - (raw.rfind(b"\n", 0, at) + 1) + 1)
    try:
        ast.parse(source)
    except SyntaxError as py_error:
        if py_error.lineno:
            return py_error.msg, py_error.lineno, py_error.offset or 1
    except Exception:  # too deep, too big...: keep libcst's words
        pass
    match = re.match(r"(?:parser error: )?error at (\d+):(\d+): (.*)", error.message, re.S)
    if match:
        return match[3], int(match[1]), int(match[2]) + 1
    return error.message, error.raw_line, error.raw_column + 1


def decode_error_message(source: bytes | str, error: Exception) -> tuple[str, int | None]:
    """What to tell about a file that is not valid in its declared encoding, and the line."""
    raw = _raw(source)
    head = raw.removeprefix(b"\xef\xbb\xbf").split(b"\n", 2)[:2]
    cookie = next((n for n, text in enumerate(head, 1) if _COOKIE.match(text)), None)
    if isinstance(error, UnicodeDecodeError):
        bom = b"\xef\xbb\xbf"
        start = error.start + (len(bom) if raw.startswith(bom) else 0)
        line = raw.count(b"\n", 0, start) + 1
        column = start - (raw.rfind(b"\n", 0, start) + 1) + 1
        match = _COOKIE.match(head[cookie - 1]) if cookie else None
        encoding = match[1].decode("ascii", "replace") if match else "utf-8"
        hint = "" if cookie else (" (no coding line: Python reads the file as UTF-8; add one "
                                  "such as `# -*- coding: cp1252 -*-` if that is what the "
                                  "file uses)")
        byte = raw[start] if start < len(raw) else 0
        return (f"cannot decode: byte 0x{byte:02x} at line {line}, column {column} is not "
                f"valid {encoding}{hint}"), line
    return f"cannot decode: {error}" + (f" (line {cookie})" if cookie else ""), cookie


_COOKIE = re.compile(rb"^[ \t\f]*#.*?coding[:=][ \t]*([-\w.]+)")


def _python2_except(module: cst.Module, source: bytes | str) -> tuple[int, int] | None:
    """Line and column of a Python 2 ``except X, e:``, if any.

    libcst reads it as PEP 758's unparenthesised ``except A, B:`` (Python 3.14); in a
    SkiROS2 module it is Python 2 code that no supported Python can import.
    """
    raw = _raw(source)
    if not EXCEPT_COMMA.search(raw) or python_parses(raw):
        return None  # the common case: ``except (A, B):``, which Python itself accepts
    by_tokens = comma_handler(raw)
    return by_tokens if by_tokens is not None else _python2_except_in_tree(module)


def _python2_except_in_tree(module: cst.Module) -> tuple[int, int] | None:
    """``_python2_except`` by libcst's tree and its position pass."""
    found: list[cst.ExceptHandler] = []

    class _Handlers(cst.CSTVisitor):
        def visit_ExceptHandler(self, node: cst.ExceptHandler) -> None:
            if node.name is None and isinstance(node.type, cst.Tuple) and not node.type.lpar:
                found.append(node)

    wrapped, positions = positions_of(module)
    wrapped.visit(_Handlers())
    if not found:
        return None
    start = getattr(positions.get(found[0]), "start", None)
    return (start.line, start.column + 1) if start is not None else (0, 0)
