"""Round-trip property: any declarative legacy description migrates to an equivalent one.

Hypothesis draws legacy modules over the whole construct table (``strategies.
legacy_source``: parameters of every kind, value and type, options, descriptions in every
slot, every condition factory and condition class, free and conventional labels, or-
conditions, odd keys, file quirks); each is migrated with ``migrate()``, both versions are
written as real files, loaded in isolated children through the verification pool and
compared (``strategies.roundtrip``). Every class must be converted and equivalent, and
the static model must be the one the legacy code builds when it runs. CI runs 300
distinct modules; ``bench/roundtrip_long.py`` runs 10,000 (see ``bench/RESULTS.md``).
"""

from __future__ import annotations

import functools

import pytest
from hypothesis import HealthCheck, Phase, given, seed, settings
from strategies.legacy_source import GeneratedModule, legacy_modules_with_names
from strategies.roundtrip import CONSTRUCTS, RoundTrip

from ezmigrate.codemod.migrate import Settings
from ezskiros_runtime.ontology.load import load_index

MODULES = 300
"""Distinct generated modules verified in CI (hypothesis repeats some texts: drawn until
this many distinct ones exist)."""


@functools.cache
def _settings() -> Settings:
    return Settings(index=load_index())


def test_generated_legacy_modules_migrate_to_equivalent_descriptions(tmp_path, summary_line):
    trip = RoundTrip(tmp_path, _settings(), jobs=2, limit=MODULES)
    for round_seed in range(8):  # fixed seeds: the same modules in every run
        if trip.full:
            break

        @seed(round_seed)
        @settings(max_examples=MODULES // 2, deadline=None, database=None,
                  phases=[Phase.generate], suppress_health_check=list(HealthCheck))
        @given(legacy_modules_with_names(max_classes=2, max_params=5, max_conditions=5,
                                         undeclared_keys=True))
        def collect(module: GeneratedModule) -> None:
            trip.add(module)

        collect()
    report = trip.run()
    summary_line("round-trip property: " + report.summary())
    summary_line("skip reasons: " + ("; ".join(report.skip_lines()) or "none"))
    summary_line("constructs (modules containing each): " + ", ".join(
        f"{k} {v}" for k, v in report.kinds.most_common()))
    assert report.failure_count == 0, report.explain()
    assert report.modules == MODULES
    assert report.converted == report.classes >= MODULES
    assert report.compared == report.equivalent >= report.classes
    assert report.static_models_checked == report.converted
    missing = [k for k in CONSTRUCTS if not report.kinds[k]]
    assert not missing, f"constructs the generator never produced: {missing}"


HEADER = '''from skiros2_common.core.abstract_skill import SkillDescription, ParamOptions
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element
'''

REGRESSIONS = {
    # keys whose sanitized name is no identifier (¼, ²) or that Python NFKC-normalizes
    # (ℌ is read as H): the migration must give them a KEY, not crash or rename the key
    "keys that are no identifiers": ('''
class Tally(SkillDescription):
    def createDescription(self):
        self.addParam("£¼b»g", Element("skiros:Location"), ParamTypes.Required)
        self.addParam("Zw²S", 0.5, ParamTypes.Optional)
        self.addParam("ℌ", Element("skiros:Product"), ParamTypes.Required)
        self.addParam("H", 1, ParamTypes.Optional)
        self.addParam("ﬁle", "a", ParamTypes.Optional)
        self.addParam("", True, ParamTypes.Optional)
        self.addPreCondition(self.getRelationCond("In", "skiros:contain", "£¼b»g", "ℌ", True))
''', ("Tally",)),
    # a key declared again with Lock after another Lock: the second declaration's
    # conditions must keep their place after the first one's
    "redeclared key with options": ('''
class MoveBox(SkillDescription):
    def createDescription(self):
        self.addParam("Offset", False, ParamTypes.Required)
        self.addParam("Gripper", Element("skiros:Location"), ParamTypes.Inferred,
                      [ParamOptions.Lock])
        self.addParam("Offset", Element("skiros:GraspingPose"), ParamTypes.Required,
                      [ParamOptions.Lock])
        self.addPreCondition(self.getRelationCond("G", "skiros:contain", "Gripper", "Offset", True))
''', ("MoveBox",)),
}


@pytest.mark.parametrize("case", sorted(REGRESSIONS))
def test_round_trip_regressions(tmp_path, case):
    text, names = REGRESSIONS[case]
    trip = RoundTrip(tmp_path, _settings(), jobs=1)
    trip.add(GeneratedModule(HEADER + text, names))
    report = trip.run()
    assert report.failure_count == 0, report.explain()
    assert report.converted == report.equivalent == len(names)


def test_the_round_trip_catches_a_migration_that_changes_meaning(tmp_path):
    """The property can fail: the same machinery, fed a migrated file that lost a ``~``,
    reports the class as not equivalent with both sides of the condition."""
    text = HEADER + '''
class Place(SkillDescription):
    def createDescription(self):
        self.addParam("Gripper", Element("rparts:GripperEffector"), ParamTypes.Required)
        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)
        self.addPostCondition(self.getRelationCond("Released", "skiros:contain", "Gripper",
                                                   "Object", False))
'''
    trip = RoundTrip(tmp_path, _settings(), jobs=1)
    trip.add(GeneratedModule(text, ("Place",)))
    report = trip.run()
    assert report.failure_count == 0, report.explain()
    migrated = (tmp_path / "after" / "gen_00001.py").read_text(encoding="utf-8")
    assert "~ Gripper.contain(Object)" in migrated
    broken = RoundTrip(tmp_path / "broken", _settings(), jobs=1,
                       alter=lambda data: data.replace(b"~ Gripper", b"Gripper"))
    broken.add(GeneratedModule(text, ("Place",)))
    report = broken.run()
    assert report.failure_count == 1 and report.equivalent == 0
    failure = report.failures[0]
    assert failure.kind == "not-equivalent" and failure.cls == "Place"
    assert "False" in failure.diff[0]["before"] and "True" in failure.diff[0]["after"]

