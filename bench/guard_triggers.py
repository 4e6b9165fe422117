"""Count how often the line guard (``ezmigrate/codemod/core/guard.py``) refuses a reading.

    python bench/guard_triggers.py fixtures /tmp/bench-tree ...

migrates every ``.py`` file under the folders given (each alone, default settings, no
verification, nothing written) through every reading ``migrate`` would try, and counts
the readings whose text the guard refuses: ``stand-in`` (the first reading, with code the
migration never reads stood in for; a refusal there costs a whole-file reading) and
``refused`` (files no reading could migrate without changing a line outside the
migration: EZ906). Both are expected to be 0. One line of ``key=value`` on stdout, then
one line per refusal.
"""

from __future__ import annotations

import sys
from pathlib import Path

from ezmigrate.codemod.migrate import Settings, guarded_readings


def main(folders: list[str]) -> int:
    files = stand_in = refused = 0
    problems: list[str] = []
    for folder in folders:
        for path in sorted(Path(folder).rglob("*.py")):
            files += 1
            outcomes = [lost for _, lost in guarded_readings(path.read_bytes(), Settings(),
                                                              str(path))]
            first_refused = outcomes[0] is not None
            stand_in += first_refused and len(outcomes) > 1
            refused += all(lost is not None for lost in outcomes)
            if first_refused:
                problems.append(f"{path}: line {outcomes[0]} (readings: {outcomes})")
    print(f"files={files} stand_in_refused={stand_in} refused={refused}")
    print("\n".join(problems))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
