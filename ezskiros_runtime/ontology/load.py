"""`load_index`: ontology files and folders to an `OntologyIndex`, through the cache.

Why apart from the index: building (`build.py`, rdflib) and caching (`cache.py`) both make
or read an `OntologyIndex`, and this is the one function that uses them both; with it in
`index.py`, the index module and the two it orchestrates imported one another.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from .bundled import bundled_ontology_path

if TYPE_CHECKING:
    from .index import OntologyIndex


def _as_path_list(
    paths: Sequence[str | os.PathLike[str]] | str | os.PathLike[str] | None,
) -> list[Path]:
    """Accept one path as well as a sequence: a bare string must not become its characters."""
    if paths is None:
        return []
    if isinstance(paths, (str, os.PathLike)):
        return [Path(paths)]
    return [Path(p) for p in paths]


def load_index(
    paths: Sequence[str | os.PathLike[str]] | None = None,
    *,
    cache: bool = True,
    cache_dir: Path | None = None,
) -> OntologyIndex:
    """Load ontology files and folders into an index; None or empty -> the bundled default.

    The file contents are hashed first; when the persistent cache holds an index for that
    hash it is returned without importing rdflib (the fast path every launch after the
    first takes). Otherwise the files are parsed with rdflib, indexed, and the result is
    cached. Raises `OntologyLoadError` naming the file that is missing or does not parse;
    a parse error is remembered too, so that a repository with a broken file among its
    ontologies (an empty `lth.owl`, which discovery then leaves out) does not import
    rdflib and parse on every run to hear it again.
    """
    _, index = _load(paths, cache, cache_dir, decode=True)
    assert index is not None  # (read from the cache, or built)
    return index


def probe_index(
    paths: Sequence[str | os.PathLike[str]] | None = None,
    *,
    cache: bool = True,
    cache_dir: Path | None = None,
) -> tuple[str, OntologyIndex | None]:
    """The fingerprint `load_index(paths)` would give its index, and the index when
    finding out took building it; raises what `load_index` raises.

    An index the cache holds is not decoded, nor its modules imported: a `check` the
    outcome cache answers needs the fingerprint alone (`config.settle_source`)."""
    return _load(paths, cache, cache_dir, decode=False)


def _load(
    paths: Sequence[str | os.PathLike[str]] | None,
    cache: bool,
    cache_dir: Path | None,
    decode: bool,
) -> tuple[str, OntologyIndex | None]:
    """`load_index`, or (``decode`` False) `probe_index`."""
    # Imported here, not at module level: the index module stays cheap to import for code
    # that only handles indexes, and `from .x import y` avoids the package's __getattr__.
    from .cache import (
        cache_path,
        default_cache_dir,
        read_cached_index,
        read_cached_refusal,
        write_cached_index,
        write_cached_refusal,
    )
    from .cache import fingerprint as content_fingerprint
    from .errors import OntologyLoadError
    from .parsing import collect_ontology_files, read_ontology_files

    requested = _as_path_list(paths) or [bundled_ontology_path()]
    files = read_ontology_files(collect_ontology_files(requested))
    sources = tuple(str(f.path) for f in files)
    fingerprint = content_fingerprint(files)
    directory = (cache_dir or default_cache_dir()) if cache else None
    if directory is not None:
        if not decode and cache_path(directory, fingerprint).is_file():
            return fingerprint, None  # (decoded, or rebuilt if unreadable, when loaded)
        cached = read_cached_index(directory, fingerprint) if decode else None
        if cached is not None:
            return fingerprint, \
                cached if cached.sources == sources else cached.with_sources(sources)
        refused = read_cached_refusal(directory, fingerprint, sources)
        if refused is not None:  # a file that did not parse does not parse now either
            raise refused
    from .build import build_index  # imports rdflib: only on a cache miss

    try:
        index = build_index(files, fingerprint)
    except OntologyLoadError as error:
        if directory is not None:
            write_cached_refusal(directory, fingerprint, sources, error)
        raise
    if directory is not None:
        write_cached_index(directory, index)
    return fingerprint, index
