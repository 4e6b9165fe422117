"""What holds the code a verification child runs: environment, network, files, processes.

``rewrite`` and ``verify`` must import the lab's modules (equivalence is proven by loading
both versions), and ``check --trace`` does when told to; everything else of ezmigrate runs
no repository code. A module imported here is a stranger's code, so its child gets:

- **a scrubbed environment** (``worker_environment``): only what loading needs, listed in
  ``PASSED``; ``HOME`` is a private empty folder, so no token, key or credential of the
  user's reaches it through a variable or ``~``;
- **no network** where Linux allows an unprivileged user, network and mount namespace
  (``contain``): the child's own loopback is down, so even a listener on the host's
  127.0.0.1 is out of reach; this user's ezmigrate and ezskiros cache folders are covered
  by an empty in-memory file system, so the cache's signing key cannot be read and no
  entry can be written;
- **nothing left running**: the child is the first process of a PID namespace of its own,
  and when it ends, or its parent dies, the kernel kills every process in it, including
  one that called ``setsid()`` or forked twice; without namespaces, its process group is
  killed (``zygote._end``), which a ``setsid()`` escapes, and the run says so once;
- **bounded time, memory and output** (``zygote``, ``child.isolate``), as before.

Where the system refuses a namespace (another kernel, a container that forbids them,
macOS) the load goes on without it and ``contain`` returns the reason, which the run
prints once. The module runs under the robot's Python too (``--python``): Python 3.8,
standard library only.
"""

from __future__ import annotations

import atexit
import contextlib
import ctypes
import ctypes.util
import os
import shutil
import signal
import site
import sys
import tempfile
from typing import Mapping

PASSED = ("PATH", "LANG", "LANGUAGE", "TZ", "TMPDIR", "PYTHONPATH", "PYTHONIOENCODING",
          "PYTHONUTF8", "VIRTUAL_ENV", "ROS_VERSION", "ROS_DISTRO", "ROS_PYTHON_VERSION",
          "SYSTEMROOT")
"""Variables a verification child keeps; also every ``LC_*`` and ``EZSKIROS_*`` one (the
locale, and the runtime's own switches: its ontology, backend and cache folder). The rest
(tokens, keys, ``SSH_AUTH_SOCK``, proxies, CI secrets) never reach the lab's code."""

_CLONE_NEWNS = 0x00020000
_CLONE_NEWUSER = 0x10000000
_CLONE_NEWPID = 0x20000000
_CLONE_NEWNET = 0x40000000
_MS_NOSUID, _MS_NODEV, _MS_REC, _MS_PRIVATE = 0x2, 0x4, 0x4000, 0x40000
_PR_SET_PDEATHSIG = 1


def worker_environment(base: Mapping[str, str], home: str) -> dict[str, str]:
    """The environment of a verification worker and its children: ``PASSED``, ``LC_*``
    and ``EZSKIROS_*`` from ``base``, ``HOME`` the private folder ``home``, and the
    ontology cache this process filled named outright (``EZSKIROS_CACHE_DIR``): under the
    private ``HOME`` the worker would look for it in an empty folder and parse the ontology
    again, with an rdflib a robot's Python (``--python``, ``python3.8``) may not have. The
    worker reads it when it starts, before any module of the repository runs; the loads'
    children cannot (``hidden_folders``)."""
    from ezskiros_runtime.ontology.cache import default_cache_dir

    kept = {name: value for name, value in base.items()
            if name in PASSED or name.startswith(("LC_", "EZSKIROS_"))}
    kept.setdefault("EZSKIROS_CACHE_DIR", str(default_cache_dir(base).resolve()))
    kept["HOME"] = home
    kept.setdefault("PATH", os.defpath)
    kept["PYTHONUSERBASE"] = base.get("PYTHONUSERBASE") or site.getuserbase()
    # (a ``pip install --user`` of ezmigrate lives under the real HOME)
    return kept


_HOME: list[str] = []


def private_home() -> str:
    """An empty folder for the workers' ``HOME``, one per run, removed when it ends."""
    if not _HOME:
        _HOME.append(tempfile.mkdtemp(prefix="ezmigrate-home-"))
        atexit.register(shutil.rmtree, _HOME[0], True)
    return _HOME[0]


_PROBED: list[str | None] = []
_SAID: list[bool] = []


def refusal() -> str | None:
    """Why this system does not hold a child (``contain``), asked once per run of a probe
    child; None when it does."""
    if not _PROBED:
        _PROBED.append(_probe() if sys.platform.startswith("linux") else "not Linux")
    return _PROBED[0]


def _probe() -> str | None:
    """``contain`` tried in a forked child, which reports and leaves."""
    _libc()  # loaded before the fork: the child of a threaded process must not dlopen
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:  # the probe: report, and leave without running anything of the parent's
        os.close(read)
        reason = contain([]) or ""
        os.write(write, reason.encode("utf-8", "replace")[:500] or b"-")
        os._exit(0)
    os.close(write)
    with os.fdopen(read, "rb") as stream:
        answer = stream.read().decode("utf-8", "replace")
    os.waitpid(pid, 0)
    return None if answer == "-" else answer or "the probe died"


