"""The folder ``check`` keeps its caches in (the loads, the files' readings, whole runs),
and how an entry is written there. Apart from the caches themselves: a run its cache
answers writes nothing and reads one entry, and imports no more than this to find it."""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

FOLDER = ".ezmigrate_cache"


def write_entry(cache: Path, folder: str, name: str, text: str | bytes) -> None:
    """``cache/folder/name`` holding ``text``, written whole (a temporary file renamed into
    place); the cache folder gets its ``.gitignore`` when it is made. A read-only checkout
    keeps nothing: same results, no cache."""
    try:
        if not cache.exists():
            cache.mkdir(parents=True)
            (cache / ".gitignore").write_text("# made by ezmigrate check\n*\n")
        (cache / folder).mkdir(exist_ok=True)
        handle, temporary = tempfile.mkstemp(dir=cache / folder, suffix=".tmp")
        with os.fdopen(handle, "wb") as stream:
            stream.write(text.encode("utf-8") if isinstance(text, str) else text)
        os.replace(temporary, cache / folder / name)
    except OSError:
        return
