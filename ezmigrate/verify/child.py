"""Inside the forked child: isolate, import one file, report its models, and exit.

The child closes stdin, captures stdout and stderr into files, limits its address space,
loads the file under the legacy import stand-ins with EzSkiROS checks only collected (a
latent type error in a skill is a finding, not a failed load), writes the outcome as JSON,
and leaves with ``os._exit`` so that nothing of the parent's state (buffers, atexit hooks)
runs twice.
"""

from __future__ import annotations

import contextlib
import json
import os
import resource
import signal
import sys
import time
import traceback
from pathlib import Path

from .overlay import overlaid
from .protocol import LoadJob, LoadOutcome, Status, compound_of

NEWER_SYNTAX = "cannot import under Python"
"""How a load that failed on syntax newer than this Python begins its message."""

OUTPUT_LIMIT = 64 * 1024 * 1024
"""Largest file the child may write (its captured output included): a module that prints
without end fills no disk before the timeout; past it a write fails with EFBIG."""


def isolate(stdout_path: str, stderr_path: str, memory_bytes: int | None) -> None:
    """Redirect the standard streams and cap resources, at the file-descriptor level.

    stdin reads nothing (``/dev/null``); stdout and stderr go to files the worker reads
    back; every other inherited descriptor (the worker's protocol pipe among them) is
    closed, so the user's module cannot corrupt or read the conversation with the worker.
    Limits: address space (``memory_bytes``), file size (``OUTPUT_LIMIT``), no core dumps.
    """
    devnull = os.open(os.devnull, os.O_RDONLY)
    os.dup2(devnull, 0)
    for fd, target in ((1, stdout_path), (2, stderr_path)):
        handle = os.open(target, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600)
        os.dup2(handle, fd)
        os.close(handle)
    os.closerange(3, _max_fd())
    sys.stdin = open(os.devnull)  # noqa: SIM115  (lives until the child exits)
    limits = [(resource.RLIMIT_CORE, 0), (resource.RLIMIT_FSIZE, OUTPUT_LIMIT)]
    if memory_bytes:
        limits.append((resource.RLIMIT_AS, memory_bytes))
    for kind, value in limits:
        with contextlib.suppress(ValueError, OSError):
            hard = resource.getrlimit(kind)[1]
            if hard != resource.RLIM_INFINITY:
                value = min(value, hard)
            resource.setrlimit(kind, (value, value))
    with contextlib.suppress(ValueError, OSError):
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)  # EFBIG instead of a killed child


def _max_fd() -> int:
    try:
        return min(int(os.sysconf("SC_OPEN_MAX")), 1 << 20)
    except (ValueError, OSError):
        return 4096


def load(job: LoadJob) -> LoadOutcome:
    """Import the job's file, then those of ``job.more`` one by one (each load restores
    ``sys.modules``), and turn whatever happens into outcomes (never raises)."""
    outcome = _load_one(job)
    outcome.more = [_load_one(other) for other in job.more]
    return outcome


_RECORDING: list[list[str]] = []
"""The files the load under way has opened (one list while a load runs, none otherwise:
the worker's own files, between loads, are nobody's)."""
_WATCHED: list[bool] = []


def _watch_opens() -> None:
    """Note every file a load opens (Python's ``open`` audit event: imports through
    ``importlib`` and data files alike), but the interpreter's and libraries' own: what a
    kept load depends on besides the file (``load_cache``). Installed once per process
    (an audit hook cannot be removed); it notes nothing outside a load."""
    if _WATCHED:
        return
    _WATCHED.append(True)
    skipped = tuple(os.path.join(os.path.realpath(p), "") for p in
                    {sys.prefix, sys.base_prefix, sys.exec_prefix}
                    | {str(Path(__file__).resolve().parents[2])})

    def hook(event: str, args: tuple) -> None:  # type: ignore[type-arg,unused-ignore]
        if event == "open" and _RECORDING and isinstance(args[0], (str, bytes, os.PathLike)) \
                and (len(args) < 2 or args[1] is None or "r" in str(args[1])):
            path = os.path.realpath(os.fsdecode(args[0]))
            if not path.startswith(skipped) and os.path.isfile(path):
                _RECORDING[0].append(path)

    sys.addaudithook(hook)


