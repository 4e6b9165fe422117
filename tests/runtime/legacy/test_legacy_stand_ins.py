"""``legacy_imports``: SkiROS2 stand-in modules, permissive stubs, clean-up; and a realistic
legacy package loaded end to end."""

from __future__ import annotations

import abc
import importlib
import os
import sys
import sysconfig
from pathlib import Path

import pytest

from ezskiros_runtime.legacy import (
    Element,
    ParamOptions,
    ParamTypes,
    SkillDescription,
    legacy_imports,
    load_file,
)
from ezskiros_runtime.legacy.abstract_skill import SkillCore
from ezskiros_runtime.legacy.processors import Processor
from ezskiros_runtime.legacy.stubs import Stub, StubBase, is_stub
from ezskiros_runtime.model import Condition, Param, SkillModel, typed

STAND_IN_NAMES = [
    "skiros2_common", "skiros2_common.core", "skiros2_common.core.abstract_skill",
    "skiros2_common.core.params", "skiros2_common.core.world_element",
    "skiros2_common.core.conditions", "skiros2_common.core.primitive",
    "skiros2_common.core.primitive_thread", "skiros2_skill",
    "skiros2_skill.core", "skiros2_skill.core.skill", "skiros2_skill.core.processors",
]


def test_stand_in_modules_serve_our_classes() -> None:
    with legacy_imports():
        from skiros2_common.core import abstract_skill, conditions, params, world_element
        from skiros2_common.core.primitive import PrimitiveBase
        from skiros2_common.core.primitive_thread import PrimitiveThreadBase
        from skiros2_skill.core import processors, skill

        assert abstract_skill.SkillDescription is SkillDescription
        assert abstract_skill.ParamOptions is ParamOptions
        assert params.ParamTypes is ParamTypes and abstract_skill.ParamTypes is ParamTypes
        assert world_element.Element is Element
        assert skill.SkillDescription is SkillDescription and skill.ParamOptions is ParamOptions
        assert issubclass(PrimitiveBase, SkillCore) and issubclass(skill.SkillBase, SkillCore)
        assert issubclass(PrimitiveThreadBase, PrimitiveBase)
        assert conditions.ConditionOr().label == "or"
        assert skill.Sequential is processors.Sequential
        # other branches' processors: any CamelCase name, one class per name
        from skiros2_skill.core.skill import ParallelFfStar

        assert issubclass(ParallelFfStar, Processor)
        assert processors.ParallelFfStar is ParallelFfStar
        with pytest.raises(ImportError):
            from skiros2_skill.core.processors import lower_case  # noqa: F401
        assert set(STAND_IN_NAMES) <= set(sys.modules)
    assert not set(STAND_IN_NAMES) & set(sys.modules)


def test_context_removes_finders_modules_and_restores_previous_ones() -> None:
    meta_path = list(sys.meta_path)
    fake = type(sys)("skiros2_common")
    sys.modules["skiros2_common"] = fake  # e.g. a real SkiROS2 loaded earlier
    try:
        with legacy_imports(permissive=True):
            assert sys.meta_path[0] is not meta_path[0]
            assert len(sys.meta_path) == len(meta_path) + 2
            import skiros2_common
            import some_ros_pkg.msg

            assert skiros2_common is not fake and is_stub(some_ros_pkg.msg)
            assert "some_ros_pkg.msg" in sys.modules
        assert sys.meta_path == meta_path
        assert sys.modules["skiros2_common"] is fake
        assert "some_ros_pkg" not in sys.modules and "some_ros_pkg.msg" not in sys.modules
    finally:
        del sys.modules["skiros2_common"]


def test_nothing_is_active_outside_the_context() -> None:
    with pytest.raises(ImportError):
        import skiros2_common  # noqa: F401
    with pytest.raises(ImportError):
        importlib.import_module("skiros2_skill.core.skill")
    with legacy_imports(permissive=False), pytest.raises(ImportError):
        import rospy  # noqa: F401  (not permissive: no stubs)


def test_permissive_finder_is_last_and_real_modules_win() -> None:
    with legacy_imports(permissive=True):
        import json
        import numbers

        assert json.dumps([1]) == "[1]" and not is_stub(numbers)
        assert type(sys.meta_path[-1]).__name__ == "_PermissiveFinder"


