"""Encodings and layout survive a rewrite byte for byte: PEP 263 cookies, a UTF-8 BOM, CRLF
and mixed line endings, tabs, a last line without newline. A file that is not valid in its
declared encoding is reported (name, line, column) and left alone.

One ``rewrite --no-verify`` run over a folder holding every case (module fixture); each
test then looks at the bytes of its own file.
"""

from __future__ import annotations

import json

import pytest
from safety_support import (
    BROKEN,
    LEGACY,
    assert_no_traceback,
    cli,
    expected_migration,
    leftovers,
    libcst_parses,
    python_parses,
)

BOM = b"\xef\xbb\xbf"


def _lines(data: bytes) -> list[bytes]:
    """Lines with their own endings (``\\r\\n``, ``\\n`` or a lone ``\\r``)."""
    return data.splitlines(keepends=True)


def _mixed(data: bytes) -> bytes:
    """``data`` with LF on even lines and CRLF on odd ones (the first line keeps LF)."""
    lines = data.split(b"\n")
    body = b"".join(line + (b"\r\n" if i % 2 else b"\n") for i, line in enumerate(lines[:-1]))
    return body + lines[-1]


def _cases() -> dict[str, bytes]:
    descriptions = (LEGACY / "descriptions.py").read_bytes()
    return {
        "latin1_cookie.py": (LEGACY / "latin1_cookie.py").read_bytes(),
        "crlf_skill.py": (LEGACY / "crlf_skill.py").read_bytes(),
        "tab_indented.py": (LEGACY / "tab_indented.py").read_bytes(),
        "no_final_newline.py": (LEGACY / "no_final_newline.py").read_bytes(),
        "bom.py": BOM + descriptions,
        "bom_crlf.py": BOM + descriptions.replace(b"\n", b"\r\n"),
        "mixed_endings.py": _mixed(descriptions),
        # not valid in their declared (or default) encoding: reported, left alone
        "invalid_utf8_no_cookie.py": (BROKEN / "invalid_utf8_no_cookie.py").read_bytes(),
        "ascii_cookie_with_latin1.py": b"# -*- coding: ascii -*-\n"
        + descriptions.replace(b"TurtleBot", b"Turtleb\xf6t", 1),
        "cp1252_undefined_byte.py": b"#!/usr/bin/env python\n# coding: cp1252\n"
        + descriptions.replace(b"navigation", b"navigation \x81", 1),
        "utf8_cookie_bad_bytes.py": b"# vim: set fileencoding=utf-8 :\n"
        + descriptions.replace(b"stack", b"stack \xff\xfe", 1),
        "unknown_encoding.py": b"# -*- coding: klingon -*-\n" + descriptions,
        "bom_with_latin1_cookie.py": BOM + b"# -*- coding: latin-1 -*-\n" + descriptions,
        # Python finds the cookie behind a byte that is no UTF-8; libcst refuses the file
        "cookie_line_not_utf8.py": b"#\x80-*- coding: latin-1 -*-\n"
        + (LEGACY / "latin1_cookie.py").read_bytes().split(b"\n", 1)[1],
    }


BAD_BYTES = {  # file -> (first byte invalid in its declared encoding, that encoding)
    "invalid_utf8_no_cookie.py": (0xB0, "utf-8"),
    "ascii_cookie_with_latin1.py": (0xF6, "ascii"),
    "cp1252_undefined_byte.py": (0x81, "cp1252"),
    "utf8_cookie_bad_bytes.py": (0xFF, "utf-8"),
}
INVALID = {
    **{name: "" for name in BAD_BYTES},
    "unknown_encoding.py": "unknown encoding: klingon (line 1)",
    "bom_with_latin1_cookie.py": "encoding problem",
}


def _where(data: bytes, byte: int) -> str:
    """``line L, column C`` (1-based) of the first ``byte`` in ``data``."""
    at = data.index(bytes([byte]))
    line = data.count(b"\n", 0, at) + 1
    column = at - (data.rfind(b"\n", 0, at) + 1) + 1
    return f"line {line}, column {column}"


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    folder = tmp_path_factory.mktemp("encodings")
    originals = _cases()
    for name, data in originals.items():
        (folder / name).write_bytes(data)
    report = folder.parent / f"{folder.name}-report.json"
    completed = cli("rewrite", folder, "--no-verify", "--report", report)
    files = {f["file"]: f for f in json.loads(report.read_text(encoding="utf-8"))["files"]}
    return folder, originals, completed, files


def _new(run, name: str) -> tuple[bytes, bytes]:
    folder, originals, _, _ = run
    return originals[name], (folder / name).read_bytes()


def test_the_run_reports_invalid_files_and_exits_1_without_traceback(run):
    folder, originals, completed, files = run
    assert completed.returncode == 1
    assert_no_traceback(completed.stderr, completed.stdout)
    assert leftovers(folder) == []
    for name, message in INVALID.items():
        if name in BAD_BYTES:
            byte, encoding = BAD_BYTES[name]
            message = (f"byte 0x{byte:02x} at {_where(originals[name], byte)} is not valid "
                       f"{encoding}")
        line = next(li for li in completed.stderr.splitlines()
                    if li.startswith(f"{folder / name}:"))
        assert "cannot decode" in line and message in line, line
        assert files[name]["error"] and not files[name]["changed"]


