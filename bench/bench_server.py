"""``ezmigrate server`` driven over its stdio as an editor drives it (issue 44).

    python bench/bench_server.py WORKSPACE --repo LAB_CHECKOUT [--changes 10000]

- **Cold start**: the server is started on WORKSPACE (for the issue's figure, the folder of
  all the public checkouts), initialised, and one skill file opened: seconds from the
  spawn to its first ``publishDiagnostics``.
- **Keystroke**: in LAB_CHECKOUT (a real lab repository), the skill file with the longest
  git history is opened; each change replaces the buffer (with the file's own versions
  from its history, cycled, one character typed on each), unsaved. The server runs with
  ``EZMIGRATE_SERVER_DEBOUNCE=0``, so the figure is its check of the buffer, not the
  pause it waits for: time from the change to the file's ``publishDiagnostics``, median
  and 95th percentile.
- **Hover and completion** on ontology terms of that file: median and 95th percentile.
- **Memory**: ``--changes`` such changes replayed; the server's resident memory (VmRSS)
  after the first minute and at the end.

Every request is answered on the real protocol; nothing is timed inside the server.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path
from typing import Any


class Client:
    """A minimal LSP client over a child's pipes: enough to time requests."""

    def __init__(self, root: Path) -> None:
        self.started = time.perf_counter()
        self.proc = subprocess.Popen([sys.executable, "-m", "ezmigrate", "server"],
                                     stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                     stderr=subprocess.DEVNULL, cwd=root,
                                     env={**os.environ, "EZMIGRATE_SERVER_DEBOUNCE": "0"})
        self.next_id = 0

    def send(self, method: str, params: Any, request: bool = False) -> int | None:
        message: dict[str, Any] = {"jsonrpc": "2.0", "method": method, "params": params}
        if request:
            self.next_id += 1
            message["id"] = self.next_id
        body = json.dumps(message).encode()
        assert self.proc.stdin is not None
        self.proc.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
        self.proc.stdin.flush()
        return message.get("id")

    def receive(self) -> dict[str, Any]:
        assert self.proc.stdout is not None
        length = 0
        while True:
            line = self.proc.stdout.readline()
            if not line:
                raise EOFError("the server hung up")
            if line in (b"\r\n", b"\n"):
                break
            if line.lower().startswith(b"content-length:"):
                length = int(line.split(b":")[1])
        return json.loads(self.proc.stdout.read(length))

    def request(self, method: str, params: Any) -> Any:
        wanted = self.send(method, params, request=True)
        while True:
            message = self.receive()
            if message.get("id") == wanted and "method" not in message:
                return message.get("result")

    def diagnostics(self, uri: str, version: int | None = None) -> list[Any]:
        while True:
            message = self.receive()
            params = message.get("params") or {}
            if message.get("method") == "textDocument/publishDiagnostics" \
                    and params.get("uri") == uri \
                    and (version is None or params.get("version") == version):
                return params["diagnostics"]

    def rss_mb(self) -> float:
        for line in Path(f"/proc/{self.proc.pid}/status").read_text().splitlines():
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024
        return 0.0

    def close(self) -> None:
        try:
            self.request("shutdown", None)
            self.send("exit", None)
            self.proc.wait(timeout=30)
        finally:
            if self.proc.poll() is None:
                self.proc.kill()


def _open(root: Path) -> Client:
    client = Client(root)
    client.request("initialize", {"processId": os.getpid(), "rootUri": root.as_uri(),
                                  "capabilities": {}})
    client.send("initialized", {})
    return client


def _did_open(client: Client, path: Path, text: str) -> None:
    client.send("textDocument/didOpen", {"textDocument": {
        "uri": path.as_uri(), "languageId": "python", "version": 1, "text": text}})


