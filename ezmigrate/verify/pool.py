"""A pool of zygote workers (``zygote.py``), fed from one queue by one thread each.

A worker that dies (killed, crashed interpreter) is replaced and its job is answered with a
``crashed`` outcome, so one hostile file never stops the run. The main process only
spawns workers with ``subprocess`` (fork+exec), so its own threads are safe.
"""

from __future__ import annotations

import contextlib
import json
import os
import queue
import signal
import subprocess
import sys
import tempfile
import threading
import time
from collections.abc import Callable, Sequence
from dataclasses import replace
from pathlib import Path
from typing import IO

from .interpreters import (
    NO_NEWER_PYTHON,
    describe,
    is_foreign,
    oldest_that_compiles,
    worker_command,
)
from .pool_config import PoolConfig
from .protocol import QUIT, LoadJob, LoadOutcome
from .sandbox import hidden_folders, private_home, say_if_not_held, worker_environment


class _Stopped(Exception):
    """The pool is stopping: no new worker starts."""


class _NotStarted(RuntimeError):
    """A worker exited before it was ready (an interpreter without a module it needs): the
    message says which interpreter and the last line it wrote."""


class _Crew:
    """Every worker process the pool started, so that an interrupt or an error stops all.

    A worker told to stop (SIGTERM) kills its current child's whole process group before it
    exits (``zygote.run_job``); a worker that does not exit in time is killed.
    """

    GRACE = 5.0
    """Seconds a worker gets to kill its child and exit before it is killed itself."""

    def __init__(self) -> None:
        self.lock = threading.Lock()
        self.processes: list[subprocess.Popen[str]] = []
        self.stopping = False

    def spawn(self, args: list[str], errors: IO[bytes],
              env: dict[str, str] | None = None) -> subprocess.Popen[str]:
        """Start a worker writing its own errors (not its loads') to ``errors``."""
        with self.lock:  # a worker is either recorded here or never started
            if self.stopping:
                raise _Stopped
            say_if_not_held()
            process = subprocess.Popen(args, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                       stderr=errors, text=True, bufsize=1,
                                       env=worker_environment(env or os.environ, private_home()))
            self.processes.append(process)
            return process

    def stop(self) -> None:
        """Stop every worker (and so their children); never raises."""
        with self.lock:
            self.stopping = True
            processes = list(self.processes)
        for process in processes:
            with contextlib.suppress(OSError):
                process.send_signal(signal.SIGTERM)
        deadline = time.monotonic() + self.GRACE
        for process in processes:
            try:
                process.wait(timeout=max(0.0, deadline - time.monotonic()))
            except subprocess.TimeoutExpired:
                with contextlib.suppress(OSError):
                    process.kill()
                    process.wait()


ZYGOTE = "ezmigrate.verify.zygote"


class _Worker:
    """One zygote (``zygote.py``), started and ready."""

    def __init__(self, config: PoolConfig, crew: _Crew) -> None:
        self.config = config
        command, env = [sys.executable, "-m", ZYGOTE], None
        if is_foreign(config.python):
            assert config.python is not None
            command, env = worker_command(config.python, ZYGOTE)
        args = [*command, "--timeout", str(config.timeout), "--memory-mb",
                str(config.memory_mb),
                *(f"--hide={folder}" for folder in hidden_folders(os.environ))]
        for path in config.ontology:
            args += ["--ontology", path]
        self.errors = tempfile.TemporaryFile()  # noqa: SIM115 (closed with the worker)
        self.process = crew.spawn(args, self.errors, env)
        self.wait_ready()

    def wait_ready(self) -> None:
        ready = self.process.stdout.readline() if self.process.stdout else ""
        if '"ready"' not in ready:
            self.kill()
            self.errors.seek(0)
            said = self.errors.read().decode("utf-8", "replace").strip().splitlines()
            self.errors.close()
            raise _NotStarted(f"the verification worker did not start under "
                              f"{self.config.python or sys.executable}"
                              + (f": {said[-1]}" if said else ""))

    def run(self, job: LoadJob) -> LoadOutcome | None:
        """The outcome, or ``None`` when the worker itself died."""
        assert self.process.stdin is not None and self.process.stdout is not None
        try:
            self.process.stdin.write(json.dumps(job.to_json()) + "\n")
            self.process.stdin.flush()
            line = self.process.stdout.readline()
        except (BrokenPipeError, OSError):
            return None
        if not line:
            return None
        return LoadOutcome.from_json(json.loads(line))

    def close(self) -> None:
        """Tell the worker to quit (``protocol.QUIT``), and wait for it (at most five seconds,
        then ``kill``)."""
        try:
            if self.process.stdin:
                with contextlib.suppress(OSError):
                    self.process.stdin.write(QUIT + "\n")
                    self.process.stdin.flush()
                self.process.stdin.close()
            self.process.wait(timeout=5)
        except (OSError, subprocess.TimeoutExpired):
            self.kill()
        self.errors.close()

    def kill(self) -> None:
        """End the worker now: one that never served (it runs no child), or one that did not
        quit when told. What it wrote to ``errors`` stays to be read."""
        with contextlib.suppress(OSError):
            self.process.kill()
        self.process.wait()
        for stream in (self.process.stdin, self.process.stdout):
            with contextlib.suppress(OSError):
                if stream is not None:
                    stream.close()


