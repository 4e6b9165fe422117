"""``ezmigrate server``: EzSkiROS in the editor, over the Language Server Protocol.

`protocol` wires pygls to the features; `workspace` checks one buffer through ``check``'s
own pipeline (its text standing for the file's bytes, nothing written, no code run);
`terms` reads the ontology's knowledge at a cursor (hover, completion, definition). May
import `checking`, `cache`, `project`, `compound`, `lint`, `codemod`, `verify`, `report`
and `files`; never the command line.
"""
