"""Step (5) of the lowering order: run the early checks, then warn or raise per policy.

Warnings are issued at the file and line of the offending ``+=`` (``warn_explicit``), so the
usual ``file:line: EzSkirosWarning: ...`` output points at the user's code, and they are
deduplicated per line through the module's ``__warningregistry__`` like ordinary warnings.
Errors become one ``SkillTypeError`` listing all of them: fixing one at a time is slow.
"""

from __future__ import annotations

import warnings
from collections.abc import Callable, Sequence
from typing import Any

from ..diagnostics import (
    DescriptionError,
    EzSkirosWarning,
    Finding,
    SkillTypeError,
    UnknownVocabularyError,
)
from .check_context import CheckContext, Trace
from .check_structure import (
    check_contradictions,
    check_declared,
    check_defaults,
    check_inferable,
)
from .check_types import check_condition_types
from .check_vocabulary import check_condition_vocabulary, check_parameter_classes
from .policy import collecting, raising
from .vocabulary import active

CHECKS: tuple[Callable[[CheckContext], None], ...] = (
    check_defaults,
    check_parameter_classes,
    check_condition_vocabulary,
    check_condition_types,
    check_declared,
    check_inferable,
    check_contradictions,
)


def run_checks(trace: Trace) -> list[Finding]:
    """Every finding for a traced description, with severities per the current policy."""
    ctx = CheckContext(trace, active())
    for check_one in CHECKS:
        check_one(ctx)
    return ctx.findings


def report(findings: Sequence[Finding], func: Callable[..., Any] | None = None) -> None:
    """Warn about warning-level findings, then raise ``SkillTypeError`` for errors (nothing
    happens inside ``collecting()``)."""
    if not findings or not raising():
        return
    module_globals = getattr(func, "__globals__", None)
    registry = module_globals.setdefault("__warningregistry__", {}) if module_globals else None
    for finding in findings:
        if finding.severity == "warning":
            warnings.warn_explicit(f"{finding.skill}: {finding.message}", EzSkirosWarning,
                                   finding.file or "<unknown>", finding.line or 0,
                                   registry=registry, module_globals=module_globals)
    errors = [f for f in findings if f.severity == "error"]
    if errors:
        raise SkillTypeError(errors)


def _failure(kind: str, exc: BaseException, skill: str) -> Finding:
    return Finding(kind, "error", str(exc), None, None, skill)


def check(target: Any) -> list[Finding]:
    """All findings for a description class or instance, without raising or warning.

    An instance already carries its findings. A class is instantiated inside
    ``collecting()``; if the description cannot even be built (a ``DescriptionError``, an
    unknown namespace attribute in a string annotation), that failure is the one finding.
    """
    if not isinstance(target, type):
        return list(getattr(target, "findings", []))
    with collecting(), warnings.catch_warnings():
        warnings.simplefilter("ignore", EzSkirosWarning)
        try:
            instance = target()
        except SkillTypeError as exc:  # a subclass raising on its own
            return list(exc.findings)
        except UnknownVocabularyError as exc:
            return [_failure("unknown-vocabulary", exc, target.__name__)]
        except DescriptionError as exc:
            return [_failure("description", exc, target.__name__)]
    return list(getattr(instance, "findings", []))


__all__ = ["CHECKS", "check", "report", "run_checks"]
