"""Writing files so that each is either wholly old or wholly new, whatever happens.

New content goes to a temporary file in the same folder (``.NAME.XXXXXXXX.ezmigrate``, never
a ``.py`` file), is flushed to disk, takes the original's permission bits (and owner, when
allowed), and replaces the original by ``os.replace``, which is atomic on POSIX. The folder
is flushed too, so the rename survives a power cut. Any failure or interruption before the
rename removes the temporary file and leaves the original as it was.

Before replacing, the original is read back and its content hash compared with the hash it
was read with at the start of the run: a file that changed or vanished since is left alone.
A file whose permission bits say read-only is left alone even when the process could write
it (root). A symlink is written through only when its target lies inside the roots the run
was given; otherwise the target is left alone.
"""

from __future__ import annotations

import fcntl
import hashlib
import os
import re
import stat
import tempfile
from collections.abc import Sequence
from contextlib import suppress
from pathlib import Path

TEMP_SUFFIX = ".ezmigrate"
"""Suffix of temporary files (``.NAME.XXXXXXXX.ezmigrate``): a run leaves none behind."""


class WriteRefused(Exception):
    """The file was not written; the message says why (it is shown to the user)."""


def digest(data: bytes) -> str:
    """Content hash used to detect files that change during a run."""
    return hashlib.sha256(data).hexdigest()


def _inside(real: Path, roots: Sequence[Path]) -> bool:
    for root in roots:
        real_root = Path(os.path.realpath(root))
        if real == real_root or real_root in real.parents:
            return True
    return False


def resolve_target(path: Path, roots: Sequence[Path] | None = None) -> Path:
    """The file that writing ``path`` would replace: the symlink's target, if allowed."""
    real = Path(os.path.realpath(path))
    if roots is not None and not _inside(real, roots):
        if path.is_symlink() or real != Path(os.path.abspath(path)):
            raise WriteRefused(f"{path}: a symlink to {real}, outside the given paths; "
                               "not written through, left alone")
        raise WriteRefused(f"{path}: outside the given paths, left alone")
    return real if path.is_symlink() else path


def atomic_write(path: Path, data: bytes, expected_digest: str | None = None, *,
                 roots: Sequence[Path] | None = None, create: bool = False,
                 mode: int | None = None) -> None:
    """Replace ``path`` with ``data`` atomically, refusing if it changed since it was read.

    ``expected_digest``: the hash the file was read with (``None``: no check). ``roots``:
    symlinks are written through only to targets inside them. ``create``: the file may not
    exist yet (``--output-dir``); it then gets ``mode`` (default 0o644 less the umask).
    """
    target = resolve_target(path, roots)
    try:
        info = os.stat(target)
    except FileNotFoundError as error:
        if not create:
            raise WriteRefused(f"{path}: vanished during the run, left alone") from error
        info = None
    except OSError as error:
        raise WriteRefused(f"{path}: cannot read back ({error.strerror})") from error
    if info is not None:
        if not stat.S_ISREG(info.st_mode):
            raise WriteRefused(f"{path}: no longer a regular file, left alone")
        mode = stat.S_IMODE(info.st_mode)
        if not mode & stat.S_IWUSR or not os.access(target, os.W_OK):
            raise WriteRefused(f"{path}: read-only, left alone")
    elif mode is None:
        umask = os.umask(0)
        os.umask(umask)
        mode = 0o666 & ~umask
    _replace(path, target, data, mode, info, expected_digest)


def _check_unchanged(path: Path, target: Path, expected_digest: str | None) -> None:
    if expected_digest is None:
        return
    try:
        current = target.read_bytes()
    except FileNotFoundError as error:
        raise WriteRefused(f"{path}: vanished during the run, left alone") from error
    except OSError as error:
        raise WriteRefused(f"{path}: cannot read back ({error.strerror})") from error
    if digest(current) != expected_digest:
        raise WriteRefused(f"{path}: changed during the run, left alone")


def _replace(path: Path, target: Path, data: bytes, mode: int,
             info: os.stat_result | None, expected_digest: str | None) -> None:
    """Write ``data`` to a locked temporary file, then rename it over ``target``.

    The content check comes last, right before the rename, after the slow part (writing
    and ``fsync``): an edit saved while we flushed is still seen. The temporary file stays
    locked (``flock``) until it is renamed or removed, which is how a later run tells a
    temporary file left by a killed run (unlocked: safe to remove) from one a running
    ezmigrate is still writing (locked: left alone), see ``remove_stale_temporary``.
    """
    folder = target.parent
    try:
        fd, temp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=TEMP_SUFFIX, dir=folder)
    except OSError as error:
        raise WriteRefused(f"{path}: cannot create a temporary file in {folder} "
                           f"({error.strerror})") from error
    try:
        try:  # closing the file flushes again and may fail again: it is inside too
            with os.fdopen(fd, "wb") as handle:
                with suppress(OSError):  # a file system without locks: no stale detection
                    fcntl.flock(handle.fileno(), fcntl.LOCK_EX | fcntl.LOCK_NB)
                handle.write(data)
                handle.flush()
                os.fsync(handle.fileno())
                os.chmod(temp, mode)
                if info is not None and (info.st_uid, info.st_gid) != _owner(temp):
                    with suppress(OSError):  # only root may give a file away
                        os.chown(temp, info.st_uid, info.st_gid)
                _check_unchanged(path, target, expected_digest)
                os.replace(temp, target)
        except OSError as error:
            raise WriteRefused(f"{path}: could not be written ({error.strerror}), "
                               "left as it was") from error
    except BaseException:
        with suppress(OSError):
            os.unlink(temp)
        raise
    _sync_folder(folder)


def _owner(path: str) -> tuple[int, int]:
    info = os.stat(path)
    return info.st_uid, info.st_gid


def _sync_folder(folder: Path) -> None:
    """Flush the folder entry of the rename (best effort: not every platform allows it)."""
    try:
        fd = os.open(folder, os.O_RDONLY)
    except OSError:
        return
    try:
        with suppress(OSError):
            os.fsync(fd)
    finally:
        os.close(fd)


TEMP_NAME = re.compile(r"\A\..+\.[a-z0-9_]{8}" + re.escape(TEMP_SUFFIX) + r"\Z", re.S)
"""Names ``_replace`` gives its temporary files (``tempfile.mkstemp``'s 8 random characters)."""


def is_temporary_name(name: str) -> bool:
    """Whether ``name`` is one of our temporary file names (never a ``.py`` file)."""
    return TEMP_NAME.match(name) is not None


def remove_stale_temporary(path: Path) -> bool:
    """Remove a temporary file of ours that no running write holds; ``False``: left alone.

    Safe because such a file is never the only copy of anything: ``os.replace`` either
    happened (then this name is gone) or not (then the original is whole and the file holds
    a migration that the next run computes again). A live writer keeps its temporary file
    locked until the rename, so a lock we can take means its writer is gone (SIGKILL, power
    cut). Symlinks and anything but a regular file are left alone.
    """
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK)
    except OSError:
        return False
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        opened = os.fstat(fd)
        named = os.lstat(path)
        if not stat.S_ISREG(opened.st_mode) or (opened.st_dev, opened.st_ino) != (
                named.st_dev, named.st_ino):
            return False
        os.unlink(path)
        return True
    except OSError:  # locked by a running write, or gone meanwhile
        return False
    finally:
        os.close(fd)


def leftover_temporaries(folder: Path) -> list[Path]:
    """Temporary files of ours under ``folder`` (there should never be any after a run)."""
    return sorted(p for p in folder.rglob(f".*{TEMP_SUFFIX}") if p.is_file())
