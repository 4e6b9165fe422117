"""``check`` keeps what each file says by content (issue 31): after one file changes, the
next run reads that file again, and the files that depend on it, and nothing else; and
its findings are those of a run without a cache.

What is read again is observed, not timed: the real reading functions are wrapped to note
the files they are given (their work is unchanged). The kept entries are JSON signed with a
key of this user's cache folder: an entry another key signed, or one naming a class that
is not ours, is a miss.
"""

from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path

import pytest
from cache_support import STAR_TREE

from ezmigrate.cache.cache_folder import Store, project_folder, user_key
from ezmigrate.cache.facts_cache import FOLDER, FactsCache
from ezmigrate.cache.facts_codec import CodecError, decode, encode, loads
from ezmigrate.cache.outcome_cache import OUTCOMES
from ezmigrate.checking import file_facts as file_facts_module
from ezmigrate.checking import reading_pool
from ezmigrate.checking.pipeline import run_check
from ezmigrate.checking.run import CheckSettings
from ezmigrate.lint.diagnostic import Diagnostic
from ezmigrate.project import settle as settle_module
from ezmigrate.verify.pool import PoolConfig
from ezskiros_runtime.ontology.index import bundled_ontology_path
from ezskiros_runtime.ontology.load import load_index
from ezskiros_runtime.world import scene as scene_module

HEADER = """\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element
"""

BASE = HEADER + """

class Move(SkillDescription):
    def createDescription(self):
        self.addParam("Target", Element("skiros:Location"), ParamTypes.Required)
"""

DERIVED = HEADER + """from .base import Move


class MoveFast(Move):
    def createDescription(self):
        Move.createDescription(self)
        self.addParam("Speed", 2.0, ParamTypes.Optional)
"""

OTHER = HEADER + """
KEY = "Obj" + "ect"


class Pick(SkillDescription):
    def createDescription(self):
        key = KEY
        self.addParam(key, Element("skiros:Product"), ParamTypes.Required)
        self.addParam("Gripper", Element("skiros:Gripperr"), ParamTypes.Required)
"""

PLAIN = HEADER + """

class Place(SkillDescription):
    def createDescription(self):
        self.addParam("Object", Element("skiros:Prodct"), ParamTypes.Required)
"""

SCENE = """\
@prefix owl: <http://www.w3.org/2002/07/owl#> .
@prefix skiros: <http://rvmi.aau.dk/ontologies/skiros.owl#> .
skiros:Scene-0 a skiros:Scene, owl:NamedIndividual ;
    skiros:contain skiros:Location-1 .
skiros:Location-1 a skiros:Location, owl:NamedIndividual .
"""


@pytest.fixture
def own_key(tmp_path: Path) -> Path:
    """This test's user cache folder, where the signing key is made."""
    return tmp_path / "user-cache"


@pytest.fixture
def repo(tmp_path: Path) -> Path:
    root = tmp_path / "repo"
    (root / "pkg").mkdir(parents=True)
    for name, text in (("base.py", BASE), ("derived.py", DERIVED), ("other.py", OTHER),
                       ("plain.py", PLAIN), ("__init__.py", "")):
        (root / "pkg" / name).write_text(text, encoding="utf-8")
    (root / "scene.turtle").write_text(SCENE, encoding="utf-8")
    subprocess.run(["git", "init", "-q", str(root)], check=True)
    return root


