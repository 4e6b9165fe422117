"""Writing files so that each is either wholly old or wholly new, whatever happens.

New content goes to a temporary file in the same folder, is flushed to disk, takes the
original's permission bits, and replaces the original by ``os.replace`` (atomic on POSIX).
The original's content hash is checked just before replacing: a file that changed or
vanished since it was read is left alone.
"""

from __future__ import annotations

import hashlib
import os
import stat
import tempfile
from pathlib import Path


class WriteRefused(Exception):
    """The file was not written; the message says why (it is shown to the user)."""


def digest(data: bytes) -> str:
    """Content hash used to detect files that change during a run."""
    return hashlib.sha256(data).hexdigest()


def atomic_write(path: Path, data: bytes, expected_digest: str | None = None) -> None:
    """Replace ``path`` with ``data`` atomically, refusing if it changed since it was read."""
    target = Path(os.path.realpath(path)) if path.is_symlink() else path
    try:
        current = target.read_bytes()
        mode = stat.S_IMODE(target.stat().st_mode)
    except FileNotFoundError as error:
        raise WriteRefused(f"{path}: vanished during the run, left alone") from error
    except OSError as error:
        raise WriteRefused(f"{path}: cannot read back ({error.strerror})") from error
    if expected_digest is not None and digest(current) != expected_digest:
        raise WriteRefused(f"{path}: changed during the run, left alone")
    if not os.access(target, os.W_OK):
        raise WriteRefused(f"{path}: read-only, left alone")
    folder = target.parent
    try:
        fd, temp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".ezmigrate", dir=folder)
    except OSError as error:
        raise WriteRefused(f"{path}: cannot create a temporary file ({error.strerror})") from error
    try:
        with os.fdopen(fd, "wb") as handle:
            handle.write(data)
            handle.flush()
            os.fsync(handle.fileno())
        os.chmod(temp, mode)
        os.replace(temp, target)
    except BaseException:
        try:
            os.unlink(temp)
        except OSError:
            pass
        raise
