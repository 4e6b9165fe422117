"""Load a legacy (or EzSkiROS) skill file by importing it, and read its descriptions' models.

This is the *dynamic* side of verification (architecture.md): the file really runs, under
``legacy_imports`` so that SkiROS2 and ROS imports resolve without a robot. Running user code
has side effects; isolating them (child process, timeout) is the caller's job. What this module
guarantees is that the interpreter is left as it was found: the imported module, the package
parents and user siblings it pulled in are removed from ``sys.modules``, ``sys.path`` is
restored, and no ``__pycache__`` is written into the user's tree.

Description classes are those *defined* in the file (``cls.__module__`` is the module) that
derive from our ``SkillDescription`` but are not implementations (``SkillCore``: ``SkillBase``,
``PrimitiveBase``; legacy-skiros2-api.md §2). Each is instantiated with no arguments, as
SkiROS2 does; one failing class becomes a finding (``class_error``) and the others still load.
"""

from __future__ import annotations

import ast
import importlib
import importlib.util
import itertools
import linecache
import os
import re
import sys
import traceback
from collections.abc import Sequence
from dataclasses import dataclass, field
from importlib.abc import Loader
from importlib.machinery import ModuleSpec
from importlib.util import module_from_spec
from pathlib import Path
from types import CodeType, ModuleType, TracebackType
from typing import Any

from ..diagnostics import Finding, class_error
from ..model import SkillModel
from .abstract_skill import SkillCore, SkillDescription
from .errors import ModuleLoadError, NotDeclarativeError, NotUpstreamAPIError
from .extract import model_of
from .stand_ins import expected_stand_in, legacy_imports, library_roots

__all__ = ["FileLoad", "ModuleLoadError", "load_bytes", "load_file", "load_source"]

_counter = itertools.count(1)


@dataclass
class FileLoad:
    """What one file yielded: models in definition order, class errors, check findings."""

    path: Path
    models: list[SkillModel] = field(default_factory=list)
    errors: list[Finding] = field(default_factory=list)
    """The classes that could not be loaded (``class_error``), one finding each."""
    findings: list[Any] = field(default_factory=list)
    stood_in: list[str] = field(default_factory=list)
    """Modules that could not be found and got a permissive stand-in, ROS and SkiROS2 aside
    (``expected_stand_in``); a relative import of a file outside any package as ``.name``."""
    compounds: list[dict[str, Any]] = field(default_factory=list)
    """Traced compound skills (``load_bytes(trace=...)``): ``CompoundModel.to_json()``, or
    ``{"implementation", "unanalysable", "line"}``."""


class _CodeLoader(Loader):
    """Executes already compiled code: no bytecode cache is read or written."""

    def __init__(self, code: CodeType) -> None:
        self._code = code

    def create_module(self, spec: ModuleSpec) -> ModuleType | None:
        return None

    def exec_module(self, module: ModuleType) -> None:
        exec(self._code, module.__dict__)


# -- naming --------------------------------------------------------------------------------

def _package_layout(path: Path, root: Path | None) -> tuple[list[str], Path]:
    """Package names above ``path`` (folders with ``__init__.py``, outermost first) and the
    folder that must be on ``sys.path`` for them; ``root`` is the highest folder considered."""
    stop = root.resolve() if root is not None else None
    parts: list[str] = []
    folder = path.parent
    top: Path | None = None
    while (folder / "__init__.py").is_file() and folder.name.isidentifier():
        parts.append(folder.name)
        top = folder
        if folder.resolve() == stop or folder.parent == folder:
            break
        folder = folder.parent
    parts.reverse()
    return parts, (top.parent if top is not None else path.parent)


STANDALONE = "_ezmigrate_standalone_"
"""Prefix of the made-up package a file outside any package is loaded in: its relative
imports (``from .helpers import x``, "no known parent package" otherwise) then find the
sibling files, or a permissive stand-in when there is none, like any missing module."""


def _unique_name(path: Path) -> str:
    stem = re.sub(r"\W", "_", path.stem) or "module"
    if stem[0].isdigit():
        stem = f"_{stem}"
    return f"{STANDALONE}{next(_counter)}.{stem}"


