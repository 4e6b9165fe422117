"""OWL classes as Python types and the prefix namespaces of the active ontology."""

from __future__ import annotations

import subprocess
import sys

import pytest
from dsl_support import ROOT, paper  # noqa: F401 - paper is a fixture

import ezskiros_runtime.ontology as ontology
from ezskiros_runtime import UnknownVocabularyError
from ezskiros_runtime.diagnostics import UnknownPrefixError
from ezskiros_runtime.ontology import cora, load_index, rparts, skiros, sumo, use_ontology
from ezskiros_runtime.ontology.namespaces import OwlClass, PropertyRef

pytestmark = pytest.mark.usefixtures("paper")
SKIROS = "http://rvmi.aau.dk/ontologies/skiros.owl#"


def test_a_class_is_a_cached_python_type_with_iri_qname_and_repr():
    product = skiros.Product
    assert isinstance(product, type)
    assert product is skiros.Product
    assert (product.iri, product.qname) == (SKIROS + "Product", "skiros:Product")
    assert repr(product) == "<OWL class skiros:Product>"
    assert product.__name__ == "Product"
    assert issubclass(product, OwlClass)


def test_issubclass_follows_the_subclass_closure_with_several_parents():
    assert issubclass(skiros.GraspingPose, skiros.TransformationPose)
    assert issubclass(skiros.GraspingPose, skiros.Location)
    assert issubclass(skiros.GraspingPose, sumo.Object)
    assert not issubclass(skiros.TransformationPose, skiros.GraspingPose)
    assert issubclass(cora.Robot, sumo.Agent) and issubclass(cora.Robot, sumo.Device)
    assert not issubclass(rparts.GripperEffector, sumo.Agent)
    assert not issubclass(float, skiros.Product)
    assert issubclass(skiros.Product, skiros.Product)


def test_properties_are_references_usable_as_vocabulary():
    contain, publish = skiros.contain, skiros.PublishTf
    assert isinstance(contain, PropertyRef)
    assert (contain.qname, contain.kind) == ("skiros:contain", "object")
    assert (publish.qname, publish.kind) == ("skiros:PublishTf", "data")
    assert repr(contain) == "<OWL object property skiros:contain>"
    assert contain == skiros.contain and len({contain, skiros.contain}) == 1


def test_an_unknown_name_is_an_attribute_error_with_suggestions():
    with pytest.raises(UnknownVocabularyError) as raised:
        skiros.GrASPingPose  # noqa: B018
    assert isinstance(raised.value, AttributeError)
    assert str(raised.value) == ("skiros.GrASPingPose is not a class or property of the "
                                 "active ontology (did you mean skiros.GraspingPose?)")
    assert not hasattr(skiros, "Nothing")


def test_an_unknown_prefix_fails_with_a_suggestion():
    message = r"no ontology prefix 'skirso' in the active ontology \(did you mean skiros\?\)"
    with pytest.raises(UnknownVocabularyError, match=message):
        ontology.skirso  # noqa: B018 - an AttributeError, so that:
    assert not hasattr(ontology, "skirso")
    assert getattr(ontology, "skirso", None) is None
    with pytest.raises(UnknownPrefixError, match=message) as raised:  # the import statement
        from ezskiros_runtime.ontology import skirso  # noqa: F401
    assert raised.value.suggestions == ("skiros",)
    assert isinstance(raised.value, ImportError)
    with pytest.raises(UnknownVocabularyError, match=r"did you mean skiros\.Product"):
        skiros.Prodcut  # noqa: B018 - inside a namespace: an AttributeError, as hasattr expects
    assert not hasattr(skiros, "Prodcut")
    assert ontology.use_ontology is use_ontology  # helpers are not prefixes


SHADOWING_TTL = """
@prefix data: <http://example.org/data#> .
@prefix cache: <http://example.org/cache#> .
@prefix owl: <http://www.w3.org/2002/07/owl#> .
data:Box a owl:Class .
cache:Shelf a owl:Class .
"""


def test_prefixes_named_like_internal_modules_win(tmp_path):
    """An ontology's ``data`` or ``cache`` prefix is importable although the package has
    submodules of those names (``cache`` is imported already, so bound as an attribute);
    the public helpers still win, and importing from the modules keeps working."""
    (tmp_path / "shadow.ttl").write_text(SHADOWING_TTL)
    use_ontology([tmp_path / "shadow.ttl"])
    from ezskiros_runtime.ontology import cache, data
    from ezskiros_runtime.ontology.cache import default_cache_dir

    assert data.Box.qname == "data:Box"
    assert cache.Shelf.qname == "cache:Shelf"
    assert ontology.cache is cache
    assert callable(default_cache_dir)
    assert ontology.load_index is load_index
    assert sys.modules["ezskiros_runtime.ontology.cache"].__name__ == \
        "ezskiros_runtime.ontology.cache"
    use_ontology(load_index())  # no such prefixes: the modules again
    from ezskiros_runtime.ontology import cache as module

    assert module is sys.modules["ezskiros_runtime.ontology.cache"]


def test_dir_lists_the_names_of_the_prefix():
    names = dir(skiros)
    assert {"GraspingPose", "Product", "contain", "hasA", "PublishTf"} <= set(names)
    assert "Robot" in dir(cora)


def test_namespaces_follow_the_active_ontology():
    with pytest.raises(UnknownVocabularyError):
        skiros.DepthCamera  # noqa: B018 - only in the bundled vocabulary
    use_ontology(load_index())
    camera = skiros.DepthCamera
    assert camera.qname == "skiros:DepthCamera"
    assert skiros.Product is not None


def test_importing_the_runtime_loads_neither_rdflib_nor_an_ontology():
    code = (
        "import sys\n"
        "import ezskiros_runtime\n"
        "from ezskiros_runtime import SkillDescription, INFERRED, OPTIONAL, REQUIRED, ELEMENT, "
        "KEY, abstract, any_of, Lock, Consume, Unspecify, RespectType, Output, "
        "SkillTypeError, Finding, check, strict\n"
        "import ezskiros_runtime.ontology\n"
        "print(sorted(m for m in ('rdflib', 'ezskiros_runtime.ontology.active', "
        "'ezskiros_runtime.ontology.index') if m in sys.modules))\n"
    )
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                            cwd=ROOT, check=True, timeout=60)
    assert result.stdout.strip() == "[]"