def test_stub_modules_behave_permissively() -> None:
    with legacy_imports(permissive=True):
        import moveit_commander
        import rospy
        import tf.transformations as tft
        from geometry_msgs.msg import Pose, PoseStamped
        namespace: dict[str, object] = {}
        exec("from some.deep.package.module import *", namespace)
        assert set(namespace) == {"__builtins__"}  # empty __all__
        assert "some.deep.package.module" in sys.modules

        assert rospy.Publisher is rospy.Publisher  # made once, kept
        pub = rospy.Publisher("/topic", Pose, queue_size=1)
        assert is_stub(pub) and is_stub(tft.quaternion_from_euler(0, 0, 1))
        assert list(PoseStamped()) == [] and len(Pose) == 0 and "x" not in Pose
        assert is_stub(Pose()[0]) and is_stub(Pose().position.x + 1.5)
        assert is_stub(2 * rospy.get_param("~speed", 0.5) - 1)
        assert (rospy.Time.now() < 3) is False and rospy.Duration == rospy.Duration
        assert rospy.X != rospy.Y and int(rospy.Z) == 0 and float(rospy.Z) == 0.0
        assert list(range(rospy.n)) == [] and f"{rospy.x:.2f}" == "rospy.x"
        with moveit_commander.MoveGroupCommander("arm") as group:
            group.set_named_target("home")
        rospy.some_attr = 3
        assert rospy.some_attr == 3
        assert not isinstance(1, rospy.Rate)

        @rospy.decorator
        def kept() -> int:
            return 7

        @rospy.decorator_factory(1, key="x")
        class Kept:
            pass

        assert kept() == 7 and Kept.__name__ == "Kept"


def test_subclassing_stubs_with_stub_and_real_bases() -> None:
    with legacy_imports(permissive=True):
        import smach
        from tf import Transformer

        class OneStub(smach.State):
            def __init__(self) -> None:
                super().__init__(outcomes=["done"])

        class TwoStubs(smach.State, Transformer):
            pass

        class WithReal(smach.State, SkillDescription):
            pass

        class WithAbc(Transformer, abc.ABC):  # a real base with a metaclass
            @abc.abstractmethod
            def run(self) -> None: ...

        instance = OneStub()
        assert issubclass(OneStub, StubBase) and is_stub(instance.userdata)
        assert TwoStubs.__mro__[1:3] == (smach.State.__mro_entries__(())[0],
                                         Transformer.__mro_entries__(())[0])
        assert issubclass(WithReal, SkillDescription)
        assert WithReal()._type == "skiros:WithReal"  # the real base works
        assert issubclass(WithAbc, abc.ABC)


def test_stubs_are_not_given_to_library_code() -> None:
    # stdlib and site-packages probe optional modules with try/except ImportError
    fake_stdlib_file = os.path.join(sysconfig.get_paths()["stdlib"], "fake_probe.py")
    code = compile("import surely_missing_module_x", fake_stdlib_file, "exec")
    with legacy_imports(permissive=True), pytest.raises(ModuleNotFoundError):
        exec(code, {})
    with legacy_imports(permissive=True):
        exec(compile("import surely_missing_module_x", "/home/user/skills.py", "exec"), {})
        assert is_stub(sys.modules["surely_missing_module_x"])  # user code gets a stub


def test_stub_object_protocols() -> None:
    stub = Stub("thing")
    assert repr(stub) == "<stub thing>" and str(stub) == "thing" and bool(stub)
    assert list(reversed(stub)) == [] and -stub is not stub and abs(stub) is not stub
    stub["k"] = 1
    del stub["k"]
    del stub.attr
    with pytest.raises(AttributeError):
        _ = stub.__wrapped__  # protocol look-ups see "absent"
    assert not issubclass(int, stub) and hash(stub) == hash(stub)


PACKAGE_INIT = "# the skills package\n"

UTILS = """\
def helper(value):
    return value * 0.5
"""

SKILLS = '''\
#!/usr/bin/env python
# -*- coding: utf-8 -*-
"""A realistic legacy skill module (descriptions mixed with implementations)."""
import rospy
import numpy as np
import tf
import moveit_commander
import geometry_msgs.msg
from geometry_msgs.msg import Pose, PoseStamped
import skiros2_common.core.params as params
import skiros2_common.core.world_element
from skiros2_common.core.abstract_skill import SkillDescription as Description, ParamOptions
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element
from skiros2_common.core.primitive import PrimitiveBase
from skiros2_skill.core.skill import SkillBase, Sequential, ParallelFf, SkillDescription
from skiros2_common.core.primitive_thread import PrimitiveThreadBase
from .utils import helper

HOME = np.array([0.0, 0.0, 1.0])
SPEED = helper(0.5)
TOPIC = rospy.get_param("~topic", "/joint_states")


class Pick(Description):
    """Pick an object with a locked gripper."""

    def createDescription(self):
        #=======Params=========
        self.addParam("Gripper", Element("rparts:GripperEffector"), ParamTypes.Required,
                      [ParamOptions.Lock])
        self.addParam("Object", skiros2_common.core.world_element.Element("skiros:Product"),
                      params.ParamTypes.Required)
        self.addParam("Speed", SPEED, ParamTypes.Optional, "speed in m/s")
        #=======PreConditions=========
        self.addPreCondition(self.getRelationCond("RobotHasGripper", "skiros:hasA", "Robot",
                                                  "Gripper", True))
        self.addPostCondition(self.getRelationCond("GripperContainObject", "skiros:contain",
                                                   "Gripper", "Object", True))


class Place(SkillDescription):
    def createDescription(self):
        self.addParam("Robot", Element("cora:Robot"), ParamTypes.Inferred)
        self.addParam("Target Location", Element(":Location"), ParamTypes.Required)


class pick(PrimitiveBase):
    def createDescription(self):
        self.setDescription(Pick(), self.__class__.__name__)

    def onInit(self):
        self.pub = rospy.Publisher(TOPIC, PoseStamped, queue_size=1)
        return True

    def execute(self):
        return self.success("done")


class pick_and_place(SkillBase):
    def createDescription(self):
        self.setDescription(Pick(), self.__class__.__name__)

    def expand(self, skill):
        skill.setProcessor(Sequential())
        skill(self.skill("Pick", ""), self.skill(ParallelFf())(self.skill("Place", "")))


class pick_slowly(PrimitiveThreadBase):
    def createDescription(self):
        self.setDescription(Pick(), self.__class__.__name__)

    def run(self):
        return self.success("done")


class Listener(tf.TransformListener, moveit_commander.RobotCommander):
    pass
'''