def _module_name(path: Path, module_name: str | None, root: Path | None) -> tuple[str, Path]:
    """The name to import ``path`` under and the folder to put on ``sys.path``."""
    is_init = path.name == "__init__.py"
    if module_name is not None:
        depth = module_name.count(".") + (1 if is_init else 0)
        search = path.parent
        for _ in range(depth):
            search = search.parent
        return module_name, search
    packages, search = _package_layout(path, root)
    if not packages:
        return _unique_name(path), path.parent
    return ".".join(packages if is_init else [*packages, path.stem]), search


# -- locations -----------------------------------------------------------------------------

def _class_lines(tree: ast.Module) -> dict[str, list[ast.ClassDef]]:
    """Qualified class name -> its ``class`` statements (module level and nested in classes,
    also inside ``if``/``try``/``with`` blocks)."""
    found: dict[str, list[ast.ClassDef]] = {}

    def visit(body: list[ast.stmt], prefix: str) -> None:
        for node in body:
            if isinstance(node, ast.ClassDef):
                found.setdefault(prefix + node.name, []).append(node)
                visit(node.body, f"{prefix}{node.name}.")
            elif not isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                for attr in ("body", "orelse", "finalbody"):
                    visit(getattr(node, attr, []), prefix)
                for part in [*getattr(node, "handlers", []), *getattr(node, "cases", [])]:
                    visit(part.body, prefix)

    visit(tree.body, "")
    return found


def _class_line(cls: type, candidates: dict[str, list[ast.ClassDef]]) -> int | None:
    """The ``class`` line of ``cls``; with several same-named definitions, the one whose
    span holds one of the class's own functions."""
    nodes = candidates.get(cls.__qualname__, [])
    if len(nodes) > 1:
        own = [v.__code__.co_firstlineno for v in vars(cls).values() if hasattr(v, "__code__")]
        for node in nodes:
            if any(node.lineno <= ln <= (node.end_lineno or node.lineno) for ln in own):
                return node.lineno
    return nodes[-1].lineno if nodes else None


def _frame_line(tb: TracebackType | None, filename: str) -> int | None:
    """The line of the innermost traceback frame that runs code of ``filename``."""
    line = None
    for frame, lineno in traceback.walk_tb(tb):
        if frame.f_code.co_filename == filename:
            line = lineno
    return line


def _innermost_user_frame(tb: TracebackType | None) -> str | None:
    """``file:line`` of the innermost frame outside the libraries (for a failing sibling)."""
    roots = library_roots()
    where = None
    for frame, lineno in traceback.walk_tb(tb):
        name = frame.f_code.co_filename
        if not name.startswith("<") and not os.path.realpath(name).startswith(roots):
            where = f"{name}:{lineno}"
    return where


def _describe(exc: BaseException) -> str:
    return str(exc) or repr(exc)


# -- loading -------------------------------------------------------------------------------

def load_file(path: str | Path, *, module_name: str | None = None, root: Path | None = None,
              permissive: bool = True) -> FileLoad:
    """Import ``path`` and return the models of the description classes defined in it.

    A file inside a package (folders with ``__init__.py``, not above ``root``) is imported under
    its dotted name with the package root's parent on ``sys.path``, so relative imports of
    siblings work; any other file under a unique top-level name with its folder on
    ``sys.path``. Raises ``ModuleLoadError`` when the module itself cannot be imported.
    """
    file = Path(path).absolute()
    return _load(file, file.read_bytes(), module_name, root, permissive)


def load_source(text: str, filename: str | Path = "<legacy>", *,
                module_name: str | None = None, root: Path | None = None,
                permissive: bool = True) -> FileLoad:
    """Like ``load_file`` but from text (nothing is written); ``filename`` names the module in
    messages and decides the package layout when it points into an existing folder."""
    return _load(Path(filename).absolute(), text.encode("utf-8"), module_name, root, permissive)


