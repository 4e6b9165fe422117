"""The exit codes every command ends with, as black's and ruff's: defined once, for the
command line to exit with and for the flows that decide them (``session.exit_code`` for
``rewrite``, ``checking/command`` for ``check``)."""

EXIT_OK, EXIT_ATTENTION, EXIT_ERROR = 0, 1, 2
"""Nothing to do; findings or changes that need attention; a usage or internal error."""
