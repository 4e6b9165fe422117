"""Early cutoff: a changed file whose reading did not change changes no finding, so the
run before answers the run (issue 40: "when one file changes, analyse again what depends
on it, not everything").

Build systems call this early cutoff: an artifact rebuilt equal to the old one stops the
rebuild there. Here the artifact is what the read stage takes of a file, all that the later
stages (per-file checks, the skill index, the trees, the world model, the judgements) know
of it: its facts (``file_facts.FileFacts``, as the facts cache writes them: one text per
reading, ``facts_codec``), the few things a later stage reads from the bytes themselves
(``BYTE_MARKERS`` and ``PATTERNS``: whether the text holds ``expand``, ``setDescription``
and the like, the file's own ROS imports), and the lines the file's findings stand on
(their columns are taken from them). When the Python files a run reads are those of a
kept run but for a few whose bytes changed, those few are read (their facts are kept for
the read stage, which takes them if the run goes on); when each one's artifact is what it
was, the kept run's outcome is this run's, and no other stage runs. A comment, a blank
line at the end, a change inside a method that reads nothing a check reads: the run costs
a read of the changed file. A change that moves a line or a declaration: every stage runs.

It does not apply, and the run goes through every stage, when a file was added or removed
or anything but Python files changed (scenes, launch file, manifests, ontology, settings:
all in the key), under ``--trace``, when the trees are not read (the judgements then parse
implementations themselves), or when a changed file is one the codemod reads
(``Declined``), an EzSkiROS file that is not ASCII (the world stage reads its lines from
its text), one the read stage does not parse (its bytes are its artifact, and for a star
import's module its code), or one whose bytes another file's reading may take (a module a
declined file's foreign bases name: ``CheckRun.shared``).
"""

from __future__ import annotations

import json
from collections.abc import Iterable
from typing import Any

from ..cache.cache_folder import Store
from ..cache.facts_cache import FactsCache
from ..cache.outcome_cache import OutcomeCache, content_digest
from ..compound.markers import ROS1_IMPORT, ROS2_IMPORT, SCAN_WHEN
from ..files.discover import Candidate
from ..lint.diagnostic import Diagnostic
from ..project.cross_file import RUNTIME_MARKER
from .run import CheckOutcome, CheckRun, text_of

MEMOS = "cutoff"
"""The sub-folder of a project's cache folder the memos are kept in."""
MOST_CHANGED = 8
"""More changed files than this: the whole run is cheaper than reading them one by one."""
BYTE_MARKERS: tuple[bytes, ...] = (*SCAN_WHEN, RUNTIME_MARKER)
"""Text a later stage looks for in a file's bytes rather than in its facts (the skill index,
the repository scan, the judgements, the compound pass). ``tests/project/test_early_cutoff``
keeps this list whole."""
PATTERNS = (ROS2_IMPORT, ROS1_IMPORT)
"""Patterns a later stage matches on a file's bytes (``analysis.ros_package_of``)."""
UNPARSED = "unparsed"
"""The facts of a file the read stage does not parse (``read_files.never_parsed``): what
the later stages take of it is its markers, and a star import's names (its code)."""


def signature(data: bytes, facts: str | None, star_source: bool = False) -> str:
    """A file's artifact: the digest of its facts' text and what a stage reads of its bytes,
    the words of its imports (the codemod's cross-file pass picks the siblings it reads by
    them), and for a ``star_source`` its code (``file_facts.code_digest``: what the star
    imports' readings took of it); for a file without facts, or one that is never cut off
    (None), its bytes."""
    from ..project.import_scan import import_words
    from .file_facts import code_digest_of

    if facts is None:
        return f"bytes:{content_digest(data)}"
    bits = "".join("1" if marker in data else "0" for marker in BYTE_MARKERS)
    bits += "".join("1" if pattern.search(data) else "0" for pattern in PATTERNS)
    words = content_digest(b"\0".join(sorted(import_words(data))))
    return f"{facts}:{bits}:{words}" + (f":{code_digest_of(data)}" if star_source else "")


def never_cut_off(data: bytes, path: str, shared: Iterable[str]) -> bool:
    """A file whose bytes are its artifact: another file's reading took them (``shared``),
    or it is an EzSkiROS file the world stage reads from its text (not ASCII:
    ``FileFacts.posts``)."""
    return path in shared or (RUNTIME_MARKER in data and not data.isascii())


def lines_digest(text: str, lines: Iterable[int]) -> str:
    """The digest of the lines of ``text`` the findings of its file stand on (split as
    ``Positions`` splits them), and of which of them the file has."""
    rows = text.splitlines()
    picked = [rows[n - 1] if 1 <= n <= len(rows) else "\0" for n in sorted(set(lines))]
    return content_digest("\n".join(picked).encode("utf-8", "surrogateescape"))


