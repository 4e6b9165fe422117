"""A reusable verification worker: warm once, then fork one isolated child per file.

Started as ``python -m ezmigrate.verify.zygote``; it imports the runtime and loads the
ontology once, then reads load jobs as JSON lines on stdin and answers each with one JSON
line on stdout. Every job runs in a forked child (per-file isolation: the user's module
never touches the worker's state), killed when it exceeds the timeout. Forking a warm
process costs milliseconds where a fresh interpreter costs a third of a second.

Before it reports ready the worker also loads two small descriptions of its own (a legacy
one and its EzSkiROS form, both written here, never user code) the way a child loads a
file: every lazy import, compiled pattern and cache that a load touches is then filled once
in the worker and inherited by every child, instead of being filled again in each child
(about a third of a child's time). The loader leaves the interpreter as it found it, so
what is kept is exactly that: the warm caches. ``logging`` is imported too: nearly every
module imports it, and SkiROS2's own process always has it (rospy does).
Finally ``gc.freeze()`` moves the warm objects out of the collector's reach, so a child's
collections do not touch (and copy) the pages it shares with the worker.
"""

from __future__ import annotations

import argparse
import contextlib
import gc
import json
import os
import select
import signal
import sys
import tempfile
import time
from pathlib import Path

from .child import run_child
from .protocol import QUIT, LoadJob, LoadOutcome
from .sandbox import contain


class ParentGone(Exception):
    """The pool hung up our stdin (it stopped or died): end the job, serve no more."""


def _wait(pid: int, timeout: float, watch: int | None = None) -> bool:
    """Whether the child ended within ``timeout``. It is left unreaped (``WNOWAIT``), so its
    pid still names its process group when ``_end`` kills that group.

    ``watch`` is our end of the pool's pipe: when every writer has gone (the pool stopped,
    or ezmigrate was killed, even by SIGKILL) it hangs up and ``ParentGone`` is raised, so
    a child looping in user code is stopped at once, not when its timeout expires.
    """
    deadline = time.monotonic() + timeout
    pidfd = None
    if hasattr(os, "pidfd_open"):
        try:
            pidfd = os.pidfd_open(pid)
        except OSError:
            pidfd = None
    poller = select.poll()
    if pidfd is not None:
        poller.register(pidfd, select.POLLIN)
    if watch is not None:
        poller.register(watch, 0)  # data never wakes us; a hang-up always does
    try:
        while True:
            if os.waitid(os.P_PID, pid, os.WEXITED | os.WNOHANG | os.WNOWAIT) is not None:
                return True
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                return False
            step = remaining if pidfd is not None else min(remaining, 0.002)
            for fd, events in poller.poll(step * 1000):
                if fd == watch and events & (select.POLLHUP | select.POLLERR):
                    raise ParentGone
    finally:
        if pidfd is not None:
            os.close(pidfd)


def _own_group() -> None:
    """In a new child: lead a process group of its own, with the default signal handlers.

    Whatever the user's module forks joins that group, so killing the group (``_end``)
    leaves no orphan; the worker's handlers (``_stop``) must not run in user code.
    """
    with contextlib.suppress(OSError):
        os.setpgid(0, 0)
    for signum in (signal.SIGTERM, signal.SIGHUP):
        signal.signal(signum, signal.SIG_DFL)
    signal.signal(signal.SIGINT, signal.default_int_handler)


def _end(pid: int) -> int:
    """Kill the child and everything in its process group, then reap it: its wait status.

    The group is killed while the child is unreaped, so its id cannot have been reused.
    """
    with contextlib.suppress(OSError):
        os.killpg(pid, signal.SIGKILL)
    with contextlib.suppress(OSError):
        os.kill(pid, signal.SIGKILL)  # in case it could not get a group of its own
    return os.waitpid(pid, 0)[1]


def _stop(signum: int, _frame: object) -> None:
    """SIGTERM, SIGHUP or SIGINT in the worker: unwind, so ``run_job`` kills the child."""
    raise SystemExit(128 + signum)


