"""What ``check`` reads of one file, from the file alone: made once per content.

A file that may hold a description is parsed once, and three passes read its syntax tree:
the static reader (``lint/plain_reader``: its plain legacy descriptions, or ``Declined``:
the codemod takes it), the compound pass (``compound.analysis.tree_facts``) and the checks
inside implementations (``implementation_code.module_facts``). Their readings depend on the
file's path and bytes and nothing else, so the tree is dropped as soon as they are taken
(a repository's trees kept alive slow every garbage collection) and ``facts_cache`` keeps
them from one run to the next.
"""

from __future__ import annotations

import ast
import functools
import hashlib
from dataclasses import dataclass, replace
from pathlib import Path

from ezskiros_runtime.compound.model import CompoundModel
from ezskiros_runtime.compound.trace import Unanalysable

from ..codemod.core.python2 import python2_refusal
from ..compound.analysis import TreeFacts, tree_facts
from ..compound.markers import READ_WHEN, SCAN_WHEN
from ..compound.repository import Recovered, recover_classes
from ..compound.static import NeedsTrace, module_tree
from ..files.discover import Candidate
from ..files.prefilter import marker_is_identifier
from ..lint.ezskiros_reader import read_ezskiros
from ..lint.newer_fstrings import older_spelling
from ..lint.plain_reader import Declined, read_plain
from ..project.cross_file import RUNTIME_MARKER
from ..report.results import FileResult
from ..verify.protocol import LoadOutcome
from .implementation_code import ModuleFacts, module_facts


@dataclass(frozen=True)
class FileFacts:
    """``static``: the plain reading, or ``Declined`` (the codemod reads the file);
    ``trees`` and ``implementation``: what the compound pass and the implementation checks
    take (None when the file has nothing for them, or they were not asked for)."""

    static: FileResult | Declined
    trees: TreeFacts | None = None
    implementation: ModuleFacts | None = None
    described: bool = True
    """False: the prefilter ruled the file out (``by_text``, ``marker_is_identifier``): no
    description is read in it; ``trees`` then holds what the compound pass will take of
    it, if it parses (``Trees.prepared``)."""
    settled: FileResult | None = None
    """For a declined file, the codemod's reading when the syntax alone gives it (an
    EzSkiROS file: ``ezskiros_reader``; Python 2 syntax: ``python2_refusal``): ``settle``
    takes it instead of parsing the file with libcst."""
    unparsed: tuple[Recovered] | None = None
    """For a file ``ast`` cannot parse (Python 2) that the repository scan reads
    (``SCAN_WHEN``), what ``recover_classes`` makes of it (one item: it may itself be
    None), for that scan (``Trees.recovered``)."""
    parsed: bool = False
    """``ast`` read the file: the repository scan need not parse it again to learn that
    (``Trees.parsed``)."""
    depends: tuple[tuple[str, str], ...] = ()
    """``(path, code_digest)`` of the other files the reading read (the lab's modules its
    star imports name, ``static.star_sources``): a kept reading is one of this code too."""
    loaded: LoadOutcome | None = None
    """For an EzSkiROS file read ``statically``, what loading it would give, read from the
    same syntax tree against the active ontology (``lint/ezskiros_static``): taken here, in
    the reading pool's workers, instead of parsing the file a second time in the main
    process. It depends on the ontology, which the cache's key then names."""
    posts: dict[str, list[tuple[int, str]]] | None = None
    """With ``loaded``, the lines of the file's post-conditions (``world_model.post_lines``)
    for the world model's EZ401, taken from the same tree (an ASCII file's: a tree's
    columns count the bytes of its text as UTF-8); None: the world stage reads them from
    the file's text."""

    def moved(self, to: Candidate) -> FileFacts:
        """The facts of a file with the same bytes at ``to``: a file's facts name its path
        in three places (the readings' ``FileResult.path``, the relative path, and the
        trees' ``CompoundModel.path``) and depend on nothing else of it, so a workspace's
        copies of one package (a fork beside its upstream, a vendored copy) are read once.
        """
        assert not self.depends, "a reading that read other files is not moved"
        path, relative = str(to.path), to.relative
        static = replace(self.static, path=relative) \
            if isinstance(self.static, FileResult) else self.static
        settled = replace(self.settled, path=relative) if self.settled is not None else None
        trees = None if self.trees is None else replace(self.trees, found=tuple(
            _moved(f, path) for f in self.trees.found))
        # the static load's findings name the file: the copy's is read where it is needed
        return replace(self, static=static, settled=settled, trees=trees, loaded=None,
                       posts=None)


def parse(data: bytes) -> ast.Module | None:
    """The module's syntax tree, or None when ``ast`` cannot read it (the codemod says why)."""
    tree = _parse(data)
    return tree if isinstance(tree, ast.Module) else None


def _parse(data: bytes) -> ast.Module | SyntaxError | None:
    """``parse``, with the error when ``ast`` refuses the syntax."""
    try:
        return ast.parse(data)
    except SyntaxError as error:
        return error
    except (ValueError, UnicodeError, LookupError, MemoryError, RecursionError):
        return None


def _moved(found: CompoundModel | Unanalysable | NeedsTrace, path: str
           ) -> CompoundModel | Unanalysable | NeedsTrace:
    """A tree's reading moved to the file at ``path`` (a partial one's model too)."""
    if isinstance(found, CompoundModel):
        return replace(found, path=path)
    if isinstance(found, NeedsTrace) and found.partial is not None:
        return replace(found, partial=replace(found.partial, path=path))
    return found


