"""How ``check``'s main process and its one reading worker share work without a broker.

``concurrent.futures.ProcessPoolExecutor`` feeds its workers from a thread of the main
process, which needs the interpreter lock to hand over each task. While the main process
reads files itself (it takes its share), that thread gets the lock only every few
milliseconds, so a worker given small tasks (a scene is about 3 ms) waited for most of
its time: 35 scenes handed over that way took a third of a second of the run's wall time
for a tenth of a second of parsing. Here nothing of the main process has to run for the
worker to go on:

- **Claims**: a task list's next task from the front (the worker) and from the back (the
  main process), counted in memory both processes share, under one lock: every task is
  taken once, by whichever gets to it first, and the two meet wherever the costs put them.
- **Batches** (main to worker): a task list the worker did not inherit (the files are known
  after it was forked) is written to a file both hold and announced on a pipe.
- **Records** (worker to main): each result is appended to a second file, and a byte on a
  status pipe says when the worker has no more of a list to take. The main process reads
  the records when it needs them; a worker that dies closes the pipe, and the main process
  does what it had taken.

Linux and macOS (``fork``); elsewhere the run reads alone.
"""

from __future__ import annotations

import mmap
import os
import pickle
import select
import struct
import tempfile
from collections.abc import Iterator
from typing import Any


def _unlinked_file() -> int:
    """A file only its holders' descriptors reach: gone with the last of them, however the
    processes end."""
    handle, path = tempfile.mkstemp(prefix="ezmigrate-reading-")
    os.unlink(path)
    return handle


_COUNTERS = struct.Struct("qq")  # a list's next task from the front, and its end
_HEADER = struct.Struct("qq")  # a batch's offset and length in the batches file
_LENGTH = struct.Struct("q")  # a record's length in the records file


class Claims:
    """The next task of each of ``lists`` task lists, taken from the front or the back."""

    def __init__(self, lists: int, lock: Any) -> None:
        self._memory = mmap.mmap(-1, _COUNTERS.size * lists)  # shared with forked children
        self._lock = lock

    def open(self, kind: int, count: int) -> None:
        """Make ``count`` tasks of list ``kind`` available (none are taken yet)."""
        with self._lock:
            _COUNTERS.pack_into(self._memory, _COUNTERS.size * kind, 0, count)

    def front(self, kind: int) -> int | None:
        """The first task of ``kind`` nobody took, now taken; None when all are."""
        return self._take(kind, from_front=True)

    def back(self, kind: int) -> int | None:
        """The last task of ``kind`` nobody took, now taken; None when all are."""
        return self._take(kind, from_front=False)

    def _take(self, kind: int, from_front: bool) -> int | None:
        with self._lock:
            first, end = _COUNTERS.unpack_from(self._memory, _COUNTERS.size * kind)
            if first >= end:
                return None
            if from_front:
                taken, first = first, first + 1
            else:
                taken = end = end - 1
            _COUNTERS.pack_into(self._memory, _COUNTERS.size * kind, first, end)
            return int(taken)


class Channel:
    """The files and pipes between the main process and its worker, made before the fork
    (each side then closes the ends it does not use: ``as_worker``, ``as_main``)."""

    def __init__(self) -> None:
        made: list[int] = []  # closed again when the next one cannot be made
        try:
            self._batches = _unlinked_file()
            made.append(self._batches)
            self._records = _unlinked_file()
            made.append(self._records)
            self._commands_r, self._commands_w = os.pipe()
            made += (self._commands_r, self._commands_w)
            self._status_r, self._status_w = os.pipe()
        except OSError:
            for handle in made:
                os.close(handle)
            raise
        self._batch_end = 0
        self._read_to = 0
        self._said: list[bytes] = []
        self.gone = False
        """The worker has ended (its end of the status pipe closed)."""

    def as_worker(self) -> None:
        os.close(self._commands_w)
        os.close(self._status_r)

    def as_main(self) -> None:
        os.close(self._commands_r)
        os.close(self._status_w)

    # the main process's side

    def send(self, batch: object) -> None:
        """Hand the worker a batch (it takes it between two tasks)."""
        data = pickle.dumps(batch, pickle.HIGHEST_PROTOCOL)
        os.pwrite(self._batches, data, self._batch_end)
        header = _HEADER.pack(self._batch_end, len(data))
        self._batch_end += len(data)
        try:
            os.write(self._commands_w, header)
        except OSError:  # BrokenPipeError: the worker has ended
            self.gone = True

    def wait(self, status: bytes) -> bool:
        """Wait until the worker says ``status`` (once more than it had been waited for),
        or has ended (False)."""
        while status not in self._said:
            if self.gone:
                return False
            said = os.read(self._status_r, 1)
            if not said:
                self.gone = True
                return False
            self._said.append(said)
        self._said.remove(status)
        return True

    def records(self) -> Iterator[Any]:
        """The records the worker wrote since the last call, in order."""
        handle = self._records
        while True:
            size = os.pread(handle, _LENGTH.size, self._read_to)
            if len(size) < _LENGTH.size:
                return
            (length,) = _LENGTH.unpack(size)
            data = os.pread(handle, length, self._read_to + _LENGTH.size)
            if len(data) < length:  # a record the worker was writing as it died
                return
            self._read_to += _LENGTH.size + length
            yield pickle.loads(data)

    def close(self) -> None:
        for handle in (self._commands_w, self._status_r, self._batches, self._records):
            try:
                os.close(handle)
            except OSError:  # closed already
                continue

    # the worker's side

    def say(self, status: bytes) -> None:
        os.write(self._status_w, status)

    def record(self, kind: int, batch: int, index: int, value: object) -> None:
        """Append the result ``value`` of task ``index`` of list ``kind`` (of batch
        ``batch``), whole, with one write at the file's end; None when it cannot be
        pickled (the main process then does the task itself)."""
        try:
            data = pickle.dumps((kind, batch, index, value), pickle.HIGHEST_PROTOCOL)
        except (pickle.PicklingError, TypeError, AttributeError, RecursionError):
            data = pickle.dumps((kind, batch, index, None), pickle.HIGHEST_PROTOCOL)
        handle = self._records
        os.pwrite(handle, _LENGTH.pack(len(data)) + data, os.fstat(handle).st_size)

    def next_batch(self, block: bool) -> Any | None:
        """The next batch the main process sent, when one came (``block``: waiting for it);
        None when none came, ``EOFError`` when the main process closed the channel."""
        if not block and not select.select([self._commands_r], [], [], 0)[0]:
            return None
        header = b""
        while len(header) < _HEADER.size:
            part = os.read(self._commands_r, _HEADER.size - len(header))
            if not part:
                raise EOFError
            header += part
        offset, length = _HEADER.unpack(header)
        return pickle.loads(os.pread(self._batches, length, offset))