@pytest.mark.parametrize("name", sorted(INVALID))
def test_a_file_invalid_in_its_encoding_is_left_byte_identical(run, name):
    old, new = _new(run, name)
    assert new == old


@pytest.mark.parametrize("name", sorted(set(_cases()) - set(INVALID)))
def test_the_written_file_is_what_the_core_produces_and_parses(run, name):
    old, new = _new(run, name)
    assert new != old
    assert new == expected_migration(old, name)
    assert python_parses(new)


def test_latin1_cookie_and_latin1_bytes_are_kept(run):
    old, new = _new(run, "latin1_cookie.py")
    assert new.startswith(b"# -*- coding: latin-1 -*-\n")
    assert b"\xb0C" in old  # the degree sign, one latin-1 byte
    for byte in sorted({b for b in old if b >= 0x80}):  # e.g. 0xb0 for the degree sign
        assert bytes([byte]) in new
    with pytest.raises(UnicodeDecodeError):
        new.decode("utf-8")  # still latin-1 on disk, not silently re-encoded
    assert "Temperatur in °C" in new.decode("latin-1")


@pytest.mark.parametrize("name", ["bom.py", "bom_crlf.py"])
def test_a_utf8_bom_is_kept_once(run, name):
    _, new = _new(run, name)
    assert new.startswith(BOM) and not new[3:].startswith(BOM) and new.count(BOM) == 1


@pytest.mark.parametrize("name", ["crlf_skill.py", "bom_crlf.py"])
def test_crlf_files_stay_crlf_on_every_line(run, name):
    _, new = _new(run, name)
    assert new.count(b"\n") == new.count(b"\r\n") > 10
    assert b"\r" not in new.replace(b"\r\n", b"")


def test_mixed_endings_untouched_lines_keep_theirs_generated_lines_use_the_default(run):
    old, new = _new(run, "mixed_endings.py")
    lf_only = expected_migration(old.replace(b"\r\n", b"\n"), "lf.py")
    assert lf_only is not None
    assert new.replace(b"\r\n", b"\n") == lf_only, "only the endings differ"
    default = b"\n"  # the first line ends in LF: the module's default newline
    assert _lines(old)[0].endswith(b"\n") and not _lines(old)[0].endswith(b"\r\n")
    by_text = {line.rstrip(b"\r\n"): line[len(line.rstrip(b"\r\n")):] for line in _lines(old)}
    by_stripped = {text.strip(): ending for text, ending in by_text.items()}
    generated = kept = 0
    for line in _lines(new):
        text = line.rstrip(b"\r\n")
        ending = line[len(text):]
        if text in by_text:  # an untouched line keeps its own ending
            kept += 1
            assert ending == by_text[text] or not text.strip(), line
        elif text.strip() in by_stripped:  # a comment moved into the signature keeps its own
            assert ending in (by_stripped[text.strip()], default), line
        elif text.rstrip().endswith(b"):"):  # the signature ends where `def` ended: its ending
            assert ending in (b"\n", b"\r\n"), line
        else:  # written by ezmigrate: the module's default newline
            generated += 1
            assert ending == default, line
    assert generated > 20 and kept > 20


def test_tabs_are_kept_and_new_lines_indent_with_tabs(run):
    old, new = _new(run, "tab_indented.py")
    for line in _lines(old):
        if line.startswith(b"\t\t") and b"addParam" not in line and b"Condition" not in line \
                and line.strip() not in (b"0.1,", b"ParamTypes.Optional,", b")", b'"Speed",'):
            assert line in new  # implementation code, byte for byte
    body = [li for li in _lines(new) if b"pre_conditions" in li or b"post_conditions" in li]
    assert body and all(li.startswith(b"\t\t") for li in body)
    assert all(li.startswith(b"\tdef ") for li in _lines(new) if b"def description" in li)


def test_a_last_line_without_newline_stays_without(run):
    old, new = _new(run, "no_final_newline.py")
    assert not old.endswith(b"\n")
    assert not new.endswith(b"\n")
    assert new.rsplit(b"\n", 1)[1] == old.rsplit(b"\n", 1)[1]
    assert b"   \n" in new, "trailing whitespace survives too"


def test_a_coding_line_only_python_reads_stays_as_it_was(run):
    """Met by the fuzz test: libcst decodes the first lines as UTF-8 to find the cookie
    and refuses the file, Python finds it all the same. The migration reads the decoded
    text; the written file keeps that first line byte for byte, and Python reads it."""
    old, new = _new(run, "cookie_line_not_utf8.py")
    assert not libcst_parses(old) and python_parses(old)
    assert new != old and new.split(b"\n", 1)[0] == old.split(b"\n", 1)[0]
    assert python_parses(new)
