"""An import error inside SkiROS2 is shown with its cause (issue 43: on the robot it
surfaced only as ``cannot import name 'SkillDescription' from 'ezskiros_runtime'``).

A real ``skiros2_common`` package in a temporary folder whose ``abstract_skill`` fails when
imported, and a real child interpreter that imports the runtime's public name the way a
migrated skill does."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

FAILURES = {
    "an attribute error": ("import os\nBROKEN = os.path.no_such_helper\n",
                           "AttributeError: module 'posixpath' has no attribute "
                           "'no_such_helper'"),
    "a missing module": ("from rospy_stand_in_that_is_missing import Time\n",
                         "ModuleNotFoundError: No module named "
                         "'rospy_stand_in_that_is_missing'"),
}


def _skiros2(root: Path, abstract_skill: str) -> None:
    core = root / "skiros2_common" / "core"
    core.mkdir(parents=True)
    (root / "skiros2_common" / "__init__.py").write_text("", encoding="utf-8")
    (core / "__init__.py").write_text("", encoding="utf-8")
    (core / "abstract_skill.py").write_text(abstract_skill, encoding="utf-8")
    (core / "params.py").write_text("class ParamTypes:\n    pass\n", encoding="utf-8")
    (core / "world_element.py").write_text("class Element:\n    pass\n", encoding="utf-8")


@pytest.mark.parametrize("failure", sorted(FAILURES))
def test_the_cause_is_named_and_chained(tmp_path: Path, failure: str) -> None:
    source, cause = FAILURES[failure]
    _skiros2(tmp_path, source)
    env = {"PATH": os.environ.get("PATH", "/usr/bin:/bin"), "PYTHONPATH": str(tmp_path),
           "EZSKIROS_BACKEND": "skiros2", "HOME": str(tmp_path)}
    run = subprocess.run([sys.executable, "-c", "from ezskiros_runtime import SkillDescription"],
                         env=env, cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert run.returncode != 0
    last = run.stderr.strip().splitlines()[-1]
    assert last.startswith("ImportError: cannot import name 'SkillDescription' from "
                           "'ezskiros_runtime': importing ezskiros_runtime."), run.stderr
    assert last.endswith(cause), run.stderr
    assert "The above exception was the direct cause" in run.stderr


def test_an_unknown_name_is_still_an_attribute_error() -> None:
    import ezskiros_runtime

    with pytest.raises(AttributeError):
        ezskiros_runtime.NoSuchName  # noqa: B018
