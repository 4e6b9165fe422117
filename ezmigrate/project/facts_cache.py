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

The entries are Python objects, kept in one pickle (``facts.pickle``, read once, written
whole with the entries the run used, so it never grows with old ones). A pickle runs code
when it is read, and ``.ezmigrate_cache`` sits in the checkout, where anybody who can push
a file could put one: the file is signed with a key that never leaves this user's cache
folder (``~/.cache/ezmigrate/key``, made on first use; ``EZMIGRATE_KEY_DIR`` names another
folder), and a file whose signature does not
match is not unpickled, only ignored. No key (a read-only home): no cache, same results.
"""

from __future__ import annotations

import hashlib
import hmac
import os
import pickle
import secrets
import sys
from collections.abc import Iterable
from pathlib import Path
from typing import Any

from .cache_folder import write_entry
from .outcome_cache import code_digest

PACK = "facts.pickle"
"""The file in ``.ezmigrate_cache`` the entries are kept in."""


KEY_DIR = "EZMIGRATE_KEY_DIR"
"""The variable naming the folder of the signing key instead of this user's cache folder
(the tests keep theirs in a temporary folder)."""


def _key_folder() -> Path:
    """``$EZMIGRATE_KEY_DIR``, else ``$XDG_CACHE_HOME/ezmigrate``, else
    ``~/.cache/ezmigrate``."""
    named = os.environ.get(KEY_DIR)
    if named:
        return Path(named)
    return Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "ezmigrate"


def _user_key() -> bytes | None:
    """This user's signing key, made on first use; None when it can be neither read nor
    made."""
    home = _key_folder()
    path = home / "key"
    try:
        return bytes.fromhex(path.read_text(encoding="ascii").strip())
    except (OSError, ValueError):
        pass
    try:
        home.mkdir(parents=True, exist_ok=True)
        key = secrets.token_hex(32)
        handle = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
        with os.fdopen(handle, "w", encoding="ascii") as stream:
            stream.write(key)
        return bytes.fromhex(key)
    except FileExistsError:  # another run made it meanwhile
        try:
            return bytes.fromhex(path.read_text(encoding="ascii").strip())
        except (OSError, ValueError):
            return None
    except OSError:
        return None


class FactsCache:
    """The entries of one ``.ezmigrate_cache`` folder: ``get`` and ``put`` by key during a
    run, ``save`` once at its end."""

    def __init__(self, folder: Path, key: bytes) -> None:
        self.folder = folder
        self._key = key
        self._old: dict[str, Any] = self._load()
        self._used: dict[str, Any] = {}
        self._added = False

    @classmethod
    def open(cls, folder: Path) -> FactsCache | None:
        """The cache of ``folder``, or None without a signing key."""
        key = _user_key()
        return None if key is None else cls(folder, key)

    @staticmethod
    def key(*parts: bytes | str) -> str:
        """The key of an entry: the release, the interpreter and ``parts`` (path, bytes)."""
        digest = hashlib.sha256(f"{code_digest()}\0{sys.version}".encode())
        for part in parts:
            data = part.encode("utf-8", "surrogateescape") if isinstance(part, str) else part
            digest.update(hashlib.sha256(data).digest())
        return digest.hexdigest()

    def get(self, key: str) -> Any | None:
        if key in self._used:
            return self._used[key]
        found = self._old.get(key)
        if found is not None:
            self._used[key] = found
        return found

    def put(self, key: str, value: Any) -> None:
        self._used[key] = value
        self._added = True

    def save(self) -> None:
        """Write the entries this run used (unchanged ones included), signed; a cache
        that cannot be written keeps nothing."""
        if not self._added and self._used.keys() == self._old.keys():
            return  # nothing new: the file on disk says it already
        try:
            data = pickle.dumps(self._used, protocol=pickle.HIGHEST_PROTOCOL)
        except (pickle.PicklingError, TypeError, AttributeError, RecursionError):
            return
        write_entry(self.folder, ".", PACK, self._sign(data) + data)

    def _sign(self, data: bytes) -> bytes:
        return hmac.new(self._key, data, hashlib.sha256).digest()

    def _load(self) -> dict[str, Any]:
        try:
            raw = (self.folder / PACK).read_bytes()
        except OSError:
            return {}
        signature, data = raw[:32], raw[32:]
        if len(raw) < 32 or not hmac.compare_digest(signature, self._sign(data)):
            return {}  # not made by this user's runs: never unpickled
        try:
            found = pickle.loads(data)  # signed by this user's key: checked above
        except Exception:  # a damaged or outdated entry is a miss, whatever it raises
            return {}
        return found if isinstance(found, dict) else {}


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
