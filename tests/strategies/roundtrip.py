"""Round trip of generated legacy modules through the real pipeline, for the property test.

``legacy_source`` writes legacy SkiROS2 modules as text; this module takes each one through
``migrate()``, writes both versions as real files, loads both in isolated children through
the verification pool (``ezmigrate.verify.pool.run_jobs``, one forked child per file) and
compares them with ``ezmigrate.verify.compare_files.compare_outcomes``, exactly as
``ezmigrate verify`` does. Every converted class must be equivalent; every class must be
found by both the static pass and the loader; a class may be skipped only for a reason in
``ALLOWED_SKIPS``.

Migrating and verifying cost far more than generating, so they are batched: ``add``
collects generated modules (dropping repeats: hypothesis sometimes draws the same text
twice), and ``run`` migrates all of them in a few forked processes, writes both versions,
and verifies them with one ``run_jobs`` call. A failure is therefore reported after
generation, with the full legacy and migrated text of its module instead of a shrunk
example.

Used by ``tests/verify/test_verify_roundtrip.py`` (CI) and ``bench/roundtrip_long.py``.
"""

from __future__ import annotations

import hashlib
import multiprocessing
import re
import time
import traceback
from collections import Counter
from collections.abc import Callable
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from ezmigrate.codemod.migrate import Settings, migrate
from ezmigrate.report.results import FileResult
from ezmigrate.verify.compare_files import compare_outcomes
from ezmigrate.verify.pool import PoolConfig, job_for, run_jobs
from ezmigrate.verify.protocol import LoadOutcome
from ezskiros_runtime.compare import compare
from ezskiros_runtime.model import SkillModel

from .legacy_source import GeneratedModule

ALLOWED_SKIPS: dict[str, str] = {}
"""Documented reasons (regex on the skip reason -> why it is acceptable) for which a
generated class may be skipped. Every generated construct is declarative, so none is
expected; a reason seen that is not here fails the property test."""


@dataclass
class Failure:
    """One thing the round trip found wrong, with everything needed to reproduce it."""

    module: str
    kind: str
    """``migrate-crash``, ``static``, ``load``, ``not-equivalent``, ``static-model``, ...."""
    message: str
    cls: str | None = None
    diff: list[dict[str, Any]] = field(default_factory=list)
    legacy: str = ""
    migrated: str | None = None

    def explain(self) -> str:
        """A self-contained account: what differs, then both versions of the module."""
        lines = [f"{self.module}{'::' + self.cls if self.cls else ''}: {self.kind}: "
                 f"{self.message}"]
        for d in self.diff[:6]:
            lines.append(f"    {d.get('where')}: {d.get('message')}")
            if d.get("before") is not None:
                lines.append(f"      legacy:   {d['before']}")
            if d.get("after") is not None:
                lines.append(f"      migrated: {d['after']}")
        lines += ["--- legacy source ---", self.legacy]
        if self.migrated is not None:
            lines += ["--- migrated source ---", self.migrated]
        return "\n".join(lines)


@dataclass
class Report:
    """Counts over a round trip; ``failures`` empty means every module round-tripped."""

    examples: int = 0
    modules: int = 0
    classes: int = 0
    converted: int = 0
    unchanged: int = 0
    skipped: Counter[str] = field(default_factory=Counter)
    changed_files: int = 0
    compared: int = 0
    equivalent: int = 0
    static_models_checked: int = 0
    failure_count: int = 0
    failures: list[Failure] = field(default_factory=list)
    """The first failures (``failure_count`` counts them all)."""
    seconds: dict[str, float] = field(default_factory=lambda: Counter())
    kinds: Counter[str] = field(default_factory=Counter)
    """Constructs seen in the legacy text (a rough coverage measure)."""

    @property
    def conversion_rate(self) -> float:
        return self.converted / self.classes if self.classes else 0.0

    def summary(self) -> str:
        skipped = sum(self.skipped.values())
        text = (f"{self.examples} examples, {self.modules} distinct modules, {self.classes} "
                f"description classes: {self.converted} converted "
                f"({100 * self.conversion_rate:.1f}%), {self.unchanged} unchanged, {skipped} "
                f"skipped; {self.changed_files} files verified, {self.compared} classes "
                f"compared, {self.equivalent} equivalent; {self.static_models_checked} static "
                f"models checked against the loaded legacy model; "
                f"{self.failure_count} failures")
        times = ", ".join(f"{k} {v:.1f} s" for k, v in sorted(self.seconds.items()))
        return text + (f" ({times})" if times else "")

    def skip_lines(self) -> list[str]:
        return [f"{n} x {reason}" for reason, n in self.skipped.most_common()]

    def explain(self, limit: int = 5) -> str:
        shown = [f.explain() for f in self.failures[:limit]]
        more = self.failure_count - min(limit, len(self.failures))
        return "\n\n".join(shown) + (f"\n\n... and {more} more failures" if more > 0 else "")