def _history(repo: Path) -> tuple[Path, list[str]]:
    """The file of ``repo`` declaring parameters (``addParam``) with the most versions in
    git, and those versions."""
    best: tuple[int, Path] | None = None
    for path in repo.rglob("*.py"):
        if b"addParam" not in path.read_bytes():
            continue
        relative = path.relative_to(repo)
        count = len(subprocess.run(["git", "-C", str(repo), "log", "--format=%H", "--",
                                    str(relative)], capture_output=True, text=True
                                   ).stdout.split())
        if best is None or count > best[0]:
            best = (count, path)
    assert best is not None, f"{repo}: no skill file"
    path = best[1]
    commits = subprocess.run(["git", "-C", str(repo), "log", "--format=%H", "--",
                              str(path.relative_to(repo))], capture_output=True,
                             text=True).stdout.split()
    versions = []
    for commit in reversed(commits):
        shown = subprocess.run(["git", "-C", str(repo), "show",
                                f"{commit}:{path.relative_to(repo).as_posix()}"],
                               capture_output=True)
        if shown.returncode == 0:
            versions.append(shown.stdout.decode("utf-8", "replace"))
    return path, versions or [path.read_text()]


def _p95(values: list[float]) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(0.95 * len(ordered)))]


def _term_positions(text: str) -> list[tuple[int, int]]:
    """Positions inside ``"prefix:Term"`` strings of ``text`` (either quote)."""
    import re

    found = []
    for number, row in enumerate(text.splitlines()):
        for match in re.finditer(r"""(["'])[a-z]+:[A-Za-z]+\1""", row):
            found.append((number, match.start() + 3))
    return found


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("workspace", type=Path)
    parser.add_argument("--repo", type=Path, required=True)
    parser.add_argument("--changes", type=int, default=10000)
    args = parser.parse_args()

    path, versions = _history(args.repo.resolve())
    # cold start: the whole workspace
    cold = _open(args.workspace.resolve())
    _did_open(cold, path, path.read_text())
    cold.diagnostics(path.as_uri())
    cold_seconds = time.perf_counter() - cold.started
    cold.close()

    client = _open(args.repo.resolve())
    uri = path.as_uri()
    _did_open(client, path, path.read_text())
    client.diagnostics(uri)
    started = time.perf_counter()
    keystrokes: list[float] = []
    rss_minute: float | None = None
    for change in range(args.changes):
        text = versions[change % len(versions)] + "#" * (change % 7) + "\n"
        version = change + 2
        before = time.perf_counter()
        client.send("textDocument/didChange", {
            "textDocument": {"uri": uri, "version": version},
            "contentChanges": [{"text": text}]})
        client.diagnostics(uri, version)
        keystrokes.append(time.perf_counter() - before)
        if rss_minute is None and time.perf_counter() - started >= 60:
            rss_minute = client.rss_mb()
    rss_end = client.rss_mb()
    text = versions[-1]
    client.send("textDocument/didChange", {"textDocument": {"uri": uri, "version": 0},
                                            "contentChanges": [{"text": text}]})
    hovers, completions = [], []
    for line, character in _term_positions(text)[:200] * 3:
        before = time.perf_counter()
        client.request("textDocument/hover", {"textDocument": {"uri": uri},
                                              "position": {"line": line,
                                                           "character": character}})
        hovers.append(time.perf_counter() - before)
        before = time.perf_counter()
        client.request("textDocument/completion", {"textDocument": {"uri": uri},
                                                   "position": {"line": line,
                                                                "character": character}})
        completions.append(time.perf_counter() - before)
    client.close()
    print(f"file: {path.relative_to(args.repo.resolve())} ({len(versions)} versions)")
    print("| measure | median | p95 | goal |")
    print("|---|---:|---:|---|")
    print(f"| cold start to first diagnostics ({args.workspace.name}) | {cold_seconds:.2f} s "
          "| | <= 2 s |")
    print(f"| keystroke to diagnostics ({len(keystrokes)} changes) | "
          f"{statistics.median(keystrokes) * 1000:.0f} ms | {_p95(keystrokes) * 1000:.0f} ms "
          "| p95 <= 150 ms |")
    if hovers:
        print(f"| hover ({len(hovers)}) | {statistics.median(hovers) * 1000:.1f} ms | "
              f"{_p95(hovers) * 1000:.1f} ms | p95 <= 50 ms |")
        print(f"| completion ({len(completions)}) | "
              f"{statistics.median(completions) * 1000:.1f} ms | "
              f"{_p95(completions) * 1000:.1f} ms | p95 <= 50 ms |")
    print(f"| memory (VmRSS) after the first minute / at the end | {rss_minute or rss_end:.0f}"
          f" MB | {rss_end:.0f} MB | growth <= 10% |")


if __name__ == "__main__":
    main()
