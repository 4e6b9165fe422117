"""Finding ontology files, reading them, and parsing them with rdflib.

Discovery and reading run on every load (their bytes are the cache key); parsing runs only
on a cache miss, so rdflib is imported inside `parse_ontology_file` and nowhere else on the
load path. Parse errors become `OntologyLoadError`s that name the file and, when the parser
knows it, the line: the user has to open that file and fix it.

Every parse goes through `parse_ontology_file`, so that is where an RDF/XML file's DTD is
vetted first (`dtd_guard`): a file is untrusted input, and one whose entities nest would
never finish parsing. A refusal is an `OntologyLoadError` like any other, so a discovered
file is skipped with one warning and a file named explicitly stops the load. The same goes
for a file over one of the size, triple, time or entity limits (`limits`): reading and
parsing are bounded, whatever the file holds.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .errors import OntologyLimitError, OntologyLoadError
from .limits import MAX_BYTES, ParseBudget, refuse

if TYPE_CHECKING:
    from rdflib import Graph

FORMAT_BY_EXTENSION: dict[str, str] = {
    ".owl": "xml",
    ".rdf": "xml",
    ".xml": "xml",
    ".ttl": "turtle",
    ".nt": "nt",
}
"""rdflib format names by file extension (lower-cased)."""

FALLBACK_FORMATS = ("xml", "turtle")
"""Tried in order for an explicitly named file whose extension says nothing."""

_FORMAT_TITLES = {"xml": "RDF/XML", "turtle": "Turtle", "nt": "N-Triples"}


class OntologyFile:
    """One file to load: where it is, how to parse it (None: guess), and its bytes.

    A plain class rather than a dataclass: this module is imported on every load, and
    generating a frozen dataclass costs more than the rest of the warm path.
    """

    __slots__ = ("data", "format", "path")

    def __init__(self, path: Path, format: str | None, data: bytes = b"") -> None:
        self.path = path
        self.format = format
        self.data = data

    def __repr__(self) -> str:
        return f"OntologyFile({str(self.path)!r}, {self.format!r}, {len(self.data)} bytes)"


def format_for(path: Path) -> str | None:
    """The rdflib format for a file name, or None for an extension we do not know."""
    return FORMAT_BY_EXTENSION.get(path.suffix.lower())


def collect_ontology_files(paths: Iterable[Path]) -> list[OntologyFile]:
    """Expand files and folders into the ordered list of files to load (no duplicates).

    Folders are searched recursively in sorted order, so the load order (and with it the
    cache key) does not depend on the file system; files with other extensions and hidden
    entries are skipped there (a folder may hold a readme). A file named explicitly is
    always loaded, guessing its format if the extension is unknown.
    """
    found: list[OntologyFile] = []
    seen: set[Path] = set()

    def add(path: Path, fmt: str | None) -> None:
        key = path.resolve()
        if key not in seen:
            seen.add(key)
            found.append(OntologyFile(key, fmt))

    for raw in paths:
        path = Path(raw).expanduser()
        if path.is_dir():
            in_folder = [
                candidate for candidate in _walk_sorted(path) if format_for(candidate) is not None
            ]
            if not in_folder:
                known = ", ".join(sorted(FORMAT_BY_EXTENSION))
                raise OntologyLoadError(
                    f"{path}: folder holds no ontology files ({known})", path=str(path)
                )
            for candidate in in_folder:
                add(candidate, format_for(candidate))
        elif path.is_file():
            add(path, format_for(path))
        else:
            raise OntologyLoadError(f"{path}: ontology file or folder not found", path=str(path))
    return found


def _walk_sorted(folder: Path) -> list[Path]:
    files: list[Path] = []
    for root, dirs, names in os.walk(folder):
        dirs[:] = sorted(d for d in dirs if not d.startswith("."))
        files.extend(Path(root) / n for n in sorted(names) if not n.startswith("."))
    return sorted(files, key=lambda p: p.relative_to(folder).parts)


def read_ontology_files(files: Iterable[OntologyFile]) -> list[OntologyFile]:
    """Read every file's bytes once: they are both hashed (cache key) and parsed.

    A file larger than ``limits.MAX_BYTES`` is refused (`OntologyLimitError`) before it
    is read whole: hashing 35 MB on every launch is already too slow for a robot."""
    loaded: list[OntologyFile] = []
    most = int(MAX_BYTES.value())
    for entry in files:
        try:
            with entry.path.open("rb") as stream:  # never more than the limit and one byte
                data = stream.read(most + 1)
        except OSError as error:
            raise OntologyLoadError(
                f"{entry.path}: cannot read ontology file: {error.strerror or error}",
                path=str(entry.path),
            ) from error
        if len(data) > most:
            raise refuse(entry.path, f"it is larger than {most:,} bytes", MAX_BYTES)
        loaded.append(OntologyFile(entry.path, entry.format, data))
    return loaded


def parse_ontology_file(entry: OntologyFile) -> Graph:
    """Parse one file's bytes into a fresh rdflib Graph (imports rdflib on first use).

    Each file gets its own graph so a failed attempt (guessing the format) leaves nothing
    behind, and so the caller knows which file each triple came from.
    """
    import rdflib

    formats = (entry.format,) if entry.format else FALLBACK_FORMATS
    if "xml" in formats:
        _refuse_unsafe_dtd(entry)
    failures: list[tuple[str, BaseException]] = []
    bounded = _bounded_graph_type(rdflib)
    for fmt in formats:
        budget = ParseBudget(entry.path)
        graph = bounded(budget)
        try:
            graph.parse(data=entry.data, format=fmt, publicID=entry.path.as_uri())
        except OntologyLimitError:
            raise  # over a limit is not "does not parse": no other format is tried
        except Exception as error:  # rdflib raises many unrelated types; all mean "bad file"
            limit = _limit_error_inside(error)
            if limit is not None:  # a parser that wrapped our refusal in its own error
                raise limit from None
            failures.append((fmt, error))
            continue
        budget.check_clock()
        return graph
    raise _load_error(entry, failures)


def _bounded_graph_type(rdflib: Any) -> Any:
    """An ``rdflib.Graph`` whose ``add`` counts against a `ParseBudget`.

    Every parser of rdflib 4.2.2 to 7 (RDF/XML, Turtle, N-Triples) hands its triples to the
    graph's ``add``, so this one hook bounds the triples and the time of any parse without
    touching rdflib's internals. Made once per process (rdflib is imported lazily)."""
    global _BOUNDED_GRAPH
    if _BOUNDED_GRAPH is None:

        class BoundedGraph(rdflib.Graph):
            """A graph that refuses its triple past the budget."""

            def __init__(self, budget: ParseBudget) -> None:
                super().__init__()
                self._budget = budget

            def add(self, triple: Any) -> Any:
                self._budget.tick()
                return super().add(triple)

        _BOUNDED_GRAPH = BoundedGraph
    return _BOUNDED_GRAPH


