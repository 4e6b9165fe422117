"""The LibCST baseline of ``bench/bench_repo.py``: a codemod that changes nothing.

Run by LibCST's own runner over the same tree as ezmigrate::

    python -m libcst.tool codemod -x -j 2 --no-format --hide-progress \
        bench.noop_codemod.NoOp TREE

Every file is read, parsed, wrapped for metadata and visited by a transformer that
returns every node unchanged, then printed back and compared with the original (equal, so
nothing is written): the fixed cost of any LibCST codemod, which is what ezmigrate is
measured against.
"""

from __future__ import annotations

from libcst.codemod import VisitorBasedCodemodCommand


class NoOp(VisitorBasedCodemodCommand):
    """Visit every node, change nothing."""

    DESCRIPTION = "A codemod that changes nothing (benchmark baseline)."
