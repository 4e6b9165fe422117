"""Which files a run looks at: ``.py`` files under the given paths, minus exclusions.

Conventions of black and ruff: excludes apply to explicitly named files too (pre-commit
passes file names), ``.gitignore`` is respected inside git checkouts, and symlinks are
followed only while they stay inside the given roots (a loop or an escape ends there).
"""

from __future__ import annotations

import fnmatch
import os
import subprocess
from collections.abc import Iterable, Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path

ALWAYS_EXCLUDED = frozenset({".git", ".hg", ".svn", "__pycache__", ".venv", "venv", ".tox",
                             ".mypy_cache", ".ruff_cache", ".pytest_cache", "node_modules",
                             "build", "dist", ".eggs"})


@dataclass(frozen=True)
class Candidate:
    """A file to consider, with the root it was found under (for relative report paths)."""

    path: Path
    root: Path

    @property
    def relative(self) -> str:
        try:
            return self.path.relative_to(self.root).as_posix() or self.path.name
        except ValueError:
            return self.path.as_posix()


def _excluded(relative: str, patterns: Sequence[str]) -> bool:
    parts = relative.split("/")
    for pattern in patterns:
        if fnmatch.fnmatch(relative, pattern) or any(fnmatch.fnmatch(p, pattern) for p in parts):
            return True
    return False


def _inside(path: Path, roots: Iterable[Path]) -> bool:
    real = path.resolve()
    return any(real == r or r in real.parents for r in roots)


def discover(paths: Sequence[Path], exclude: Sequence[str] = (),
             respect_gitignore: bool = True) -> tuple[list[Candidate], list[str]]:
    """All candidate files, sorted and unique, plus messages about what was passed over."""
    notes: list[str] = []
    found: dict[Path, Candidate] = {}
    for given in paths:
        if not given.exists() and not given.is_symlink():
            notes.append(f"{given}: no such file or directory")
            continue
        root = given if given.is_dir() else given.parent
        real_roots = [root.resolve()]
        if given.is_file():
            rel = given.name
            if not _excluded(rel, exclude):
                found.setdefault(given.resolve(), Candidate(given, root))
            continue
        for file in _walk(given, real_roots, notes):
            rel = Candidate(file, root).relative
            if not _excluded(rel, exclude):
                found.setdefault(file.resolve(), Candidate(file, root))
    candidates = sorted(found.values(), key=lambda c: str(c.path))
    if respect_gitignore:
        ignored = _git_ignored([c.path for c in candidates])
        candidates = [c for c in candidates if c.path.resolve() not in ignored]
    return candidates, notes


def _walk(top: Path, roots: list[Path], notes: list[str]) -> Iterator[Path]:
    seen: set[Path] = set()
    stack = [top]
    while stack:
        folder = stack.pop()
        real = folder.resolve()
        if real in seen:
            notes.append(f"{folder}: symlink loop, not followed again")
            continue
        seen.add(real)
        try:
            entries = sorted(os.scandir(folder), key=lambda e: e.name)
        except OSError as error:
            notes.append(f"{folder}: cannot list ({error.strerror})")
            continue
        for entry in entries:
            path = Path(entry.path)
            if entry.name in ALWAYS_EXCLUDED:
                continue
            if entry.is_symlink() and not _inside(path, roots):
                notes.append(f"{path}: symlink leads outside the given paths, skipped")
                continue
            if entry.is_dir():
                stack.append(path)
            elif entry.name.endswith(".py") and entry.is_file():
                yield path


def _git_ignored(files: list[Path]) -> set[Path]:
    """Files git ignores, asked once per checkout; nothing when git is absent."""
    by_top: dict[Path, list[Path]] = {}
    for file in files:
        by_top.setdefault(file.resolve().parent, []).append(file.resolve())
    ignored: set[Path] = set()
    checked: dict[Path, Path | None] = {}
    groups: dict[Path, list[Path]] = {}
    for folder, group in by_top.items():
        top = checked.get(folder)
        if folder not in checked:
            top = _git_top(folder)
            checked[folder] = top
        if top is not None:
            groups.setdefault(top, []).extend(group)
    for top, group in groups.items():
        try:
            proc = subprocess.run(["git", "-C", str(top), "check-ignore", "--stdin", "-z"],
                                  input="\0".join(str(p) for p in group).encode(),
                                  capture_output=True, timeout=60, check=False)
        except (OSError, subprocess.TimeoutExpired):
            continue
        ignored |= {Path(p.decode()).resolve() for p in proc.stdout.split(b"\0") if p}
    return ignored


def _git_top(folder: Path) -> Path | None:
    try:
        proc = subprocess.run(["git", "-C", str(folder), "rev-parse", "--show-toplevel"],
                              capture_output=True, timeout=30, check=False)
    except (OSError, subprocess.TimeoutExpired):
        return None
    return Path(proc.stdout.decode().strip()).resolve() if proc.returncode == 0 else None
