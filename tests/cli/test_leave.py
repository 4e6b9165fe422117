"""``ezmigrate.__main__.leave``: a finished command ends without the interpreter's
tear-down, yet as the interpreter would end it: its exit code, its whole output through a
pipe, the exit hooks run. With another thread still running it exits as usual.

Each case runs the real command in a fresh interpreter and watches two markers: one an
``atexit`` hook writes (it must always be written) and one a module-level object's
``__del__`` writes when the interpreter tears its modules down (written only by the usual
exit).
"""

from __future__ import annotations

import json
import subprocess
import sys
import textwrap
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]

RUN = textwrap.dedent("""
    import atexit, sys, threading
    hooked, torn, extra = sys.argv[1:4]
    atexit.register(lambda: open(hooked, "w").write("ran"))

    class TornDown:  # what it needs is bound now: the tear-down clears the modules first
        def __init__(self, path, write=open):
            self.path, self.write = path, write

        def __del__(self):
            with self.write(self.path, "w") as out:
                out.write("ran")

    keep = TornDown(torn)
    if extra == "thread":  # a thread still running when the command ends
        release = threading.Event()
        threading.Thread(target=release.wait, args=(30,), daemon=True).start()
    sys.argv = ["ezmigrate", *sys.argv[4:]]
    from ezmigrate.__main__ import main
    main()
""")


def _run(tmp_path: Path, extra: str, *args: str) -> tuple[subprocess.CompletedProcess[str],
                                                            bool, bool]:
    hooked, torn = tmp_path / "hooked", tmp_path / "torn"
    done = subprocess.run([sys.executable, "-c", RUN, str(hooked), str(torn), extra, *args],
                          capture_output=True, text=True, timeout=300, cwd=REPO, check=False)
    return done, hooked.exists(), torn.exists()


def test_a_finished_command_leaves_without_the_tear_down(tmp_path: Path) -> None:
    done, hooked, torn = _run(tmp_path, "", "check", "--output-format", "json",
                              "--no-cache", "fixtures/legacy")
    assert done.returncode == 1  # the fixtures hold errors: the code is the command's
    assert len(json.loads(done.stdout)) > 10  # the whole output came through the pipe
    assert "files checked" in done.stderr
    assert hooked and not torn


def test_another_thread_means_the_usual_exit(tmp_path: Path) -> None:
    done, hooked, torn = _run(tmp_path, "thread", "check", "--output-format", "json",
                              "--no-cache", "fixtures/legacy")
    assert done.returncode == 1
    assert len(json.loads(done.stdout)) > 10
    assert hooked and torn


def test_usage_errors_keep_their_code(tmp_path: Path) -> None:
    done, hooked, torn = _run(tmp_path, "", "check", "--output-format", "xml", ".")
    assert done.returncode == 2 and "xml" in done.stderr
    assert hooked and not torn