class Reads:
    """The files the run parses, hands to the codemod, and the scenes rdflib parses."""

    def __init__(self, monkeypatch: pytest.MonkeyPatch) -> None:
        self.parsed: list[str] = []
        self.settled: list[str] = []
        self.scenes: list[str] = []
        real_facts, real_settle = reading_pool.file_facts, settle_module.settle
        real_scene = scene_module._parsed

        def file_facts(candidate, data, *args, **kwargs):  # type: ignore[no-untyped-def]
            self.parsed.append(candidate.path.name)
            return real_facts(candidate, data, *args, **kwargs)

        def settle(candidates, *args, **kwargs):  # type: ignore[no-untyped-def]
            self.settled += [c.path.name for c in candidates]
            return real_settle(candidates, *args, **kwargs)

        def parsed_scene(where, text):  # type: ignore[no-untyped-def]
            self.scenes.append(Path(where).name)
            return real_scene(where, text)

        monkeypatch.setattr(reading_pool, "file_facts", file_facts)  # one worker: here
        monkeypatch.setattr(file_facts_module, "file_facts", file_facts)  # early_cutoff
        monkeypatch.setattr(settle_module, "settle", settle)  # ``check`` imports it late
        monkeypatch.setattr(scene_module, "_parsed", parsed_scene)

    def clear(self) -> None:
        self.parsed, self.settled, self.scenes = [], [], []


def _folder(repo: Path) -> Path:
    return project_folder(repo.parent / "user-cache", repo)


def _run(repo: Path, cached: bool) -> list[Diagnostic]:
    scene_module._KNOWN.clear()  # each run as a new process starts: nothing parsed yet
    index = load_index([bundled_ontology_path()])
    outcome = run_check([repo], index, PoolConfig(workers=1),
                        CheckSettings(cache_dir=_folder(repo) if cached else None))
    return outcome.diagnostics


def _edit(path: Path) -> None:
    path.write_text(path.read_text(encoding="utf-8") + "# edited\n", encoding="utf-8")


def test_one_changed_file_is_read_again_alone(repo: Path, own_key: Path,
                                             monkeypatch: pytest.MonkeyPatch) -> None:
    reads = Reads(monkeypatch)
    first = _run(repo, cached=True)
    assert sorted(reads.parsed) == ["base.py", "derived.py", "other.py", "plain.py"]
    assert sorted(reads.settled) == ["derived.py", "other.py"]  # declined by the plain reader
    assert reads.scenes == ["scene.turtle"]
    assert {d.code for d in first} >= {"EZ209"}  # the typos are found
    assert first == _run(repo, cached=False)

    _edit(repo / "pkg" / "plain.py")  # a plain file no other file imports from
    reads.clear()
    again = _run(repo, cached=True)
    assert (reads.parsed, reads.settled, reads.scenes) == (["plain.py"], [], [])
    assert again == _run(repo, cached=False)

    _edit(repo / "pkg" / "other.py")  # declined, and no base of anybody's
    reads.clear()
    again = _run(repo, cached=True)
    assert (reads.parsed, reads.settled) == (["other.py"], ["other.py"])
    assert again == _run(repo, cached=False)