_BOUNDED_GRAPH: Any = None


def _limit_error_inside(error: BaseException) -> OntologyLimitError | None:
    """Our refusal when a parser re-raised it inside its own exception, else None."""
    seen = 0
    current: BaseException | None = error
    while current is not None and seen < 8:
        if isinstance(current, OntologyLimitError):
            return current
        current = current.__cause__ or current.__context__
        seen += 1
    return None


def _refuse_unsafe_dtd(entry: OntologyFile) -> None:
    """Raise when the file's DTD may not reach rdflib (``dtd_guard`` says why and where)."""
    from .dtd_guard import refusal  # (a load the cache answers parses nothing)

    found = refusal(entry.data)
    if found is not None and found.limit is not None:
        raise refuse(entry.path, found.reason, found.limit, line=found.line)
    if found is not None:
        raise OntologyLoadError(
            f"{entry.path}:{found.line}: refused before parsing: {found.reason}; an "
            "ontology file's DTD may only declare flat entities such as "
            '<!ENTITY owl "http://www.w3.org/2002/07/owl#">',
            path=str(entry.path),
            line=found.line,
        )


def _load_error(
    entry: OntologyFile, failures: list[tuple[str, BaseException]]
) -> OntologyLoadError:
    attempts = [(fmt, error, _error_line(error, entry.data, fmt)) for fmt, error in failures]
    if len(attempts) == 1:
        fmt, error, line = attempts[0]
        where = f"{entry.path}:{line}" if line else str(entry.path)
        return OntologyLoadError(
            f"{where}: cannot parse as {_FORMAT_TITLES.get(fmt, fmt)}: {_error_text(error)}",
            path=str(entry.path),
            line=line,
        )
    tried = "; ".join(
        f"as {_FORMAT_TITLES.get(fmt, fmt)}"
        + (f" (line {line})" if line else "")
        + f": {_error_text(error)}"
        for fmt, error, line in attempts
    )
    return OntologyLoadError(
        f"{entry.path}: unknown extension and the content does not parse {tried}",
        path=str(entry.path),
        line=attempts[-1][2],
    )


def _error_line(error: BaseException, data: bytes, fmt: str) -> int | None:
    """The 1-based line of a parse error, from whatever the rdflib parser exposes."""
    if fmt == "nt":
        return _first_bad_n_triples_line(data)
    get_line = getattr(error, "getLineNumber", None)  # xml.sax.SAXParseException
    if callable(get_line):
        try:
            line = get_line()
        except Exception:
            line = None
        if isinstance(line, int) and line > 0:
            return line
    lines = getattr(error, "lines", None)  # notation3.BadSyntax: newlines before the error
    if isinstance(lines, int) and lines >= 0:
        return lines + 1
    return None


def _first_bad_n_triples_line(data: bytes) -> int | None:
    """The first line that does not parse on its own, or None.

    rdflib's N-Triples errors carry no line number, but the format is one triple per line,
    so on this error-only path each line is re-parsed alone to find the culprit.
    """
    import rdflib

    for number, text in enumerate(data.decode("utf-8", "replace").splitlines(), start=1):
        if not text.strip() or text.lstrip().startswith("#"):
            continue
        try:
            rdflib.Graph().parse(data=text + "\n", format="nt")
        except Exception:
            return number
    return None


def _error_text(error: BaseException) -> str:
    why = getattr(error, "_why", None)  # BadSyntax's str() repeats the whole document
    if isinstance(why, str) and why:
        return why
    message = getattr(error, "getMessage", None)
    if callable(message):
        try:
            return str(message())
        except Exception:
            pass
    text = str(error).strip() or type(error).__name__
    return text if len(text) <= 300 else text[:297] + "..."
