"""``check``'s cache of loaded EzSkiROS files, so that CI's second run costs a read.

Loading an EzSkiROS file (a child process imports it, traces its descriptions and runs the
runtime's checks) is most of what ``check`` spends on a migrated repository. The outcome of
a load depends on the file, on what it imports, on the ontology and on the interpreter, so
the key is all of them: the file's path and bytes, a digest of every Python file of the run
(a changed helper module changes every key: conservative, and still a full hit on the
unchanged repository CI checks again), the ontology's fingerprint, the interpreter and this
release. Like ``.ruff_cache``, the folder holds a ``.gitignore`` of its own, entries are
written whole (a temporary file renamed into place) and a damaged entry is a miss.
Timeouts and crashes are never cached: they say more about the machine than the file.
``--no-cache`` turns it off.
"""

from __future__ import annotations

import hashlib
import json
import os
import sys
import tempfile
from collections.abc import Callable, Iterable, Sequence
from pathlib import Path

from .. import __version__
from ..verify.protocol import LoadJob, LoadOutcome

FOLDER = ".ezmigrate_cache"
CACHED = frozenset({"ok", "import-error", "syntax", "exit"})
"""Statuses that depend on the file alone: cached. Timeouts, crashes and memory are not."""


class LoadCache:
    """Outcomes of loads by key, in ``folder`` (created on first write)."""

    def __init__(self, folder: Path, salt: str) -> None:
        self.folder = folder
        self.salt = salt
        self.hits = 0

    @classmethod
    def for_run(cls, folder: Path, sources: Iterable[tuple[str, bytes]], ontology: str,
                python: str | None) -> LoadCache:
        """A cache whose keys change with any Python file of the run, the ontology and the
        interpreter (``python``: None is this one)."""
        digest = hashlib.sha256()
        for path, data in sorted(sources):
            digest.update(path.encode() + b"\0" + hashlib.sha256(data).digest())
        salt = "\0".join([__version__, sys.version, python or sys.executable, ontology,
                          digest.hexdigest()])
        return cls(folder, salt)

    def key(self, job: LoadJob, data: bytes) -> str:
        return hashlib.sha256(
            "\0".join([self.salt, job.path, job.root or ""]).encode() + b"\0" + data
        ).hexdigest()

    def get(self, key: str) -> LoadOutcome | None:
        try:
            data = json.loads((self.folder / key[:2] / f"{key}.json").read_text("utf-8"))
            outcome = LoadOutcome.from_json(data)
        except (OSError, ValueError, TypeError, KeyError):
            return None
        self.hits += 1
        return outcome

    def put(self, key: str, outcome: LoadOutcome) -> None:
        if outcome.status not in CACHED:
            return
        write_entry(self.folder, key[:2], f"{key}.json", json.dumps(outcome.to_json()))


def write_entry(cache: Path, folder: str, name: str, text: str) -> None:
    """``cache/folder/name`` holding ``text``, written whole (a temporary file renamed into
    place); the cache folder gets its ``.gitignore`` when it is made. A read-only checkout
    keeps nothing: same results, no cache."""
    try:
        if not cache.exists():
            cache.mkdir(parents=True)
            (cache / ".gitignore").write_text("# made by ezmigrate check\n*\n")
        (cache / folder).mkdir(exist_ok=True)
        handle, temporary = tempfile.mkstemp(dir=cache / folder, suffix=".tmp")
        with os.fdopen(handle, "w", encoding="utf-8") as stream:
            stream.write(text)
        os.replace(temporary, cache / folder / name)
    except OSError:
        return


def cached_loads(jobs: Sequence[LoadJob], sources: Sequence[bytes],
                 load: Callable[[list[LoadJob]], list[LoadOutcome]],
                 cache: LoadCache | None) -> list[LoadOutcome]:
    """The outcome of each job: from ``cache`` when it has it, else by ``load`` (the
    misses together, in one batch of workers), stored for the next run."""
    if cache is None:
        return load(list(jobs)) if jobs else []
    keys = [cache.key(job, data) for job, data in zip(jobs, sources, strict=True)]
    outcomes: list[LoadOutcome | None] = [cache.get(key) for key in keys]
    missing = [i for i, outcome in enumerate(outcomes) if outcome is None]
    if missing:
        for i, outcome in zip(missing, load([jobs[i] for i in missing]), strict=True):
            outcomes[i] = outcome
            cache.put(keys[i], outcome)
    return [outcome for outcome in outcomes if outcome is not None]
