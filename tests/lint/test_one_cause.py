"""One cause, one finding (issue 42): a typo of a condition's key or relation is reported
as the typo (EZ104, EZ209), not again as what it breaks beside it: the retraction it was
meant to be (EZ401 double-place) or the mention of an inferred parameter (EZ105). Real
files in a temporary folder, the real check core."""

from __future__ import annotations

from pathlib import Path

from check_support import legacy, lint

REQ, INF = "ParamTypes.Required", "ParamTypes.Inferred"
PARAMS = (f'self.addParam("Box", Element("skiros:Location"), {REQ})\n'
          f'self.addParam("Bin", Element("skiros:Location"), {REQ})\n'
          f'self.addParam("Item", Element("skiros:Product"), {REQ})\n')


def rel(label: str, which: str, relation: str, subject: str, obj: str, desired: bool) -> str:
    return (f'self.add{which}Condition(self.getRelationCond("{label}", "{relation}", '
            f'"{subject}", "{obj}", {desired}))\n')


def moves(retraction: str) -> str:
    return legacy(PARAMS + rel("In", "Pre", "skiros:contain", "Box", "Item", True)
                  + rel("Moved", "Post", "skiros:contain", "Bin", "Item", True) + retraction)


def codes(tmp_path: Path, source: str) -> list[str]:
    return sorted(d.code for d in lint(tmp_path, source)
                  if d.severity != "info" and d.code != "EZ901")


def test_a_misspelt_key_in_the_retraction_is_the_typo_alone(tmp_path: Path):
    assert codes(tmp_path / "ok", moves(rel("Out", "Post", "skiros:contain", "Box", "Item",
                                            False))) == []
    assert codes(tmp_path / "none", moves("")) == ["EZ401"]  # the real mistake stays
    assert codes(tmp_path / "key", moves(rel("Out", "Post", "skiros:contain", "Bx", "Item",
                                             False))) == ["EZ104"]


def test_a_misspelt_relation_in_the_retraction_is_the_typo_alone(tmp_path: Path):
    found = codes(tmp_path / "t", moves(rel("Out", "Post", "skiros:contan", "Box", "Item",
                                            False)))
    assert "EZ401" not in found and found, found


def test_a_misspelt_key_does_not_leave_its_inferred_parameter_unmentioned(tmp_path: Path):
    source = legacy(f'self.addParam("Box", Element("skiros:Location"), {REQ})\n'
                    f'self.addParam("Item", Element("skiros:Product"), {INF})\n'
                    + rel("In", "Pre", "skiros:contain", "Box", "Iteem", True))
    found = [d for d in lint(tmp_path / "t", source) if d.code in ("EZ104", "EZ105")]
    assert [d.code for d in found] == ["EZ104"], [str(d) for d in found]
