"""What a migration is told (``Settings``) and the names it writes, without libcst.

A process that only hands files to the codemod's workers (``rewrite``'s main process, the
command line starting up) needs these and nothing else of the codemod: kept apart from
``migrate`` so that it never imports libcst, and the workers import it in parallel.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ezskiros_runtime.ontology.index import OntologyIndex

    from .core.ir import Operation

DEFAULT_TARGET = (3, 10)
"""The Python migrated code must run on when nothing says otherwise: the oldest that ROS 2
(Humble) runs. A ROS 1 package means Noetic's 3.8 (``ezmigrate.project.target``)."""

RUNTIME_ROOT = "ezskiros_runtime"
"""The package migrated code imports the DSL from."""


@dataclass(frozen=True)
class Settings:
    """What a migration needs besides the source: the ontology, and the package around it.

    ``index`` decides between short forms (``skiros.Product``) and verbatim forms
    (``ELEMENT("scalable:Ur5")``). ``external`` maps names of description classes defined in
    other files of the same package to their operations (for bases imported by name).
    """

    index: OntologyIndex | None = None
    external: Mapping[str, list[Operation]] = field(default_factory=dict)
    held: Mapping[str, str] = field(default_factory=dict)
    """Classes to leave exactly as they are, with the reason (verification refused them)."""
    exported: frozenset[str] = frozenset()
    """Names other modules of the package import from this one (``*``: a star import): their
    legacy imports stay, or migrating this file would break those modules."""
    migrated_bases: frozenset[str] = frozenset()
    """Imported bases that a sibling file defines as EzSkiROS descriptions (an earlier run
    migrated them): a class here deriving from one with a ``createDescription`` is legacy."""
    target: tuple[int, int] = DEFAULT_TARGET
    """The oldest Python the migrated code must run on (``target-version``; a ROS 1
    package means ROS Noetic's 3.8): the emitter writes only what it runs."""
    unresolved_bases: Mapping[str, str] = field(default_factory=dict)
    """Imported bases whose file is not part of the run -> why a class deriving from one with
    a ``createDescription`` is kept (its base's declarations cannot be read)."""
