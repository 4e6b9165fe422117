"""No pool worker outlives a run killed with SIGKILL (issue 41: two reading workers stayed
asleep forever after a SIGKILL of ``rewrite`` in its first seconds).

The run is held by construction where its workers are busy (``holdpoint``: ``migrating``
in ``rewrite``, ``checking`` in ``check``), its descendants are listed from ``/proc``,
then it is killed; every descendant must end (``lifetime.exit_with_parent``). The wait on
each is bounded only to fail, never to pass."""

from __future__ import annotations

import contextlib
import os
import select
import shutil
import signal
import subprocess
import sys
from pathlib import Path

import pytest
from process_tree import descendants, ends

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures"

pytestmark = pytest.mark.skipif(not hasattr(os, "pidfd_open") or not Path("/proc").is_dir(),
                                reason="needs Linux's /proc and pidfd_open")


def _held(args: list[str], point: str, repo: Path, hold: Path) -> subprocess.Popen[bytes]:
    env = dict(os.environ, EZMIGRATE_HOLD_DIR=str(hold), EZMIGRATE_HOLD_AT=point)
    process = subprocess.Popen([sys.executable, "-m", "ezmigrate", *args], cwd=repo, env=env,
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    reached = hold / f"{point}.reached"
    handle = os.pidfd_open(process.pid)
    try:  # the run reaches the point, or ends: whichever comes first
        while not reached.exists():
            if select.select([handle], [], [], 0.05)[0]:
                pytest.fail(f"the run ended before reaching {point}")
    finally:
        os.close(handle)
    return process


@pytest.mark.parametrize(("args", "point"), [
    (["rewrite", "--dry-run", "--no-verify", "--jobs", "2", "."], "migrating"),
    (["check", "--no-cache", "--exit-zero", "--jobs", "2", "."], "checking"),
])
def test_no_worker_outlives_a_killed_run(tmp_path: Path, args: list[str], point: str) -> None:
    repo = tmp_path / "repo"
    for copy in range(4):  # enough distinct files for the pool's workers to be forked
        shutil.copytree(FIXTURES / "legacy", repo / f"pkg{copy}")
        for path in (repo / f"pkg{copy}").glob("*.py"):
            path.write_bytes(path.read_bytes() + f"# copy {copy}\n".encode())
    hold = tmp_path / "hold"
    hold.mkdir()
    process = _held(args, point, repo, hold)
    try:
        family = descendants(process.pid)
        assert family, "the run has workers at this point"
        process.send_signal(signal.SIGKILL)
        process.wait()
        assert [pid for pid in family if not ends(pid)] == []
    finally:
        with contextlib.suppress(OSError):
            process.kill()
        (hold / f"{point}.go").touch()
