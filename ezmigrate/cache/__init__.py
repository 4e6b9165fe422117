"""What one run of ``check`` keeps for the next, where nobody else can write it.

`cache_folder` is the user's cache folder (one folder per project, signed JSON entries,
pruned); `facts_codec` turns a file's readings into JSON and back (no pickle); `facts_cache`
keeps each file's and scene's readings by content, `load_cache` each ``--trace`` load by the
file and every file it opened, and `outcome_cache` a whole run by the bytes of everything
it read. May import `files`, `report`, `verify`, `lint` and `project`; never the command line.
"""
