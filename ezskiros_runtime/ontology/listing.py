"""``os.walk`` for the searches of one command, each folder listed once.

``check`` searches one repository four times before it reads a file: for its Python files,
its ``owl/`` folders, its scenes and its launch files (and the packages those name). Each
search lists the same folders again; on the 21 public repositories a listing of them all
costs a run about 10 ms of system calls and directory entries every time. Within
``shared_listings`` (which ``vendored.shared_rules`` enters for the searches of one
command) a folder is listed once, by whichever search gets there first (``remember``, for
a search that lists folders itself), and ``walk`` answers from that listing exactly as
``os.walk`` would from its own: top down, folders listed in the order the system gives
them, a folder that cannot be listed passed over, symbolic links to folders listed but not
entered. Outside it (a robot's runtime, a test that changes a tree between two walks)
``walk`` is ``os.walk``.

Runs on the robot's Python 3.8.
"""

from __future__ import annotations

import contextlib
import os
from typing import FrozenSet, Iterable, Iterator, Tuple

Listing = Tuple[Tuple[str, ...], Tuple[str, ...], FrozenSet[str]]
"""A folder's sub-folders and other entries (names, in the system's order), and which of
the sub-folders are symbolic links."""

_listings: dict[str, Listing | None] | None = None


@contextlib.contextmanager
def shared_listings() -> Iterator[None]:
    """Within it, ``walk`` lists each folder once (a listing kept by its absolute path)."""
    global _listings
    outer, _listings = _listings, {}
    try:
        yield
    finally:
        _listings = outer


def walk(top: str | os.PathLike[str]) -> Iterator[tuple[str, list[str], list[str]]]:
    """``os.walk(top)``: ``(folder, sub-folders, other names)``, top down; the caller may
    prune the sub-folders it is given, as with ``os.walk``."""
    if _listings is None:
        yield from os.walk(top)
        return
    yield from _walk(os.fspath(top))


def _walk(top: str) -> Iterator[tuple[str, list[str], list[str]]]:
    listing = _listed(top)
    if listing is None:
        return
    folders, others, links = listing
    dirs = list(folders)
    yield top, dirs, list(others)
    for name in dirs:
        if name not in links:
            yield from _walk(os.path.join(top, name))


def remember(folder: str | os.PathLike[str], entries: Iterable[os.DirEntry[str]]) -> None:
    """Keep the listing of ``folder`` a search made itself (its entries in the system's
    order), for the ``walk`` of the searches after it."""
    if _listings is not None:
        _listings[os.path.abspath(folder)] = _listing(entries)


def _listed(folder: str) -> Listing | None:
    assert _listings is not None
    key = os.path.abspath(folder)
    if key not in _listings:
        try:
            with os.scandir(folder) as entries:
                _listings[key] = _listing(entries)
        except OSError:  # as os.walk: a folder that cannot be listed yields nothing
            _listings[key] = None
    return _listings[key]


def _listing(entries: Iterable[os.DirEntry[str]]) -> Listing:
    """``os.walk``'s reading of a folder's entries: a folder is an entry ``is_dir`` says
    is one (following links; an entry it cannot tell is not one)."""
    folders: list[str] = []
    others: list[str] = []
    links = set()
    for entry in entries:
        try:
            is_dir = entry.is_dir()
        except OSError:
            is_dir = False
        if is_dir:
            folders.append(entry.name)
            with contextlib.suppress(OSError):  # os.walk's ``islink``: False on an error
                if entry.is_symlink():
                    links.add(entry.name)
        else:
            others.append(entry.name)
    return tuple(folders), tuple(others), frozenset(links)
