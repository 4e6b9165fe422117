"""Backend selection: SkiROS2's own classes when ``skiros2_common`` is importable.

The real backend is exercised with the recording stand-in package in ``recording_skiros2``,
in a subprocess so that this process keeps the legacy backend it started with.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest
from dsl_support import PAPER, ROOT

from ezskiros_runtime import SkillDescription
from ezskiros_runtime.dsl.backend import select_backend
from ezskiros_runtime.dsl.skill import BACKEND
from ezskiros_runtime.legacy.abstract_skill import SkillDescription as LegacyDescription

HERE = os.path.dirname(os.path.abspath(__file__))
RECORDING = os.path.join(HERE, "recording_skiros2")

PICK_CALLS = [
    "addParam('Robot', Element('cora:Robot'), ParamTypes.Inferred, [], '')",
    "addParam('ObjectLocation', Element('skiros:Location'), ParamTypes.Inferred, [], '')",
    "addParam('Object', Element('skiros:Product'), ParamTypes.Required, [], '')",
    "addParam('Gripper', Element('rparts:GripperEffector'), ParamTypes.Required, [], '')",
    "getRelationCond('ObjectLocationContainObject', 'skiros:contain', 'ObjectLocation', "
    "'Object', True)",
    "addPreCondition(getRelationCond('ObjectLocationContainObject', 'skiros:contain', "
    "'ObjectLocation', 'Object', True))",
    "getRelationCond('NotGripperContainObject', 'skiros:contain', 'Gripper', 'Object', False)",
    "addPreCondition(getRelationCond('NotGripperContainObject', 'skiros:contain', 'Gripper', "
    "'Object', False))",
    "getRelationCond('GripperContainObject', 'skiros:contain', 'Gripper', 'Object', True)",
    "addPostCondition(getRelationCond('GripperContainObject', 'skiros:contain', 'Gripper', "
    "'Object', True))",
    "generateDefParams()",
]


def run(args: list[str], **env: str) -> subprocess.CompletedProcess[str]:
    environment = {k: v for k, v in os.environ.items()
                   if k not in ("EZSKIROS_BACKEND", "PYTHONPATH")}
    environment.update(EZSKIROS_ONTOLOGY=str(PAPER), **env)
    return subprocess.run([sys.executable, *args], capture_output=True, text=True, cwd=ROOT,
                          env=environment, timeout=120)


def test_pick_on_the_real_backend_makes_exactly_the_legacy_calls():
    result = run([os.path.join(HERE, "real_backend_probe.py")])
    assert result.returncode == 0, result.stderr
    data = json.loads(result.stdout)
    assert data["backend"] == "skiros2"
    assert data["derives"] is True
    assert data["findings"] == []
    assert data["pick"] == PICK_CALLS
    assert data["legacy_pick"] == PICK_CALLS
    assert data["switch"] == data["legacy_switch"]
    assert "or#1.addCondition(getAbstractRelationCond('NotGripperContainPose', " \
           "'skiros:contain', 'Gripper', 'Pose', False))" in data["switch"]
    assert data["switch"][0] == ("addParam('Gripper', Element('rparts:GripperEffector'), "
                                 "ParamTypes.Required, [ParamOptions.Lock], '')")


PROBE = (
    "import sys; sys.path.insert(0, {path!r})\n"
    "from ezskiros_runtime.dsl.skill import BACKEND\n"
    "print(BACKEND.name, BACKEND.SkillDescription.__module__)\n"
)


def test_the_environment_variable_can_force_the_legacy_backend():
    result = run(["-c", PROBE.format(path=RECORDING)], EZSKIROS_BACKEND="legacy")
    assert result.returncode == 0, result.stderr
    assert result.stdout.split() == ["legacy", "ezskiros_runtime.legacy.abstract_skill"]


def test_forcing_skiros2_without_it_is_an_import_error():
    result = run(["-c", PROBE.format(path=os.path.join(HERE, "no_such_dir"))],
                 EZSKIROS_BACKEND="skiros2")
    assert result.returncode != 0
    assert "ImportError: EZSKIROS_BACKEND=skiros2 but skiros2_common cannot be imported" \
        in result.stderr


def test_forcing_skiros2_with_it_present_uses_it():
    result = run(["-c", PROBE.format(path=RECORDING)], EZSKIROS_BACKEND="skiros2")
    assert result.stdout.split() == ["skiros2", "skiros2_common.core.abstract_skill"]


def test_without_skiros2_this_process_uses_the_legacy_backend():
    assert os.environ.get("EZSKIROS_BACKEND") in (None, "", "auto", "legacy")
    assert BACKEND.name == "legacy"
    assert issubclass(SkillDescription, LegacyDescription)
    with pytest.raises(ValueError, match="EZSKIROS_BACKEND='ros': expected one of"):
        select_backend("ros")
