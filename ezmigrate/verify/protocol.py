"""What crosses the process boundary during verification: load jobs and their outcomes.

A job says which file to import (and, for a rewrite not yet written, the bytes to import
instead of the file's own); an outcome carries the models, class errors, check findings,
traced compound skills and captured output, or why the load failed. Both travel as JSON
and are rebuilt as the project's own types on arrival (``from_json``): class errors and
findings as the runtime's one ``Finding``, traced trees as ``CompoundModel``
or ``Unanalysable``, so no reader digs in dictionaries. Models keep their canonical JSON
(``SkillModel.to_json``), the form reports and comparisons are defined on.
"""

from __future__ import annotations

import base64
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Literal

from ezskiros_runtime.diagnostics import Finding

if TYPE_CHECKING:
    from ezskiros_runtime.compound.model import CompoundModel
    from ezskiros_runtime.compound.trace import Unanalysable

QUIT = '{"quit": true}'
"""The pool's last line to a worker: serve no more. Said, not left to the end of stdin: a
process forked from the pool's (a reading worker) holds a copy of the pipe, and stdin ends
only when every copy is closed."""

Status = Literal["ok", "import-error", "syntax", "timeout", "crashed", "exit", "memory"]


@dataclass
class LoadJob:
    """Import ``path`` (or ``source`` in its place, keeping its package layout)."""

    path: str
    source: bytes | None = None
    root: str | None = None
    overlays: dict[str, bytes] = field(default_factory=dict)
    """Sibling modules (absolute path -> bytes) to import from memory instead of disk."""
    trace: list[str] = field(default_factory=list)
    """Compound skill classes whose ``expand`` to trace once the module is loaded."""
    collect: bool = True
    """Read and check the module's descriptions (False: a load only to trace)."""
    more: list[LoadJob] = field(default_factory=list)
    """Further loads for the same child, one after the other (``LoadOutcome.more``): a
    batch pays for one fork and one cold start instead of one each."""

    def to_json(self) -> dict[str, Any]:
        return {"path": self.path, "root": self.root,
                "source": None if self.source is None else _encode(self.source),
                "overlays": {p: _encode(data) for p, data in self.overlays.items()},
                "trace": self.trace, "collect": self.collect,
                "more": [job.to_json() for job in self.more]}

    @classmethod
    def from_json(cls, data: dict[str, Any]) -> LoadJob:
        raw = data.get("source")
        overlays = {p: base64.b64decode(v) for p, v in data.get("overlays", {}).items()}
        return cls(data["path"], None if raw is None else base64.b64decode(raw),
                   data.get("root"), overlays, list(data.get("trace", ())),
                   bool(data.get("collect", True)),
                   [cls.from_json(job) for job in data.get("more", ())])


def _encode(data: bytes) -> str:
    return base64.b64encode(data).decode("ascii")


@dataclass
class LoadOutcome:
    """The result of one load. ``models`` are ``SkillModel.to_json()`` dicts."""

    status: Status
    message: str = ""
    line: int | None = None
    models: list[dict[str, Any]] = field(default_factory=list)
    errors: list[Finding] = field(default_factory=list)
    """The classes that could not be loaded (``class_error``), one finding each."""
    findings: list[Finding] = field(default_factory=list)
    stdout: str = ""
    stderr: str = ""
    seconds: float = 0.0
    stood_in: list[str] = field(default_factory=list)
    """Unresolvable imports that got a permissive stand-in (ROS and SkiROS2 aside)."""
    newer_syntax: bool = False
    """The file failed on syntax newer than the interpreter that loaded it."""
    python: str = ""
    """The interpreter that loaded the file when it was not ezmigrate's own."""
    compounds: list[CompoundModel | Unanalysable] = field(default_factory=list)
    """Traced compound skills (``LoadJob.trace``)."""
    more: list[LoadOutcome] = field(default_factory=list)
    """The outcomes of ``LoadJob.more``, in order; fewer when the child died on the way."""
    read: list[str] = field(default_factory=list)
    """Files of the repository the load opened (a module ``importlib`` loaded, a data file
    read at import: ``child.reads``), whose bytes a kept load depends on."""
    unread: list[tuple[str, int, str]] = field(default_factory=list)
    """A file read from its syntax (``check`` without ``--trace``): the classes that are or
    may be descriptions and were not read, each with the shape that stopped the reading
    (empty for a class that merely derives from a class of another module)."""

    def to_json(self) -> dict[str, Any]:
        return {**{name: getattr(self, name) for name in self.__dataclass_fields__},
                "errors": [e.to_json() for e in self.errors],
                "findings": [f.to_json() for f in self.findings],
                "compounds": [compound_json(c) for c in self.compounds],
                "more": [o.to_json() for o in self.more]}

    @classmethod
    def from_json(cls, data: dict[str, Any]) -> LoadOutcome:
        return cls(**{**data,
                      "errors": [Finding.from_json(e) for e in data.get("errors", ())],
                      "findings": [Finding.from_json(f) for f in data.get("findings", ())],
                      "compounds": [compound_of(c) for c in data.get("compounds", ())],
                      "more": [cls.from_json(item) for item in data.get("more", ())]})

    @property
    def loaded(self) -> bool:
        return self.status == "ok"


def compound_of(data: dict[str, Any]) -> CompoundModel | Unanalysable:
    """A traced tree from its JSON (``FileLoad.compounds``): the model, or why none."""
    from ezskiros_runtime.compound.model import model_from_json
    from ezskiros_runtime.compound.trace import Unanalysable

    if "unanalysable" in data:
        return Unanalysable(str(data.get("implementation", "")), str(data["unanalysable"]),
                            int(data.get("line") or 0))
    return model_from_json(data)


def compound_json(found: CompoundModel | Unanalysable) -> dict[str, Any]:
    """``compound_of``'s inverse."""
    from ezskiros_runtime.compound.trace import Unanalysable

    if isinstance(found, Unanalysable):
        return {"implementation": found.implementation, "unanalysable": found.reason,
                "line": found.line}
    return found.to_json()