class Standby:
    """Workers started before their jobs are known, so that a run does not wait for them.

    A worker's start-up (an interpreter that loads the ontology and warms the loader) costs
    about 0.1 s of a core; ``check`` starts one in the background as soon as its static
    pass finds a compound skill to trace, and the pass goes on meanwhile. ``run_jobs(...,
    standby=)`` takes them before starting new ones; ``close`` stops those never taken. An
    interrupt stops them like any other worker (they share the run's crew).
    """

    def __init__(self, config: PoolConfig, count: int) -> None:
        self.config = config
        self.crew = _Crew()
        self._ready: queue.Queue[_Worker | None] = queue.Queue()
        self._threads = [threading.Thread(target=self._start, daemon=True)
                         for _ in range(max(1, count))]
        for thread in self._threads:
            thread.start()

    def _start(self) -> None:
        try:
            self._ready.put(_Worker(self.config, self.crew))
        except (_Stopped, RuntimeError, OSError):
            self._ready.put(None)

    def take(self) -> _Worker | None:
        """A started worker (waiting for one still starting), or None when none is left."""
        while any(t.is_alive() for t in self._threads) or not self._ready.empty():
            try:
                return self._ready.get(timeout=0.05)
            except queue.Empty:
                continue
        return None

    def close(self) -> None:
        """Stop the workers nobody took (an interrupt may have come before every thread
        was started: those have nothing to wait for)."""
        for thread in self._threads:
            if thread.ident is not None:
                thread.join()
        while not self._ready.empty():
            worker = self._ready.get_nowait()
            if worker is not None:
                worker.close()


def run_jobs(jobs: Sequence[LoadJob], config: PoolConfig,
             progress: Callable[[int, LoadOutcome], None] | None = None,
             standby: Standby | None = None) -> list[LoadOutcome]:
    """Run every job on the pool; outcomes in job order (``standby``: workers to use first).

    An interrupt or error while they run stops every worker and their children before it
    propagates: a module looping at import must not outlive the run until its timeout.
    """
    results: list[LoadOutcome | None] = [None] * len(jobs)
    todo: queue.Queue[int] = queue.Queue()
    for index in range(len(jobs)):
        todo.put(index)
    lock = threading.Lock()
    crew = standby.crew if standby is not None else _Crew()
    unstarted: list[str] = []  # why a worker did not start: the others would not either

    def serve() -> None:
        worker: _Worker | None = standby.take() if standby is not None else None
        try:
            while True:
                try:
                    index = todo.get_nowait()
                except queue.Empty:
                    return
                if worker is None and not unstarted:
                    try:
                        worker = _Worker(config, crew)
                    except _Stopped:
                        return
                    except _NotStarted as failure:
                        unstarted.append(str(failure))
                if worker is None:
                    with lock:
                        results[index] = LoadOutcome("crashed", unstarted[0])
                    continue
                outcome = worker.run(jobs[index])
                if outcome is None:  # the worker died: replace it, report this file
                    worker.close()
                    worker = None
                    outcome = LoadOutcome("crashed", "the verification worker died while "
                                          "loading this file")
                with lock:
                    results[index] = outcome
                    if progress is not None:
                        progress(index, outcome)
        finally:
            if worker is not None:
                worker.close()

    count = max(1, min(config.workers, len(jobs)))
    threads = [threading.Thread(target=serve, daemon=True) for _ in range(count)]
    try:
        for thread in threads:
            thread.start()
        for thread in threads:
            thread.join()
    except BaseException:  # Interrupted (a signal), KeyboardInterrupt, anything
        crew.stop()
        raise
    outcomes = [r if r is not None else LoadOutcome("crashed", "no result") for r in results]
    if is_foreign(config.python):
        for outcome in outcomes:
            outcome.python = describe(config.python or "")
    if not config.python_given:
        _retry_newer_syntax(jobs, outcomes, config)
    return outcomes