def file_facts(candidate: Candidate, data: bytes, compounds: bool,
               verdict: bool | None = True, statically: bool = False) -> FileFacts:
    """The facts of a file; ``compounds``: also what the compound pass and the
    implementation checks read; ``statically``: an EzSkiROS file's descriptions too, read
    from its syntax (``FileFacts.loaded``). ``verdict``: the prefilter's text on it
    (``by_text``); when it could not tell (None) the prefilter's parse is taken here, in
    the reading pool's workers and kept by the cache, rather than file by file in the main
    process. A file
    ruled out (``described`` False) is parsed only for the compound pass (a tree or an
    implementation outside a description file) and the repository scan (a description
    class; ``SCAN_WHEN``), and read only when it parses."""
    described = verdict is True or (verdict is None and marker_is_identifier(data))
    read_when = compounds and any(m in data for m in READ_WHEN)
    scanned = compounds and any(m in data for m in SCAN_WHEN)
    if not described:
        tree = parse(data) if scanned else None
        return FileFacts(FileResult(path=candidate.relative), described=False,
                         trees=tree_facts(tree, str(candidate.path))
                         if tree is not None and read_when else None,
                         implementation=_implementation(tree, data),
                         unparsed=(recover_classes(data),) if scanned and tree is None
                         else None, parsed=tree is not None,
                         depends=_depends(tree, str(candidate.path))
                         if tree is not None and read_when else ())
    parsed = _parse(data)
    if not isinstance(parsed, ast.Module):
        settled = python2_refusal(candidate.relative, data, parsed) \
            if isinstance(parsed, SyntaxError) else None  # the codemod's answer too
        static = _newer_syntax(candidate.relative, data) \
            if isinstance(parsed, SyntaxError) and settled is None else Declined()
        return FileFacts(static, settled=settled,
                         unparsed=(recover_classes(data),) if scanned else None)
    tree = parsed
    runtime = RUNTIME_MARKER in data
    static = read_plain(data, candidate.relative, tree) if not runtime else Declined()
    settled = read_ezskiros(tree, candidate.relative) if runtime else None
    if not compounds:
        facts = FileFacts(static, settled=settled, parsed=True)
    else:
        trees = tree_facts(tree, str(candidate.path)) if read_when else None
        facts = FileFacts(static, trees, _implementation(tree, data), settled=settled,
                          parsed=True,
                          depends=_depends(tree, str(candidate.path)) if read_when else ())
    if runtime and statically:  # last: the reading may renumber the tree's annotations
        from ..lint.world_model import post_lines

        posts = post_lines(tree, data.decode("ascii")) if data.isascii() else None
        facts = replace(facts, loaded=static_load(tree, str(candidate.path)), posts=posts)
    return facts


def static_load(tree: ast.Module, path: str) -> LoadOutcome:
    """What loading the EzSkiROS module ``tree`` (the file ``path``) would give, read from
    its syntax against the active ontology: no code of the repository runs."""
    from ..lint.ezskiros_static import read_ezskiros_statically

    return read_ezskiros_statically(tree, path).outcome()


def _depends(tree: ast.Module, path: str) -> tuple[tuple[str, str], ...]:
    """``FileFacts.depends`` of a module whose trees were read."""
    from ..compound.static import star_sources

    found = []
    for source in star_sources(tree, path):
        digest = code_digest(source)
        if digest is not None:
            found.append((source, digest))
    return tuple(found)


def code_digest(path: str) -> str | None:
    """The digest of a module's code, not of its text: its syntax tree without positions
    (what a star import's reading takes of it is names, a function of that tree), so a
    comment or a moved line leaves it as it was; of its bytes when ``ast`` cannot parse
    it; None when it cannot be read."""
    try:
        return code_digest_of(Path(path).read_bytes())
    except OSError:
        return None


@functools.lru_cache(maxsize=64)
def code_digest_of(data: bytes) -> str:
    """``code_digest`` of a module's bytes. Kept by content: the modules a lab star-imports
    are imported by many of its files, each asking for their digest (``_depends``, and
    ``still_read`` on every run that takes a kept reading); parsed once with the star
    imports' reading of it (``static.module_tree``)."""
    tree = module_tree(data)
    if tree is None:
        return "bytes:" + hashlib.sha256(data).hexdigest()
    return hashlib.sha256(ast.dump(tree, include_attributes=False).encode()).hexdigest()


def still_read(facts: FileFacts) -> bool:
    """Whether every other file a reading read still holds the code it read."""
    return all(code_digest(path) == digest for path, digest in facts.depends)


def _newer_syntax(relative: str, data: bytes) -> FileResult | Declined:
    """The plain reading of a file that ``ast`` refused only for Python 3.12's f-strings
    (``older_spelling``: the same tree, read from bytes this Python parses); everything
    else ``check`` takes of the file stays as for a file ``ast`` cannot read."""
    tree = respelt(data) if RUNTIME_MARKER not in data else None
    return read_plain(data, relative, tree) if tree is not None else Declined()


def respelt(data: bytes) -> ast.Module | None:
    """The syntax tree of a module ``ast`` refuses only for Python 3.12's f-strings, read
    from the same code respelt for this Python (``older_spelling``); None otherwise."""
    older = older_spelling(data)
    return parse(older) if older is not None else None


def _implementation(tree: ast.Module | None, data: bytes) -> ModuleFacts | None:
    """What the implementation checks read of a parsed file that may implement a skill."""
    return module_facts(tree, data) if tree is not None and b"setDescription" in data else None
