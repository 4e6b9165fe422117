"""Another Python for files this one cannot import (``--python``, or the newest on PATH).

About 1% of real skill classes live in files with syntax newer than the Python running
ezmigrate (3.12 f-strings such as ``f"{d["key"]}"``). libcst migrates them, but verifying
needs an interpreter that can import them. ``--python PATH`` (or ``[tool.ezmigrate]
python``) names one; otherwise, for the files that need it, the oldest ``python3.X`` newer
than this one that compiles them is chosen (on ``PATH``, else in pyenv's versions folder),
and the summary and the report give its absolute path.

Every interpreter is resolved to an absolute path before it runs, and the search never
looks where the repository under check could have put one: a relative ``PATH`` entry (an
empty one, ``.``, any other that is not absolute) names a folder of the working directory,
which is usually the repository, and ``never_search`` keeps the paths the command was given,
and their git top levels, out of the search too. A repository's own ``./python3.8`` is
repository code, which ``rewrite --dry-run`` and ``check`` promise not to run.

The other interpreter runs the verification worker from our own source folders (linked
into a private folder put on its ``PYTHONPATH``), with ``-B`` so that it writes no bytecode
beside them. It needs no third-party package: the ontology index comes from the cache the
parent filled (JSON, read by our own code), and libcst is only asked for a second opinion
on syntax errors, which the worker skips when libcst is missing.
"""

from __future__ import annotations

import atexit
import functools
import os
import shutil
import subprocess
import sys
import tempfile
from collections.abc import Iterable, Sequence
from pathlib import Path

from ezskiros_runtime.ontology.vendored import git_top

PACKAGES = ("ezskiros_runtime", "ezmigrate")
_COMPILES = ("import sys\n"
             "for path in sys.argv[1:]:\n"
             "    compile(open(path, 'rb').read(), path, 'exec', dont_inherit=True)\n")


_UNSEARCHED: set[str] = set()
"""The real paths of the folders no interpreter search of this process looks in
(``never_search``)."""


def never_search(paths: Iterable[Path]) -> None:
    """Keep the repository the command works on out of every later interpreter search:
    each of ``paths`` (a file's folder, for a file) and its git top level. Its own
    ``bin/python3.8`` is its code, and a run must not start it to find out its version."""
    for path in paths:
        if str(path) == "-":  # stdin: the file it stands for is given as another path
            continue
        real = Path(os.path.realpath(path))
        folder = real if real.is_dir() else real.parent
        _UNSEARCHED.add(str(folder))
        top = git_top(folder)
        if top is not None:
            _UNSEARCHED.add(os.path.realpath(top))


def _searchable(folder: str) -> bool:
    """Whether an interpreter may be looked for in ``folder``: an absolute path (a relative
    one is read from the working directory, usually the repository) outside the folders
    ``never_search`` was given."""
    if not os.path.isabs(folder):
        return False
    real = os.path.realpath(folder)
    return not any(real == root or real.startswith(root.rstrip(os.sep) + os.sep)
                   for root in _UNSEARCHED)


def on_path(name: str) -> str | None:
    """The absolute path of the executable ``name`` in the first searchable ``PATH`` entry
    that holds one (``_searchable``), or None."""
    entries = [entry for entry in os.environ.get("PATH", "").split(os.pathsep)
               if _searchable(entry)]
    if not entries:
        return None
    return shutil.which(name, path=os.pathsep.join(entries))


def resolve(python: str) -> str | None:
    """``python`` (``--python``, ``[tool.ezmigrate] python``) as an absolute path to run:
    a path (holding ``/``) made absolute, a bare name looked up by ``on_path``; None when
    it names no executable file."""
    if os.sep not in python and (os.altsep is None or os.altsep not in python):
        return on_path(python)
    path = os.path.abspath(python)
    return path if os.path.isfile(path) and os.access(path, os.X_OK) else None


def is_foreign(python: str | None) -> bool:
    """Whether ``python`` is another interpreter than the one running us."""
    if not python:
        return False
    found = resolve(python) or python
    return os.path.realpath(found) != os.path.realpath(sys.executable)


