"""No file decides ``check``'s verdict but the ones it checks (issue 40): the cache lives in
the user's cache folder, every entry is signed, and an entry that is forged, foreign,
damaged or planted in the checkout gives the verdict ``--no-cache`` gives. A change of the
tool's code, even without a new version number, is never answered from an old entry."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

from cache_support import check_json, entries

from ezmigrate.cache.cache_folder import MAX_AGE, Store, prune, user_key
from ezmigrate.cache.outcome_cache import OUTCOMES

ROOT = Path(__file__).resolve().parents[2]

MISTYPED = '''\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


class Fetch(SkillDescription):
    def createDescription(self):
        self.addParam("Object", Element("skiros;:Product"), ParamTypes.Required)
'''


def _repo(tmp_path: Path) -> Path:
    repo = tmp_path / "repo"
    repo.mkdir()
    (repo / "fetch.py").write_text(MISTYPED, encoding="utf-8")
    subprocess.run(["git", "init", "-q", str(repo)], check=True)
    return repo


def _check(repo: Path, *extra: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "ezmigrate", "check", "--output-format",
                           "json", "--cache-dir", str(repo.parent / "user-cache"), *extra,
                           "."], cwd=repo, capture_output=True, text=True, timeout=600,
                          check=False)


def _kept(repo: Path) -> Path:
    (entry,) = (entries(repo) / OUTCOMES).glob("*.json")
    return entry


def test_a_forged_entry_gives_the_uncached_verdict(tmp_path: Path) -> None:
    repo = _repo(tmp_path)
    first = _check(repo)
    assert first.returncode == 1 and '"EZ212"' in first.stdout, first.stderr
    entry = _kept(repo)
    signature, payload = entry.read_bytes().split(b"\n", 1)
    data = json.loads(payload)
    data["diagnostics"] = []  # what an attacker wants: no finding, exit 0
    entry.write_bytes(signature + b"\n" + json.dumps(data).encode())
    again = _check(repo)
    assert (again.returncode, again.stdout) == (1, first.stdout)


def test_an_entry_signed_with_another_key_is_a_miss(tmp_path: Path) -> None:
    repo = _repo(tmp_path)
    first = _check(repo)
    entry = _kept(repo)
    payload = json.loads(entry.read_bytes().split(b"\n", 1)[1])
    payload["diagnostics"] = []
    name = f"{OUTCOMES}/{entry.name}"
    Store(entries(repo), b"somebody else's key").write(name, json.dumps(payload).encode())
    assert _check(repo).returncode == 1
    assert _check(repo).stdout == first.stdout


def test_a_damaged_entry_is_a_miss(tmp_path: Path) -> None:
    repo = _repo(tmp_path)
    first = _check(repo)
    entry = _kept(repo)
    entry.write_bytes(entry.read_bytes()[:-20])  # cut short
    assert _check(repo).stdout == first.stdout
    entry.write_bytes(b"")
    assert _check(repo).stdout == first.stdout


def test_nothing_in_the_checkout_is_read_as_cache(tmp_path: Path) -> None:
    """The old place of the cache, in the repository, is a folder like any other: a file
    committed there cannot make the run pass, and the run writes nothing into the tree."""
    repo = _repo(tmp_path)
    first = _check(repo)
    assert not (repo / ".ezmigrate_cache").exists()
    planted = repo / ".ezmigrate_cache" / OUTCOMES
    planted.mkdir(parents=True)
    kept = _kept(repo)
    payload = json.loads(kept.read_bytes().split(b"\n", 1)[1])
    (planted / kept.name).write_text(json.dumps({**payload, "diagnostics": []}))
    shutil.rmtree(repo.parent / "user-cache")
    again = _check(repo)
    assert (again.returncode, again.stdout) == (1, first.stdout)


def test_a_code_change_without_a_new_version_gives_fresh_messages(tmp_path: Path) -> None:
    """The key holds a digest of the tool's sources: a copy of the tool whose message
    changed answers with the new text from the same cache folder, version unchanged."""
    repo = _repo(tmp_path)
    first = check_json(repo)
    assert "the prefix is mistyped" in first.stdout, first.stderr
    tool = tmp_path / "tool"
    for package in ("ezmigrate", "ezskiros_runtime"):
        shutil.copytree(ROOT / package, tool / package,
                        ignore=shutil.ignore_patterns("__pycache__"))
    legacy = tool / "ezmigrate" / "lint" / "legacy.py"
    text = legacy.read_text(encoding="utf-8")
    assert "the prefix is mistyped" in text
    legacy.write_text(text.replace("the prefix is mistyped", "the prefix has a typo"),
                      encoding="utf-8")
    env = dict(os.environ, PYTHONPATH=str(tool))
    run = subprocess.run([sys.executable, "-m", "ezmigrate", "check", "--exit-zero",
                          "--output-format", "json", "--cache-dir",
                          str(repo.parent / "user-cache"), "."], cwd=repo, env=env,
                         capture_output=True, text=True, timeout=600, check=False)
    assert "the prefix has a typo" in run.stdout, run.stdout + run.stderr


def test_old_entries_are_pruned(tmp_path: Path) -> None:
    root = tmp_path / "cache"
    key = user_key(root)
    assert key is not None
    store = Store(root / "projects" / "p", key)
    store.write("outcomes/old.json", b"{}")
    store.write("outcomes/new.json", b"{}")
    old = root / "projects" / "p" / "outcomes" / "old.json"
    stamp = old.stat().st_mtime - MAX_AGE - 10
    os.utime(old, (stamp, stamp))
    prune(root)
    assert not old.exists()
    assert store.read("outcomes/new.json") == b"{}"
    assert (root / "key").exists()
