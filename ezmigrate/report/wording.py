"""How a count reads in the one-line summaries (``1 file``, ``2 files``): apart from the
reports, so that a run the cache answers says its summary without importing them."""

from __future__ import annotations


def counted(number: int, noun: str) -> str:
    """``1 file``, ``2 files``: the summary reads as English."""
    return f"{number} {noun}" + ("" if number == 1 else "s")
