"""``ezmigrate check``'s own checks of legacy code and of a robot's world.

`plain_reader` reads a plain legacy description with ``ast`` (the fast path; the
codemod's reader takes what it declines; `newer_fstrings` respells Python 3.12's
f-strings for it), `ezskiros_reader` an EzSkiROS file with no legacy description in it,
as the codemod would read it, `ezskiros_static` the descriptions of an EzSkiROS
file from their syntax, with the runtime's checks and no code of the file run, `legacy`
holds the checks only legacy code needs,
`robot_vocabulary` and `world_model` the checks against the lab's ontology, scenes and
launch files (`scene_search` finds the scenes), `scene_diagram` draws a scene for the
report, `skill_library` says whether a file is in a package the skill manager imports
(how bad a syntax error in it is), `diagnostic` is one line of output and `select` applies
``--select``/``--ignore`` and suppression comments. May import `codemod`, `verify`,
`report` and `files`, and the runtime.
"""
