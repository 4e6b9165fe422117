"""ezmigrate: move SkiROS2 skill descriptions to EzSkiROS and prove nothing changed."""

__version__ = "0.1.0"
