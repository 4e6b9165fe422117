"""The persistent index cache: indexes as JSON, keyed by the content of the ontology files.

Parsing OWL with rdflib (and importing rdflib at all) dominates start-up, yet the files
almost never change between launches. So the index is stored under a hash of everything
that determines it: a format version, the bytes of each file in load order (not their
paths, so a moved checkout still hits), the package version, and the source of the
modules that build the index (so editing that code cannot serve a stale index).

The cache is an optimisation only: an unreadable, corrupt or unwritable cache is ignored
and the index is rebuilt. Writes are atomic (temporary file in the same folder, then
os.replace), so a concurrent reader never sees half a file. Each write keeps only the
most recently used indexes, since every edit of an ontology creates a new key, and drops
entries unused for ``MAX_AGE_DAYS``.

No pickle (issue 40): the file name depends only on content, and any process that ran
once as the user could have written it, so an entry is data that cannot run code (JSON,
``index_codec``) and is checked field by field when read; whatever does not check out is
ignored and the index is rebuilt from the files. Pickles of earlier versions are never
read, only deleted. The other readers of this cache (the verification worker under
another Python, ``ezmigrate.verify.interpreters``) go through ``load_index`` as well.
"""

from __future__ import annotations

import contextlib
import os
import sys
from collections.abc import Callable, Iterable, Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .errors import OntologyLoadError

if TYPE_CHECKING:
    from .index import OntologyIndex
    from .parsing import OntologyFile

CACHE_FORMAT_VERSION = "4"  # 2: sub-properties add their parents' domains and ranges;
# 3: the index keeps the files' individuals; 4: JSON with direct edges only, no pickle
"""Bump when the stored shape of the index changes incompatibly."""

_INDEX_CODE = (
    "build.py",
    "cache.py",
    "closure.py",
    "dtd_guard.py",
    "expressions.py",
    "index.py",
    "index_codec.py",
    "individuals.py",
    "limits.py",
    "load.py",
    "naming.py",
    "parsing.py",
)
"""The runtime's modules whose code decides what the index contains or how it is stored:
their source is part of the key, so a changed runtime never reads an entry of another."""

KEEP_INDEXES = 16
"""How many cached indexes a write leaves in the folder (most recently used first)."""

MAX_AGE_DAYS = 30
"""Entries not used for this long are deleted at the next write."""

INDEX_PATTERN = "ontology-index-*.json"
LEGACY_PATTERN = "ontology-index-*.pickle"
"""Entries of earlier versions: deleted, never read."""

_code_digest_memo: str | None = None


class CacheStats:
    """Counters for this process, so tests and `--verbose` output can show what happened."""

    __slots__ = ("hits", "ignored_errors", "misses", "writes")

    def __init__(self) -> None:
        self.hits = self.misses = self.writes = self.ignored_errors = 0

    def __repr__(self) -> str:
        return (
            f"CacheStats(hits={self.hits}, misses={self.misses}, writes={self.writes}, "
            f"ignored_errors={self.ignored_errors})"
        )


stats = CacheStats()


def _sha256_factory() -> Callable[[], Any]:
    """sha256, preferably from CPython's built-in module.

    `import hashlib` loads OpenSSL, about 5 ms: most of a warm load. The built-in
    implementation gives the same digest; hashlib remains the fallback.
    """
    try:
        from _sha256 import sha256  # CPython <= 3.11
    except ImportError:
        try:
            from _sha2 import sha256  # CPython >= 3.12
        except ImportError:
            from hashlib import sha256
    return sha256


def default_cache_dir(environ: Mapping[str, str] | None = None) -> Path:
    """`EZSKIROS_CACHE_DIR`, else `$XDG_CACHE_HOME/ezskiros`, else `~/.cache/ezskiros`."""
    env = os.environ if environ is None else environ
    explicit = env.get("EZSKIROS_CACHE_DIR")
    if explicit:
        return Path(explicit).expanduser()
    xdg = env.get("XDG_CACHE_HOME")
    if xdg:
        return Path(xdg).expanduser() / "ezskiros"
    return Path.home() / ".cache" / "ezskiros"


