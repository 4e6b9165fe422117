"""``check`` reads a description built in a loop over constants as its unrolled form: a
class typo inside the loop is EZ209 (it was EZ902, "kept, not checked"), and the loop
and the unrolled form give the same findings."""

from __future__ import annotations

from pathlib import Path

from check_support import legacy, lint

REQ = "ParamTypes.Required"
LOOP = legacy(f'''
    for key, cls in (("Left", "skiros:Locaton"), ("Right", "skiros:Location")):
        self.addParam(key, Element(cls), {REQ})
    self.addParam("Item", Element("skiros:Product"), {REQ})
    for side in ("Left", "Right"):
        self.addPreCondition(self.getRelationCond("Holds", "skiros:contain", side, "Item", True))
''')
UNROLLED = legacy(f'''
    self.addParam("Left", Element("skiros:Locaton"), {REQ})
    self.addParam("Right", Element("skiros:Location"), {REQ})
    self.addParam("Item", Element("skiros:Product"), {REQ})
    self.addPreCondition(self.getRelationCond("Holds", "skiros:contain", "Left", "Item", True))
    self.addPreCondition(self.getRelationCond("Holds", "skiros:contain", "Right", "Item", True))
''')


def test_a_class_typo_inside_a_loop_over_constants_is_reported(tmp_path: Path) -> None:
    found = lint(tmp_path / "loop", LOOP)
    codes = [d.code for d in found]
    assert "EZ902" not in codes, "\n".join(map(str, found))
    [typo] = [d for d in found if d.code == "EZ209"]
    assert "skiros:Locaton" in typo.message and "skiros:Location" in typo.message
    assert typo.line == 9  # the addParam inside the loop (the `for` is line 8)


def test_the_loop_and_its_unrolled_form_give_the_same_findings(tmp_path: Path) -> None:
    def findings(name: str, source: str) -> list[tuple[str, str, str]]:
        return sorted((d.code, d.severity, d.message) for d in lint(tmp_path / name, source))

    assert findings("loop", LOOP) == findings("unrolled", UNROLLED)


def test_a_loop_over_a_computed_value_is_still_kept_and_said_so(tmp_path: Path) -> None:
    found = lint(tmp_path / "computed", legacy(f'''
        for key in sorted(("B", "A")):
            self.addParam(key, Element("skiros:Locaton"), {REQ})
    '''))
    assert [d.code for d in found if d.code in ("EZ209", "EZ902")] == ["EZ902"]
    [kept] = [d for d in found if d.code == "EZ902"]
    assert "a loop at line" in kept.message and "sorted" in kept.message