def _load_one(job: LoadJob) -> LoadOutcome:
    """``load`` for one file, with the files it opened noted in the outcome (``read``)."""
    _watch_opens()
    _RECORDING[:] = [[]]
    try:
        outcome = _loaded(job)
    finally:
        opened, _RECORDING[:] = _RECORDING[0], []
    outcome.read = [p for p in dict.fromkeys(opened) if p != os.path.realpath(job.path)]
    return outcome


def _loaded(job: LoadJob) -> LoadOutcome:
    """What loading the job's file gives."""
    from ezskiros_runtime.diagnostics import Finding
    from ezskiros_runtime.dsl.policy import collecting
    from ezskiros_runtime.legacy.errors import ModuleLoadError
    from ezskiros_runtime.legacy.loader import load_bytes

    started = time.perf_counter()
    path = Path(job.path)
    try:
        source = job.source if job.source is not None else path.read_bytes()
        with collecting(), overlaid(job.overlays):
            result = load_bytes(source, path, root=Path(job.root) if job.root else None,
                                trace=job.trace, collect=job.collect)
    except SystemExit as stop:
        return LoadOutcome("exit", f"the module called sys.exit({stop.code!r}) while loading")
    except MemoryError:
        return LoadOutcome("memory", "the module ran out of memory while loading")
    except ModuleLoadError as error:
        status: Status = "syntax" if isinstance(error.__cause__, SyntaxError) \
            else "import-error"
        message, line = str(error), getattr(error, "line", None)
        cause = error.__cause__
        newer = False
        if isinstance(cause, SyntaxError):
            message, line, newer = syntax_message(cause, source, path, message, line)
        return LoadOutcome(status, message, line, newer_syntax=newer)
    except Exception as error:  # a loader bug still gives a verdict for this file only
        traceback.print_exc(limit=8)  # into the captured stderr, not into the message
        first = (str(error).splitlines() or [""])[0]
        return LoadOutcome("import-error", f"{type(error).__name__}: {first} (an internal "
                           "error while loading; its traceback is in the captured stderr)")
    return LoadOutcome(
        "ok",
        models=[m.to_json() for m in result.models], errors=list(result.errors),
        findings=[f for f in result.findings if isinstance(f, Finding)],
        seconds=time.perf_counter() - started, stood_in=result.stood_in,
        compounds=[compound_of(c) for c in result.compounds])


def syntax_message(error: SyntaxError, source: bytes, path: Path, message: str,
                   line: int | None) -> tuple[str, int | None, bool]:
    """Why a file does not compile, the line to report, and whether the syntax is only
    newer than this Python's.

    "cannot import under Python 3.11" only when the syntax is newer than this Python: libcst
    (which knows newer grammars) parses the file and Python's own parser does not. A Python 2
    file, a NUL byte or a truncated file is plain invalid syntax, reported at its line and
    column (a NUL byte's SyntaxError carries no position: it is found in the bytes).
    """
    try:
        import libcst
    except ImportError:  # under another interpreter (--python): no libcst, no second opinion
        return f"SyntaxError in {path.name} at line {error.lineno}: {error.msg}", line, False
    data = source
    if error.filename and Path(error.filename) != path:  # raised in a module it imports
        with contextlib.suppress(OSError):
            data = Path(error.filename).read_bytes()
    try:
        libcst.parse_module(data)
    except Exception:  # any parser failure: the syntax is simply invalid
        pass
    else:
        version = f"{sys.version_info.major}.{sys.version_info.minor}"
        return f"{NEWER_SYNTAX} {version}: {message}", line, True
    row, column = error.lineno, error.offset
    if row is None and b"\0" in data:
        before = data[:data.index(b"\0")]
        row, column = before.count(b"\n") + 1, len(before) - (before.rfind(b"\n") + 1) + 1
    where = f"line {row}, column {column}" if row is not None and column is not None \
        else f"line {row}" if row is not None else "unknown position"
    name = Path(error.filename).name if error.filename else path.name
    return (f"SyntaxError in {name} at {where}: {error.msg}",
            line if line is not None else row, False)


def run_child(job: LoadJob, result_path: str, stdout_path: str, stderr_path: str,
              memory_bytes: int | None) -> None:
    """The whole life of a forked child; ends the process."""
    code = 0
    try:
        isolate(stdout_path, stderr_path, memory_bytes)
        outcome = load(job)
        with open(result_path, "w", encoding="utf-8") as handle:
            json.dump(outcome.to_json(), handle)
    except BaseException:  # the child must always reach os._exit
        code = 70
    finally:
        try:
            sys.stdout.flush()
            sys.stderr.flush()
        finally:
            os._exit(code)
