"""``rewrite -`` from an editor: ``--stdin-filename`` anchors the project; without it, only
a git checkout or ROS package around the working directory is searched for ``owl/`` files.
"""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures"
PACKAGE = FIXTURES / "noetic_package"


def _rewrite(*args: object, cwd: Path, stdin: bytes) -> subprocess.CompletedProcess[bytes]:
    return subprocess.run([sys.executable, "-m", "ezmigrate", "rewrite", "--dry-run",
                           "--no-verify", *map(str, args)], cwd=cwd, input=stdin,
                          capture_output=True, timeout=600, check=False)


def test_stdin_from_a_home_folder_does_not_scan_its_subfolders(tmp_path: Path) -> None:
    home = tmp_path / "home"
    (home / "other_project" / "owl").mkdir(parents=True)
    (home / "other_project" / "owl" / "broken.owl").write_text("<rdf:RDF")  # not ours
    run = _rewrite("-", cwd=home, stdin=(FIXTURES / "legacy" / "param_values.py").read_bytes())
    stderr = run.stderr.decode()
    assert run.returncode == 0, stderr
    assert "broken.owl" not in stderr and "the bundled default" in stderr


def test_stdin_filename_takes_the_files_project_ontology_and_robot(tmp_path: Path) -> None:
    package = tmp_path / "paint_cell"
    shutil.copytree(PACKAGE, package)
    named = package / "src" / "paint_cell" / "descriptions.py"
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    run = _rewrite("--stdin-filename", named, "-", cwd=elsewhere, stdin=named.read_bytes())
    stderr, diff = run.stderr.decode(), run.stdout.decode()
    assert run.returncode == 0, stderr
    assert "owl/paintcell.owl" in stderr  # the package's own vocabulary
    assert "Booth: paintcell.SprayBooth" in diff  # ... used in the short form
    assert "OPTIONAL[LIST[float]]" in diff  # a ROS 1 package: written for Python 3.8
    assert "descriptions.py" in diff.splitlines()[0]  # the diff names the file


def _check(*args: object, cwd: Path, stdin: bytes) -> subprocess.CompletedProcess[bytes]:
    return subprocess.run([sys.executable, "-m", "ezmigrate", "check", "--exit-zero",
                           *map(str, args)], cwd=cwd, input=stdin, capture_output=True,
                          timeout=600, check=False)


def test_check_reads_stdin_and_names_the_file_it_stands_for(tmp_path: Path) -> None:
    source = (FIXTURES / "legacy" / "param_values.py").read_bytes()
    plain = _check("-", cwd=tmp_path, stdin=source)
    assert plain.returncode == 0, plain.stderr
    lines = plain.stdout.decode().splitlines()
    assert lines and all(line.startswith("-:") for line in lines), lines
    named = _check("--stdin-filename", "skills/values.py", "-", cwd=tmp_path, stdin=source)
    renamed = [line.replace("skills/values.py:", "-:", 1)
               for line in named.stdout.decode().splitlines()]
    assert renamed == lines  # the same findings, under the name given
    assert b"1 file checked" in named.stderr
    refused = _check("--fix", "-", cwd=tmp_path, stdin=source)
    assert refused.returncode == 2 and b"not on stdin" in refused.stderr
