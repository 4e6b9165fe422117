"""A description built in a loop over constants: ``rewrite`` unrolls it, verifies it by
loading both versions, and ``verify`` then finds the written file equal to the legacy one."""

from __future__ import annotations

from pathlib import Path

from verify_support import HEADER, cli, read_json, skills_of, tree

LOOPS = HEADER + '''
SIDES = ("Left", "Right")


class Sort(SkillDescription):
    def createDescription(self):
        self.addParam("Item", Element("skiros:Product"), ParamTypes.Required)
        # one location per side
        for key, cls in (("Left", "skiros:Location"), ("Right", "skiros:Location")):
            self.addParam(key, Element(cls), ParamTypes.Required)
        for side in SIDES:
            self.addPreCondition(self.getRelationCond("Empty", "skiros:contain", side, "Item",
                                                      False))
            self.addPostCondition(self.getRelationCond("Holds", "skiros:contain", side, "Item",
                                                       True))
        for name in ["Speed", "Force"]:
            self.addParam(name, 0.5, ParamTypes.Optional)
'''


def test_a_loop_over_constants_is_rewritten_and_the_result_verifies(tmp_path: Path) -> None:
    folder = tree(tmp_path / "skills", {"sort.py": LOOPS})
    before = tree(tmp_path / "before", {"sort.py": LOOPS})
    report = tmp_path / "r.json"
    run = cli("rewrite", folder, "--report", report)
    assert run.returncode == 0, run.stderr
    sort = skills_of(read_json(report), "sort.py")["Sort"]
    assert sort["status"] == "converted" and sort["equivalent"] is True, sort
    text = (folder / "sort.py").read_text(encoding="utf-8")
    assert "for " not in text and "createDescription" not in text
    assert text.index("Left: skiros.Location") < text.index("Right: skiros.Location") \
        < text.index("Speed: OPTIONAL[float] = 0.5") < text.index("Force:")
    proof = cli("verify", before, folder)
    assert proof.returncode == 0, proof.stderr
    assert "1 classes, 1 equivalent, 0 not equivalent" in proof.stderr, proof.stderr
