"""The ``ezmigrate`` command and ``python -m ezmigrate``: a Python version gate, then the CLI.

The project installs under the robot's Python 3.8 (ROS Noetic) for ``ezskiros_runtime``, but
the command needs 3.10 (libcst, click and our own code are not installed or written for
less). Under an older Python this says so in one line and exits 2, never with a traceback;
so this module is written for every Python the project installs on and imports the CLI
only past the gate. A Ctrl-C while the CLI is still being imported (libcst takes a
noticeable part of a second) is one line and exit 130, as it is once the CLI runs.
"""

import sys

COMMAND_PYTHON = (3, 10)


def main() -> None:
    """Run the CLI, or explain in one line why it cannot run under this Python."""
    if sys.version_info < COMMAND_PYTHON:
        found = ".".join(str(part) for part in sys.version_info[:3])
        needed = ".".join(str(part) for part in COMMAND_PYTHON)
        sys.stderr.write(f"ezmigrate: the command needs Python {needed} or newer, this is "
                         f"Python {found} ({sys.executable}); ezskiros_runtime, which "
                         "migrated skills import, does run here\n")
        raise SystemExit(2)
    try:
        from .cli.commands import main as cli

        cli()
    except KeyboardInterrupt:  # Ctrl-C before the CLI's own handlers are installed
        sys.stderr.write("ezmigrate: interrupted by SIGINT before any file was written: "
                         "every file is as it was\n")
        raise SystemExit(130) from None


if __name__ == "__main__":
    main()
