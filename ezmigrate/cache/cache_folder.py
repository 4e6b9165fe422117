"""Where ``check`` keeps what it learnt, and how an entry is written, trusted and pruned.

A repository under check is a stranger's pull request, so no file it holds may decide a
verdict: the cache lives in this user's own cache folder, as black's does
(``$EZMIGRATE_CACHE_DIR``, else ``$XDG_CACHE_HOME/ezmigrate``, else
``~/.cache/ezmigrate``; ``check --cache-dir`` names another), one folder per project.
Every entry is JSON (nothing in it can run code when read) signed with a key that never
leaves the cache folder (``key``, made on first use, readable by this user alone): an
entry whose signature does not match (forged, copied from elsewhere, damaged, cut short)
is a miss, never trusted. Code that ``rewrite`` or ``check --trace`` loads cannot read the
key or write an entry: its sandbox covers the cache folder with an empty file system
(``verify/sandbox``); where the system refuses that sandbox, the key is made anew when the
run ends, so whatever the loaded code learnt of it is worth nothing.

Entries unused for ``MAX_AGE`` are removed, and the oldest go when the folder holds more
than ``MAX_BYTES`` (looked at once an hour at most); a read-only cache folder keeps
nothing, with the same results.
"""

from __future__ import annotations

import contextlib
import hashlib
import hmac
import os
import tempfile
import time
from collections.abc import Iterable
from pathlib import Path

ENVIRONMENT = "EZMIGRATE_CACHE_DIR"
KEY_FILE = "key"
MAX_AGE = 30 * 24 * 3600
"""An entry nobody read for this long (seconds) is removed."""
MAX_BYTES = 512 * 1024 * 1024
"""Past this size the oldest entries are removed."""
PRUNE_EVERY = 3600
"""Seconds between two prunings of a cache root (``Store.prune``)."""
_SIGNATURE = 64  # hexadecimal SHA-256 on the entry's first line


def cache_root(named: Path | None = None) -> Path:
    """The user's cache folder: ``named`` (``--cache-dir``), ``$EZMIGRATE_CACHE_DIR``,
    ``$XDG_CACHE_HOME/ezmigrate``, else ``~/.cache/ezmigrate``."""
    if named is not None:
        return named
    if os.environ.get(ENVIRONMENT):
        return Path(os.environ[ENVIRONMENT])
    return Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "ezmigrate"


def project_folder(root: Path, project: Path) -> Path:
    """The folder of one project's entries under the cache ``root``."""
    digest = hashlib.sha256(os.fsencode(os.path.realpath(project))).hexdigest()[:24]
    return root / "projects" / digest


class Store:
    """Signed entries under ``folder`` (a project's), with the key of its cache root."""

    def __init__(self, folder: Path, key: bytes) -> None:
        self.folder = folder
        self._key = key

    @classmethod
    def open(cls, folder: Path) -> Store | None:
        """The store of ``folder`` (``<root>/projects/<project>``), or None when the key
        can be neither read nor made (a read-only home: no cache, same results)."""
        key = user_key(folder.parent.parent)
        return None if key is None else cls(folder, key)

    def _sign(self, name: str, payload: bytes) -> bytes:
        return hmac.new(self._key, name.encode("utf-8") + b"\0" + payload,
                        hashlib.sha256).hexdigest().encode("ascii")

    def read(self, name: str) -> bytes | None:
        """The payload of entry ``name`` (a relative path), or None when it is missing or
        its signature does not match; a hit is marked as used (its time stamp)."""
        path = self.folder / name
        try:
            raw = path.read_bytes()
        except OSError:
            return None
        signature, payload = raw[:_SIGNATURE], raw[_SIGNATURE + 1:]
        if len(raw) <= _SIGNATURE or not hmac.compare_digest(signature,
                                                             self._sign(name, payload)):
            return None
        with contextlib.suppress(OSError):
            os.utime(path)
        return payload

    def has_any(self, folder: str) -> bool:
        """Whether a sub-folder holds any entry (signed or not: a guess, never a verdict)."""
        try:
            with os.scandir(self.folder / folder) as entries:
                return any(entry.is_file() for entry in entries)
        except OSError:
            return False

    def write(self, name: str, payload: bytes) -> None:
        """Entry ``name`` holding ``payload``, signed and written whole (a temporary file
        renamed into place); a cache that cannot be written keeps nothing."""
        path = self.folder / name
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            handle, temporary = tempfile.mkstemp(dir=path.parent, suffix=".tmp")
            with os.fdopen(handle, "wb") as stream:
                stream.write(self._sign(name, payload) + b"\n" + payload)
            os.replace(temporary, path)
        except OSError:
            return

    def prune(self) -> None:
        """``prune`` the whole cache root, at most once every ``PRUNE_EVERY`` seconds (its
        walk lists every entry of every project: not work for each run)."""
        root = self.folder.parent.parent
        stamp = root / "pruned"
        try:
            if time.time() - stamp.stat().st_mtime < PRUNE_EVERY:
                return
        except OSError:
            pass  # never pruned yet
        prune(root)
        try:
            stamp.touch()
        except OSError:
            return


