"""Verification: load the legacy and the migrated version in isolated children, compare.

`pool` keeps the worker processes (`pool_config` says how they run) and `zygote` is one
of them: it imports the runtime and
loads the ontology once, then forks a child per file; `child`, `overlay` and `protocol` run
in those children, possibly under the robot's Python, so they are written for Python 3.8,
as is `sandbox`, which holds each child (environment, network, files, processes);
`interpreters` finds that Python; `verdicts` judges a migrated file from the two models;
`compare_files` and `command` are the ``verify`` command's comparison of two trees. May
import `files` and `report`, and the runtime.
"""
