"""``check`` keeps whole runs (issue 31): a second run of an unchanged repository gives the
same bytes without analysing anything again, and any change of what the run reads misses.

"Without analysing" is held by construction, not by a clock: a compound skill whose tree
only tracing can read writes a marker file when the tracing child imports it, so a run that
traced it leaves the marker and one that did not leaves none.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from cache_support import check_json, entries

from ezmigrate.cache.outcome_cache import OUTCOMES

TRACED = '''\
import pathlib
pathlib.Path(__file__).with_name("traced.marker").write_text("imported")

from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element
from skiros2_skill.core.skill import SkillBase


class Tour(SkillDescription):
    def createDescription(self):
        self.addParam("Pause", 1.0, ParamTypes.Optional)


class tour(SkillBase):
    def createDescription(self):
        self.setDescription(Tour(), self.__class__.__name__)

    def expand(self, skill):
        for key in ("Duration",):
            skill(self.skill("Wait", "", specify={"Time": 1.0}))
'''

SCENE = """\
@prefix owl: <http://www.w3.org/2002/07/owl#> .
@prefix skiros: <http://rvmi.aau.dk/ontologies/skiros.owl#> .
skiros:Scene-0 a skiros:Scene, owl:NamedIndividual ;
    skiros:contain skiros:Location-1 .
skiros:Location-1 a skiros:Location, owl:NamedIndividual{extra} .
"""


def _repo(tmp_path: Path) -> Path:
    repo = tmp_path / "repo"
    (repo / "pkg").mkdir(parents=True)
    (repo / "pkg" / "tour.py").write_text(TRACED, encoding="utf-8")
    (repo / "scene.turtle").write_text(SCENE.format(extra=""), encoding="utf-8")
    subprocess.run(["git", "init", "-q", str(repo)], check=True)
    return repo


def test_an_unchanged_repository_is_answered_from_the_kept_run(tmp_path: Path) -> None:
    repo = _repo(tmp_path)
    marker = repo / "pkg" / "traced.marker"
    first = check_json(repo, "--trace")
    assert first.returncode == 0, first.stderr
    assert "EZ307" in first.stdout and marker.exists()  # the tree was traced
    assert len(list((entries(repo) / OUTCOMES).glob("*.json"))) == 1
    marker.unlink()
    second = check_json(repo, "--trace")
    assert (second.stdout, second.stderr) == (first.stdout, first.stderr)
    assert not marker.exists()  # nothing was traced again
    uncached = check_json(repo, "--trace", "--no-cache")
    assert uncached.stdout == first.stdout and marker.exists()


def test_what_the_run_reads_is_the_key(tmp_path: Path) -> None:
    repo = _repo(tmp_path)
    first = check_json(repo, "--trace")
    (repo / "scene.turtle").write_text(SCENE.format(extra=" ;\n    skiros:hasA skiros:Gone-9"),
                                       encoding="utf-8")
    changed = check_json(repo, "--trace")
    assert "EZ404" in changed.stdout and "EZ404" not in first.stdout
    (repo / "pkg" / "tour.py").write_text(TRACED.replace('"Time"', '"Duration"'),
                                          encoding="utf-8")
    fixed = check_json(repo, "--trace")
    assert "EZ307" not in fixed.stdout
    for entry in (entries(repo) / OUTCOMES).glob("*.json"):
        entry.write_text("{not json")  # a damaged entry is a miss, and the run is redone
    assert check_json(repo, "--trace").stdout == fixed.stdout


def test_a_run_over_named_files_is_not_kept(tmp_path: Path) -> None:
    repo = _repo(tmp_path)
    run = subprocess.run([sys.executable, "-m", "ezmigrate", "check", "--exit-zero",
                          "pkg/tour.py"], cwd=repo, capture_output=True,
                         text=True, timeout=600, check=False)
    assert run.returncode == 0, run.stderr
    assert not (entries(repo) / OUTCOMES).exists()


MANIFEST = """<package format="2"><name>tours</name>
<buildtool_depend>{tool}</buildtool_depend></package>
"""


def test_the_package_manifests_are_part_of_the_key(tmp_path: Path) -> None:
    """The compound stage reads a package's flavour and name from its ``package.xml``
    (``ros_package_of``): a kept run is not taken once the manifest changed."""
    from ezmigrate.checking.pipeline import check_run
    from ezmigrate.checking.run import CheckSettings
    from ezmigrate.verify.pool import PoolConfig
    from ezskiros_runtime.ontology.index import bundled_ontology_path
    from ezskiros_runtime.ontology.load import load_index

    repo = _repo(tmp_path)
    manifest = repo / "pkg" / "package.xml"
    manifest.write_text(MANIFEST.format(tool="catkin"), encoding="utf-8")
    index = load_index([bundled_ontology_path()])
    settings = CheckSettings(cache_dir=tmp_path / "cache" / "projects" / "repo")

    def answered_whole() -> bool:
        return check_run([repo], index, PoolConfig(workers=1), settings).done

    assert not answered_whole()
    assert answered_whole()  # unchanged: the kept run answers
    manifest.write_text(MANIFEST.format(tool="ament_cmake"), encoding="utf-8")
    assert not answered_whole()
    assert answered_whole()


UNKNOWN_CLASS = '''\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


class Fetch(SkillDescription):
    def createDescription(self):
        self.addParam("Thing", Element("skiros:Gadget"), ParamTypes.Required)
'''

GADGET = """\
@prefix owl: <http://www.w3.org/2002/07/owl#> .
@prefix rdfs: <http://www.w3.org/2000/01/rdf-schema#> .
@prefix skiros: <http://rvmi.aau.dk/ontologies/skiros.owl#> .
skiros:Gadget a owl:Class ; rdfs:subClassOf skiros:Product .
"""

# ``check`` as ``check_json`` runs it, saying on stderr's last line whether the run
# imported the ontology's index (the module a run needs to decode it).
INDEX_IMPORTED = """\
import sys
sys.argv = ["ezmigrate", *sys.argv[1:]]
from ezmigrate.__main__ import main
try:
    main()
