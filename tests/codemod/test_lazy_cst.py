"""libcst is imported by the process that runs the codemod, and by no other
(``ezmigrate/codemod/core/lazy_cst.py``).

``check`` reads plain descriptions through the codemod's IR and rules, whose modules bind
``cst`` to a stand-in: a run whose files are all plain never pays libcst's import, and in
a run with a few declined files only the main process imports it (``reading_pool``). Each case
runs the real command in a fresh interpreter (this one has libcst imported already) and
asks, at its exit, which of its processes imported libcst.
"""

from __future__ import annotations

import subprocess
import sys
import textwrap
from pathlib import Path

from ezmigrate.checking.reading_pool import TAKES_ON
from ezmigrate.codemod.core.lazy_cst import cst

HEADER = """\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element
"""

PLAIN = HEADER + textwrap.dedent("""
    class Pick{n}(SkillDescription):
        def createDescription(self):
            self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)
            self.addParam("Speed", 0.5, ParamTypes.Optional, "m/s")  # a comment, migrated
    """)

DECLINED = HEADER + textwrap.dedent("""
    class Place{n}(SkillDescription):
        def createDescription(self):
            for key in ("A", "B"):
                self.addParam(key, Element("skiros:Product"), ParamTypes.Required)
    """)

PROBE = """\
import os, sys

def say(what):
    os.write(2, f"PROBE {what} {os.getpid()}\\n".encode())

class Watch:
    def find_spec(self, name, path=None, target=None):
        if name == "libcst":
            say("libcst")
        return None

say("main")
os.register_at_fork(after_in_child=lambda: say("child"))
sys.meta_path.insert(0, Watch())
sys.argv = ["ezmigrate", *sys.argv[1:]]
from ezmigrate.__main__ import main
main()
"""


def _imported(tmp_path: Path, files: dict[str, str], jobs: int) -> tuple[bool, list[bool]]:
    """Whether the main process imported libcst, and for each forked process whether it
    did, after ``check --no-cache --no-trace`` over ``files`` (a finder that every process
    inherits says which process asked for libcst)."""
    for name, text in files.items():
        (tmp_path / name).write_text(text)
    done = subprocess.run(
        [sys.executable, "-c", PROBE, "check", "--no-cache", "--exit-zero", "--no-trace",
         "--jobs", str(jobs), str(tmp_path)],
        capture_output=True, text=True, timeout=120, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    said = [line.split()[1:] for line in done.stderr.splitlines() if line.startswith("PROBE ")]
    [main] = [pid for what, pid in said if what == "main"]
    children = [pid for what, pid in said if what == "child"]
    imported = {pid for what, pid in said if what == "libcst"}
    return main in imported, [pid in imported for pid in children]


def test_plain_files_import_no_libcst(tmp_path: Path) -> None:
    files = {f"pick{n}.py": PLAIN.format(n=n) for n in range(40)}
    main, workers = _imported(tmp_path, files, jobs=2)
    assert workers  # the files were shared with a forked reader
    assert not main and not any(workers)


PYTHON_2 = HEADER + textwrap.dedent("""
    class Wait{n}(SkillDescription):
        def createDescription(self):
            self.addParam("Duration", 1.0, ParamTypes.Required)

    def call():
        try:
            pass
        except IOError, e:
            pass
    """)

NEWER_FSTRINGS = PLAIN + textwrap.dedent("""
    LABELS = {{"speed": "m/s"}}
    BANNER = f"speed in {{LABELS["speed"]}}"
    """)


def test_python_2_and_newer_f_strings_import_no_libcst(tmp_path: Path) -> None:
    """Python's error answers a Python 2 file (``python2_refusal``), and an f-string of
    Python 3.12 is respelt for this Python's ``ast`` (``newer_fstrings``)."""
    files = {f"pick{n}.py": PLAIN.format(n=n) for n in range(30)}
    files.update({f"wait{n}.py": PYTHON_2.format(n=n) for n in range(5)})
    files.update({f"newer{n}.py": NEWER_FSTRINGS.format(n=n) for n in range(5)})
    main, workers = _imported(tmp_path, files, jobs=2)
    assert workers
    assert not main and not any(workers)


def test_a_few_declined_files_import_it_in_the_main_process_alone(tmp_path: Path) -> None:
    files = {f"pick{n}.py": PLAIN.format(n=n) for n in range(40)}
    files.update({f"place{n}.py": DECLINED.format(n=n)
                  for n in range(0, 40, 40 // (TAKES_ON - 1))[:TAKES_ON - 1]})
    main, workers = _imported(tmp_path, files, jobs=2)
    assert workers
    assert main and not any(workers)


def test_many_declined_files_import_it_in_every_reader(tmp_path: Path) -> None:
    """A worker that meets ``TAKES_ON`` of them reads them itself: both cores on them."""
    files = {f"place{n:02}.py": DECLINED.format(n=n) for n in range(60)}
    main, workers = _imported(tmp_path, files, jobs=2)
    assert workers
    assert main and all(workers)


def test_the_stand_in_is_libcst() -> None:
    import libcst

    assert cst.Name is libcst.Name
    assert "Name" in vars(cst)  # kept: a second lookup skips the import machinery
