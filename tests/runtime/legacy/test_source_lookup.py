"""Looking up a class's source for a finding's line never makes a valid class unloadable.

Verification loads a rewrite from bytes before it is written, so the file on disk still
holds other code; tokenizing that (a banner or docstring cut in the middle) raised
``TokenError: EOF in multi-line string`` and failed a valid class.
"""

from __future__ import annotations

from pathlib import Path

from ezskiros_runtime.legacy.loader import load_bytes

MIGRATED = b'''#| Licence banner
#| of several lines
from ezskiros_runtime import SkillDescription, INFERRED
from ezskiros_runtime.ontology import skiros


class Place(SkillDescription):
    """Puts an object down."""

    def description(self,
                    Object: skiros.Product,
                    Target: INFERRED[skiros.Location]):
        pass
        # self.pre_conditions += Target.contain(Object)
'''

ON_DISK = '''#| Licence banner
#| of several lines
"""A module docstring that the old file opened at the very line the class starts on
'''  # never closed: tokenizing from any line below it fails


def test_a_finding_points_at_the_loaded_bytes_not_at_the_file_on_disk(tmp_path: Path):
    """Before: the lookup tokenized the file on disk, failed, and fell back to line 10."""
    path = tmp_path / "place.py"
    path.write_text(ON_DISK + "\n" * 20, encoding="utf-8")
    loaded = load_bytes(MIGRATED, path)
    assert loaded.errors == []
    assert [m.name for m in loaded.models] == ["Place"]
    lines = {f.kind: f.line for f in loaded.findings}
    assert lines.get("uninferable") == 12, loaded.findings  # the Target parameter's line
