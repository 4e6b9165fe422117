"""A faithful migration keeps a legacy typo verbatim; the robot still hears of it at launch
(issue 28, part 4).

``ezmigrate rewrite`` turns ``Element("skiros:TarnsformationPose")`` into
``ELEMENT("skiros:TarnsformationPose")`` and a condition on the undeclared key ``"Hreon"``
into ``self.param("Hreon")``: the meaning is kept, typo and all. Where the typed form
(``skiros.TarnsformationPose``) would fail at import, these load; the early checks then
report each absent name against the ontology actually loaded, at its file and line and
with a did-you-mean, as a warning (an error under strict). The module below is written
as ``rewrite`` writes it, to a real file, and imported from there.
"""

from __future__ import annotations

import importlib.util
import warnings
from collections.abc import Iterator
from pathlib import Path
from types import ModuleType
from typing import Any

import pytest
from dsl_support import line_of

from ezskiros_runtime import EzSkirosWarning, SkillTypeError, check, strict
from ezskiros_runtime.ontology import active_index, use_ontology
from ezskiros_runtime.ontology.index import bundled_ontology_path

MIGRATED = '''\
from ezskiros_runtime import SkillDescription, ELEMENT
from ezskiros_runtime.ontology import skiros


class Pick(SkillDescription):
    def description(self,
                    Pose: ELEMENT("skiros:TarnsformationPose"),
                    Hero: skiros.Location,
                    Obj: skiros.Product):
        self.pre_conditions += self.param("Hreon").contain(Obj).named("HeroHasObj")
        self.pre_conditions += Hero.relation("skiros:contian", Obj)
        self.pre_conditions += Obj.property("skiros:FrameID", "=", "base")
'''
TYPOS = {
    # written in the file -> (kind, the line's marker, the first suggestion)
    "skiros:TarnsformationPose": ("unknown-vocabulary", 'Pose: ELEMENT("skiros:Tarns',
                                  "skiros:TransformationPose"),
    "Hreon": ("undeclared-parameter", 'self.param("Hreon")', "Hero"),
    "skiros:contian": ("unknown-vocabulary", '"skiros:contian"', "skiros:contain"),
    "skiros:FrameID": ("unknown-vocabulary", '"skiros:FrameID"', "skiros:FrameId"),
}
FIXED = {"skiros:TarnsformationPose": "skiros:TransformationPose", '"Hreon"': '"Hero"',
         "skiros:contian": "skiros:contain", "skiros:FrameID": "skiros:FrameId"}


@pytest.fixture(autouse=True)
def core() -> Iterator[None]:
    """The bundled SkiROS2 core is the loaded ontology; strict mode as the test sets it."""
    previous = active_index()
    use_ontology([bundled_ontology_path()])
    with strict(None):
        try:
            yield
        finally:
            use_ontology(previous)


def _migrated(folder: Path, text: str = MIGRATED) -> tuple[ModuleType, Path]:
    """The module written to ``folder`` and imported from that file."""
    path = folder / "pick_skills.py"
    path.write_text(text, encoding="utf-8")
    spec = importlib.util.spec_from_file_location(f"pick_skills_{id(folder)}", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module, path


def _by_name(found: list[Any]) -> dict[str, Any]:
    return {f.actual if f.kind == "unknown-vocabulary" else f.param: f for f in found}


def test_each_verbatim_typo_warns_at_its_line_with_a_suggestion(tmp_path: Path) -> None:
    module, path = _migrated(tmp_path)
    with pytest.warns(EzSkirosWarning) as caught:
        built = module.Pick()
    found = _by_name(built.findings)
    assert set(found) == set(TYPOS)
    for written, (kind, marker, suggestion) in TYPOS.items():
        finding = found[written]
        assert (finding.kind, finding.severity) == (kind, "warning"), written
        assert (finding.file, finding.line) == (str(path), line_of(marker, path)), written
        assert finding.suggestions[0] == suggestion, written
        assert f"did you mean {suggestion}" in finding.message, written
    shown = sorted((Path(w.filename), w.lineno) for w in caught)
    assert shown == sorted((path, line_of(marker, path)) for _, marker, _ in TYPOS.values())
    kept = built._pre_conditions[0]  # the meaning is kept: the condition is on "Hreon"
    assert (kept.subject_key, kept.relation, kept.object_key) == ("Hreon", "skiros:contain", "Obj")


def test_the_undeclared_key_is_matched_against_the_descriptions_own_keys(
        tmp_path: Path) -> None:
    module, _ = _migrated(tmp_path, MIGRATED.replace("Hero: skiros.Location",
                                                     "Heron: skiros.Location"
                                                     ).replace("Hero.", "Heron."))
    found = _by_name(check(module.Pick))["Hreon"]
    assert found.suggestions[0] == "Heron"
    assert found.message.endswith("(did you mean Heron?)")


def test_a_key_like_no_declared_one_is_reported_without_a_guess(tmp_path: Path) -> None:
    module, _ = _migrated(tmp_path, MIGRATED.replace('"Hreon"', '"Workpiece"'))
    found = _by_name(check(module.Pick))["Workpiece"]
    assert found.kind == "undeclared-parameter" and found.suggestions == ()
    assert "did you mean" not in found.message


@pytest.mark.parametrize("how", ["strict()", "EZSKIROS_STRICT=1"])
def test_under_strict_every_typo_is_an_error_and_the_skill_does_not_load(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch, how: str) -> None:
    module, path = _migrated(tmp_path)
    if how == "strict()":
        strict(True)
    else:
        monkeypatch.setenv("EZSKIROS_STRICT", "1")
    with pytest.raises(SkillTypeError) as caught:
        module.Pick()
    found = _by_name(list(caught.value.findings))
    assert set(found) == set(TYPOS)
    assert {f.severity for f in found.values()} == {"error"}
    assert f"{path.name}:{line_of('self.param(', path)}" in str(caught.value)
    assert "(did you mean Hero?)" in str(caught.value)


def test_the_same_skill_spelt_right_loads_without_a_word(tmp_path: Path) -> None:
    text = MIGRATED
    for typo, right in FIXED.items():
        text = text.replace(typo, right)
    module, _ = _migrated(tmp_path, text)
    with warnings.catch_warnings():
        warnings.simplefilter("error", EzSkirosWarning)
        built = module.Pick()
    assert built.findings == []
    with strict(True):
        assert check(module.Pick) == []
