"""The world model as the robot will see it: scenes read and checked, post-conditions that
leave it inconsistent, and whether a skill can start from a scene.

``read_scene`` and everything below it import rdflib only when a scene is parsed.
"""

from __future__ import annotations

from .grounding import Grounding, can_start
from .postconditions import DoublePlace, RelationUse, double_places
from .scene import Scene, SceneError, read_scene
from .scene_checks import check_scene, check_scene_file
from .vocabulary import DEFAULT_SINGLE_VALUED, single_valued

__all__ = ["DEFAULT_SINGLE_VALUED", "DoublePlace", "Grounding", "RelationUse", "Scene",
           "SceneError", "can_start", "check_scene", "check_scene_file",
           "double_places", "read_scene", "single_valued"]
