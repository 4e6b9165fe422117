"""``ezmigrate server``: EzSkiROS in the editor, over the Language Server Protocol.

`protocol` wires pygls to the features; `workspace` checks one buffer through ``check``'s
own pipeline (its text standing for the file's bytes, nothing written, no code run);
`terms` reads the ontology's knowledge at a cursor (hover, completion, definition), and
`skills` the child skills of a tree from ``check``'s skill index; `migration` is the
"Migrate this skill" code action, the codemod's rewrite of one class. May import
`checking`, `cache`, `project`, `compound`, `lint`, `codemod`, `verify`, `report` and
`files`; never the command line.
"""
