"""A recording stand-in for SkiROS2's ``skiros2_common`` package (tests only).

Put ``tests/runtime/dsl/recording_skiros2`` on ``sys.path`` (in a subprocess) and the runtime picks
this package as the *real* SkiROS2 backend. Its ``SkillDescription`` records every public
call, so a test can assert that an EzSkiROS description makes exactly the calls a legacy one
makes. It imports no ROS, like the real package's top level.
"""
