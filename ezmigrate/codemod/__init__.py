"""The libcst transformation: ``migrate(source, settings) -> FileResult``, pure, no I/O.

`migrate` plans a module and rewrites its legacy descriptions; `core` is the machinery it
walks with (the IR, the reader, the emitter, imports, replay through the legacy backend,
the ``ast`` facts, the stand-ins for code it never reads, the line guard); `rules` holds
one module per legacy construct and the ordered rule table; `settings` is what a
migration is told, importable without libcst (a process that only hands files to the
workers never loads it). No user code runs and no file
is touched here, so a worker process can run it on any bytes. May import `report` (the
results it returns) and the runtime; never the rooms that run it.
"""
