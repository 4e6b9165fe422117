"""A pool of zygote workers (``zygote.py``), fed from one queue by one thread each.

A worker that dies (killed, crashed interpreter) is replaced and its job is answered with a
``crashed`` outcome, so one hostile file never stops the run. The main process only
spawns workers with ``subprocess`` (fork+exec), so its own threads are safe.
"""

from __future__ import annotations

import json
import queue
import subprocess
import sys
import threading
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

from .protocol import LoadJob, LoadOutcome


@dataclass(frozen=True)
class PoolConfig:
    """How verification workers run: count, per-file timeout, memory cap, ontology."""

    workers: int = 2
    timeout: float = 20.0
    memory_mb: int = 2048
    ontology: tuple[str, ...] = ()


class _Worker:
    def __init__(self, config: PoolConfig) -> None:
        self.config = config
        args = [sys.executable, "-m", "ezmigrate.verify.zygote", "--timeout",
                str(config.timeout), "--memory-mb", str(config.memory_mb)]
        for path in config.ontology:
            args += ["--ontology", path]
        self.process = subprocess.Popen(args, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                        stderr=subprocess.DEVNULL, text=True, bufsize=1)
        ready = self.process.stdout.readline() if self.process.stdout else ""
        if '"ready"' not in ready:
            raise RuntimeError("a verification worker failed to start")

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
        try:
            if self.process.stdin:
                self.process.stdin.close()
            self.process.wait(timeout=5)
        except (OSError, subprocess.TimeoutExpired):
            self.process.kill()
            self.process.wait()


def run_jobs(jobs: Sequence[LoadJob], config: PoolConfig,
             progress: Callable[[int, LoadOutcome], None] | None = None) -> list[LoadOutcome]:
    """Run every job on the pool; outcomes in job order."""
    results: list[LoadOutcome | None] = [None] * len(jobs)
    todo: queue.Queue[int] = queue.Queue()
    for index in range(len(jobs)):
        todo.put(index)
    lock = threading.Lock()

    def serve() -> None:
        worker: _Worker | None = None
        try:
            while True:
                try:
                    index = todo.get_nowait()
                except queue.Empty:
                    return
                if worker is None:
                    worker = _Worker(config)
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
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    return [r if r is not None else LoadOutcome("crashed", "no result") for r in results]


def job_for(path: Path, source: bytes | None = None, root: Path | None = None) -> LoadJob:
    """A job for ``path`` (absolute), optionally importing ``source`` in its place."""
    return LoadJob(str(path.absolute()), source, str(root.absolute()) if root else None)
