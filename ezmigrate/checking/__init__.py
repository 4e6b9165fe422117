"""``ezmigrate check``: the linter a SkiROS2 repository keeps in CI, before and after migrating.

`pipeline` runs the stages in order over one run object (`run`): `discover` (the files,
scenes and launch file; the outcome cache's answer, or `early_cutoff`'s when the few files
that changed read as before), `read_files` (each file read once, into `file_facts`, shared
with `reading_pool`'s forked worker through `worker_channel`), `per_file` (legacy and
EzSkiROS descriptions on their own), `skill_index` (every description a tree may name), `compound`
(the trees' EZ3xx checks), `world` (EZ4xx), `judgements` (the checks inside implementation
classes, `implementation_code`; EZ105/EZ209 by `uninferable`; the robot's vocabulary) and
`keep` (the caches for the next run). `command` is the command's flow around the pipeline
(stdin, selection, `fixes`, the exit code); `launch` reads SkiROS2 launch files. May import
`files`, `report`, `codemod`, `verify`, `lint`, `compound`, `project` and `cache`; never the
command line.
"""
