"""Run in a subprocess by test_dsl_backend.py: lower descriptions on the recording SkiROS2.

``recording_skiros2`` goes first on ``sys.path``, so ``skiros2_common`` is importable and
the runtime must choose it as the real backend. Prints JSON: the backend, whether
``SkillDescription`` derives from the recording class, and the calls of an EzSkiROS and a
legacy version of each skill.
"""

import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "recording_skiros2"))

from skiros2_common.core.abstract_skill import (
    ParamOptions,
)
from skiros2_common.core.abstract_skill import (
    SkillDescription as RealDescription,
)
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element

from ezskiros_runtime import (
    INFERRED,
    KEY,
    OPTIONAL,
    REQUIRED,
    Lock,
    SkillDescription,
    abstract,
)
from ezskiros_runtime.dsl.skill import BACKEND
from ezskiros_runtime.ontology import cora, rparts, skiros


class Pick(SkillDescription):
    def description(self,
                    Robot: INFERRED[cora.Robot],
                    ObjectLocation: INFERRED[skiros.Location],
                    Object: skiros.Product,
                    Gripper: rparts.GripperEffector):
        self.pre_conditions += ObjectLocation.contain(Object)
        self.pre_conditions += ~ Gripper.contain(Object)
        self.post_conditions += Gripper.contain(Object)


class LegacyPick(RealDescription):
    def createDescription(self):
        self.addParam("Robot", Element("cora:Robot"), ParamTypes.Inferred)
        self.addParam("ObjectLocation", Element("skiros:Location"), ParamTypes.Inferred)
        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)
        self.addParam("Gripper", Element("rparts:GripperEffector"), ParamTypes.Required)
        self.addPreCondition(self.getRelationCond("ObjectLocationContainObject",
                                                  "skiros:contain", "ObjectLocation",
                                                  "Object", True))
        self.addPreCondition(self.getRelationCond("NotGripperContainObject", "skiros:contain",
                                                  "Gripper", "Object", False))
        self.addPostCondition(self.getRelationCond("GripperContainObject", "skiros:contain",
                                                   "Gripper", "Object", True))


class Switch(SkillDescription):
    def description(self,
                    Gripper: REQUIRED[rparts.GripperEffector, Lock],
                    Pose: INFERRED[skiros.GraspingPose],
                    On_Off: REQUIRED[bool, KEY("On/Off")] = True,
                    Speed: OPTIONAL[float, "m/s"] = 0.5):  # noqa: F821 - a description
        self.pre_conditions += Gripper.contain(Pose) | abstract(~ Gripper.contain(Pose))
        self.hold_conditions += (Gripper.PositionX > 1.0).named("Far")
        self.post_conditions += self.param("On/Off").is_specified()


class LegacySwitch(RealDescription):
    def createDescription(self):
        self.addParam("Gripper", Element("rparts:GripperEffector"), ParamTypes.Required,
                      [ParamOptions.Lock])
        self.addParam("Pose", Element("skiros:GraspingPose"), ParamTypes.Inferred)
        self.addParam("On/Off", True, ParamTypes.Required)
        self.addParam("Speed", 0.5, ParamTypes.Optional, [], "m/s")
        either = self.getOrCond(True)
        either.addCondition(self.getRelationCond("GripperContainPose", "skiros:contain",
                                                 "Gripper", "Pose", True))
        either.addCondition(self.getAbstractRelationCond("NotGripperContainPose",
                                                         "skiros:contain", "Gripper", "Pose",
                                                         False))
        self.addPreCondition(either)
        self.addHoldCondition(self.getPropCond("Far", "skiros:PositionX", "Gripper", ">", 1.0,
                                               True))
        self.addPostCondition(self.getIsSpecifiedCond("On/OffSpecified", "On/Off", True))


def main() -> None:
    pick = Pick()
    print(json.dumps({
        "backend": BACKEND.name,
        "derives": isinstance(pick, RealDescription),
        "findings": [str(f) for f in pick.findings],
        "pick": pick.calls,
        "legacy_pick": LegacyPick().calls,
        "switch": Switch().calls,
        "legacy_switch": LegacySwitch().calls,
    }))


if __name__ == "__main__":
    main()
