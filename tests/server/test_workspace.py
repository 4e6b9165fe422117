"""A buffer is checked as typed (``server/workspace.py``), whichever reader ``check`` takes
for it, and the file on disk is never read in its place."""

from __future__ import annotations

from pathlib import Path

from ezmigrate.checking.run import CheckSettings
from ezmigrate.lint.select import Selection
from ezmigrate.server.workspace import Workspace
from ezmigrate.verify.pool import PoolConfig
from ezskiros_runtime.ontology.index import bundled_ontology_path
from ezskiros_runtime.ontology.load import load_index

# a description through another one of the module: the plain reader declines it and
# the codemod reads it (``read_files.declarations``)
THROUGH_A_BASE = '''\
from skiros2_skill.core.skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


class Base(SkillDescription):
    def createDescription(self):
        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)


class Pick(Base):
    def createDescription(self):
        Base.createDescription(self)
        self.addParam("Place", Element("skiros:Location"), ParamTypes.Required)
'''
PLAIN = '''\
from skiros2_skill.core.skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


class Pick(SkillDescription):
    def createDescription(self):
        self.addParam("Place", Element("skiros:Location"), ParamTypes.Required)
'''


def _workspace(root: Path) -> Workspace:
    (root / "package.xml").write_text("<package><name>ws</name></package>\n")
    return Workspace(root, load_index([bundled_ontology_path()]), PoolConfig(workers=1),
                     CheckSettings(), Selection())


def test_an_unsaved_buffer_is_checked_as_typed_by_either_reader(tmp_path: Path) -> None:
    ws = _workspace(tmp_path)
    for name, text in (("through_a_base.py", THROUGH_A_BASE), ("plain.py", PLAIN)):
        path = tmp_path / name
        path.write_text(text)
        assert not [d for d in ws.diagnose(path, text) if d.code == "EZ209"]
        typed = text.replace("skiros:Location", "skiros:Lcoation")
        [typo] = [d for d in ws.diagnose(path, typed) if d.code == "EZ209"]
        assert "skiros:Lcoation" in typo.message, name
        assert path.read_text() == text  # the disk keeps what was saved
        assert not [d for d in ws.diagnose(path, text) if d.code == "EZ209"]
