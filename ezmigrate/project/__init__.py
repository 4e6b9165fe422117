"""Running over a repository: what a command does between its settings and its output.

`settle` owns a migration (migrate every file, derive what crosses files, verify, hold
back, repeat); `runner` reads the files and runs the codemod in parallel workers, with
`import_scan` and `cross_file` for what links files; `holding` and `static_refusal` hold
back the skills that will not be written (`refusals` works out what the runtime's
early checks refuse); `session` is ``rewrite`` (it writes what settled,
under `interrupt`'s deferral) and `earlier` adds what an earlier run migrated to its report;
`check` is ``check``, reading each file once into `file_facts` (in `reading_pool`'s
forked workers, with the scenes, from the heap `frozen_heap` keeps out of the collector's
reach, as `runner`'s workers do), with `load_cache`,
`facts_cache` and `outcome_cache` for its next run (each load, each file's and scene's
reading by content, the whole run; `cache_folder` is where they write, signed, in the
user's cache folder, and `facts_codec` turns the readings into JSON and back),
`launch` for the launch files it reads, `uninferable` judging EZ105 and EZ209 by what the
trees pass and the scenes hold, and `implementation_code` for the checks inside
implementation classes; `target` says which robot's Python the code is for; `progress`
draws the progress line; `lifetime` ends a pool worker with its run; `holdpoint` lets a
test stop a run at a named point; `stdin` is
``rewrite -`` and ``check -`` (one file in, one whole file out) and `fixes` is ``check
--fix`` and ``--diff`` (the command line prints what they return). May import `compound`,
`lint`, `codemod`, `verify`, `report` and `files`; never the command line.
"""
