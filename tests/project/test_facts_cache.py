"""``check`` keeps what each file says by content (issue 31): after one file changes, the
next run reads that file again, and the files that depend on it, and nothing else; and
its findings are those of a run without a cache.

What is read again is observed, not timed: the real reading functions are wrapped to note
the files they are given (their work is unchanged). The kept entries are signed with a key
of this user's: a pack another key signed is never unpickled.
"""

from __future__ import annotations

import pickle
import subprocess
from pathlib import Path

import pytest

from ezmigrate.lint.diagnostic import Diagnostic
from ezmigrate.project import facts_cache, reading_pool
from ezmigrate.project import settle as settle_module
from ezmigrate.project.cache_folder import FOLDER
from ezmigrate.project.check import run_check
from ezmigrate.project.facts_cache import KEY_DIR, PACK, FactsCache
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
def own_key(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """This test's user cache folder, where the signing key is made."""
    home = tmp_path / "user-cache"
    monkeypatch.setenv(KEY_DIR, str(home))
    return home


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

        def file_facts(candidate, data, compounds, verdict=True):  # type: ignore[no-untyped-def]
            self.parsed.append(candidate.path.name)
            return real_facts(candidate, data, compounds, verdict)

        def settle(candidates, *args, **kwargs):  # type: ignore[no-untyped-def]
            self.settled += [c.path.name for c in candidates]
            return real_settle(candidates, *args, **kwargs)

        def parsed_scene(where, text):  # type: ignore[no-untyped-def]
            self.scenes.append(Path(where).name)
            return real_scene(where, text)

        monkeypatch.setattr(reading_pool, "file_facts", file_facts)  # one worker: here
        monkeypatch.setattr(settle_module, "settle", settle)  # ``check`` imports it late
        monkeypatch.setattr(scene_module, "_parsed", parsed_scene)

    def clear(self) -> None:
        self.parsed, self.settled, self.scenes = [], [], []


def _run(repo: Path, cached: bool) -> list[Diagnostic]:
    scene_module._KNOWN.clear()  # each run as a new process starts: nothing parsed yet
    index = load_index([bundled_ontology_path()])
    outcome = run_check([repo], index, PoolConfig(workers=1),
                        cache_dir=repo / FOLDER if cached else None)
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


def test_a_pack_signed_with_another_key_is_never_unpickled(repo: Path, own_key: Path,
                                                           tmp_path: Path,
                                                           monkeypatch: pytest.MonkeyPatch
                                                           ) -> None:
    """A pack committed to the checkout (or left by another user) is ignored: unpickling it
    would run what it says (here: write a marker file)."""
    _run(repo, cached=True)
    pack = repo / FOLDER / PACK
    assert pack.exists()
    marker = tmp_path / "unpickled.marker"
    hostile = pickle.dumps(_Hostile(str(marker)))
    monkeypatch.setenv(KEY_DIR, str(tmp_path / "somebody-else"))
    stranger = FactsCache.open(repo / FOLDER)
    assert stranger is not None
    pack.write_bytes(stranger._sign(hostile) + hostile)  # a valid pack, for their key
    monkeypatch.setenv(KEY_DIR, str(own_key))
    mine = FactsCache.open(repo / FOLDER)
    assert mine is not None and not marker.exists()
    assert mine.get(FactsCache.key("anything")) is None
    assert _run(repo, cached=True) == _run(repo, cached=False)  # the run reads everything


class _Hostile:
    def __init__(self, path: str) -> None:
        self.path = path

    def __reduce__(self) -> tuple[object, tuple[str, str]]:
        return (Path.write_text, (Path(self.path), "ran"))  # type: ignore[return-value]


def test_without_a_key_there_is_no_cache_and_the_same_findings(
        repo: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    blocked = tmp_path / "not-a-folder"
    blocked.write_text("a file where the cache folder would be", encoding="utf-8")
    monkeypatch.setenv(KEY_DIR, str(blocked))
    assert facts_cache._user_key() is None
    assert FactsCache.open(repo / FOLDER) is None
    assert _run(repo, cached=True) == _run(repo, cached=False)
    assert not (repo / FOLDER / PACK).exists()


def test_the_key_lives_in_the_users_cache_folder_unless_a_folder_is_named(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv(KEY_DIR, raising=False)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    made = facts_cache._user_key()
    assert made is not None
    assert (tmp_path / "xdg" / "ezmigrate" / "key").read_text(encoding="ascii") == made.hex()
    monkeypatch.setenv(KEY_DIR, str(tmp_path / "named"))
    other = facts_cache._user_key()
    assert other is not None and other != made
    assert (tmp_path / "named" / "key").read_text(encoding="ascii") == other.hex()