def _package_version() -> str:
    """The package version if the package states one, without importlib.metadata.

    importlib.metadata costs ~30 ms to import, more than the whole warm load; the code
    digest below already changes whenever the index-building code does.
    """
    package = sys.modules.get("ezskiros_runtime")
    return str(getattr(package, "__version__", ""))


def _code_digest() -> str:
    global _code_digest_memo
    if _code_digest_memo is None:
        digest = _sha256_factory()()
        here = Path(__file__).resolve().parent
        for name in _INDEX_CODE:
            digest.update(name.encode() + b"\0")
            try:
                digest.update((here / name).read_bytes())
            except OSError:  # installed without sources (zipapp, .pyc only): version only
                digest.update(b"?")
        _code_digest_memo = digest.hexdigest()
    return _code_digest_memo


def fingerprint(files: Iterable[OntologyFile]) -> str:
    """The content hash of a set of ontology files, in load order; paths do not count."""
    digest = _sha256_factory()()
    for part in (
        b"ezskiros-ontology-index",
        CACHE_FORMAT_VERSION.encode(),
        _package_version().encode(),
        _code_digest().encode(),
    ):
        digest.update(part + b"\0")
    for entry in files:
        digest.update((entry.format or "auto").encode() + b"\0")
        digest.update(len(entry.data).to_bytes(8, "big"))
        digest.update(entry.data)
    return digest.hexdigest()


def cache_path(directory: Path, fingerprint: str) -> Path:
    """Where the index with this fingerprint is (or would be) stored."""
    return directory / f"ontology-index-{fingerprint}.json"


def read_cached_index(directory: Path, fingerprint: str) -> OntologyIndex | None:
    """The cached index for `fingerprint`, or None on a miss or any problem with the file:
    unreadable, not JSON, truncated, of another shape or for other content (``decode``
    checks every field). Nothing in the file can run code."""
    import json

    from .index_codec import decode

    path = cache_path(directory, fingerprint)
    try:
        with path.open("rb") as stream:
            data = stream.read(_MAX_ENTRY_BYTES + 1)
        if len(data) > _MAX_ENTRY_BYTES:
            raise ValueError("larger than any index this code writes")
        index = decode(json.loads(data), fingerprint, CACHE_FORMAT_VERSION)
    except FileNotFoundError:
        stats.misses += 1
        return None
    except Exception as error:  # corrupt, truncated, forged, unreadable: rebuild
        stats.misses += 1
        _ignored("ignoring ontology cache %s: %s", path, error)
        return None
    stats.hits += 1
    with contextlib.suppress(OSError):  # recency for pruning; a read-only cache still works
        os.utime(path)
    return index


_MAX_ENTRY_BYTES = 512 * 1024 * 1024
"""An entry larger than this is not read (the limits keep real ones far below)."""


def write_cached_index(directory: Path, index: OntologyIndex) -> Path | None:
    """Store `index` atomically; returns the file, or None when the cache is unwritable."""
    import json

    from .index_codec import encode

    target = cache_path(directory, index.fingerprint)
    data = json.dumps(encode(index, CACHE_FORMAT_VERSION), separators=(",", ":"),
                      ensure_ascii=False).encode("utf-8")
    return target if _store(target, data, INDEX_PATTERN) else None


def _store(target: Path, data: bytes, pattern: str) -> bool:
    """Write ``data`` to ``target`` atomically (a temporary file in the same folder, then
    ``os.replace``), then prune the entries of ``pattern`` (``_prune``); False when the
    cache cannot be written: a read-only home, a full disk, a file where the folder
    should be."""
    import tempfile

    directory = target.parent
    temporary: str | None = None
    try:
        directory.mkdir(parents=True, exist_ok=True)
        handle, temporary = tempfile.mkstemp(
            dir=directory, prefix="." + pattern.partition("*")[0], suffix=".tmp"
        )
        with os.fdopen(handle, "wb") as stream:
            stream.write(data)
        os.replace(temporary, target)
        temporary = None
    except Exception as error:  # the next load builds or parses again
        _ignored("cannot write ontology cache %s: %s", target, error)
        return False
    finally:
        if temporary is not None:
            with contextlib.suppress(OSError):
                os.unlink(temporary)
    stats.writes += 1
    _prune(directory, keep=target, pattern=pattern)
    return True