def load_bytes(source: bytes, filename: str | Path, *, module_name: str | None = None,
               root: Path | None = None, permissive: bool = True,
               trace: Sequence[str] = (), collect: bool = True) -> FileLoad:
    """Like ``load_file`` with the file's bytes given (a rewrite not yet written to disk).

    Bytes, not text, so that a PEP 263 cookie or BOM in the source still decides decoding.
    ``trace`` names compound skill classes whose ``expand`` to run with recording stand-ins
    (``ezskiros_runtime.compound.trace``) while the module is loaded; ``compounds`` holds
    their trees (or why none could be read) as JSON-ready dicts. ``collect=False`` skips the
    descriptions' models and checks (a load for tracing alone).
    """
    return _load(Path(filename).absolute(), source, module_name, root, permissive, trace,
                 collect)


def _load(file: Path, source: bytes, module_name: str | None, root: Path | None,
          permissive: bool, trace: Sequence[str] = (), collect: bool = True) -> FileLoad:
    filename = str(file)
    name, search = _module_name(file, module_name, root)
    parents = [name.rsplit(".", i)[0] for i in range(name.count("."), 0, -1)]
    owned = [*parents, name]
    stashed = {n: sys.modules.pop(n) for n in owned if n in sys.modules}
    before = set(sys.modules)
    saved_path = list(sys.path)
    saved_bytecode = sys.dont_write_bytecode
    sys.dont_write_bytecode = True
    result = FileLoad(file)
    try:
        with legacy_imports(permissive=permissive) as stood_in:
            sys.path.insert(0, str(search))
            try:
                module = _import(file, filename, source, name, parents)
            except ModuleLoadError as error:
                raise _with_star_stand_ins(error, source, _worth_a_note(stood_in)) from \
                    error.__cause__
            finally:
                result.stood_in = _worth_a_note(stood_in)
            if collect:
                _collect(module, source, filename, result)
            result.compounds = [_traced(module, name, filename) for name in trace]
    finally:
        sys.path[:] = saved_path
        sys.dont_write_bytecode = saved_bytecode
        _forget_user_modules(before, owned, search)
        sys.modules.update(stashed)
    return result


def _traced(module: ModuleType, name: str, filename: str) -> dict[str, Any]:
    """The tree of compound class ``name`` of ``module``, traced, as JSON-ready data."""
    from ..compound.trace import Unanalysable, trace

    cls = getattr(module, name, None)
    if not isinstance(cls, type):
        return {"implementation": name, "line": 0,
                "unanalysable": f"the module has no class {name} once loaded"}
    found = trace(cls, path=filename)
    if isinstance(found, Unanalysable):
        return {"implementation": name, "line": found.line, "unanalysable": found.reason}
    return found.to_json()


def _with_star_stand_ins(error: ModuleLoadError, source: bytes,
                         stood_in: list[str]) -> ModuleLoadError:
    """A ``NameError`` in a file that star-imports a stood-in module: the name probably
    came from there, so say which module could not be found."""
    if error.exc_type != "NameError" or not stood_in:
        return error
    starred = [n for n in stood_in if re.search(
        rb"from\s+" + re.escape(n.encode()) + rb"\s+import\s+\*", source)]
    if not starred:
        return error
    return ModuleLoadError(error.path, error.line, error.exc_type, error.message + (
        f" (perhaps from {', '.join(starred)}, imported with * but not found: it was stood "
        "in, and a stand-in provides no names to a star import; give its folder too)"),
        error.origin)


def _worth_a_note(stood_in: list[str]) -> list[str]:
    """The stood-in modules a reader should hear of, as the file spelled them."""
    shown = []
    for name in stood_in:
        if name.startswith(STANDALONE):
            name = "." + name.partition(".")[2]
        if name and not expected_stand_in(name.lstrip(".")):
            shown.append(name)
    return sorted(set(shown))