def write_package(tmp_path: Path) -> Path:
    package = tmp_path / "my_skills"
    package.mkdir()
    (package / "__init__.py").write_text(PACKAGE_INIT)
    (package / "utils.py").write_text(UTILS)
    (package / "skills.py").write_text(SKILLS.rstrip("\n"))  # no final newline, as often
    return package / "skills.py"


def test_realistic_legacy_package_loads(tmp_path: Path) -> None:
    path = write_package(tmp_path)
    sys_path, meta_path, modules = list(sys.path), list(sys.meta_path), set(sys.modules)
    result = load_file(path)
    assert result.errors == [] and result.findings == []
    assert [m.name for m in result.models] == ["Pick", "Place"]
    pick, place = result.models
    lock = [Condition("property", label, "skiros:StateProperty", "Gripper", operator="=",
                      value=typed("Idle"), desired_state=typed(desired))
            for label, desired in (("GripperIdle", True), ("GripperBusy", False),
                                   ("GripperIdle", True))]
    assert pick == SkillModel(
        "Pick", "skiros:Pick",
        params=(Param("Gripper", "Required", "Element", "rparts:GripperEffector",
                      options=("Lock",)),
                Param("Object", "Required", "Element", "skiros:Product"),
                # the real sibling ran (0.5 * 0.5), and the description passed 4th is dropped
                Param("Speed", "Optional", "float", values=(typed(0.25),)),
                Param("Robot", "Inferred", "Element", "sumo:Agent")),
        pre=(lock[0], Condition("relation", "RobotHasGripper", "skiros:hasA", "Robot",
                                "Gripper", desired_state=typed(True))),
        hold=(lock[1],),
        post=(lock[2], Condition("relation", "GripperContainObject", "skiros:contain",
                                 "Gripper", "Object", desired_state=typed(True))),
    )
    assert (pick.source, pick.line) == (str(path), 25)
    assert place.params == (Param("Robot", "Inferred", "Element", "cora:Robot"),
                            Param("Target Location", "Required", "Element", ":Location"))
    # the interpreter is left as it was found
    assert sys.path == sys_path and sys.meta_path == meta_path
    new = set(sys.modules) - modules
    assert not {n for n in new if n.split(".")[0] in (
        "my_skills", "rospy", "numpy", "tf", "geometry_msgs", "moveit_commander",
        "skiros2_common", "skiros2_skill")}
    assert sorted(p.name for p in path.parent.iterdir()) == ["__init__.py", "skills.py",
                                                             "utils.py"]  # no __pycache__


def test_realistic_package_needs_permissive_mode(tmp_path: Path) -> None:
    from ezskiros_runtime.legacy import ModuleLoadError

    path = write_package(tmp_path)
    with pytest.raises(ModuleLoadError, match=r"skills\.py:4: .*ModuleNotFoundError.*rospy"):
        load_file(path, permissive=False)


def test_a_version_check_on_a_stub_module_runs(tmp_path: Path) -> None:
    """``if np.__version__ >= "1.20"`` at module level must not make a legacy file
    unloadable: stub modules carry a version string every comparison accepts."""
    path = tmp_path / "versioned.py"
    path.write_text(
        "import numpy as np\n"
        "from skiros2_common.core.abstract_skill import SkillDescription\n"
        "from skiros2_common.core.params import ParamTypes\n"
        "NEW_API = np.__version__ >= '1.20'\n\n\n"
        "class Measure(SkillDescription):\n"
        "    def createDescription(self):\n"
        "        self.addParam('Fast', NEW_API, ParamTypes.Optional)\n", encoding="utf-8")
    result = load_file(path)
    assert result.errors == [], result.errors
    (model,) = result.models
    assert model.params[0].key == "Fast" and model.params[0].values == (typed(False),)
