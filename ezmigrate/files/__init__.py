"""The files of a repository, and nothing of what they say about skills.

`discover` decides which files a run looks at (exclusions, ``.gitignore``, vendored
copies of SkiROS2, the repository around a named file; `git_ignored` asks git),
`prefilter` which of them may hold a description at all, `paths` how a path is printed,
`package_xml` what a ROS package's manifest declares (its name, ROS 1 or 2, the runtime
dependency), and `writing` how a file is replaced so that it is always wholly old or
wholly new. Every room that reads or writes files uses these. May import only the
runtime (its ontology discovery helpers): nothing here knows what a skill is.
"""
