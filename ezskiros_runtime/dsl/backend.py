"""Which SkiROS2 API an EzSkiROS description lowers to: SkiROS2's own, or our legacy one.

On a robot ``skiros2_common`` is importable and migrated skills must derive from SkiROS2's
own ``SkillDescription`` so the skill manager runs them unchanged. Everywhere else the
project's re-implementation (``ezskiros_runtime.legacy``) stands in. Detection imports
``skiros2_common`` itself, never ROS (legacy-skiros2-api.md §8.11): the package is the thing
we need, and probing ``rospy`` would pick the wrong backend on ROS machines without SkiROS2.

``EZSKIROS_BACKEND`` overrides detection: ``legacy`` always uses ours, ``skiros2`` insists on
the real one (an ImportError if it is missing), ``auto`` or unset detects.
"""

from __future__ import annotations

import importlib
import os
from dataclasses import dataclass
from typing import Any

ENV_VAR = "EZSKIROS_BACKEND"
CHOICES: tuple[str, ...] = ("auto", "skiros2", "legacy")


@dataclass(frozen=True)
class Backend:
    """The four names lowering needs, taken from one SkiROS2 API implementation."""

    name: str
    SkillDescription: type
    ParamTypes: Any
    ParamOptions: Any
    Element: Any


def _from_modules(name: str, skill: str, params: str, element: str) -> Backend:
    skill_module = importlib.import_module(skill)
    return Backend(
        name=name,
        SkillDescription=skill_module.SkillDescription,
        ParamTypes=importlib.import_module(params).ParamTypes,
        ParamOptions=skill_module.ParamOptions,
        Element=importlib.import_module(element).Element,
    )


def skiros2_backend() -> Backend:
    """SkiROS2's own classes (``skiros2_common.core``)."""
    return _from_modules("skiros2", "skiros2_common.core.abstract_skill",
                         "skiros2_common.core.params", "skiros2_common.core.world_element")


def legacy_backend() -> Backend:
    """The project's re-implementation of the legacy API."""
    return _from_modules("legacy", "ezskiros_runtime.legacy.abstract_skill",
                         "ezskiros_runtime.legacy.params",
                         "ezskiros_runtime.legacy.world_element")


def _skiros2_importable() -> bool:
    try:
        importlib.import_module("skiros2_common")
    except ModuleNotFoundError as exc:
        if exc.name == "skiros2_common":
            return False
        raise
    return True


def select_backend(choice: str | None = None) -> Backend:
    """The backend for ``choice`` (default: the environment variable, else ``auto``)."""
    if choice is None:
        choice = os.environ.get(ENV_VAR, "").strip().lower() or "auto"
    if choice not in CHOICES:
        raise ValueError(f"{ENV_VAR}={choice!r}: expected one of {', '.join(CHOICES)}")
    if choice == "legacy":
        return legacy_backend()
    if _skiros2_importable():
        real = skiros2_backend()
        legacy = legacy_backend()
        # legacy.stand_ins serves our own classes under SkiROS2's names while it loads
        # legacy files: that is still the legacy backend, whatever the module is called.
        return legacy if real.SkillDescription is legacy.SkillDescription else real
    if choice == "skiros2":
        raise ImportError(f"{ENV_VAR}=skiros2 but skiros2_common cannot be imported; install "
                          "SkiROS2 (or source its workspace) or unset the variable")
    return legacy_backend()


__all__ = ["CHOICES", "ENV_VAR", "Backend", "legacy_backend", "select_backend",
           "skiros2_backend"]
