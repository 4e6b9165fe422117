"""Running a migration over a repository: what ``rewrite`` does between its settings and
its output.

`settle` owns a migration (migrate every file, derive what crosses files, verify, hold
back, repeat); `runner` reads the files and runs the codemod in parallel workers, with
`import_scan` and `cross_file` for what links files; `holding` and `static_refusal` hold
back the skills that will not be written (`refusals` works out what the runtime's
early checks refuse); `session` is ``rewrite`` (it writes what settled,
under `interrupt`'s deferral) and `earlier` adds what an earlier run migrated to its report;
`frozen_heap` keeps the heap a run starts with out of the collector's reach; `target` says
which robot's Python the code is for; `progress` draws the progress line; `lifetime` ends a
pool worker with its run; `holdpoint` lets a test stop a run at a named point; `stdin` is
``rewrite -`` and ``check -`` (one file in, one whole file out); `exit_codes` are the
commands' exit codes. May import `compound`,
`lint`, `codemod`, `verify`, `report` and `files`; never the command line.
"""
