"""Shared by the cache tests: ``ezmigrate check`` run as a lab runs it, a real process in the
repository's folder, its findings as JSON (the bytes the cache must not change)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path


def user_cache(repo: Path) -> Path:
    """The cache folder of the tests' runs on ``repo`` (``--cache-dir``), beside it."""
    return repo.parent / "user-cache"


def entries(repo: Path) -> Path:
    """The folder of ``repo``'s entries in ``user_cache``."""
    from ezmigrate.cache.cache_folder import project_folder

    return project_folder(user_cache(repo), repo)


def check_json(repo: Path, *extra: str) -> subprocess.CompletedProcess[str]:
    """``ezmigrate check --exit-zero --output-format json [extra] .`` in ``repo``, its
    cache in ``user_cache``."""
    return subprocess.run([sys.executable, "-m", "ezmigrate", "check", "--exit-zero",
                           "--output-format", "json", "--cache-dir", str(user_cache(repo)),
                           *extra, "."], cwd=repo,
                          capture_output=True, text=True, timeout=600, check=False)


# A compound skill whose processor comes from a star import of the lab's own module
# (``processors_here.py``): what its reading takes of that module is its names.
STAR_TREE = '''\
from skiros2_skill.core.skill import SkillDescription, SkillBase
from processors_here import *


class Patrol(SkillDescription):
    def createDescription(self):
        pass


class patrol(SkillBase):
    def createDescription(self):
        self.setDescription(Patrol(), self.__class__.__name__)

    def expand(self, skill):
        skill.setProcessor(LabSequence())
        skill(self.skill("Patrol", ""))
'''
