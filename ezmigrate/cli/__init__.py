"""The command line: the click commands and what they print.

`commands` holds the ``ezmigrate`` group (``rewrite``, ``verify``, ``check``, ``scene``):
each turns its options into settings, calls the project and prints what comes back, so no
decision is taken here. `arguments` holds each command's options as one object, built in
one place from what click parsed; `options` and `config` resolve the settings a command
runs with (the command line over ``[tool.ezmigrate]``), and `shared_options` defines once
the options several commands take; `rewrite_output` prints and writes what ``rewrite`` and
``verify`` report (apart, so that ``check`` never imports it); `output_formats` renders
``check``'s findings for machines (JSON, SARIF, GitHub, JUnit); `terminal` decides
colour (a terminal, ``NO_COLOR``, ``--color``) and colours diffs and findings; `rules_doc` with
`rules_precision` writes docs/rules.md from the catalogue. May import `server`,
`checking`, `cache`, `project`, `compound`, `lint`, `codemod`, `verify`, `report` and
`files`; only ``ezmigrate.__main__`` imports this room.
"""