def test_a_changed_base_reads_the_files_deriving_from_it_again(
        repo: Path, own_key: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    reads = Reads(monkeypatch)
    _run(repo, cached=True)
    base = repo / "pkg" / "base.py"
    base.write_text(BASE.replace('"Target"', '"Goal"'), encoding="utf-8")
    reads.clear()
    changed = _run(repo, cached=True)
    assert (reads.parsed, reads.settled) == (["base.py"], ["derived.py"])
    uncached = _run(repo, cached=False)
    assert changed == uncached
    derived = [d for d in changed if d.path.endswith("derived.py")]
    assert derived == [d for d in uncached if d.path.endswith("derived.py")]


def _entries(repo: Path) -> list[Path]:
    return sorted((_folder(repo) / FOLDER).glob("*.json"))


def test_entries_signed_with_another_key_are_misses(repo: Path, own_key: Path,
                                                    monkeypatch: pytest.MonkeyPatch) -> None:
    """Entries made by somebody else (another user's key, or files planted in the cache
    folder) are ignored, even when they hold readings of our own classes."""
    first = _run(repo, cached=True)
    entries = _entries(repo)
    assert entries
    mine = FactsCache.open(_folder(repo))
    assert mine is not None
    keys = [entry.stem for entry in entries]
    assert all(mine.get(key) is not None for key in keys)  # what the first run kept
    stranger = Store(_folder(repo), b"another key of 32 bytes, not ours")
    for entry, key in zip(entries, keys, strict=True):
        stranger.write(FactsCache.entry(key), entry.read_bytes().split(b"\n", 1)[1])
    fresh = FactsCache.open(_folder(repo))
    assert fresh is not None and all(fresh.get(key) is None for key in keys)
    shutil.rmtree(_folder(repo) / OUTCOMES)  # the whole run is not answered at once
    reads = Reads(monkeypatch)
    assert _run(repo, cached=True) == first == _run(repo, cached=False)
    assert sorted(set(reads.parsed)) == ["base.py", "derived.py", "other.py", "plain.py"]


def test_a_corrupt_entry_is_a_miss_for_its_file_alone(
        repo: Path, own_key: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """An entry that does not decode (here, it names a class outside our packages, signed
    with our own key) is read again, and the others are still taken from the cache."""
    first = _run(repo, cached=True)
    [spoiled] = [e for e in _entries(repo) if b":FileFacts" in e.read_bytes()
                 and b"plain.py" in e.read_bytes()]
    key = user_key(own_key)
    assert key is not None
    Store(_folder(repo), key).write(FactsCache.entry(spoiled.stem),
                                    b'{"c":"os:system","f":[]}')
    shutil.rmtree(_folder(repo) / OUTCOMES)  # the whole run is not answered at once
    reads = Reads(monkeypatch)
    assert _run(repo, cached=True) == first
    assert reads.parsed == ["plain.py"]  # the spoiled entry's file alone


def test_the_codec_makes_nothing_but_our_own_readings(tmp_path: Path) -> None:
    """Decoding never calls what the data names: a class outside our packages, a function
    or a name that is no class is refused, and so is a field a dataclass does not have."""
    marker = tmp_path / "ran.marker"
    for forged in ({"c": "os:system", "f": []},
                   {"c": "pathlib:Path", "f": [["_raw_paths", [str(marker)]]]},
                   {"c": "ezmigrate.cache.facts_codec:decode", "f": []},
                   {"c": "ezmigrate.lint.diagnostic:Diagnostic", "f": [["__class__", 1]]},
                   {"t": [1], "extra": 2}, {"unknown": 1}):
        with pytest.raises(CodecError):
            decode(json.loads(json.dumps(forged)))
        with pytest.raises(CodecError):
            loads(json.dumps(forged))
    assert not marker.exists()
    index = load_index([bundled_ontology_path()])
    found = run_check([Path(__file__).parents[2] / "fixtures" / "legacy"], index,
                      PoolConfig(workers=1)).diagnostics
    assert decode(json.loads(json.dumps(encode(found)))) == found
    assert loads(json.dumps(encode(found))) == found


def test_without_a_key_there_is_no_cache_and_the_same_findings(
        repo: Path, tmp_path: Path) -> None:
    blocked = tmp_path / "user-cache"
    blocked.write_text("a file where the cache folder would be", encoding="utf-8")
    assert user_key(blocked) is None
    assert FactsCache.open(_folder(repo)) is None
    assert _run(repo, cached=True) == _run(repo, cached=False)
    assert not (_folder(repo) / FOLDER).exists()




def test_a_reading_kept_by_its_bytes_is_read_again_when_a_star_imported_module_changes(
        tmp_path: Path, own_key: Path) -> None:
    """What a tree's module binds comes also from the lab's module it star-imports: when
    that module no longer defines the processor, the kept reading of the unchanged tree is
    not taken, and the run says what --no-cache says (EZ317)."""
    repo = tmp_path / "repo"
    (repo / "pkg").mkdir(parents=True)
    (repo / "pkg" / "processors_here.py").write_text("class LabSequence:\n    pass\n")
    (repo / "pkg" / "tree.py").write_text(STAR_TREE)
    subprocess.run(["git", "init", "-q", str(repo)], check=True)
    assert not [d for d in _run(repo, cached=True) if d.code == "EZ317"]
    (repo / "pkg" / "processors_here.py").write_text("class LabSequenceRenamed:\n    pass\n")
    again = _run(repo, cached=True)
    assert again == _run(repo, cached=False)
    assert [d.code for d in again if "LabSequence" in d.message] == ["EZ317"]
