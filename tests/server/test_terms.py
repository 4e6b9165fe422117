"""The ontology at a cursor (``server/terms.py``) and child skills (``server/skills.py``),
against the real bundled SkiROS2 core."""

from __future__ import annotations

from pathlib import Path

from ezmigrate.server import skills, terms
from ezskiros_runtime.compound.library import SkillIndex
from ezskiros_runtime.ontology.index import bundled_ontology_path
from ezskiros_runtime.ontology.load import load_index

INDEX = load_index([bundled_ontology_path()])
EZ = '''\
class Pick(SkillDescription):
    def description(self, Gripper: INFERRED[rparts.GripperEffector], Object: skiros.Product):
        self.pre_conditions += Gripper.
'''


def test_a_term_is_read_in_both_forms_and_only_where_the_ontology_has_it() -> None:
    legacy = 'self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)'
    found = terms.term_at(INDEX, legacy, 0, legacy.index("Product"))
    assert found is not None and found.compact == "skiros:Product"
    assert terms.term_at(INDEX, legacy, 0, legacy.index("Object")) is None  # a key, no term
    typo = legacy.replace("Product", "Prodcut")
    assert terms.term_at(INDEX, typo, 0, typo.index("Prodcut")) is None
    row = EZ.splitlines()[1]
    found = terms.term_at(INDEX, EZ, 1, row.index("GripperEffector") + 1)
    assert found is not None and found.iri.endswith("GripperEffector")


def test_hover_says_the_superclasses_and_where_the_class_is_defined() -> None:
    notes = terms.read_notes(INDEX)
    term = terms.term_at(INDEX, '"skiros:Product"', 0, 3)
    assert term is not None
    said = terms.hover_text(INDEX, notes, term)
    assert "subclass of" in said and "skiros:Manipulatable" in said
    where = terms.definition(notes, term)
    assert where is not None
    assert "Product" in Path(where.path).read_text().splitlines()[where.line]


def test_properties_after_a_parameter_come_with_those_its_domain_admits_first() -> None:
    line = EZ.splitlines()[2]
    found = terms.completions(INDEX, EZ, 2, len(line))
    cls = INDEX.expand("rparts:GripperEffector")
    assert cls is not None

    def tier(label: str) -> int:
        infos = [INDEX.property(i) for i in INDEX.properties_named(label)]
        best = 3
        for info in infos:
            assert info is not None
            best = min(best, 1 if not info.domains else
                       0 if any(INDEX.satisfies(cls, d) for d in info.domains) else 2)
        return best

    tiers = [tier(c.label) for c in found]
    assert tiers == sorted(tiers) and tiers[0] == 0 and 2 in tiers
    unknown = terms.completions(INDEX, EZ.replace("INFERRED[rparts.GripperEffector]", "str"),
                                2, len(line))
    assert [c.label for c in unknown] != [c.label for c in found]  # no class: by name only


def test_a_child_call_is_read_for_its_type_label_and_keys(tmp_path: Path) -> None:
    row = '        self.skill("Pick", "pick_fast", specify={"Spe'
    assert skills.child_at(row, 0, row.index("Pick") + 2) == skills.ChildAt(
        "type", "Pick", "pick_fast", "Pi", row.index("Pick"), row.index("Pick") + 4)
    label = skills.child_at(row, 0, row.index("pick_fast") + 4)
    assert label is not None and (label.kind, label.typed) == ("label", "pick")
    key = skills.child_at(row, 0, len(row))
    assert key is not None and (key.kind, key.type, key.typed) == ("key", "Pick", "Spe")
    (tmp_path / "impl.py").write_text("import x\n\n\nclass pick_fast(SkillBase):\n    pass\n")
    assert skills.definition(SkillIndex(), label, tmp_path) == (str(tmp_path / "impl.py"), 4)
