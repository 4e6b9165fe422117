"""Mutated legacy sources and the checks every run over them must pass (fuzz test and the
long run in ``bench/fuzz_long.py``).

A batch is a handful of files, each a ``fixtures/legacy`` source put through random
mutations: deletions, insertions of Python-ish tokens or raw bytes, truncation, byte
garbage, wrong encodings (re-encoded text, lying or unknown coding cookies, BOMs), line
ending changes and duplicated lines. One ``rewrite`` subprocess runs over the whole batch
(a process per file would spend the time budget on interpreter start-up).

What must hold for every batch: the exit code is 0, 1 or 2; no traceback on stdout or
stderr; every file written parses (with libcst; and with Python's own parser when its input
did); every file reported as not processed, or whose skills were all skipped or failed, or
that is not reported as changed, is byte-identical to before; no temporary file is left.
"""

from __future__ import annotations

import json
import subprocess
import sys
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

from hypothesis import strategies as st
from safety_support import LEGACY, assert_no_traceback, leftovers, libcst_parses, python_parses

SOURCES = sorted(LEGACY.glob("*.py"))
TOKENS = [b"(", b")", b"[", b"]", b":", b",", b"\n", b"\r\n", b"\r", b"\t", b"    ", b'"',
          b"'", b'"""', b"#", b"\\", b"\x00", b"\xff", b"\xe9", b"\xc3\xa9", b"\xe2\x82\xac",
          b"\xef\xbb\xbf", b"def ", b"class ", b"self.", b"addParam(", b"Element(",
          b"ParamTypes.Required", b"createDescription", b"SkillDescription", b"lambda: ",
          b"print ", b"except Exception, e:", b"f'{x!r:>{w}}'", b"async ", b"await ",
          b"import ", b"from . import x\n", b"pass\n", b"return\n", b"yield ", b"*", b"**",
          b"=", b"==", b":=", b"@", b"->", b"...", b"0x", b"1e-3", b"-", b"~", b"not ",
          b"global x\n", b"del self\n", b"if True:\n", b"else:\n"]
COOKIES = [b"# -*- coding: latin-1 -*-\n", b"# coding: utf-8\n", b"# coding: ascii\n",
           b"# -*- coding: cp1252 -*-\n", b"# coding: utf-16\n", b"# coding: klingon\n",
           b"# vim: set fileencoding=koi8-r :\n", b"\xef\xbb\xbf", b"#!/usr/bin/env python\n"]
ENCODINGS = ["latin-1", "cp1252", "utf-16", "utf-16-le", "utf-8-sig", "koi8-r", "ascii"]


@st.composite
def mutated_source(draw: st.DrawFn) -> bytes:
    data = bytearray(draw(st.sampled_from(SOURCES)).read_bytes())
    for _ in range(draw(st.integers(0, 6))):
        kind = draw(st.sampled_from(["delete", "insert", "truncate", "garbage", "encoding",
                                     "cookie", "endings", "duplicate"]))
        at = draw(st.integers(0, len(data)))
        if kind == "delete":
            del data[at:at + draw(st.integers(1, 200))]
        elif kind == "insert":
            piece = draw(st.one_of(st.sampled_from(TOKENS), st.binary(min_size=1, max_size=8),
                                   st.text(min_size=1, max_size=4).map(str.encode)))
            data[at:at] = piece
        elif kind == "truncate":
            del data[at:]
        elif kind == "garbage":
            data[at:at + draw(st.integers(1, 16))] = draw(st.binary(min_size=1, max_size=16))
        elif kind == "encoding":
            text = bytes(data).decode("utf-8", "replace")
            data = bytearray(text.encode(draw(st.sampled_from(ENCODINGS)), "replace"))
        elif kind == "cookie":
            data[0:0] = draw(st.sampled_from(COOKIES))
        elif kind == "endings":
            newline = draw(st.sampled_from([b"\r\n", b"\r", b"\n"]))
            data = bytearray(bytes(data).replace(b"\r\n", b"\n").replace(b"\n", newline))
        else:
            lines = bytes(data).splitlines(keepends=True)
            if lines:
                index = draw(st.integers(0, len(lines) - 1))
                lines.insert(index, lines[index])
            data = bytearray(b"".join(lines))
    return bytes(data)


