"""``check``'s cache of what each file says, so that one changed file is read again alone
(issue 31).

The whole-run cache (``outcome_cache``) answers an unchanged repository; once one file
changes its key does too. What the static pass learns of a file (its legacy descriptions,
the facts the compound pass and the implementation checks take from its syntax tree) is
made of that file alone, and a parsed scene of its text alone, so they are kept here by
content: the release's code, the interpreter, the file's path and its bytes. The passes
that join files together (the cross-file bases, the compound trees against the skill
index, the world model) run again on what is kept, which is cheap; the parses and the
readings are what a run saves.

The entries are kept in one JSON file (``facts.json``, read once, written whole with the
entries the run used, so it never grows with old ones), in this user's cache folder and
signed (``cache_folder``); the objects are rebuilt by ``facts_codec``, which makes only this
project's own classes and runs no code named by the data. A pack that is missing, foreign,
forged or damaged is a miss: the files are read again.
"""

from __future__ import annotations

import hashlib
import json
import sys
from collections.abc import Iterable
from pathlib import Path
from typing import Any

from .cache_folder import Store
from .facts_codec import CodecError, decode, encode
from .outcome_cache import code_digest

PACK = "facts.json"
"""The entry of a project's cache folder the readings are kept in."""


class FactsCache:
    """The readings of one project's cache folder: ``get`` and ``put`` by key during a
    run, ``save`` once at its end."""

    def __init__(self, store: Store) -> None:
        self._store = store
        self._old: dict[str, Any] = self._load()
        """Entries as the pack holds them (JSON data), decoded when a run asks for one."""
        self._used: dict[str, Any] = {}
        self._kept_raw: dict[str, Any] = {}
        """Entries of the pack this run used unchanged: written back as they were read."""
        self._added: dict[str, Any] = {}

    @classmethod
    def open(cls, folder: Path) -> FactsCache | None:
        """The cache of ``folder``, or None without a signing key."""
        store = Store.open(folder)
        return None if store is None else cls(store)

    @staticmethod
    def key(*parts: bytes | str) -> str:
        """The key of an entry: the release, the interpreter and ``parts`` (path, bytes)."""
        digest = hashlib.sha256(f"{code_digest()}\0{sys.version}".encode())
        for part in parts:
            data = part.encode("utf-8", "surrogateescape") if isinstance(part, str) else part
            digest.update(hashlib.sha256(data).digest())
        return digest.hexdigest()

    def get(self, key: str) -> Any | None:
        """The entry of ``key``; None when there is none, or it does not decode."""
        if key in self._used:
            return self._used[key]
        raw = self._old.get(key)
        if raw is None:
            return None
        try:
            found = decode(raw)
        except (ValueError, TypeError, RecursionError, AttributeError):
            return None  # CodecError is a ValueError: a corrupt entry is a miss
        self._used[key] = found
        self._kept_raw[key] = raw
        return found

    def put(self, key: str, value: Any) -> None:
        self._used[key] = value
        self._kept_raw.pop(key, None)
        self._added[key] = value

    def save(self) -> None:
        """Write the entries this run used (unchanged ones as they were read: only what
        this run added is encoded); an entry that holds something not of ours
        (``CodecError``) is not kept."""
        if not self._added and self._used.keys() == self._old.keys():
            return  # nothing new: the file on disk says it already
        kept = {key: raw for key, raw in self._kept_raw.items() if key in self._used}
        for key, value in self._added.items():
            try:
                kept[key] = encode(value)
            except (CodecError, RecursionError):
                continue
        self._store.write(PACK, json.dumps(kept).encode("utf-8"))

    def _load(self) -> dict[str, Any]:
        payload = self._store.read(PACK)
        if payload is None:
            return {}
        try:
            data = json.loads(payload)
        except (ValueError, RecursionError):
            return {}
        return {str(k): v for k, v in data.items()} if isinstance(data, dict) else {}


def seed_scenes(cache: FactsCache, paths: Iterable[Path]) -> set[Path]:
    """Hand ``read_scene`` the parses an earlier run kept of these scenes' texts; returns
    the scenes it had."""
    from ezskiros_runtime.world.scene import Scene, seed_scene

    seeded = set()
    for path in paths:
        text = _text(path)
        found = None if text is None else cache.get(cache.key("scene", str(path), text))
        if isinstance(found, Scene):
            seed_scene(path, text or "", found)
            seeded.add(path)
    return seeded


def keep_scenes(cache: FactsCache, paths: Iterable[Path]) -> None:
    """Keep the parses this run made of these scenes (one the run did not need, or that
    does not parse, is not kept)."""
    from ezskiros_runtime.world.scene import known_scene

    for path in paths:
        text = _text(path)
        found = None if text is None else known_scene(path, text)
        if found is not None:
            cache.put(cache.key("scene", str(path), text or ""), found)


def _text(path: Path) -> str | None:
    try:
        return path.read_text(encoding="utf-8")
    except (OSError, UnicodeError):
        return None
