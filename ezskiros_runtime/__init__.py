"""EzSkiROS: ontology-typed SkiROS2 skill descriptions with early checks."""