@functools.lru_cache(maxsize=1)
def package_links() -> str:
    """A folder holding links to our packages: the other interpreter's ``PYTHONPATH``."""
    folder = Path(tempfile.mkdtemp(prefix="ezmigrate-python-"))
    atexit.register(shutil.rmtree, folder, True)
    here = Path(__file__).resolve().parents[2]
    for name in PACKAGES:
        (folder / name).symlink_to(here / name, target_is_directory=True)
    return str(folder)


def worker_command(python: str, module: str) -> tuple[list[str], dict[str, str]]:
    """The command line and environment that start ``module`` under ``python``."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [package_links(),
                                                       env.get("PYTHONPATH", "")]))
    return [python, "-B", "-m", module], env


def find_python(version: str) -> str | None:
    """The absolute path of ``python3.X`` for ``version`` ("3.8"): on PATH first (its
    absolute entries outside the checked repository, ``on_path``), else in pyenv's versions
    folder (``$PYENV_ROOT``, default ``~/.pyenv``), newest patch release first; None when
    neither has it. pyenv's shims are not used: they run whatever version the folder
    selects."""
    name = f"python{version}"
    found = on_path(name)
    if found is not None and "shims" not in Path(found).parts:
        return found
    candidates = sorted(_pyenv_root().glob(f"versions/{version}.*/bin/{name}"),
                        key=lambda path: _patch(path.parts[-3]), reverse=True)
    return next((str(path) for path in candidates
                 if _searchable(str(path.parent)) and os.access(path, os.X_OK)), None)


def _pyenv_root() -> Path:
    return Path(os.environ.get("PYENV_ROOT") or Path.home() / ".pyenv")


def _patch(release: str) -> int:
    """18 for ``3.8.18``; -1 for a name that is no plain release (``3.8-dev``)."""
    last = release.rsplit(".", 1)[-1]
    return int(last) if last.isdigit() else -1


def version_of(python: str | None) -> str:
    """``3.8.18``: the version of ``python`` (None: this one), asked of the interpreter."""
    if not is_foreign(python):
        return ".".join(str(part) for part in sys.version_info[:3])
    assert python is not None
    run = subprocess.run([python, "-c", "import sys; print('%d.%d.%d' % sys.version_info[:3])"],
                         capture_output=True, text=True, timeout=60, check=False)
    return run.stdout.strip() or "unknown"


def rdflib_version() -> str:
    """The rdflib that read the ontology (in this process: workers get the parsed index)."""
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("rdflib")
    except PackageNotFoundError:  # pragma: no cover - rdflib is a dependency
        return "unknown"


def describe(python: str) -> str:
    """``/usr/bin/python3.13``, for the summary and the report: the absolute path of the
    interpreter that ran, which a bare name (``python3.13``) would leave to guess."""
    return os.path.abspath(python)


def compiles(python: str, sources: Sequence[bytes]) -> bool:
    """Whether ``python`` compiles every source (each written to a private file)."""
    with tempfile.TemporaryDirectory(prefix="ezmigrate-compile-") as folder:
        paths = []
        for number, data in enumerate(sources):
            path = Path(folder, f"source_{number}.py")
            path.write_bytes(data)
            paths.append(str(path))
        try:
            run = subprocess.run([python, "-B", "-c", _COMPILES, *paths],
                                 stdin=subprocess.DEVNULL, capture_output=True, timeout=120,
                                 check=False)
        except (OSError, subprocess.TimeoutExpired):
            return False
        return run.returncode == 0


def oldest_that_compiles(sources: Sequence[bytes], above: str | None = None) -> str | None:
    """The oldest ``python3.X`` (on PATH, else in pyenv's versions folder) newer than
    ``above`` (an interpreter; None: this one) that compiles every source, or None.

    The oldest, not the newest: a ROS 2 package whose files need 3.12 runs on Jazzy (3.12),
    not on whatever newest Python the developer has, and verifying is worth most under the
    Python closest to the robot's."""
    minor = int(version_of(above).split(".")[1]) if is_foreign(above) else \
        sys.version_info.minor
    newer = (find_python(f"3.{m}") for m in range(minor + 1, minor + 21))
    return next((p for p in newer if p is not None and compiles(p, sources)), None)


NO_NEWER_PYTHON = ("no newer Python on PATH or in pyenv's versions folder reads it: verify "
                   "with --python naming one that does")
