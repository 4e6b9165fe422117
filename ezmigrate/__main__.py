"""The ``ezmigrate`` command and ``python -m ezmigrate``: a Python version gate, then the CLI.

The project installs under the robot's Python 3.8 (ROS Noetic) for ``ezskiros_runtime``, but
the command needs 3.10 (libcst, click and our own code are not installed or written for
less). Under an older Python this says so in one line and exits 2, never with a traceback;
so this module is written for every Python the project installs on and imports the CLI
only past the gate. A Ctrl-C while the CLI is still being imported (libcst takes a
noticeable part of a second) is one line and exit 130, as it is once the CLI runs. A
finished command ends without the interpreter's tear-down (``leave``).
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
    except SystemExit as done:  # the command's end: its exit code
        if isinstance(done.code, int) or done.code is None:
            leave(done.code or 0)
        raise


def leave(code: int) -> None:
    """End the process now, as the interpreter would, without tearing it down.

    A command's heap (a repository's readings, the ontology's index) takes the interpreter
    tens of milliseconds to free at exit (40 ms of a 0.75 s ``check`` of the 21 public
    repositories), and nobody needs it freed. So once the command is done: the exit hooks
    run (temporary folders, multiprocessing's), the standard streams are flushed, and the
    process ends with ``os._exit``. Only when this is the process's only thread (every
    pool was shut down by the command; another thread would be cut short) and the streams
    flush; else this returns and the interpreter exits as usual.
    """
    import atexit
    import os
    import threading

    if threading.active_count() != 1:
        return
    try:
        atexit._run_exitfuncs()
        sys.stdout.flush()
        sys.stderr.flush()
    except Exception:  # a closed pipe, say: the usual exit reports it as it always did
        return
    os._exit(code)


if __name__ == "__main__":
    main()
