"""Paths: symlinks are followed for reading only inside the given roots and never written
through to a target outside them; symlink loops end; files that change or vanish during the
run (their own import did it, while being verified) are detected by the content hash and
left alone."""

from __future__ import annotations

import os
import shutil

import pytest
from safety_support import LEGACY, assert_no_traceback, cli, expected_migration, leftovers

DESCRIPTIONS = LEGACY / "descriptions.py"
PICK = LEGACY / "pick_and_place.py"


@pytest.fixture
def layout(tmp_path):
    root, outside = tmp_path / "root", tmp_path / "outside"
    root.mkdir()
    outside.mkdir()
    shutil.copy(DESCRIPTIONS, root / "descriptions.py")
    shutil.copy(PICK, outside / "pick_and_place.py")
    shutil.copy(DESCRIPTIONS, outside / "other.py")
    return root, outside


def test_a_symlink_to_a_file_outside_the_root_is_not_written_through(layout):
    root, outside = layout
    (root / "linked.py").symlink_to(outside / "pick_and_place.py")
    (root / "linked_dir").symlink_to(outside, target_is_directory=True)

    run = cli("rewrite", root, "--no-verify")

    assert_no_traceback(run.stderr)
    assert (outside / "pick_and_place.py").read_bytes() == PICK.read_bytes()
    assert (outside / "other.py").read_bytes() == DESCRIPTIONS.read_bytes()
    assert (root / "linked.py").is_symlink() and (root / "linked_dir").is_symlink()
    assert f"{root / 'linked.py'}: symlink leads outside the given paths" in run.stderr
    assert f"{root / 'linked_dir'}: symlink leads outside the given paths" in run.stderr
    assert (root / "descriptions.py").read_bytes() == expected_migration(
        DESCRIPTIONS.read_bytes())
    assert leftovers(root.parent) == []


def test_a_symlink_named_on_the_command_line_is_not_written_through_to_outside(layout):
    root, outside = layout
    (root / "linked.py").symlink_to(outside / "pick_and_place.py")

    run = cli("rewrite", root / "linked.py", "--no-verify")

    assert run.returncode == 1
    assert_no_traceback(run.stderr)
    assert "outside the given paths; not written through, left alone" in run.stderr
    assert (outside / "pick_and_place.py").read_bytes() == PICK.read_bytes()
    assert (root / "linked.py").is_symlink()
    assert leftovers(root.parent) == []


def test_a_symlink_inside_the_root_is_written_through_once_and_stays_a_symlink(layout):
    root, _ = layout
    (root / "sub").mkdir()
    (root / "sub" / "alias.py").symlink_to("../descriptions.py")

    run = cli("rewrite", root, "--no-verify")

    assert run.returncode == 0, run.stderr
    assert (root / "sub" / "alias.py").is_symlink()
    assert os.readlink(root / "sub" / "alias.py") == "../descriptions.py"
    assert (root / "descriptions.py").read_bytes() == expected_migration(
        DESCRIPTIONS.read_bytes())
    assert "1 file changed" in run.stderr


def test_directory_symlink_loops_end(layout):
    root, _ = layout
    (root / "loop").symlink_to(".", target_is_directory=True)
    (root / "sub").mkdir()
    (root / "sub" / "back").symlink_to("..", target_is_directory=True)
    (root / "sub" / "away").symlink_to("../..", target_is_directory=True)

    run = cli("rewrite", root, "--no-verify", timeout=120)

    assert run.returncode == 0, run.stderr
    assert_no_traceback(run.stderr)
    assert "symlink loop, not followed again" in run.stderr
    assert (root / "descriptions.py").read_bytes() == expected_migration(
        DESCRIPTIONS.read_bytes())


def test_file_symlink_loops_end_and_the_rest_is_migrated(layout):
    root, _ = layout
    (root / "self.py").symlink_to("self.py")
    (root / "a.py").symlink_to("b.py")
    (root / "b.py").symlink_to("a.py")

    run = cli("rewrite", root, "--no-verify", timeout=120)

    assert_no_traceback(run.stderr)
    assert run.returncode in (0, 1), run.stderr
    assert "symlink loop" in run.stderr
    assert (root / "descriptions.py").read_bytes() == expected_migration(
        DESCRIPTIONS.read_bytes())
    assert all((root / n).is_symlink() for n in ("self.py", "a.py", "b.py"))


SELF_MODIFYING = '''
# importing this module changes its own file on disk (a generated-constants pattern gone
# wrong): verification imports it before anything is written
with open(__file__, "a", encoding="utf-8") as _handle:
    _handle.write("# touched by its own import\\n")
'''

SELF_DELETING = '''
import os as _os
if _os.path.exists(__file__):
    _os.remove(__file__)
'''


def test_a_file_changed_between_read_and_write_is_left_alone(tmp_path):
    module = tmp_path / "self_modifying.py"
    original = DESCRIPTIONS.read_bytes() + SELF_MODIFYING.encode()
    module.write_bytes(original)
    shutil.copy(PICK, tmp_path / "pick_and_place.py")

    run = cli("rewrite", tmp_path, "--timeout", "60")

    assert run.returncode == 1, run.stderr
    assert_no_traceback(run.stderr)
    assert f"{module}: changed during the run, left alone" in run.stderr
    now = module.read_bytes()
    assert now.startswith(original)  # our version was never written over its change
    assert now[len(original):].count(b"# touched by its own import\n") >= 1
    assert b"def description" not in now
    assert b"def description" in (tmp_path / "pick_and_place.py").read_bytes()
    assert leftovers(tmp_path) == []


def test_a_file_that_vanished_during_the_run_is_not_recreated(tmp_path):
    module = tmp_path / "self_deleting.py"
    module.write_bytes(DESCRIPTIONS.read_bytes() + SELF_DELETING.encode())

    run = cli("rewrite", tmp_path, "--timeout", "60")

    assert_no_traceback(run.stderr)
    assert not module.exists()
    assert f"{module}: vanished during the run, left alone" in run.stderr
    assert run.returncode == 1
    assert leftovers(tmp_path) == []
