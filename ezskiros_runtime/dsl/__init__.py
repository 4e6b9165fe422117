"""The EzSkiROS DSL: kind markers, symbolic parameters, condition expressions, tracing.

Import the public names from ``ezskiros_runtime``; this package stays empty so that importing
one piece (say, the markers) never chooses a backend. Where things live, in lowering order:

- ``markers``: ``INFERRED``/``OPTIONAL``/``REQUIRED``, ``Annotated``, ``ELEMENT``, ``KEY``,
  ``DESC``, the options;
- ``parameters``: the ``description`` signature as ``addParam`` specs (step 1);
- ``symbols``, ``conditions``, ``collectors``, ``tracing``: running the body on symbols and
  recording every ``+=`` with its file and line (step 2);
- ``backend``, ``lowering``, ``skill``: SkiROS2's or the legacy API, and the calls made to
  it (steps 3 and 4);
- ``vocabulary``, ``check_*``, ``checking``, ``policy``: the early checks and what they
  raise or warn (step 5).
"""