def digests_of(paths: Iterable[str]) -> dict[str, str] | None:
    """The SHA-256 of each file an entry depends on beyond its key (what a load read);
    None when one cannot be read (the entry is then not kept)."""
    found = {}
    for path in paths:
        digest = _digest(path)
        if digest is None:
            return None
        found[path] = digest
    return found


def unchanged(read: dict[str, str]) -> bool:
    """Whether every file of ``digests_of`` still has the bytes it had."""
    return all(_digest(path) == digest for path, digest in read.items())


def _digest(path: str) -> str | None:
    try:
        with open(path, "rb") as handle:
            return hashlib.sha256(handle.read()).hexdigest()
    except OSError:
        return None


def prune(root: Path, now: float | None = None) -> None:
    """Remove the entries of the cache ``root`` not used for ``MAX_AGE``, then the oldest
    while it holds more than ``MAX_BYTES``."""
    now = time.time() if now is None else now
    entries: list[tuple[float, int, Path]] = []
    for folder, _, files in os.walk(root / "projects"):
        for name in files:
            path = Path(folder, name)
            try:
                status = path.stat()
            except OSError:
                continue
            if now - status.st_mtime > MAX_AGE:
                _remove(path)
            else:
                entries.append((status.st_mtime, status.st_size, path))
    total = sum(size for _, size, _ in entries)
    for _, size, path in sorted(entries):
        if total <= MAX_BYTES:
            break
        _remove(path)
        total -= size


def _remove(path: Path) -> None:
    with contextlib.suppress(OSError):
        path.unlink()


def user_key(root: Path) -> bytes | None:
    """The signing key of the cache ``root``, made on first use (readable by this user
    alone); None when it can be neither read nor made."""
    path = root / KEY_FILE
    try:
        return bytes.fromhex(path.read_text(encoding="ascii").strip())
    except (OSError, ValueError):
        pass
    try:
        root.mkdir(parents=True, exist_ok=True)
        return _new_key(path)
    except FileExistsError:  # another run made it meanwhile
        try:
            return bytes.fromhex(path.read_text(encoding="ascii").strip())
        except (OSError, ValueError):
            return None
    except OSError:
        return None


def _new_key(path: Path) -> bytes:
    key = os.urandom(32).hex()  # (as secrets.token_hex, without its imports)
    handle = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
    with os.fdopen(handle, "w", encoding="ascii") as stream:
        stream.write(key)
    return bytes.fromhex(key)


def renew_key(root: Path) -> None:
    """Make the key of ``root`` anew (every entry signed with the old one becomes a miss):
    after code ran outside the sandbox, which may have read the old key."""
    path = root / KEY_FILE
    temporary = root / f"{KEY_FILE}.{os.getpid()}.tmp"
    try:
        _remove(temporary)
        _new_key(temporary)
        os.replace(temporary, path)
    except OSError:
        _remove(path)  # no key at all is better than a known one
