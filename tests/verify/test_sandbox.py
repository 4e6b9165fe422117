"""A module loaded for verification is held (``verify/sandbox.py``): it sees no secret of
the environment, reaches no listener (not even one on the host's 127.0.0.1), cannot read
the cache's signing key, and nothing it starts outlives the run, ``setsid()`` included.
Every worker also ends when ``rewrite`` is killed.

The hostile module writes what it managed into marker files; the listener is the test's
own, on 127.0.0.1 only. Processes are held by construction: the grandchild that calls
``setsid()`` holds the write end of a FIFO the test reads, so its death is the FIFO's end
of file; the module that must be killed blocks on a FIFO nobody writes.
"""

from __future__ import annotations

import contextlib
import os
import signal
import socket
import subprocess
import sys
import threading
from collections.abc import Iterator
from pathlib import Path

import pytest
from process_tree import descendants, ends

from ezmigrate.verify.sandbox import refusal, worker_environment

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="Linux only")

DESCRIPTION = '''
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


class Fetch(SkillDescription):
    def createDescription(self):
        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)
'''


def _hostile(markers: Path, port: int, key: Path, fifo: Path) -> str:
    return f'''import os, socket, select
_M = {str(markers)!r}
def _note(name, text):
    with open(os.path.join(_M, name), "w") as handle:
        handle.write(text)
_note("token", os.environ.get("CI_SECRET_TOKEN", ""))
_note("home", os.environ.get("HOME", ""))
try:
    socket.create_connection(("127.0.0.1", {port}), timeout=10).close()
    _note("network", "connected")
except OSError as error:
    _note("network", "refused")
try:
    with open({str(key)!r}) as handle:
        _note("key", handle.read())
except OSError:
    _note("key", "unreadable")
_fd = os.open({str(fifo)!r}, os.O_WRONLY | os.O_NONBLOCK)
os.write(_fd, b"x")
if os.fork() == 0:
    os.setsid()
    if os.fork() == 0:
        select.select([], [], [])  # forever, holding the FIFO open
    os._exit(0)
os.close(_fd)
''' + DESCRIPTION


@contextlib.contextmanager
def _listener() -> Iterator[tuple[int, list[str]]]:
    """A listener on 127.0.0.1 that records every connection it accepts."""
    server = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    server.bind(("127.0.0.1", 0))
    server.listen()
    accepted: list[str] = []

    def serve() -> None:
        with contextlib.suppress(OSError):
            while True:
                connection, _ = server.accept()
                accepted.append("connection")
                connection.close()

    thread = threading.Thread(target=serve, daemon=True)
    thread.start()
    try:
        yield server.getsockname()[1], accepted
    finally:
        server.close()


def test_environment_keeps_only_what_loading_needs(tmp_path: Path) -> None:
    env = worker_environment({"PATH": "/usr/bin", "CI_SECRET_TOKEN": "s3cret",
                              "AWS_SECRET_ACCESS_KEY": "k", "SSH_AUTH_SOCK": "/tmp/a",
                              "LC_ALL": "C", "EZSKIROS_ONTOLOGY": "owl",
                              "HOME": "/root"}, str(tmp_path))
    assert env["HOME"] == str(tmp_path)
    assert {"PATH", "LC_ALL", "EZSKIROS_ONTOLOGY"} <= set(env)
    assert not {"CI_SECRET_TOKEN", "AWS_SECRET_ACCESS_KEY", "SSH_AUTH_SOCK"} & set(env)


@pytest.mark.skipif(refusal() is not None, reason="this system refuses namespaces")
def test_a_loaded_module_is_held(tmp_path: Path) -> None:
    markers, keys = tmp_path / "markers", tmp_path / "keys"
    markers.mkdir()
    keys.mkdir()
    (keys / "key").write_text("the signing key")
    fifo = tmp_path / "held"
    os.mkfifo(fifo)
    reader = os.open(fifo, os.O_RDONLY | os.O_NONBLOCK)
    repo = tmp_path / "repo"
    repo.mkdir()
    try:
        with _listener() as (port, accepted):
            (repo / "fetch.py").write_text(_hostile(markers, port, keys / "key", fifo))
            env = dict(os.environ, CI_SECRET_TOKEN="s3cret", EZMIGRATE_CACHE_DIR=str(keys))
            run = subprocess.run([sys.executable, "-m", "ezmigrate", "rewrite", "--dry-run",
                                  "."], cwd=repo, env=env, capture_output=True, text=True,
                                 timeout=300, check=False)
        assert run.returncode == 0, run.stderr
        assert "Fetch" in run.stdout  # migrated and verified: the module really ran
        assert (markers / "token").read_text() == ""
        assert (markers / "home").read_text() not in ("", str(Path.home()))
        assert (markers / "network").read_text() == "refused"
        assert accepted == []
        assert (markers / "key").read_text() == "unreadable"
        written = os.read(reader, 64)
        assert written.startswith(b"x")  # a grandchild held it open
        try:  # every writer gone (the setsid grandchildren among them): end of file
            assert os.read(reader, 64) == b""
        except BlockingIOError:
            pytest.fail("a process the module started with setsid() outlived the run")
    finally:
        os.close(reader)


@pytest.mark.skipif(not hasattr(os, "pidfd_open"), reason="needs pidfd_open")
def test_no_worker_outlives_a_killed_rewrite(tmp_path: Path) -> None:
    gate = tmp_path / "gate"
    os.mkfifo(gate)
    stuck = tmp_path / "stuck"
    os.mkfifo(stuck)
    repo = tmp_path / "repo"
    repo.mkdir()
    (repo / "fetch.py").write_text(
        f"import os\nos.close(os.open({str(gate)!r}, os.O_WRONLY))\n"
        f"os.read(os.open({str(stuck)!r}, os.O_RDONLY), 1)\n" + DESCRIPTION)
    process = subprocess.Popen([sys.executable, "-m", "ezmigrate", "rewrite", "--dry-run",
                                "--jobs", "2", "."], cwd=repo, stdout=subprocess.DEVNULL,
                               stderr=subprocess.DEVNULL)
    try:
        os.close(os.open(gate, os.O_RDONLY))  # returns once the module is being loaded
        family = descendants(process.pid)
        assert family, "the load runs in a worker of rewrite"
        process.send_signal(signal.SIGKILL)
        process.wait()
        alive = [pid for pid in family if not ends(pid, 30)]
        assert alive == [], f"left running after rewrite was killed: {alive}"
    finally:
        with contextlib.suppress(OSError):
            process.kill()
        # whatever still blocks on the FIFO is released
        with contextlib.suppress(OSError):
            os.close(os.open(stuck, os.O_WRONLY | os.O_NONBLOCK))
