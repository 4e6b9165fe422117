"""A reusable verification worker: warm once, then fork one isolated child per file.

Started as ``python -m ezmigrate.verify.zygote``; it imports the runtime and loads the
ontology once, then reads load jobs as JSON lines on stdin and answers each with one JSON
line on stdout. Every job runs in a forked child (per-file isolation: the user's module
never touches the worker's state), killed when it exceeds the timeout. Forking a warm
process costs milliseconds where a fresh interpreter costs a third of a second.
"""

from __future__ import annotations

import argparse
import json
import os
import select
import signal
import sys
import tempfile
import time
from pathlib import Path

from .child import run_child
from .protocol import LoadJob, LoadOutcome


def _wait(pid: int, timeout: float) -> int | None:
    """The child's wait status, or ``None`` if it was still running at the timeout."""
    deadline = time.monotonic() + timeout
    pidfd = None
    if hasattr(os, "pidfd_open"):
        try:
            pidfd = os.pidfd_open(pid)
        except OSError:
            pidfd = None
    try:
        while True:
            done, status = os.waitpid(pid, os.WNOHANG)
            if done:
                return status
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                return None
            if pidfd is not None:
                select.select([pidfd], [], [], remaining)
            else:
                time.sleep(min(remaining, 0.002))
    finally:
        if pidfd is not None:
            os.close(pidfd)


def run_job(job: LoadJob, timeout: float, memory_bytes: int | None) -> LoadOutcome:
    """Fork a child for ``job``, wait for it, and read what it reported."""
    with tempfile.TemporaryDirectory(prefix="ezmigrate-") as scratch:
        result = os.path.join(scratch, "result.json")
        out = os.path.join(scratch, "stdout")
        err = os.path.join(scratch, "stderr")
        sys.stdout.flush()
        sys.stderr.flush()
        started = time.perf_counter()
        pid = os.fork()
        if pid == 0:  # the child never returns from here
            run_child(job, result, out, err, memory_bytes)
        status = _wait(pid, timeout)
        if status is None:
            os.kill(pid, signal.SIGKILL)
            os.waitpid(pid, 0)
            outcome = LoadOutcome("timeout", f"loading took longer than {timeout:g} s and "
                                  "was stopped")
        else:
            outcome = _read(result, status)
        outcome.stdout = _tail(out)
        outcome.stderr = _tail(err)
        outcome.seconds = time.perf_counter() - started
        return outcome


def _read(result: str, status: int) -> LoadOutcome:
    if os.path.exists(result):
        with open(result, encoding="utf-8") as handle:
            return LoadOutcome.from_json(json.load(handle))
    if os.WIFSIGNALED(status):
        signame = signal.Signals(os.WTERMSIG(status)).name
        return LoadOutcome("crashed", f"the loading process was killed by {signame}")
    code = os.WEXITSTATUS(status)
    return LoadOutcome("exit", f"the loading process exited with code {code} before "
                       "reporting (os._exit in the module?)")


def _tail(path: str, limit: int = 20_000) -> str:
    """Captured output, its end kept when long (the report shows it, it must stay small)."""
    try:
        data = Path(path).read_bytes()
    except OSError:
        return ""
    text = data.decode("utf-8", errors="replace")
    return text if len(text) <= limit else "...\n" + text[-limit:]


def main(argv: list[str] | None = None) -> int:
    """Serve jobs until stdin closes."""
    parser = argparse.ArgumentParser(prog="ezmigrate.verify.zygote")
    parser.add_argument("--ontology", action="append", default=[])
    parser.add_argument("--timeout", type=float, default=20.0)
    parser.add_argument("--memory-mb", type=int, default=2048)
    args = parser.parse_args(argv)
    os.environ["EZSKIROS_BACKEND"] = "legacy"
    from ezskiros_runtime.ontology.active import use_ontology
    from ezskiros_runtime.ontology.index import load_index

    use_ontology(load_index(args.ontology or None))
    import ezskiros_runtime  # noqa: F401  (warm imports shared with every child)
    import ezskiros_runtime.legacy.loader  # noqa: F401

    protocol_out = os.fdopen(os.dup(1), "w", encoding="utf-8")
    os.dup2(2, 1)  # stray prints of ours must never corrupt the protocol
    print(json.dumps({"ready": True}), file=protocol_out, flush=True)
    memory = args.memory_mb * 1024 * 1024 if args.memory_mb > 0 else None
    for line in sys.stdin:
        if not line.strip():
            continue
        job = LoadJob.from_json(json.loads(line))
        outcome = run_job(job, args.timeout, memory)
        print(json.dumps(outcome.to_json()), file=protocol_out, flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
