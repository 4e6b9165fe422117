"""``check``'s cache of loaded EzSkiROS files, so that CI's second run costs a read.

Loading an EzSkiROS file (a child process imports it, traces its descriptions and runs the
runtime's checks) is most of what ``check`` spends on a migrated repository. The outcome of
a load depends on the file, on what it imports, on the ontology and on the interpreter, so
the key is all of them: the file's path and bytes, the bytes of every Python file of the run
it may import (``_Imports``: a changed helper module changes the keys of the files that
import it, and no other), the ontology's fingerprint, the interpreter and this release.
Like ``.ruff_cache``, the folder holds a ``.gitignore`` of its own, entries are
written whole (a temporary file renamed into place) and a damaged entry is a miss.
Timeouts and crashes are never cached: they say more about the machine than the file.
``--no-cache`` turns it off.
"""

from __future__ import annotations

import hashlib
import json
import os
import sys
from collections.abc import Callable, Iterable, Sequence
from pathlib import Path

from ..project.cross_file import module_name
from ..project.import_scan import import_words
from ..verify.protocol import LoadJob, LoadOutcome
from .cache_folder import Store, digests_of, unchanged
from .outcome_cache import code_digest

CACHED = frozenset({"ok", "import-error", "syntax", "exit"})
"""Statuses that depend on the file alone: cached. Timeouts, crashes and memory are not."""


class LoadCache:
    """Outcomes of loads by key, in ``folder`` (created on first write)."""

    def __init__(self, folder: Path, salt: str,
                 sources: Iterable[tuple[str, bytes]] = ()) -> None:
        self.folder = folder
        self.salt = salt
        self.hits = 0
        self._store = Store.open(folder)
        self._imports = _Imports(sources)

    @classmethod
    def for_run(cls, folder: Path, sources: Iterable[tuple[str, bytes]], ontology: str,
                python: str | None) -> LoadCache:
        """A cache whose keys change with the ontology, the interpreter (``python``: None
        is this one) and, for each file, with the Python files of the run it may import."""
        salt = "\0".join([code_digest(), sys.version, python or sys.executable, ontology])
        return cls(folder, salt, sources)

    def key(self, job: LoadJob, data: bytes) -> str:
        digest = hashlib.sha256("\0".join([self.salt, job.path, job.root or ""]).encode()
                                + b"\0" + data)
        for path, content in self._imports.closure(job.path, data):
            digest.update(path.encode() + b"\0" + content)
        return digest.hexdigest()

    def get(self, key: str) -> LoadOutcome | None:
        payload = self._store.read(f"loads/{key[:2]}/{key}.json") if self._store else None
        if payload is None:
            return None
        try:
            data = json.loads(payload)
            outcome = LoadOutcome.from_json(data["outcome"])
            read = data["read"]
        except (ValueError, TypeError, KeyError):
            return None
        if not unchanged(read):
            return None
        self.hits += 1
        return outcome

    def put(self, key: str, outcome: LoadOutcome) -> None:
        if outcome.status not in CACHED or self._store is None:
            return
        read = digests_of(outcome.read)
        if read is None:
            return
        self._store.write(f"loads/{key[:2]}/{key}.json", json.dumps(
            {"outcome": outcome.to_json(), "read": read}).encode("utf-8"))


class _Imports:
    """Which files of the run a file may import, for the keys of its load.

    Loading a file runs its imports, and theirs: its key holds every file of the run it can
    reach that way, so a change elsewhere in the repository leaves it be. A file may import
    another when the other's module name is a word of its import statements
    (``import_scan``), and importing a module runs the ``__init__.py`` of each package
    around it; both are followed to the end. A module imported by a name no import
    statement spells (``importlib``) is not followed: the whole-run cache
    (``outcome_cache``) still answers only an unchanged repository.
    """

    def __init__(self, sources: Iterable[tuple[str, bytes]]) -> None:
        self._data = {os.path.abspath(path): data for path, data in sources}
        self._by_module: dict[bytes, list[str]] = {}
        for path in sorted(self._data):
            self._by_module.setdefault(module_name(path).encode(), []).append(path)
        self._words: dict[str, frozenset[bytes]] = {}

    def closure(self, path: str, data: bytes) -> list[tuple[str, bytes]]:
        """``(path, digest)`` of every other file of the run ``path`` may import, sorted."""
        start = os.path.abspath(path)
        seen = {start}
        pending = [(start, data)]
        while pending:
            here, content = pending.pop()
            if here not in self._words:
                self._words[here] = import_words(content)
            reached = [p for word in self._words[here] for p in self._by_module.get(word, ())]
            reached += [p for p in _packages_around(here) if p in self._data]
            for other in reached:
                if other not in seen:
                    seen.add(other)
                    pending.append((other, self._data[other]))
        return [(p, hashlib.sha256(self._data[p]).digest()) for p in sorted(seen - {start})]


def _packages_around(path: str) -> list[str]:
    """The ``__init__.py`` of every folder above ``path``, nearest first."""
    found = []
    folder = os.path.dirname(path)
    while True:
        found.append(os.path.join(folder, "__init__.py"))
        parent = os.path.dirname(folder)
        if parent == folder:
            return found
        folder = parent


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
