"""Compound skills (the behaviour trees built in ``expand``) in ``check`` and reports.

`static` reads a tree from the syntax when ``expand`` is literal, `analysis` traces what the
syntax cannot give (in the verification sandbox, by `tracing`, which starts as soon as the
files are read) and checks every tree against the skill index, `repository` scans the
repository around the run for the descriptions and trees a tree refers to, `markers` holds
what these look for in a file's bytes, and `diagram` draws a tree as Mermaid. May import
`lint`, `codemod`, `verify`, `report` and `files`, and the runtime.
"""