CONSTRUCTS = {
    "addParam": "addParam(", "Element()": "Element()", "options": "ParamOptions.",
    "Lock": ".Lock", "Consume": ".Consume", "Unspecify": ".Unspecify",
    "RespectType": ".RespectType", "Output": ".Output", "description=": "description=",
    "getRelationCond": "getRelationCond(", "getAbstractRelationCond": "getAbstractRelationCond(",
    "getPropCond": "getPropCond(", "getHasPropCond": "getHasPropCond(",
    "getIsSpecifiedCond": "getIsSpecifiedCond(", "getGenerateCond": "getGenerateCond(",
    "getOnTypeCond": "getOnTypeCond(", "getOrCond(True)": "getOrCond(True)",
    "getOrCond(False)": "getOrCond(False)", "ConditionRelation": "ConditionRelation(",
    "ConditionProperty": "ConditionProperty(", "ConditionHasProperty": "ConditionHasProperty(",
    "addHoldCondition": "addHoldCondition(", "Inferred": "Inferred",
}


def normalize_reason(reason: str | None) -> str:
    """A skip reason without the parts that vary per module (code, line numbers, names)."""
    text = (reason or "").splitlines()[0] if reason else ""
    text = re.sub(r"`[^`]*`", "`...`", text)
    text = re.sub(r"\bline \d+", "line N", text)
    text = re.sub(r"'[^']*'|\"[^\"]*\"", "'...'", text)
    return text[:200]


def allowed_skip(reason: str) -> bool:
    return any(re.search(pattern, reason) for pattern in ALLOWED_SKIPS)


_SETTINGS: Settings | None = None


def _init_migrate(settings: Settings) -> None:
    global _SETTINGS
    _SETTINGS = settings


def _migrate(name: str, data: bytes) -> FileResult | str:
    """``migrate()`` in a worker; a traceback string if it raised (it promises not to)."""
    assert _SETTINGS is not None
    try:
        return migrate(data, _SETTINGS, name)
    except Exception:
        return traceback.format_exc(limit=8)


