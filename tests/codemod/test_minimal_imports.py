"""Minimal diff: an import goes only when the migration removed its last use, and the new
imports cannot be rebound by a later star import.

Real repositories import far more than they use (loggers, ``State``, ``SkillWrapper``,
``ParallelFf``, ``PrimitiveBase``, ``SkillManager``); deleting those would put unrelated
lines in the review and could drop an import-time side effect.
"""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

from codemod_case import assert_migrates, assert_unchanged

UNUSED_BEFORE = '''\
import rospy
import skiros2_common.tools.logger as log
from skiros2_skill.core.skill import SkillDescription, SkillBase, State, SkillWrapper, ParallelFf
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element
from skiros2_common.core.primitive import PrimitiveBase  # kept for the plugin loader
from skiros2_skill.ros.skill_manager import SkillManager
'''

BODY = '''

class Pick(SkillDescription):
    def createDescription(self):
        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)


class pick(SkillBase):
    def createDescription(self):
        self.setDescription(Pick(), self.__class__.__name__)
'''

MIGRATED_BODY = '''

class Pick(SkillDescription):
    def description(self,
                    Object: skiros.Product):
        pass


class pick(SkillBase):
    def createDescription(self):
        self.setDescription(Pick(), self.__class__.__name__)
'''


def test_imports_unused_before_the_migration_stay_byte_for_byte():
    """Only SkillDescription, ParamTypes and Element lost their last use; the rest stays."""
    assert_migrates(UNUSED_BEFORE + BODY, '''\
import rospy
import skiros2_common.tools.logger as log
from ezskiros_runtime import SkillDescription
from ezskiros_runtime.ontology import skiros
from skiros2_skill.core.skill import SkillBase, State, SkillWrapper, ParallelFf
from skiros2_common.core.primitive import PrimitiveBase  # kept for the plugin loader
from skiros2_skill.ros.skill_manager import SkillManager
''' + MIGRATED_BODY)


def test_a_name_still_used_elsewhere_stays_and_an_aliased_one_goes_with_its_use():
    source = '''\
from skiros2_common.core.abstract_skill import SkillDescription as SD
from skiros2_common.core.params import ParamTypes as PT
from skiros2_common.core.world_element import Element


class Pick(SD):
    def createDescription(self):
        self.addParam("Object", Element("skiros:Product"), PT.Required)


def make(kind=PT.Optional):
    return kind
'''
    assert_migrates(source, '''\
from ezskiros_runtime import SkillDescription
from ezskiros_runtime.ontology import skiros
from skiros2_common.core.params import ParamTypes as PT


class Pick(SkillDescription):
    def description(self,
                    Object: skiros.Product):
        pass


def make(kind=PT.Optional):
    return kind
''')


def test_new_imports_go_after_a_star_import_that_could_rebind_them():
    """``helpers`` re-exports the legacy SkillDescription: imported before it, ours would
    be rebound and the migrated class would derive from the legacy base."""
    source = '''\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element
from .helpers import *


class Pick(SkillDescription):
    def createDescription(self):
        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)
'''
    assert_migrates(source, '''\
from .helpers import *
from ezskiros_runtime import SkillDescription
from ezskiros_runtime.ontology import skiros


class Pick(SkillDescription):
    def description(self,
                    Object: skiros.Product):
        pass
''')


def test_a_star_import_before_the_legacy_imports_changes_nothing_about_placement():
    source = '''\
from math import *
# SkiROS2
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes


class Wait(SkillDescription):
    def createDescription(self):
        self.addParam("Duration", 1.0, ParamTypes.Required)
'''
    assert_migrates(source, '''\
from math import *
# SkiROS2
from ezskiros_runtime import SkillDescription


class Wait(SkillDescription):
    def description(self,
                    Duration: float = 1.0):
        pass
''')


def test_a_module_without_descriptions_keeps_its_unused_imports():
    assert_unchanged(UNUSED_BEFORE + "\n\nclass pick(SkillBase):\n    pass\n")


HELPERS = '''\
"""Shared helpers; re-exports the legacy API for the skill modules (as real labs do)."""
from skiros2_common.core.abstract_skill import SkillDescription, ParamOptions  # noqa: F401
from skiros2_common.core.params import ParamTypes  # noqa: F401


def clamp(value, low, high):
    return max(low, min(high, value))
'''

