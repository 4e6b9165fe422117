"""``--exclude`` patterns are matched as one compiled expression (issue 31: a run asks it of
every folder and name of every file); the answers are ``fnmatch``'s, pattern by pattern."""

from __future__ import annotations

import fnmatch
import random

import pytest

from ezmigrate.files.discover import _excluded


def _by_fnmatch(relative: str, patterns: list[str]) -> bool:
    parts = relative.split("/")
    prefixes = ["/".join(parts[:i]) for i in range(1, len(parts) + 1)]
    return any(fnmatch.fnmatch(p, pattern) for pattern in patterns
               for p in (*prefixes, *parts))


@pytest.mark.parametrize(("relative", "patterns", "excluded"), [
    ("src/legacy/a.py", ["src/legacy"], True),
    ("src/legacyx/a.py", ["src/legacy"], False),
    ("pkg/.hidden/a.py", [".*"], True),
    ("a/b/c_pb2.py", ["*_pb2.py"], True),
    ("abd/e.py", ["a[bc]d"], True),
    ("a!d/e.py", ["a[!bc]d"], True),
    ("q/r.py", ["build", "*.pyc"], False),
    ("q/r.py", [], False),
])
def test_a_pattern_matches_the_path_a_name_in_it_or_its_leading_folders(
        relative: str, patterns: list[str], excluded: bool) -> None:
    assert _excluded(relative, patterns) is excluded
    assert _by_fnmatch(relative, patterns) is excluded


def test_the_compiled_patterns_answer_as_fnmatch_does() -> None:
    chance = random.Random(31)
    for _ in range(3000):
        relative = "/".join("".join(chance.choice("abxyz_.[]*?!") for _ in
                                    range(chance.randint(1, 4)))
                            for _ in range(chance.randint(1, 3)))
        patterns = ["".join(chance.choice("abxyz_.*?[]!/") for _ in range(chance.randint(1, 5)))
                    for _ in range(chance.randint(0, 3))]
        assert _excluded(relative, patterns) == _by_fnmatch(relative, patterns), \
            (relative, patterns)
