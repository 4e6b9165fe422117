"""Early cutoff (issue 40): when the few Python files that changed since the kept run read
as they did (their facts, what the stages look for in their bytes, the lines their findings
stand on), the kept run answers, and no stage after ``discover`` runs; otherwise every
stage runs. Either way the findings are the bytes ``--no-cache`` gives.

Whether the run was cut off is read from the run object (``CheckRun.done`` after
``discover``), not from a clock.
"""

from __future__ import annotations

import ast
import subprocess
from pathlib import Path

import pytest
from cache_support import STAR_TREE

from ezmigrate.cache.cache_folder import Store, project_folder
from ezmigrate.checking import early_cutoff
from ezmigrate.checking.pipeline import check_run
from ezmigrate.checking.run import CheckRun, CheckSettings
from ezmigrate.lint.diagnostic import Diagnostic
from ezmigrate.verify.pool import PoolConfig
from ezskiros_runtime.ontology.index import bundled_ontology_path
from ezskiros_runtime.ontology.load import load_index
from ezskiros_runtime.world import scene as scene_module

PLACE = """\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


class Place(SkillDescription):
    def createDescription(self):
        self.addParam("Object", Element("skiros:Prodct"), ParamTypes.Required)
"""


PROCESSORS = "class LabSequence:\n    pass\n"


@pytest.fixture
def repo(tmp_path: Path) -> Path:
    root = tmp_path / "repo"
    (root / "pkg").mkdir(parents=True)
    (root / "pkg" / "place.py").write_text(PLACE, encoding="utf-8")
    (root / "pkg" / "tree.py").write_text(STAR_TREE, encoding="utf-8")
    (root / "pkg" / "processors_here.py").write_text(PROCESSORS, encoding="utf-8")
    subprocess.run(["git", "init", "-q", str(root)], check=True)
    return root


def _run(repo: Path, cached: bool = True) -> CheckRun:
    scene_module._KNOWN.clear()  # each run as a new process starts
    folder = project_folder(repo.parent / "user-cache", repo)
    return check_run([repo], load_index([bundled_ontology_path()]), PoolConfig(workers=1),
                     CheckSettings(cache_dir=folder if cached else None))


def _cut_off(repo: Path) -> tuple[bool, list[Diagnostic]]:
    """Whether the run was answered without its stages, and its findings, which must be
    ``--no-cache``'s."""
    run = _run(repo)
    assert run.diagnostics == _run(repo, cached=False).diagnostics
    return run.done and run.reader is None, run.diagnostics


def _append(path: Path, text: str) -> None:
    path.write_text(path.read_text(encoding="utf-8") + text, encoding="utf-8")


def test_a_comment_changes_no_reading_and_the_kept_run_answers(repo: Path) -> None:
    first = _run(repo)
    assert not first.done and "EZ209" in {d.code for d in first.diagnostics}
    _append(repo / "pkg" / "place.py", "# a comment\n")
    assert _cut_off(repo) == (True, first.diagnostics)
    _append(repo / "pkg" / "place.py", "\n\nSPEED = 2.0  # read by no check\n")
    assert _cut_off(repo)[0]
    assert _run(repo).done  # and the cut-off run was kept whole


def test_a_changed_declaration_runs_every_stage(repo: Path) -> None:
    _run(repo)
    place = repo / "pkg" / "place.py"
    place.write_text(PLACE.replace('"Object"', '"Thing"'), encoding="utf-8")
    cut, found = _cut_off(repo)
    assert not cut and any(d.skill == "Place" and d.param == "Thing" for d in found)
    place.write_text("\n" + PLACE, encoding="utf-8")  # every line moves down
    assert not _cut_off(repo)[0]


def test_a_comment_on_a_finding_line_runs_every_stage(repo: Path) -> None:
    """A finding's span is taken from its line's text: a comment at its end moves the
    span's end, so the kept findings no longer describe the file."""
    first = _run(repo)
    [typo] = [d for d in first.diagnostics if d.code == "EZ209"]
    place = repo / "pkg" / "place.py"
    lines = place.read_text(encoding="utf-8").splitlines(keepends=True)
    lines[typo.line - 1] = lines[typo.line - 1].rstrip("\n") + "  # the typo\n"
    place.write_text("".join(lines), encoding="utf-8")
    cut, found = _cut_off(repo)
    [moved] = [d for d in found if d.code == "EZ209"]
    assert not cut and moved.end_column > typo.end_column


def test_a_star_imported_module_is_cut_off_only_while_its_code_stays(repo: Path) -> None:
    """tree.py's reading took processors_here.py's names: a comment there changes nothing,
    a renamed class changes tree.py's findings (EZ317), and the run says so."""
    first = _run(repo)
    assert not [d for d in first.diagnostics if d.code == "EZ317"]
    processors = repo / "pkg" / "processors_here.py"
    _append(processors, "# the lab's processors\n")
    assert _cut_off(repo)[0]
    processors.write_text(PROCESSORS.replace("LabSequence", "LabSequenceRenamed"),
                          encoding="utf-8")
    cut, found = _cut_off(repo)
    assert not cut and [d.code for d in found if "LabSequence" in d.message] == ["EZ317"]