class RoundTrip:
    """Migrate, write, verify and compare generated modules (see the module docstring)."""

    def __init__(self, workdir: Path, settings: Settings, *, jobs: int = 2,
                 timeout: float = 20.0, keep_failures: int = 50,
                 limit: int | None = None,
                 alter: Callable[[bytes], bytes] | None = None) -> None:
        self.workdir = workdir
        self.settings = settings
        self.jobs = jobs
        self.config = PoolConfig(workers=jobs, timeout=timeout)
        self.keep_failures = keep_failures
        self.limit = limit
        """Distinct modules to keep at most (later ones are counted as examples only)."""
        self.alter = alter
        """Applied to each migrated source before it is written: a way to show that the
        round trip fails when a migration changes meaning."""
        self.report = Report()
        self._seen: set[str] = set()
        self._pending: list[tuple[str, GeneratedModule]] = []

    @property
    def full(self) -> bool:
        return self.limit is not None and self.report.modules >= self.limit

    def add(self, module: GeneratedModule) -> None:
        """Keep a generated module for the next ``run`` (repeats and extras are dropped)."""
        self.report.examples += 1
        digest = hashlib.sha256(module.text.encode("utf-8")).hexdigest()
        if digest in self._seen or self.full:
            return
        self._seen.add(digest)
        self.report.modules += 1
        self._pending.append((f"gen_{self.report.modules:05d}.py", module))
        for kind, marker in CONSTRUCTS.items():
            if marker in module.text:
                self.report.kinds[kind] += 1

    def run(self, progress: Callable[[str], None] | None = None) -> Report:
        """Migrate, write, verify and compare every module added since the last run."""
        items, self._pending = self._pending, []
        if not items:
            return self.report
        before, after = self.workdir / "before", self.workdir / "after"
        before.mkdir(parents=True, exist_ok=True)
        after.mkdir(parents=True, exist_ok=True)
        started = time.perf_counter()
        results = self._migrate_all(items)
        self.report.seconds["migrate"] += time.perf_counter() - started
        changed: list[tuple[str, GeneratedModule, FileResult]] = []
        for (name, module), result in zip(items, results, strict=True):
            if isinstance(result, str):
                self._record(Failure(name, "migrate-crash", result, legacy=module.text))
                continue
            for failure in self._static_checks(name, module, result):
                self._record(failure)
            if isinstance(result.new_source, bytes):
                if self.alter is not None:
                    result = replace(result, new_source=self.alter(result.new_source))
                (before / name).write_bytes(module.text.encode("utf-8"))
                (after / name).write_bytes(result.new_source)
                changed.append((name, module, result))
        self.report.changed_files += len(changed)
        if progress is not None:
            progress(f"migrated {len(items)} modules, verifying {len(changed)} files")
        started = time.perf_counter()
        jobs = [job_for(folder / name) for name, _, _ in changed for folder in (before, after)]
        outcomes = run_jobs(jobs, self.config)
        self.report.seconds["verify"] += time.perf_counter() - started
        for index, (name, module, result) in enumerate(changed):
            self._compare(name, module, result, outcomes[2 * index], outcomes[2 * index + 1])
        return self.report

    def _migrate_all(self, items: list[tuple[str, GeneratedModule]]) -> list[FileResult | str]:
        """``migrate()`` over every item, in ``jobs`` forked processes (no thread runs yet:
        the verification pool starts its threads only afterwards)."""
        names = [name for name, _ in items]
        datas = [module.text.encode("utf-8") for _, module in items]
        if self.jobs <= 1 or len(items) < 8:
            _init_migrate(self.settings)
            return [_migrate(n, d) for n, d in zip(names, datas, strict=True)]
        context = multiprocessing.get_context("fork")
        with ProcessPoolExecutor(max_workers=self.jobs, mp_context=context,
                                 initializer=_init_migrate, initargs=(self.settings,)) as pool:
            return list(pool.map(_migrate, names, datas, chunksize=4))

    def _static_checks(self, name: str, module: GeneratedModule,
                       result: FileResult) -> list[Failure]:
        out = []
        if result.error is not None:
            out.append(Failure(name, "static", f"migrate() reported a file error: "
                               f"{result.error}", legacy=module.text))
        names = [s.name for s in result.skills]
        if names != list(module.class_names):
            out.append(Failure(name, "static", f"migrate() found the classes {names}, the "
                               f"module has {list(module.class_names)}", legacy=module.text))
        for skill in result.skills:
            self.report.classes += 1
            if skill.status == "converted":
                self.report.converted += 1
            elif skill.status == "unchanged":
                self.report.unchanged += 1
            else:
                reason = normalize_reason(skill.reason)
                self.report.skipped[reason] += 1
                if skill.status != "skipped" or not allowed_skip(reason):
                    out.append(Failure(name, "skipped", f"{skill.status}: {skill.reason}",
                                       skill.name, legacy=module.text))
        if any(s.status == "converted" for s in result.skills) and result.new_source is None:
            out.append(Failure(name, "static", "classes were converted but no new source "
                               "was produced", legacy=module.text))
        return out

    def _compare(self, name: str, module: GeneratedModule, result: FileResult,
                 before: LoadOutcome, after: LoadOutcome) -> None:
        migrated = result.new_source.decode("utf-8") if isinstance(result.new_source,
                                                                   bytes) else None

        def fail(kind: str, message: str, cls: str | None = None,
                 diff: list[dict[str, Any]] | None = None) -> None:
            self._record(Failure(name, kind, message, cls, diff or [], module.text, migrated))

        for side, outcome in (("legacy", before), ("migrated", after)):
            if not outcome.loaded:
                stderr = outcome.stderr.strip()[-1500:]
                fail("load", f"the {side} version did not load: {outcome.status}: "
                             f"{outcome.message}" + (f"\n{stderr}" if stderr else ""))
                return
        for side, outcome in (("legacy", before), ("migrated", after)):
            for error in outcome.errors:
                fail("class-error", f"the {side} class fails to load: {error.message}",
                     error.skill)
        loaded = [m["name"] for m in before.models]
        if sorted(loaded) != sorted(module.class_names):
            fail("static", f"the loader found the classes {loaded}, the module has "
                           f"{list(module.class_names)}")
        converted = {s.name: s for s in result.skills if s.status == "converted"}
        verdicts = compare_outcomes(before, after)
        for verdict in verdicts:
            self.report.compared += 1
            if verdict.equivalent:
                self.report.equivalent += 1
            else:
                fail("not-equivalent", f"{verdict.verdict}: {verdict.message}", verdict.name,
                     verdict.diff)
        missing = set(converted) - {v.name for v in verdicts}
        for cls in sorted(missing):
            fail("not-equivalent", "a converted class was not compared", cls)
        # the static model (what the report and the findings are computed from) must be the
        # model SkiROS2 builds when it runs the legacy code
        dynamic = {m["name"]: SkillModel.from_json(m) for m in before.models}
        for cls, skill in converted.items():
            if skill.model is None or cls not in dynamic:
                continue
            self.report.static_models_checked += 1
            diffs = compare(dynamic[cls], SkillModel.from_json(skill.model))
            if diffs:
                fail("static-model", "the static model differs from the loaded legacy model",
                     cls, [d.to_json() for d in diffs])

    def _record(self, failure: Failure) -> None:
        if len(self.report.failures) < self.keep_failures:
            self.report.failures.append(failure)
        self.report.failure_count += 1