def say_if_not_held() -> None:
    """Say once per run, on stderr, when loaded modules run without namespaces (and make
    the cache's key anew when the run ends: ``_spoil_keys``)."""
    if _SAID:
        return
    _SAID.append(True)
    reason = refusal()
    if reason is not None:
        atexit.register(_spoil_keys, hidden_folders(os.environ))
        sys.stderr.write(f"ezmigrate: loaded modules run without a network, file and process "
                         f"sandbox here ({reason}): they can reach the network, and a "
                         "process they start with setsid() may outlive the run\n")


def _spoil_keys(folders: list[str]) -> None:
    """Remove the cache's signing key (``cache/cache_folder``) from ``folders`` once the
    run is over: code loaded without the sandbox may have read it, and the next run makes
    a new one, so every entry signed with the old key is a miss."""
    for folder in folders:
        with contextlib.suppress(OSError):
            os.unlink(os.path.join(folder, "key"))


def die_with_parent(expected_parent: int | None = None) -> None:
    """Ask the kernel to kill this process when its parent ends (Linux; elsewhere the
    worker's hang-up detection, ``zygote._wait``, still ends its jobs). When the parent
    already died before the request, end now."""
    libc = _libc()
    if libc is None:
        return
    libc.prctl(_PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
    if expected_parent is not None and os.getppid() != expected_parent:
        os._exit(0)


def hidden_folders(environ: Mapping[str, str]) -> list[str]:
    """The folders a child must neither read nor write: this user's ezmigrate cache (the
    signing key and the kept runs) and the runtime's ontology cache, wherever configured."""
    home = environ.get("EZMIGRATE_REAL_HOME") or os.path.expanduser("~")
    cache = environ.get("XDG_CACHE_HOME") or os.path.join(home, ".cache")
    found = [os.path.join(cache, "ezmigrate"), os.path.join(cache, "ezskiros")]
    for name in ("EZMIGRATE_CACHE_DIR", "EZSKIROS_CACHE_DIR"):
        if environ.get(name):
            found.append(environ[name])
    return [os.path.realpath(path) for path in found]


def contain(hidden: list[str]) -> str | None:
    """Enter the namespaces that hold a child (module docstring); None when it is held,
    else why not. Call it in a freshly forked, single-threaded child, before the module
    runs. The caller returns in a new process two forks down, and the processes above it
    never return:

    - this one waits outside the namespaces and ends as the caller ends (its exit code,
      or the signal that killed it), so the worker sees what it always saw;
    - the first process of the new PID namespace (its init) waits for the caller and
      passes its status up; when it ends, the kernel kills everything left in the
      namespace. The caller is not that init: the kernel spares an init the signals it
      sends itself, and a module that kills itself must die as it would on the robot.
    """
    libc = _libc()
    if libc is None:
        return "no C library to ask for namespaces"
    parent = os.getppid()
    die_with_parent(parent)
    user = os.geteuid() != 0
    uid, gid = os.geteuid(), os.getegid()
    flags = _CLONE_NEWNET | _CLONE_NEWNS | _CLONE_NEWPID | (_CLONE_NEWUSER if user else 0)
    if libc.unshare(flags) != 0:
        return f"the system refused namespaces ({os.strerror(ctypes.get_errno())})"
    if user:
        _map_user(uid, gid)
    mounted = libc.mount(b"none", b"/", None, _MS_REC | _MS_PRIVATE, None) == 0
    for folder in hidden:
        if mounted and os.path.isdir(folder):
            libc.mount(b"tmpfs", folder.encode(), b"tmpfs", _MS_NOSUID | _MS_NODEV,
                       b"size=64k,mode=0700")
    read, write = os.pipe()
    sys.stdout.flush()
    sys.stderr.flush()
    if os.fork() != 0:  # outside: end as the load ended
        os.close(write)
        with os.fdopen(read, "rb") as stream:
            told = stream.read()
        _end_as(int(told) if told.strip().isdigit() else None)
    os.close(read)
    die_with_parent()
    pid = os.fork()
    if pid != 0:  # the namespace's init: report the load's status, then end the namespace
        _, status = os.waitpid(pid, 0)
        os.write(write, str(status).encode("ascii"))
        os._exit(0)
    os.close(write)
    die_with_parent()
    return None


def _end_as(status: int | None) -> None:
    """Leave with a wait ``status`` of another process: its exit code, or its signal."""
    if status is not None and os.WIFSIGNALED(status):
        signum = os.WTERMSIG(status)
        signal.signal(signum, signal.SIG_DFL)
        os.kill(os.getpid(), signum)
    os._exit(os.WEXITSTATUS(status) if status is not None and os.WIFEXITED(status) else 70)


def _map_user(uid: int, gid: int) -> None:
    """Map this user to itself inside the new user namespace (files keep their owner)."""
    for name, text in (("setgroups", "deny"), ("uid_map", f"{uid} {uid} 1"),
                       ("gid_map", f"{gid} {gid} 1")):
        try:
            with open(f"/proc/self/{name}", "w") as handle:
                handle.write(text)
        except OSError:
            pass


_LIBC: list[ctypes.CDLL | None] = []


def _libc() -> ctypes.CDLL | None:
    if not _LIBC:
        found = None
        if sys.platform.startswith("linux"):
            try:
                found = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6",
                                    use_errno=True)
            except OSError:
                found = None
        _LIBC.append(found)
    return _LIBC[0]


__all__ = ["PASSED", "contain", "die_with_parent", "hidden_folders", "private_home",
           "refusal", "say_if_not_held", "worker_environment"]
