"""What a run found, as picklable data and as documents a reviewer reads.

`results` holds the types workers return (a file changed, unchanged or failed; each skill
converted, skipped, failed or unchanged) and `static_facts` what a legacy description
declares; `findings` the notes migration keeps for the reviewer; `diffs` the unified
diffs; `written_lines` the line numbers as the written file has them; `reports` the
one-line summary and the JSON and Markdown reports (`wording`: how a count reads in
it); `once` keeps the findings of one cause once, with their count. Every other room
builds on these types. May import only the runtime: the results must unpickle in any
process, whatever it imported.
"""
