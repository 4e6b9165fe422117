"""What crosses the process boundary during verification: load jobs and their outcomes.

Plain JSON-ready dataclasses: a job says which file to import (and, for a rewrite not yet
written, the bytes to import instead of the file's own); an outcome carries the models,
class errors, check findings and captured output, or why the load failed.
"""

from __future__ import annotations

import base64
from dataclasses import asdict, dataclass, field
from typing import Any, Literal

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
    errors: list[dict[str, Any]] = field(default_factory=list)
    findings: list[dict[str, Any]] = field(default_factory=list)
    stdout: str = ""
    stderr: str = ""
    seconds: float = 0.0
    stood_in: list[str] = field(default_factory=list)
    """Unresolvable imports that got a permissive stand-in (ROS and SkiROS2 aside)."""
    newer_syntax: bool = False
    """The file failed on syntax newer than the interpreter that loaded it."""
    python: str = ""
    """The interpreter that loaded the file when it was not ezmigrate's own."""
    compounds: list[dict[str, Any]] = field(default_factory=list)
    """Traced compound skills (``LoadJob.trace``), as ``FileLoad.compounds``."""
    more: list[LoadOutcome] = field(default_factory=list)
    """The outcomes of ``LoadJob.more``, in order; fewer when the child died on the way."""

    def to_json(self) -> dict[str, Any]:
        return asdict(self)

    @classmethod
    def from_json(cls, data: dict[str, Any]) -> LoadOutcome:
        more = [cls.from_json(item) for item in data.get("more", ())]
        return cls(**{**data, "more": more})

    @property
    def loaded(self) -> bool:
        return self.status == "ok"