def refusal_path(directory: Path, fingerprint: str, sources: Sequence[str]) -> Path:
    """Where the refusal of these files, at these paths, is (or would be) remembered.

    Unlike an index, a refusal names a file: the paths count, and so does the rdflib that
    refused (its module file's place, size and time: another rdflib may word it apart, or
    read the file), and so do the limits in force (``limits.stamp``: a raised limit must
    load the file again)."""
    from .limits import stamp

    digest = _sha256_factory()()
    for part in (fingerprint, *sources, _rdflib_stamp(), stamp()):
        digest.update(part.encode("utf-8", "surrogateescape") + b"\0")
    return directory / f"ontology-refusal-{digest.hexdigest()}.json"


def _rdflib_stamp() -> str:
    """Which rdflib is installed, without importing it (that is what a hit saves)."""
    from importlib.util import find_spec

    try:
        spec = find_spec("rdflib")
        origin = spec.origin if spec is not None else None
        state = os.stat(origin) if origin else None
    except (ImportError, ValueError, OSError):
        return "?"
    return f"{origin}:{state.st_size}:{state.st_mtime_ns}" if state else "?"


def read_cached_refusal(directory: Path, fingerprint: str, sources: Sequence[str]
                        ) -> OntologyLoadError | None:
    """The error an earlier load of these very files raised, or None."""
    import json

    path = refusal_path(directory, fingerprint, sources)
    try:
        kept = json.loads(path.read_text(encoding="utf-8"))
        message, where, line = kept["message"], kept["path"], kept["line"]
        if not (isinstance(message, str) and isinstance(where, (str, type(None)))
                and (line is None or (isinstance(line, int) and not isinstance(line, bool)))):
            raise ValueError("not a refusal this code wrote")
        error = OntologyLoadError(message, path=where, line=line)
    except FileNotFoundError:
        return None
    except Exception as error:  # corrupt or foreign: load the files again
        _ignored("cannot read ontology refusal %s: %s", path, error)
        return None
    stats.hits += 1
    with contextlib.suppress(OSError):
        os.utime(path)
    return error


def write_cached_refusal(directory: Path, fingerprint: str, sources: Sequence[str],
                         error: OntologyLoadError) -> None:
    """Remember that these files were refused, and why (atomically, as an index)."""
    import json

    kept = {"message": str(error), "path": error.path, "line": error.line}
    _store(refusal_path(directory, fingerprint, sources), json.dumps(kept).encode("utf-8"),
           "ontology-refusal-*.json")


def _prune(directory: Path, keep: Path, pattern: str, now: float | None = None) -> None:
    """Delete all but the `KEEP_INDEXES` most recently used entries of ``pattern`` (never
    `keep`), the entries unused for `MAX_AGE_DAYS`, and the pickles of earlier versions."""
    import time

    oldest = (time.time() if now is None else now) - MAX_AGE_DAYS * 24 * 3600
    try:
        found = [
            (entry.stat().st_mtime, entry)
            for entry in directory.glob(pattern)
            if entry != keep
        ]
        legacy = list(directory.glob(LEGACY_PATTERN))
    except OSError as error:
        _ignored("cannot list ontology cache %s: %s", directory, error)
        return
    found.sort(reverse=True)
    stale = [entry for mtime, entry in found[KEEP_INDEXES - 1 :]]
    stale += [entry for mtime, entry in found[: KEEP_INDEXES - 1] if mtime < oldest]
    for entry in [*stale, *legacy]:
        with contextlib.suppress(OSError):
            entry.unlink()


def _ignored(message: str, *args: object) -> None:
    import logging

    stats.ignored_errors += 1
    logging.getLogger(__name__).debug(message, *args)
