"""Where the vocabulary shipped with the package lies.

Apart from the index because the searches ask for it before anything is loaded
(``config.resolve_ontology_paths`` puts it first among a repository's files), and a
``check`` the cache answers then never imports the index and its class expressions.

Runs on the robot's Python 3.8.
"""

from __future__ import annotations

from pathlib import Path

_DATA_DIR = Path(__file__).resolve().parent / "data"


def bundled_ontology_path() -> Path:
    """The vocabulary shipped with the package, used when nothing else is configured."""
    return _DATA_DIR / "skiros-core.ttl"
