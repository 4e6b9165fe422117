"""Writes are atomic: temporary file in the same folder, flushed, same permission bits,
replaced by rename; a write that fails leaves the original whole and no temporary file."""

from __future__ import annotations

import json
import os
import resource
import stat

from safety_support import (
    LEGACY,
    assert_no_traceback,
    cli,
    copy_fixtures,
    expected_migration,
    leftovers,
    mode_of,
    snapshot,
)

NAMES = ("pick_and_place.py", "descriptions.py", "conditions.py", "inheritance.py")


def test_rewrite_replaces_by_rename_keeping_permission_bits(tmp_path):
    originals = copy_fixtures(tmp_path, [LEGACY / n for n in NAMES])
    modes = {"pick_and_place.py": 0o755, "descriptions.py": 0o640, "conditions.py": 0o600,
             "inheritance.py": 0o664}
    for name, mode in modes.items():
        os.chmod(tmp_path / name, mode)
    inodes = {n: os.stat(tmp_path / n).st_ino for n in NAMES}
    owners = {n: (os.stat(tmp_path / n).st_uid, os.stat(tmp_path / n).st_gid) for n in NAMES}

    run = cli("rewrite", tmp_path, "--no-verify")

    assert run.returncode in (0, 1), run.stderr
    assert_no_traceback(run.stderr, run.stdout)
    for name in NAMES:
        path = tmp_path / name
        expected = expected_migration(originals[name], name)
        assert expected is not None
        assert path.read_bytes() == expected
        assert mode_of(path) == modes[name], name
        assert (os.stat(path).st_uid, os.stat(path).st_gid) == owners[name]
        assert os.stat(path).st_ino != inodes[name], "replaced by rename, not rewritten in place"
    assert leftovers(tmp_path) == []
    assert sorted(snapshot(tmp_path)) == sorted(NAMES)


def test_output_dir_copies_are_whole_and_keep_permission_bits(tmp_path):
    source, out = tmp_path / "src", tmp_path / "out"
    originals = copy_fixtures(source, [LEGACY / n for n in NAMES])
    os.chmod(source / "pick_and_place.py", 0o755)

    run = cli("rewrite", source, "--no-verify", "--output-dir", out)

    assert run.returncode in (0, 1), run.stderr
    assert snapshot(source) == originals, "the sources are not touched"
    for name in NAMES:
        assert (out / name).read_bytes() == expected_migration(originals[name], name)
    assert mode_of(out / "pick_and_place.py") == 0o755
    assert leftovers(out) == [] and leftovers(source) == []


def _tiny_file_size_limit() -> None:
    """Writes past 1 KiB fail with EFBIG (Python ignores SIGXFSZ): a full disk, for real."""
    resource.setrlimit(resource.RLIMIT_FSIZE, (1024, 1024))


def test_a_write_that_fails_leaves_the_original_whole_and_no_temporary_file(tmp_path):
    originals = copy_fixtures(tmp_path, [LEGACY / n for n in NAMES])

    run = cli("rewrite", tmp_path, "--no-verify", preexec_fn=_tiny_file_size_limit)

    assert run.returncode == 1, run.stderr
    assert_no_traceback(run.stderr, run.stdout)
    assert snapshot(tmp_path) == originals
    assert leftovers(tmp_path) == []
    for name in NAMES:
        assert f"{name}: could not be written (File too large), left as it was" in run.stderr


def test_a_file_made_read_only_is_reported_and_left_alone(tmp_path):
    originals = copy_fixtures(tmp_path, [LEGACY / n for n in NAMES])
    locked = tmp_path / "descriptions.py"
    os.chmod(locked, stat.S_IRUSR | stat.S_IRGRP | stat.S_IROTH)  # 0o444, even for root

    run = cli("rewrite", tmp_path, "--no-verify", "--report", tmp_path.parent / "r.json")

    assert run.returncode == 1
    assert_no_traceback(run.stderr, run.stdout)
    assert f"{locked}: read-only, left alone" in run.stderr
    assert "3 files changed" in run.stderr  # the summary counts what is on disk
    report = json.loads((tmp_path.parent / "r.json").read_text(encoding="utf-8"))
    unwritten = [s for s in report["skills"] if s["file"] == "descriptions.py"]
    assert unwritten and all(s["status"] == "failed" and "read-only" in s["reason"]
                             for s in unwritten), unwritten  # still legacy on disk
    assert locked.read_bytes() == originals["descriptions.py"]
    assert mode_of(locked) == 0o444
    others = [n for n in NAMES if n != "descriptions.py"]
    for name in others:  # the run goes on
        assert (tmp_path / name).read_bytes() == expected_migration(originals[name], name)
