"""``check``'s cache of whole runs: a second ``check`` of an unchanged repository reads and
hashes its files, and nothing else (issue 31).

``load_cache`` keeps the loads of EzSkiROS files; the static pass, the compound trees, the
checks inside implementations and the world model ran again on every run, and on a large
repository they are most of what is left. Their findings depend on nothing but what the
run reads and how it is set up, so the key is all of it: every Python file of the run
(path and bytes), every scene (the run's and the launch file's ``init_scene``), the launch
file, the skill libraries' files, the ontology's fingerprint, the interpreter, the settings
that change what is analysed (single-valued relations, whether trees are read, whether
user code may run) and the code of this release (a digest of the two packages' sources,
so that a changed rule never meets an old entry). A hit is the outcome as the run left it
(diagnostics before selection, so ``--select`` and suppressions apply as on a miss);
anything missing or damaged is a miss. Only runs over folders are kept: a run over named
files (pre-commit) also reads the repository around them, which the key would have to
read too.
"""

from __future__ import annotations

import functools
import hashlib
import json
import os
import sys
from collections.abc import Iterable
from pathlib import Path
from typing import Any

from .. import __version__
from ..lint.diagnostic import Diagnostic
from .cache_folder import Store, digests_of, unchanged

OUTCOMES = "outcomes"
"""The sub-folder of a project's cache folder (``cache_folder``) the runs are kept in."""


@functools.lru_cache(maxsize=1)
def code_digest() -> str:
    """A digest of this release's source (``ezmigrate`` and ``ezskiros_runtime``)."""
    digest = hashlib.sha256(__version__.encode())
    root = str(Path(__file__).resolve().parents[2])
    for package in ("ezmigrate", "ezskiros_runtime"):
        files = [os.path.join(folder, name)
                 for folder, _, names in os.walk(os.path.join(root, package))
                 for name in names if name.endswith(".py")]
        for path in sorted(files):  # (every run reads them all: plain strings, no Path)
            digest.update(path[len(root) + 1:].replace(os.sep, "/").encode() + b"\0")
            with open(path, "rb") as file:
                digest.update(hashlib.sha256(file.read()).digest())
    return digest.hexdigest()


def run_key(files: Iterable[tuple[str, str]], settings: dict[str, Any]) -> str:
    """The key of a run: every file it reads (path and ``content_digest``), its settings
    and the code."""
    digest = hashlib.sha256(json.dumps({**settings, "code": code_digest(),
                                        "python": sys.version}, sort_keys=True).encode())
    for path, content in sorted(files):
        digest.update(f"{path}\0{content}\0".encode())
    return digest.hexdigest()


def content_digest(data: bytes) -> str:
    """The digest of a file's bytes, as the keys and early cutoff's memo name them."""
    return hashlib.sha256(data).hexdigest()


def read_all(paths: Iterable[Path]) -> list[tuple[str, bytes]] | None:
    """``(path, bytes)`` of each file; None when one cannot be read (no caching then)."""
    found = []
    for path in paths:
        try:
            found.append((str(path), path.read_bytes()))
        except OSError:
            return None
    return found


class OutcomeCache:
    """Whole runs of ``check`` by key, in ``folder/outcomes`` (signed: ``cache_folder``)."""

    def __init__(self, folder: Path) -> None:
        self.folder = folder
        self._store = Store.open(folder)

    def get(self, key: str) -> dict[str, Any] | None:
        """The stored run (``diagnostics`` as ``Diagnostic`` objects), or None."""
        payload = self._store.read(f"{OUTCOMES}/{key}.json") if self._store else None
        if payload is None:
            return None
        try:
            data = json.loads(payload)
            data["diagnostics"] = [Diagnostic(**d) for d in data["diagnostics"]]
            if not isinstance(data["files"], int) or not isinstance(data["skills"], int):
                return None
            if not unchanged(data.get("read", {})):
                return None  # a file a load of ``--trace`` read has changed
        except (ValueError, TypeError, KeyError, AttributeError):
            return None
        return dict(data)

    def keeps_any(self) -> bool:
        """Whether any run is kept here (a run's outcome may then be one of them)."""
        return self._store is not None and self._store.has_any(OUTCOMES)

    def put(self, key: str, files: int, skills: int, notes: list[str],
            diagnostics: list[Diagnostic], read: Iterable[str] = ()) -> None:
        """Keep a run (written whole; a read-only cache folder keeps nothing); ``read``:
        the files its loads opened, whose bytes it depends on too."""
        digests = digests_of(read)
        if self._store is None or digests is None:
            return
        payload = {"files": files, "skills": skills, "notes": notes, "read": digests,
                   "diagnostics": [dict(vars(d)) for d in diagnostics]}  # (flat: asdict's
        # deep copy of each field was most of a kept run's cost)
        self._store.write(f"{OUTCOMES}/{key}.json", json.dumps(payload).encode("utf-8"))
        self._store.prune()