finally:
    sys.stderr.write(f"index imported: {'ezskiros_runtime.ontology.index' in sys.modules}\\n")
"""


def test_a_run_the_cache_answers_decodes_no_ontology(tmp_path: Path) -> None:
    """The outcome's key takes the ontology's fingerprint, known from the files before the
    index is decoded (``settle_source``): the index is loaded only by a run that reads. A
    change of the repository's ``owl/`` files is a miss all the same."""
    repo = tmp_path / "repo"
    (repo / "pkg").mkdir(parents=True)
    (repo / "pkg" / "skill.py").write_text(UNKNOWN_CLASS, encoding="utf-8")
    subprocess.run(["git", "init", "-q", str(repo)], check=True)

    def run() -> tuple[str, str, str]:
        done = subprocess.run([sys.executable, "-c", INDEX_IMPORTED, "check", "--exit-zero",
                               "--output-format", "json", "--cache-dir",
                               str(tmp_path / "user-cache"), "."], cwd=repo,
                              capture_output=True, text=True, timeout=600, check=True)
        *said, imported = done.stderr.splitlines()
        return done.stdout, "\n".join(said), imported

    unknown, _, imported = run()
    assert "EZ209" in unknown and imported == "index imported: True"
    again = run()
    assert again[0] == unknown and again[2] == "index imported: False"
    (repo / "owl").mkdir()
    (repo / "owl" / "lab.ttl").write_text(GADGET, encoding="utf-8")
    known, said, imported = run()
    assert "EZ209" not in known and imported == "index imported: True"
    assert "owl/lab.ttl" in said
    assert run() == (known, said, "index imported: False")
    assert check_json(repo, "--no-cache").stdout == known
