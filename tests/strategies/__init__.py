"""Hypothesis strategies shared by the test-suite (generated legacy SkiROS2 source text)."""

from .legacy_source import (
    GeneratedModule,
    description_class_names,
    legacy_module_texts,
    legacy_modules,
    legacy_modules_with_names,
)

__all__ = [
    "GeneratedModule",
    "description_class_names",
    "legacy_module_texts",
    "legacy_modules",
    "legacy_modules_with_names",
]
