"""EZ403 says what a second spatial parent costs (issue 30): a pose re-expressed in the wrong
parent's frame is a warning, a second node in the GUI's tree is info, and a property the
lab's ontology makes spatial is one finding for all the elements it touches. Real rdflib on
files written here; runs on the robot's Python 3.8 too (no ezmigrate import)."""

from __future__ import annotations

from pathlib import Path

import pytest
from shared_data import skiros2

from ezskiros_runtime.ontology.load import load_index
from ezskiros_runtime.world import check_scene_file

LAB_OWL = """\
@prefix owl: <http://www.w3.org/2002/07/owl#> .
@prefix rdfs: <http://www.w3.org/2000/01/rdf-schema#> .
@prefix skiros: <http://rvmi.aau.dk/ontologies/skiros.owl#> .
skiros:nextTo a owl:ObjectProperty ; rdfs:subPropertyOf skiros:spatiallyRelated .
"""

SCENE = """\
@prefix rdf: <http://www.w3.org/1999/02/22-rdf-syntax-ns#> .
@prefix owl: <http://www.w3.org/2002/07/owl#> .
@prefix xsd: <http://www.w3.org/2001/XMLSchema#> .
@prefix skiros: <http://rvmi.aau.dk/ontologies/skiros.owl#> .
@prefix rparts: <http://www.inf.ufrgs.br/phi-group/ontologies/RParts.owl#> .
skiros:Scene-0 a skiros:Scene, owl:NamedIndividual ;
    skiros:FrameId "map"^^xsd:string ;
    skiros:contain skiros:Location-1, skiros:Location-2, skiros:Location-3,
        skiros:Container-4, skiros:TransformationPose-5, rparts:ArmDevice-6 .
skiros:Location-1 a skiros:Location, owl:NamedIndividual ;
    skiros:nextTo skiros:Location-2, skiros:Location-3 .
skiros:Location-2 a skiros:Location, owl:NamedIndividual .
skiros:Location-3 a skiros:Location, owl:NamedIndividual ;
    skiros:nextTo skiros:Location-2 .
skiros:Container-4 a skiros:Location, owl:NamedIndividual ;
    skiros:hasA skiros:TransformationPose-5, rparts:ArmDevice-6 .
skiros:TransformationPose-5 a skiros:TransformationPose, owl:NamedIndividual ;
    skiros:FrameId "skiros:TransformationPose-5"^^xsd:string ;
    skiros:PositionZ "-0.4"^^xsd:float .
rparts:ArmDevice-6 a rparts:ArmDevice, owl:NamedIndividual .
"""


@pytest.fixture(scope="module")
def index(tmp_path_factory: pytest.TempPathFactory):
    folder = tmp_path_factory.mktemp("owl")
    (folder / "lab.ttl").write_text(LAB_OWL, encoding="utf-8")
    return load_index([skiros2(), folder / "lab.ttl"], cache=False)


def _parents(path: Path, index) -> list[tuple[str, str, int]]:
    return [(f.kind, f.severity, f.line) for f in check_scene_file(path, index)
            if f.code == "EZ403"]


def test_a_pose_under_two_parents_warns_an_element_without_one_is_info(tmp_path, index):
    scene = tmp_path / "scene.turtle"
    scene.write_text(SCENE, encoding="utf-8")
    found = {f.subject.rsplit("#", 1)[-1]: f for f in check_scene_file(scene, index)
             if f.kind == "scene-two-parents"}
    assert sorted(found) == ["ArmDevice-6", "TransformationPose-5"]
    assert found["TransformationPose-5"].severity == "warning"
    assert "its pose, in a frame of its own" in found["TransformationPose-5"].message
    assert found["ArmDevice-6"].severity == "info"
    assert "no pose of its own" in found["ArmDevice-6"].message


def test_a_property_the_lab_makes_spatial_is_one_finding_for_every_element(tmp_path, index):
    """Location-2 gets two extra parents and Location-3 one through skiros:nextTo: one info
    finding, at its first use, counting the two elements."""
    scene = tmp_path / "scene.turtle"
    scene.write_text(SCENE, encoding="utf-8")
    declared = [f for f in check_scene_file(scene, index)
                if f.kind == "scene-spatial-declaration"]
    assert len(declared) == 1
    (only,) = declared
    assert (only.code, only.severity, only.line) == ("EZ403", "info", 11)
    assert "skiros:nextTo is a sub-property of skiros:spatiallyRelated" in only.message
    assert "gives 2 element(s)" in only.message


def test_without_the_declaration_nothing_is_said_of_those_elements(tmp_path):
    index = load_index([skiros2()], cache=False)
    scene = tmp_path / "scene.turtle"
    scene.write_text(SCENE, encoding="utf-8")
    kinds = [f.kind for f in check_scene_file(scene, index) if f.code == "EZ403"]
    assert "scene-spatial-declaration" not in kinds
