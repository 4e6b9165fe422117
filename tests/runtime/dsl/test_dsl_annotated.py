"""``Annotated[A, items...]`` (issue 43): the form that keeps strings where linters do not
parse them, equal to the ``KIND[...]`` form it stands for.

pyflakes reads every string inside an annotation as a forward reference (F722 "syntax error
in forward annotation", F821 for ``DESC("compliant|joint_config")``), except the items after
the first of a subscript named ``Annotated``. So the migrator writes ``DESC``, ``KEY`` and a
verbatim ``ELEMENT`` type there; the old spellings keep working. Each pair below is written
to real module files, loaded by the runtime's loader, and must give the same model; a
variant must not (so the equality is not vacuous). Annotations are evaluated both when the
``def`` runs and, with ``from __future__ import annotations``, from their strings.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from ezskiros_runtime import DESC, ELEMENT, INFERRED, KEY, OPTIONAL, REQUIRED, Annotated, Lock
from ezskiros_runtime.diagnostics import DescriptionError
from ezskiros_runtime.dsl.markers import ParamAnnotation
from ezskiros_runtime.dsl.policy import collecting
from ezskiros_runtime.legacy.loader import load_bytes

HEADER = ("from ezskiros_runtime import (SkillDescription, Annotated, INFERRED, OPTIONAL, "
          "REQUIRED, ELEMENT, KEY, DESC, Lock, Consume)\n"
          "from ezskiros_runtime.ontology import skiros\n\n"
          "CONSTANT = 3\n\n\n")

PAIRS = [
    # (the KIND[...] form, the Annotated form), each one parameter line
    ('X: REQUIRED[skiros.Product, DESC("The position of the prompt object")]',
     'X: Annotated[skiros.Product, DESC("The position of the prompt object")]'),
    ('S: OPTIONAL[float, DESC("m/s")] = 0.5',
     'S: Annotated[OPTIONAL[float], DESC("m/s")] = 0.5'),
    ('C: REQUIRED[str, DESC("compliant|joint_config")] = ""',
     'C: Annotated[str, DESC("compliant|joint_config")] = ""'),
    ('On_Off: REQUIRED[bool, KEY("On/Off")] = True',
     'On_Off: Annotated[bool, KEY("On/Off")] = True'),
    ('M: INFERRED[ELEMENT("scalable:Ur5")]',
     'M: Annotated[INFERRED, ELEMENT("scalable:Ur5")]'),
    ('X: ELEMENT(":Location")',
     'X: Annotated[REQUIRED, ELEMENT(":Location")]'),
    ('Cam: INFERRED[ELEMENT(":Cam"), Lock, DESC("c")]',
     'Cam: Annotated[INFERRED, ELEMENT(":Cam"), Lock, DESC("c")]'),
    ('Cam: REQUIRED[skiros.Location, DESC("x"), Lock, Consume, KEY("Cam 1")]',
     'Cam: Annotated[REQUIRED[skiros.Location, Lock, Consume], DESC("x"), KEY("Cam 1")]'),
    ('S: OPTIONAL[int, DESC("how many")] = CONSTANT',
     'S: Annotated[OPTIONAL, int, DESC("how many")] = CONSTANT'),
]


pytestmark = pytest.mark.usefixtures("core_ontology")


def _models(folder: Path, name: str, line: str, future: bool) -> list[str]:
    """The models (JSON, without their source) of one class ``Row`` whose ``description``
    takes the parameter ``line``, loaded from a real file."""
    text = ("from __future__ import annotations\n" if future else "") + HEADER + (
        "class Row(SkillDescription):\n"
        f"    def description(self, {line}):\n"
        "        pass\n")
    path = folder / f"{name}.py"
    path.write_text(text, encoding="utf-8")
    with collecting():
        found = load_bytes(path.read_bytes(), path)
    assert [e.message for e in found.errors] == []
    return [json.dumps({**m.to_json(), "source": ""}, sort_keys=True) for m in found.models]


@pytest.mark.parametrize("future", [False, True], ids=["evaluated", "strings"])
@pytest.mark.parametrize(("old", "new"), PAIRS, ids=[new.split(":")[0] for _, new in PAIRS])
def test_the_annotated_form_loads_equal_to_the_kind_form(tmp_path: Path, old: str, new: str,
                                                         future: bool) -> None:
    expected = _models(tmp_path, "old_form", old, future)
    assert len(expected) == 1
    assert _models(tmp_path, "new_form", new, future) == expected


def test_a_changed_item_changes_the_model(tmp_path: Path) -> None:
    base = _models(tmp_path, "base", 'X: Annotated[skiros.Product, DESC("one")]', False)
    for n, variant in enumerate([
            'X: Annotated[skiros.Product, DESC("two")]',
            'X: Annotated[skiros.Product, DESC("one"), KEY("Y")]',
            'X: Annotated[OPTIONAL[skiros.Product], DESC("one")]',
            'X: Annotated[REQUIRED, ELEMENT("skiros:Product"), Lock, DESC("one")]']):
        assert _models(tmp_path, f"variant{n}", variant, False) != base, variant


def test_items_after_a_kind_form_join_its_own() -> None:
    assert Annotated[REQUIRED[float, Lock], DESC("d")] == REQUIRED[float, Lock, DESC("d")]
    assert Annotated[INFERRED, ELEMENT("p:C"), KEY("k")] == INFERRED[ELEMENT("p:C"), KEY("k")]
    # a bare marker and no type: the default is the value, as in ``S: OPTIONAL = CONSTANT``
    assert Annotated[OPTIONAL, DESC("d")] == ParamAnnotation("Optional", None, "d")


@pytest.mark.parametrize(("build", "words"), [
    (lambda: Annotated[float], "at least one item"),
    (lambda: Annotated[DESC("x"), float], "first item must be the annotation"),
    (lambda: Annotated["float", DESC("x")], "first item must be the annotation"),
    (lambda: Annotated[float, ELEMENT("p:C")], "unexpected item"),
    (lambda: Annotated[OPTIONAL[float, DESC("a")], DESC("b")], "two descriptions"),
    (lambda: Annotated[REQUIRED[float, KEY("a")], KEY("b")], "two KEY"),
    (lambda: REQUIRED[Annotated, DESC("x")], "first item must be the type"),
])
def test_misuse_is_a_description_error(build, words: str) -> None:
    with pytest.raises(DescriptionError, match=words):
        build()


def test_a_bare_annotated_is_refused_when_the_class_is_built(tmp_path: Path) -> None:
    path = tmp_path / "bare.py"
    path.write_text(HEADER + "class Row(SkillDescription):\n"
                    "    def description(self, X: Annotated = 1):\n        pass\n",
                    encoding="utf-8")
    with collecting():
        found = load_bytes(path.read_bytes(), path)
    assert [e.skill for e in found.errors] == ["Row"]
    assert "bare Annotated" in found.errors[0].message