def _remember_source(filename: str, source: bytes) -> None:
    """Make source lookups (``inspect``, tracebacks) see the bytes that were loaded.

    Verification loads a rewrite before it is written: the file on disk still holds the
    legacy code, and ``inspect.getsourcelines`` would tokenize the wrong lines (a
    ``TokenError`` in a long banner or docstring). A ``linecache`` entry without mtime is
    never checked against the disk."""
    text = importlib.util.decode_source(source)
    linecache.cache[filename] = (len(text), None, text.splitlines(True), filename)


def _import(file: Path, filename: str, source: bytes, name: str,
            parents: list[str]) -> ModuleType:
    try:
        for parent in parents:
            if parent.startswith(STANDALONE):
                package = ModuleType(parent)
                package.__path__ = [str(file.parent)]
                package.__package__ = parent
                sys.modules[parent] = package
            else:
                importlib.import_module(parent)
        code = compile(source, filename, "exec", dont_inherit=True)
        _remember_source(filename, source)
        spec = ModuleSpec(name, _CodeLoader(code), origin=filename,
                          is_package=file.name == "__init__.py")
        spec.has_location = True
        if spec.submodule_search_locations is not None:
            spec.submodule_search_locations.append(str(file.parent))
        module = module_from_spec(spec)
        sys.modules[name] = module
        if parents:
            setattr(sys.modules[parents[-1]], name.rpartition(".")[2], module)
        spec.loader.exec_module(module)  # type: ignore[union-attr]
        return module
    except (Exception, SystemExit) as exc:
        tb = exc.__traceback__
        line = _frame_line(tb, filename)
        if isinstance(exc, SyntaxError) and exc.filename == filename:
            line = exc.lineno
        origin = _innermost_user_frame(tb)
        if origin is not None and origin == f"{filename}:{line}":
            origin = None
        raise ModuleLoadError(filename, line, type(exc).__name__, _describe(exc),
                              origin) from exc


def _error_kind(exc: BaseException) -> str:
    if isinstance(exc, NotUpstreamAPIError):
        return "not-upstream-api"
    if isinstance(exc, NotDeclarativeError):
        return "not-declarative"
    return "description"


def _description_classes(module: ModuleType) -> list[type[SkillDescription]]:
    seen: dict[int, type[SkillDescription]] = {}
    for value in list(vars(module).values()):
        if (isinstance(value, type) and value.__module__ == module.__name__
                and issubclass(value, SkillDescription) and not issubclass(value, SkillCore)):
            seen.setdefault(id(value), value)
    return list(seen.values())


def _collect(module: ModuleType, source: bytes, filename: str, result: FileLoad) -> None:
    try:
        lines = _class_lines(ast.parse(source, filename))
    except SyntaxError:  # compiled fine, so this cannot happen; keep going without lines
        lines = {}
    for cls in _description_classes(module):
        line = _class_line(cls, lines)
        try:
            instance = cls()
        except (Exception, SystemExit) as exc:
            result.errors.append(_class_error(cls, line, exc, filename))
            continue
        result.findings.extend(getattr(instance, "findings", None) or [])
        try:
            result.models.append(model_of(instance).with_location(filename, line))
        except Exception as exc:
            result.errors.append(_class_error(cls, line, exc, filename))


def _class_error(cls: type, line: int | None, exc: BaseException, filename: str) -> Finding:
    raised_at = _frame_line(exc.__traceback__, filename)
    where = f" (line {raised_at})" if raised_at is not None else ""
    return class_error(cls.__name__, line, f"{type(exc).__name__}: {_describe(exc)}{where}",
                       filename, _error_kind(exc))


def _forget_user_modules(before: set[str], owned: list[str], search: Path) -> None:
    """Drop the loaded module, its package parents and the user modules it imported (new
    modules whose file lies under ``search`` and outside the libraries); real third-party
    modules stay, since C extensions cannot be imported twice."""
    folder = os.path.join(os.path.realpath(search), "")
    roots = library_roots()
    for name in [n for n in sys.modules if n not in before]:
        module = sys.modules[name]
        file = getattr(module, "__file__", None)
        real = os.path.realpath(file) if isinstance(file, str) else ""
        if name in owned or (real.startswith(folder) and not real.startswith(roots)):
            del sys.modules[name]