def remember(run: CheckRun) -> None:
    """Keep what the next run needs to cut off early: each Python file's bytes, artifact and
    finding lines, and the key of this run's outcome (kept by ``keep``)."""
    cache, folder = run.facts_cache, run.settings.cache_dir
    if run.cutoff_key is None or run.kept_key is None or cache is None or folder is None:
        return
    store = Store.open(folder)
    if store is None:
        return
    lines: dict[str, set[int]] = {}
    for found in run.outcome.diagnostics:
        lines.setdefault(found.path, set()).add(found.line)
    files: dict[str, list[str]] = {}
    for candidate, data in run.read:
        path = str(candidate.path)
        key = run.fact_keys.get(path)  # None: the read stage did not parse it
        facts = None if never_cut_off(data, path, run.shared) \
            else cache.digest(key) if key is not None else UNPARSED
        files[path] = [content_digest(data), signature(data, facts, path in run.star_sources),
                       lines_digest(text_of(data), lines.get(path, ()))]
    payload = {"outcome": run.kept_key, "files": files, "shared": sorted(run.shared),
               "star_sources": sorted(run.star_sources)}
    store.write(f"{MEMOS}/{run.cutoff_key}.json", json.dumps(payload).encode("utf-8"))


def recall(run: CheckRun, data: dict[str, bytes], digests: dict[str, str]
           ) -> CheckOutcome | None:
    """The outcome of a run whose changed Python files (``data``: every input's bytes by
    path; ``digests``: their ``content_digest``) read as they did in the kept run (see the
    module doc); None when the run must go through every stage. The changed files' facts
    go to the facts cache either way."""
    settings = run.settings
    if run.cutoff_key is None or settings.cache_dir is None or settings.trace \
            or not settings.compounds:
        return None
    store = Store.open(settings.cache_dir)
    memo = _memo(store, run.cutoff_key) if store is not None else None
    if memo is None or set(memo["files"]) != {str(c.path) for c in run.candidates}:
        return None
    changed = [c for c in run.candidates
               if digests[str(c.path)] != memo["files"][str(c.path)][0]]
    if not changed or len(changed) > MOST_CHANGED:
        return None
    outcomes = OutcomeCache(settings.cache_dir)
    kept = outcomes.get(str(memo["outcome"]))
    cache = FactsCache.open(settings.cache_dir)
    if kept is None or cache is None:
        return None
    run.facts_cache = cache  # the read stage takes what this reads
    same = all(_reads_as_before(run, cache, c, data[str(c.path)], memo, kept["diagnostics"])
               for c in changed)
    cache.save()
    if not same:
        return None
    for candidate in changed:
        memo["files"][str(candidate.path)][0] = digests[str(candidate.path)]
    assert store is not None and run.kept_key is not None
    memo["outcome"] = run.kept_key
    outcomes.put(run.kept_key, kept["files"], kept["skills"], kept["notes"],
                 kept["diagnostics"])
    store.write(f"{MEMOS}/{run.cutoff_key}.json", json.dumps(memo).encode("utf-8"))
    return CheckOutcome(files=kept["files"], skills=kept["skills"],
                        diagnostics=kept["diagnostics"], notes=kept["notes"])


def _reads_as_before(run: CheckRun, cache: FactsCache, candidate: Candidate, data: bytes,
                     memo: dict[str, Any], kept: Iterable[Diagnostic]) -> bool:
    """Whether a changed file's artifact and the lines its kept findings stand on are the
    kept run's."""
    path = str(candidate.path)
    before = memo["files"][path]
    lines = {found.line for found in kept if found.path == path}
    return _artifact(run, cache, candidate, data, memo) == before[1] \
        and lines_digest(text_of(data), lines) == before[2]


def _artifact(run: CheckRun, cache: FactsCache, candidate: Candidate, data: bytes,
              memo: dict[str, Any]) -> str:
    """The artifact of a changed file, read as the read stage reads it (its facts kept in
    ``cache`` for that stage); its bytes when it is a file that is never cut off (as the
    kept run found it: ``memo``)."""
    from ..files.prefilter import by_text
    from ..lint.plain_reader import Declined
    from .file_facts import file_facts
    from .read_files import facts_key, never_parsed, static_against

    verdict, star_source = by_text(data), str(candidate.path) in memo["star_sources"]
    if never_cut_off(data, str(candidate.path), memo["shared"]):
        return signature(data, None)
    if never_parsed(data, verdict, True):
        return signature(data, UNPARSED, star_source)
    key = facts_key(cache, candidate, data, True, static_against(run))
    facts = cache.get(key)
    if facts is None:
        facts = file_facts(candidate, data, True, verdict, statically=True)
        cache.put(key, facts)
    digest = cache.digest(key)
    declined = isinstance(facts.static, Declined) and facts.settled is None
    if digest is None or facts.depends or declined:  # the codemod reads its bytes
        return signature(data, None)
    return signature(data, digest, star_source)


def _memo(store: Store, key: str) -> dict[str, Any] | None:
    """The memo of ``key`` when it is signed by this user's key and well formed."""
    payload = store.read(f"{MEMOS}/{key}.json")
    try:
        memo = json.loads(payload) if payload is not None else None
    except ValueError:
        return None
    if not isinstance(memo, dict) or not isinstance(memo.get("outcome"), str) \
            or not isinstance(memo.get("files"), dict) \
            or not all(isinstance(memo.get(name), list) and all(isinstance(p, str)
                                                               for p in memo[name])
                       for name in ("shared", "star_sources")) \
            or not all(isinstance(v, list) and len(v) == 3 and all(isinstance(x, str) for x in v)
                       for v in memo["files"].values()):
        return None
    return memo