EZ_BASE = """\
from ezskiros_runtime import SkillDescription
from ezskiros_runtime.ontology import skiros


class Hold(SkillDescription):
    def description(self, Object: skiros.Product):
        pass
"""

EZ_USER = """\
from ezskiros_runtime import SkillDescription
from ezskiros_runtime.ontology import skiros

from .ez_base import Hold


class Inspect(SkillDescription):
    def description(self, Object: skiros.Product):
        pass


DEFAULTS = Hold
"""

LEGACY_DERIVED = """\
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element

from .place import Place


class PlaceGently(Place):
    def createDescription(self):
        self.addParam("Speed", 0.1, ParamTypes.Required)
"""


def test_a_module_only_ezskiros_files_import_is_cut_off(repo: Path) -> None:
    """ez_user.py imports ez_base.py, but its classes derive from the runtime's
    ``SkillDescription``: the codemod's cross-file pass reads no sibling for it, so a
    comment in ez_base.py is cut off like any other."""
    (repo / "pkg" / "ez_base.py").write_text(EZ_BASE, encoding="utf-8")
    (repo / "pkg" / "ez_user.py").write_text(EZ_USER, encoding="utf-8")
    first = _run(repo)
    assert not first.done
    _append(repo / "pkg" / "ez_base.py", "# a comment\n")
    assert _cut_off(repo) == (True, first.diagnostics)


def test_a_changed_ezskiros_file_is_read_against_the_runs_ontology(
        repo: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Early cutoff reads a changed EzSkiROS file before the read stage: against the run's
    ontology, not whichever one the process had active (here, one without ``skiros``)."""
    from ezskiros_runtime.ontology import active

    typo = repo / "pkg" / "ez_typo.py"
    typo.write_text(EZ_BASE.replace("skiros.Product", "skiros.Prodct"), encoding="utf-8")
    first = _run(repo)
    assert any("skiros:Product" in d.message for d in first.diagnostics)
    other = tmp_path / "other.ttl"
    other.write_text("@prefix lab: <http://example.org/lab#> .\n"
                     "@prefix owl: <http://www.w3.org/2002/07/owl#> .\n"
                     "lab:Thing a owl:Class .\n", encoding="utf-8")
    monkeypatch.setattr(active, "_active", load_index([other]))  # (restored after)
    _append(typo, "# a comment\n")
    assert _cut_off(repo) == (True, first.diagnostics)


def test_a_legacy_base_another_file_derives_from_runs_every_stage(repo: Path) -> None:
    """place_gently.py derives from place.py's ``Place``: the cross-file pass reads
    place.py's bytes for it, so even a comment there runs every stage."""
    (repo / "pkg" / "place_gently.py").write_text(LEGACY_DERIVED, encoding="utf-8")
    first = _run(repo)
    assert not first.done and any(d.skill == "Place" for d in first.diagnostics)
    _append(repo / "pkg" / "place.py", "# a comment\n")
    assert not _cut_off(repo)[0]


def test_a_memo_signed_by_another_key_is_not_taken(repo: Path) -> None:
    run = _run(repo)
    folder = project_folder(repo.parent / "user-cache", repo)
    [memo] = (folder / early_cutoff.MEMOS).glob("*.json")
    stranger = Store(folder, b"another key of 32 bytes, not ours")
    stranger.write(f"{early_cutoff.MEMOS}/{memo.name}", memo.read_bytes().split(b"\n", 1)[1])
    assert run.cutoff_key is not None and memo.stem == run.cutoff_key
    _append(repo / "pkg" / "place.py", "# a comment\n")
    assert not _cut_off(repo)[0]


STAGES = ("per_file", "skill_index", "compound", "world", "judgements", "uninferable",
          "implementation_code", "launch")
"""The modules of the stages after ``read_files`` (and what they call in ``checking``)."""


def test_what_the_stages_look_for_in_a_files_bytes_is_part_of_its_artifact() -> None:
    """Every ``b"..." in data`` a later stage (``checking``, ``compound``) tests is one of
    ``BYTE_MARKERS``, or is written with a name the markers module defines: else a change
    of such a text would change a finding with no change of the artifact."""
    root = Path(early_cutoff.__file__).resolve().parents[1]
    files = [root / "checking" / f"{name}.py" for name in STAGES]
    files += [p for p in (root / "compound").glob("*.py") if p.name != "markers.py"]
    for path in files:
        for node in ast.walk(ast.parse(path.read_bytes())):
            if isinstance(node, ast.Compare) and isinstance(node.ops[0], ast.In) \
                    and isinstance(node.left, ast.Constant) \
                    and isinstance(node.left.value, bytes):
                assert node.left.value in early_cutoff.BYTE_MARKERS, (path, node.lineno)