def _scratch_base() -> str | None:
    """Where per-job scratch folders go: ``/dev/shm`` unless ``TMPDIR`` says otherwise.

    Each job makes a folder and three files and removes them again; on a journaling file
    system that costs milliseconds per job (up to ten under load), in memory microseconds.
    (A child's output is capped by ``child.OUTPUT_LIMIT``, so memory use stays bounded.)
    """
    shm = "/dev/shm"
    if "TMPDIR" not in os.environ and os.path.isdir(shm) and os.access(shm, os.W_OK | os.X_OK):
        return shm
    return None


_SCRATCH_BASE = _scratch_base()


def run_job(job: LoadJob, timeout: float, memory_bytes: int | None,
            watch: int | None = None, hidden: list[str] | None = None) -> LoadOutcome:
    """Fork a child for ``job``, wait for it, and read what it reported.

    The child and whatever it forked are killed when it times out, when it is done (a
    daemon its module started must not outlive the load), and when the worker stops (a
    signal, ``ParentGone`` from ``watch``), so nothing of a job ever outlives it: the child
    runs in namespaces of its own (``sandbox.contain``; ``hidden``: the folders it must not
    see), so a process it started with ``setsid()`` dies with it too.
    """
    with tempfile.TemporaryDirectory(prefix="ezmigrate-", dir=_SCRATCH_BASE) as scratch:
        result = os.path.join(scratch, "result.json")
        out = os.path.join(scratch, "stdout")
        err = os.path.join(scratch, "stderr")
        sys.stdout.flush()
        sys.stderr.flush()
        started = time.perf_counter()
        pid = os.fork()
        if pid == 0:  # the child never returns from here
            try:
                _own_group()
                contain(hidden or [])  # refused: the run said so when it began
            finally:
                run_child(job, result, out, err, memory_bytes)
        with contextlib.suppress(OSError):  # here too: killpg must find it from now on
            os.setpgid(pid, pid)
        ended = False
        try:
            ended = _wait(pid, timeout, watch)
        finally:
            status = _end(pid)
        if not ended:
            outcome = LoadOutcome("timeout", f"loading took longer than {timeout:g} s and "
                                  "was stopped")
        else:
            outcome = _read(result, status)
        outcome.stdout = _tail(out)
        outcome.stderr = _tail(err)
        outcome.seconds = time.perf_counter() - started
        return outcome


def _read(result: str, status: int) -> LoadOutcome:
    if os.path.exists(result):
        with open(result, encoding="utf-8") as handle:
            return LoadOutcome.from_json(json.load(handle))
    if os.WIFSIGNALED(status):
        signame = signal.Signals(os.WTERMSIG(status)).name
        return LoadOutcome("crashed", f"the loading process was killed by {signame}")
    code = os.WEXITSTATUS(status)
    return LoadOutcome("exit", f"the loading process exited with code {code} before "
                       "reporting (os._exit in the module?)")


def _tail(path: str, limit: int = 20_000) -> str:
    """Captured output, its end kept when long (the report shows it, it must stay small)."""
    try:
        data = Path(path).read_bytes()
    except OSError:
        return ""
    text = data.decode("utf-8", errors="replace")
    return text if len(text) <= limit else "...\n" + text[-limit:]


WARM_UP_LEGACY = b'''\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element
from skiros2_skill.core.skill import SerialStar, SkillBase
import rospy


class EzmigrateWarmUp(SkillDescription):
    def createDescription(self):
        self.addParam("Arm", Element("rparts:ArmDevice"), ParamTypes.Required)
        self.addParam("Object", Element("skiros:Product"), ParamTypes.Inferred)
        self.addParam("Speed", 0.5, ParamTypes.Optional)
        self.addPreCondition(self.getRelationCond("RobotHasAArm", "skiros:hasA", "Robot",
                                                  "Arm", True))
        self.addPostCondition(self.getPropCond("ObjectOpen", "skiros:StateProperty",
                                               "Object", "=", "Open", True))


class ezmigrate_warm_up_tree(SkillBase):
    def createDescription(self):
        self.setDescription(EzmigrateWarmUp(), self.__class__.__name__)

    def expand(self, skill):
        skill.setProcessor(SerialStar())
        for key in ("Arm", "Object"):
            skill(self.skill("Wait", "", remap={"Robot": key},
                             specify={"Duration": self.params["Speed"].value}))
'''
"""A legacy description and compound skill of ours that a warm-up load goes through and
traces (never user code)."""