SKILL = '''\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element
from .helpers import *


class Pick(SkillDescription):
    def createDescription(self):
        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)
        self.addParam("Speed", 0.5, ParamTypes.Optional)


def speed_for(weight):
    return clamp(1.0 / weight, 0.0, 1.0)
'''


def test_a_star_imported_helper_re_exporting_the_legacy_base_still_verifies(tmp_path: Path):
    """End to end, real verification: the migrated class derives from the EzSkiROS base."""
    package = tmp_path / "lab_skills"
    package.mkdir()
    (package / "__init__.py").write_text("", encoding="utf-8")
    (package / "helpers.py").write_text(HELPERS, encoding="utf-8")
    (package / "pick.py").write_text(SKILL, encoding="utf-8")
    original = tmp_path / "original"
    shutil.copytree(package, original / "lab_skills")
    run = subprocess.run([sys.executable, "-m", "ezmigrate", "rewrite", str(package)],
                         capture_output=True, text=True, check=False, timeout=600)
    assert run.returncode == 0, run.stderr
    assert "1 skill found, 1 converted, 0 skipped, 0 failed" in run.stderr, run.stderr
    text = (package / "pick.py").read_text(encoding="utf-8")
    assert text.index("from .helpers import *") < text.index("from ezskiros_runtime import")
    assert "class Pick(SkillDescription):" in text and "def description(self," in text
    assert (package / "helpers.py").read_text(encoding="utf-8") == HELPERS
    proof = subprocess.run([sys.executable, "-m", "ezmigrate", "verify",
                            str(original / "lab_skills"), str(package)],
                           capture_output=True, text=True, check=False, timeout=600)
    assert proof.returncode == 0, proof.stderr
    assert "1 classes, 1 equivalent, 0 not equivalent" in proof.stderr, proof.stderr


def test_an_attribute_of_the_same_name_is_no_use_of_an_import():
    """Issue 43: ``wmi.Element(...)`` is an attribute of another module, ``self.params`` one
    of the instance; neither keeps ``Element`` (whose last use was migrated), and ``params``,
    unused before as now, stays byte for byte."""
    source = '''\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element
import skiros2_common.core.world_element as wmi
import skiros2_common.core.params as params
from skiros2_common.core.primitive import PrimitiveBase


class Pick(SkillDescription):
    def createDescription(self):
        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)


class pick(PrimitiveBase):
    def createDescription(self):
        self.setDescription(Pick(), self.__class__.__name__)

    def execute(self):
        place = wmi.Element("skiros:Location", label=self.params["Object"].value.label)
        return self.success(place.label)
'''
    assert_migrates(source, '''\
from ezskiros_runtime import SkillDescription
from ezskiros_runtime.ontology import skiros
import skiros2_common.core.world_element as wmi
import skiros2_common.core.params as params
from skiros2_common.core.primitive import PrimitiveBase


class Pick(SkillDescription):
    def description(self,
                    Object: skiros.Product):
        pass


class pick(PrimitiveBase):
    def createDescription(self):
        self.setDescription(Pick(), self.__class__.__name__)

    def execute(self):
        place = wmi.Element("skiros:Location", label=self.params["Object"].value.label)
        return self.success(place.label)
''')


def test_a_replaced_dotted_base_takes_only_its_module_reference_with_it():
    """``abstract_skill.SkillDescription`` refers to ``abstract_skill``, not to the imported
    ``SkillDescription``, which the skipped ``Later`` still derives from."""
    source = '''\
from skiros2_common.core.abstract_skill import SkillDescription
import skiros2_common.core.abstract_skill as abstract_skill
from skiros2_common.core.params import ParamTypes


class Wait(abstract_skill.SkillDescription):
    def createDescription(self):
        self.addParam("Duration", 1.0, ParamTypes.Required)


class Later(SkillDescription):
    def createDescription(self):
        self.addParam(compute(), 1.0, ParamTypes.Required)
'''
    result = assert_migrates(source, '''\
from skiros2_common.core.abstract_skill import SkillDescription
from ezskiros_runtime import SkillDescription as EzSkillDescription
from skiros2_common.core.params import ParamTypes


class Wait(EzSkillDescription):
    def description(self,
                    Duration: float = 1.0):
        pass


class Later(SkillDescription):
    def createDescription(self):
        self.addParam(compute(), 1.0, ParamTypes.Required)
''')
    assert [(s.name, s.status) for s in result.skills] == [("Wait", "converted"),
                                                           ("Later", "skipped")]
