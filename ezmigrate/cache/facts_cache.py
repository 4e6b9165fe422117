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

Each entry is a JSON file of its own (``facts/<key>.json``) in this user's cache folder,
signed (``cache_folder``): a run opens the entries it asks for and writes the ones it
made, nothing else (one pack of every entry cost a run after a one-file change 0.1 s of a
core to parse and 0.1 s to write back). Entries no run asked for in a month go with the
folder's pruning. The objects are rebuilt by ``facts_codec``, which makes only this
project's own classes and runs no code named by the data. An entry that is missing,
foreign, forged or damaged is a miss: its file is read again.
"""

from __future__ import annotations

import hashlib
import json
import sys
from collections.abc import Iterable
from pathlib import Path
from typing import Any

from .cache_folder import Store
from .facts_codec import CodecError, encode, loads
from .outcome_cache import code_digest

FOLDER = "facts"
"""The sub-folder of a project's cache folder the readings are kept in."""


class FactsCache:
    """The readings of one project's cache folder: ``get`` and ``put`` by key during a
    run, ``save`` once at its end."""

    def __init__(self, store: Store) -> None:
        self._store = store
        self._known: dict[str, Any] = {}
        """Entries this run read or made, by key."""
        self._added: dict[str, Any] = {}
        """Entries this run made: ``save`` writes them."""
        self._digests: dict[str, str] = {}
        """The SHA-256 of each entry's text, read or made (``digest``)."""
        self._texts: dict[str, bytes] = {}
        """The text of an entry this run made, once ``digest`` encoded it (``save``
        writes it as it is)."""

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

    @staticmethod
    def entry(key: str) -> str:
        """The name of ``key``'s entry in the project's cache folder."""
        return f"{FOLDER}/{key}.json"

    def get(self, key: str) -> Any | None:
        """The entry of ``key``; None when there is none, or it does not decode."""
        if key in self._known:
            return self._known[key]
        payload = self._store.read(self.entry(key))
        if payload is None:
            return None
        try:
            found = loads(payload)
        except (ValueError, TypeError, RecursionError, AttributeError):
            return None  # CodecError is a ValueError: a corrupt entry is a miss
        self._known[key] = found
        self._digests[key] = hashlib.sha256(payload).hexdigest()
        return found

    def digest(self, key: str) -> str | None:
        """The SHA-256 of ``key``'s entry as this run read or made it: the same reading
        gives the same text (``facts_codec`` writes sets in one order), so two files whose
        readings are equal have equal digests (``checking.early_cutoff``); None for an
        entry this run neither read nor made, or one that holds something not of ours."""
        if key not in self._digests and key in self._added:
            text = _entry_text(self._added[key])
            if text is not None:
                self._texts[key] = text
                self._digests[key] = hashlib.sha256(text).hexdigest()
        return self._digests.get(key)

    def put(self, key: str, value: Any) -> None:
        """Keep ``value`` as ``key``'s entry (a key names the bytes its value was read
        from, so an entry this run read already is not written again)."""
        if key not in self._known:
            self._known[key] = self._added[key] = value

    def save(self) -> None:
        """Write the entries this run made; one that holds something not of ours
        (``CodecError``) is not kept."""
        for key in self._added:
            if self.digest(key) is not None:  # encoded once, here or for the digest
                self._store.write(self.entry(key), self._texts.pop(key))
        self._added.clear()


def _entry_text(value: Any) -> bytes | None:
    """The entry text ``value`` is kept as (None: it holds something not of ours)."""
    try:
        return json.dumps(encode(value), separators=(",", ":")).encode("utf-8")
    except (CodecError, RecursionError):
        return None


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