def batches(min_files: int = 3, max_files: int = 8) -> st.SearchStrategy[list[bytes]]:
    return st.lists(mutated_source(), min_size=min_files, max_size=max_files)


@dataclass
class Tally:
    """What the runs did, for the long run's record."""

    runs: int = 0
    verified_runs: int = 0
    files: int = 0
    written: int = 0
    unchanged: int = 0
    file_errors: int = 0
    exit_codes: Counter[int] = field(default_factory=Counter)
    seconds: float = 0.0

    def line(self) -> str:
        codes = ", ".join(f"{code}: {n}" for code, n in sorted(self.exit_codes.items()))
        return (f"{self.runs} runs ({self.verified_runs} verifying), {self.files} mutated "
                f"files: {self.written} written, "
                f"{self.unchanged} left byte-identical ({self.file_errors} reported as not "
                f"processable); exit codes {{{codes}}}; {self.seconds:.0f} s")


def check_batch(folder: Path, sources: list[bytes], verify: bool = False,
                tally: Tally | None = None, timeout: float = 600) -> None:
    """Run ``rewrite`` over ``sources`` written into ``folder``; assert the guarantees."""
    import time

    folder.mkdir(parents=True, exist_ok=True)
    names = [f"mutant_{i}.py" for i in range(len(sources))]
    for name, data in zip(names, sources, strict=True):
        (folder / name).write_bytes(data)
    report = folder.parent / f"{folder.name}-report.json"
    args = [sys.executable, "-m", "ezmigrate", "rewrite", str(folder), "--report", str(report)]
    args += ["--timeout", "10"] if verify else ["--no-verify"]
    started = time.monotonic()
    run = subprocess.run(args, capture_output=True, text=True, timeout=timeout, check=False,
                         stdin=subprocess.DEVNULL)
    elapsed = time.monotonic() - started
    assert run.returncode in (0, 1, 2), run.stderr
    assert_no_traceback(run.stdout, run.stderr)
    assert leftovers(folder) == [], run.stderr
    assert report.exists(), run.stderr
    data = json.loads(report.read_text(encoding="utf-8"))
    files = {f["file"]: f for f in data["files"]}
    skills: dict[str, list[str]] = {}
    for skill in data["skills"]:
        skills.setdefault(skill["file"], []).append(skill["status"])
    written = 0
    for name, before in zip(names, sources, strict=True):
        after = (folder / name).read_bytes()
        entry = files.get(name, {})
        statuses = skills.get(name, [])
        must_be_identical = (not entry.get("changed") or entry.get("error") is not None
                             or (statuses and set(statuses) <= {"skipped", "failed"}))
        if must_be_identical:
            assert after == before, f"{name}: reported {entry} {statuses} but was changed " \
                f"({run.stderr[-2000:]})"
            continue
        written += 1
        assert after != before
        # whichever parser read the original reads the written file (``migrate``); a file
        # only Python reads (libcst refuses a coding line that is not UTF-8) stays so
        if libcst_parses(before):
            assert libcst_parses(after), f"{name}: the written file does not parse " \
                f"({run.stderr})"
        if python_parses(before):
            assert python_parses(after), f"{name}: parsed with Python before, not after"
        assert libcst_parses(after) or python_parses(after), f"{name}: nothing reads it"
    if tally is not None:
        tally.runs += 1
        tally.verified_runs += verify
        tally.files += len(sources)
        tally.written += written
        tally.unchanged += len(sources) - written
        tally.file_errors += sum(1 for f in files.values() if f.get("error"))
        tally.exit_codes[run.returncode] += 1
        tally.seconds += elapsed
