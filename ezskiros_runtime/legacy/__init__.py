"""Our re-implementation of the legacy SkiROS2 description API (used when SkiROS2 is absent)."""