WARM_UP_MIGRATED = b'''\
from ezskiros_runtime import SkillDescription, INFERRED, OPTIONAL
from ezskiros_runtime.ontology import rparts, skiros, sumo
import rospy


class EzmigrateWarmUp(SkillDescription):
    def description(self,
                    Arm: rparts.ArmDevice,
                    Object: INFERRED[skiros.Product],
                    *,
                    Speed: OPTIONAL[float] = 0.5,
                    Robot: INFERRED[sumo.Agent]):
        self.pre_conditions += Robot.hasA(Arm)
        self.post_conditions += (Object.StateProperty == "Open").named("ObjectOpen")
'''
"""``WARM_UP_LEGACY`` as ``rewrite`` writes it: the DSL side of a load."""


def warm_up() -> list[LoadOutcome]:
    """Load the two warm-up descriptions in this process; their outcomes (for tests)."""
    import logging  # noqa: F401  (see the module docstring)

    from ezskiros_runtime.legacy.stand_ins import library_roots

    from .child import load

    library_roots()
    outcomes = []
    with tempfile.TemporaryDirectory(prefix="ezmigrate-warm-") as scratch:
        for name, source in (("legacy", WARM_UP_LEGACY), ("migrated", WARM_UP_MIGRATED)):
            path = Path(scratch, name, "ezmigrate_warm_up.py")
            path.parent.mkdir()
            path.write_bytes(source)
            trace = ["ezmigrate_warm_up_tree"] if name == "legacy" else []
            outcomes.append(load(LoadJob(str(path), None, None, trace=trace)))
    return outcomes


def main(argv: list[str] | None = None) -> int:
    """Serve jobs until stdin closes."""
    parser = argparse.ArgumentParser(prog="ezmigrate.verify.zygote")
    parser.add_argument("--ontology", action="append", default=[])
    parser.add_argument("--timeout", type=float, default=20.0)
    parser.add_argument("--memory-mb", type=int, default=2048)
    parser.add_argument("--hide", action="append", default=[],
                        help="a folder the loaded modules must not see (repeatable)")
    args = parser.parse_args(argv)
    for signum in (signal.SIGTERM, signal.SIGHUP, signal.SIGINT):
        signal.signal(signum, _stop)
    os.environ["EZSKIROS_BACKEND"] = "legacy"
    # warm imports shared with every child; the runtime's public names are lazy, so the DSL
    # and its checks are named too, or every child that loads an EzSkiROS file imports (and
    # compiles) them again, ~70 ms per file
    import ezskiros_runtime.compound.trace
    import ezskiros_runtime.dsl.skill
    import ezskiros_runtime.legacy.loader
    import ezskiros_runtime.ontology.namespaces
    import ezskiros_runtime.ontology.suggest  # noqa: F401
    from ezskiros_runtime.ontology.active import use_ontology
    from ezskiros_runtime.ontology.load import load_index

    use_ontology(load_index(args.ontology or None))
    with contextlib.suppress(Exception):  # only a lost speed-up if it fails
        warm_up()
    gc.collect()
    gc.freeze()
    protocol_out = os.fdopen(os.dup(1), "w", encoding="utf-8")
    os.dup2(2, 1)  # stray prints of ours must never corrupt the protocol
    print(json.dumps({"ready": True}), file=protocol_out, flush=True)
    memory = args.memory_mb * 1024 * 1024 if args.memory_mb > 0 else None
    for line in sys.stdin:
        if not line.strip():
            continue
        if line.strip() == QUIT:
            return 0
        job = LoadJob.from_json(json.loads(line))
        try:
            outcome = run_job(job, args.timeout, memory, watch=sys.stdin.fileno(),
                              hidden=args.hide)
        except ParentGone:
            return 0
        print(json.dumps(outcome.to_json()), file=protocol_out, flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