BATCH = 8
"""Loads one verification child does one after the other: a fork and a cold start for
eight files instead of one each; a file that hangs costs its batch one timeout, then the
batch is loaded again one file per child."""


def run_batched(jobs: Sequence[LoadJob], config: PoolConfig, size: int,
                standby: Standby | None = None,
                alone: Callable[[LoadOutcome], bool] = lambda outcome: False,
                ) -> list[LoadOutcome]:
    """``run_jobs`` with ``size`` consecutive jobs loaded one after the other in one child:
    one fork and one cold start per batch instead of one each (``LoadJob.more``; every load
    restores ``sys.modules``, so none sees another's modules).

    A batch is run again one job per child when it did not finish (a file hung or crashed
    its child: the verdict must land on the file that caused it), when a load failed on
    syntax newer than the worker's Python (``run_jobs`` retries those under a newer one),
    and when ``alone`` picks one of its outcomes (a failed load, whose captured output must
    be its own): every outcome that stands is exactly what a child of its own would say.
    """
    if size <= 1 or len(jobs) <= 1:
        return run_jobs(jobs, config, standby=standby)
    batches = [list(jobs[i:i + size]) for i in range(0, len(jobs), size)]
    firsts = run_jobs([replace(b[0], more=b[1:]) for b in batches], config, standby=standby)
    outcomes: list[LoadOutcome | None] = []
    for batch, first in zip(batches, firsts, strict=True):
        done = [replace(first, more=[]), *first.more]
        if len(done) != len(batch) or any(o.newer_syntax or alone(o) for o in done):
            outcomes += [None] * len(batch)
            continue
        for outcome in done:
            outcome.python = first.python  # the interpreter that ran the batch
            outcome.stdout = outcome.stderr = ""  # the batch's output is nobody's own
        outcomes += done
    again = [i for i, outcome in enumerate(outcomes) if outcome is None]
    for i, retried in zip(again, run_jobs([jobs[i] for i in again], config), strict=True):
        outcomes[i] = retried
    return [o if o is not None else LoadOutcome("crashed", "no result") for o in outcomes]


def _retry_newer_syntax(jobs: Sequence[LoadJob], outcomes: list[LoadOutcome],
                        config: PoolConfig) -> None:
    """Load again, under the oldest ``python3.X`` newer than the run's that compiles them,
    the files that failed on syntax newer than the run's Python; the outcomes say which
    interpreter loaded them."""
    again = [i for i, outcome in enumerate(outcomes) if _newer_syntax(outcome, jobs[i], config)]
    if not again:
        return
    sources = [jobs[i].source if jobs[i].source is not None else Path(jobs[i].path).read_bytes()
               for i in again]
    python = oldest_that_compiles([s for s in sources if s is not None], config.python)
    if python is None:
        for i in again:
            outcomes[i] = replace(outcomes[i], message=f"{outcomes[i].message} "
                                                       f"({NO_NEWER_PYTHON})")
        return
    try:
        retried = run_jobs([jobs[i] for i in again],
                           replace(config, python=python, python_given=True))
    except RuntimeError:  # its worker could not start there (no cached index): as it was
        return
    for i, outcome in zip(again, retried, strict=True):
        if outcome.status != "crashed":  # a worker that died there proves nothing
            outcomes[i] = outcome


def _newer_syntax(outcome: LoadOutcome, job: LoadJob, config: PoolConfig) -> bool:
    """Whether the load failed on syntax newer than the interpreter that ran it. Our own
    worker says so (``newer_syntax``); another interpreter's has no libcst for a second
    opinion, so a syntax error there counts when libcst, here, reads the file."""
    if outcome.newer_syntax:
        return True
    if not (is_foreign(config.python) and outcome.status == "syntax"):
        return False
    import libcst

    try:
        libcst.parse_module(job.source if job.source is not None
                            else Path(job.path).read_bytes())
    except Exception:  # invalid under every grammar libcst knows: no newer Python helps
        return False
    return True


def job_for(path: Path, source: bytes | None = None, root: Path | None = None,
            trace: tuple[str, ...] = ()) -> LoadJob:
    """A job for ``path`` (absolute), optionally importing ``source`` in its place, and
    tracing the compound skill classes named in ``trace``."""
    return LoadJob(str(path.absolute()), source, str(root.absolute()) if root else None,
                   trace=list(trace))
