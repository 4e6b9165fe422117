"""The fixture corpus, the legacy-source strategy and the repository generator are what they
claim to be: parseable where they should parse, broken where they should be broken, with the
byte-level quirks (CRLF, tabs, no final newline, latin-1) really present."""

from __future__ import annotations

import ast
import io
import json
import re
import shutil
import subprocess
import sys
import tokenize
from pathlib import Path
from types import ModuleType

import libcst
import pytest
from bench_generator import generator as load_generator
from hypothesis import HealthCheck, given, settings

try:
    from strategies.legacy_source import (
        GeneratedModule,
        description_class_names,
        legacy_module_texts,
        legacy_modules,
        legacy_modules_with_names,
    )
except ImportError:  # tests/ made a package later: import through it
    from tests.strategies.legacy_source import (
        GeneratedModule,
        description_class_names,
        legacy_module_texts,
        legacy_modules,
        legacy_modules_with_names,
    )

ROOT = Path(__file__).resolve().parents[1]
FIXTURES = ROOT / "fixtures"
LEGACY = FIXTURES / "legacy"
BROKEN = FIXTURES / "broken"
ISOLATION = FIXTURES / "isolation"
GENERATOR = ROOT / "bench" / "generate_repo.py"

REQUIRED_LEGACY = {
    "pick_and_place.py", "param_values.py", "param_kinds_and_options.py", "unusual_keys.py",
    "conditions.py", "condition_classes.py", "import_styles.py", "inheritance.py",
    "descriptions.py", "empty_descriptions.py", "comments_and_banners.py", "crlf_skill.py",
    "tab_indented.py", "no_final_newline.py", "latin1_cookie.py", "mixed_impl.py",
    "nothing_to_do.py", "implementations_only.py", "not_convertible.py", "already_migrated.py",
}
REQUIRED_BROKEN = {
    "py2_print_statement.py", "py2_except_comma.py", "truncated_mid_call.py",
    "invalid_utf8_no_cookie.py", "fstring_pep701.py",
}
REQUIRED_ISOLATION = {
    "raises_on_import.py", "loops_forever.py", "calls_sys_exit.py", "prints_stdout.py",
    "allocates_memory.py", "creates_marker.py",
}


def _files(folder: Path) -> list[Path]:
    return sorted(folder.glob("*.py"))


def _decode(path: Path) -> str:
    """The source text, decoded as Python would (coding cookie, else UTF-8)."""
    raw = path.read_bytes()
    encoding, _ = tokenize.detect_encoding(io.BytesIO(raw).readline)
    return raw.decode(encoding)


# --------------------------------------------------------------------------------------
# fixtures/legacy
# --------------------------------------------------------------------------------------


def test_corpus_is_complete() -> None:
    assert {p.name for p in _files(LEGACY)} >= REQUIRED_LEGACY
    assert {p.name for p in _files(BROKEN)} >= REQUIRED_BROKEN
    assert {p.name for p in _files(ISOLATION)} >= REQUIRED_ISOLATION


@pytest.mark.parametrize("path", _files(LEGACY), ids=lambda p: p.name)
def test_legacy_file_parses_on_311_and_has_realistic_size(path: Path) -> None:
    text = _decode(path)
    ast.parse(text, filename=str(path))
    compile(path.read_bytes(), str(path), "exec", dont_inherit=True)
    lines = len(text.splitlines())
    assert 40 <= lines <= 200, f"{path.name}: {lines} lines"


@pytest.mark.parametrize("path", _files(LEGACY), ids=lambda p: p.name)
def test_legacy_file_round_trips_through_libcst(path: Path) -> None:
    raw = path.read_bytes()
    assert libcst.parse_module(raw).bytes == raw


def test_description_classes_are_where_the_readme_says() -> None:
    assert description_class_names(_decode(LEGACY / "nothing_to_do.py")) == []
    assert description_class_names(_decode(LEGACY / "implementations_only.py")) == []
    assert description_class_names(_decode(LEGACY / "pick_and_place.py")) == [
        "Pick", "Place", "PickAndPlace"]
    assert len(description_class_names(_decode(LEGACY / "not_convertible.py"))) >= 8
    assert "SkillDescription" in _decode(LEGACY / "nothing_to_do.py")  # the prefilter trap


def test_crlf_file_really_uses_crlf() -> None:
    raw = (LEGACY / "crlf_skill.py").read_bytes()
    assert raw.count(b"\r\n") > 40
    assert raw.count(b"\n") == raw.count(b"\r\n")
    assert raw.count(b"\r") == raw.count(b"\r\n")


def test_tab_file_really_uses_tabs() -> None:
    lines = (LEGACY / "tab_indented.py").read_text(encoding="utf-8").split("\n")
    indented = [line for line in lines if line[:1].isspace()]
    assert len(indented) > 20
    assert all(line.startswith("\t") for line in indented)
    assert not any(re.match(r"^\t* ", line) for line in lines)


def test_no_final_newline_file() -> None:
    raw = (LEGACY / "no_final_newline.py").read_bytes()
    assert not raw.endswith((b"\n", b"\r"))
    lines = raw.decode("utf-8").split("\n")
    assert lines[0].startswith("#!")
    assert re.match(r"^# -\*- coding: utf-8 -\*-$", lines[1])
    assert sum(1 for line in lines if line != line.rstrip()) >= 3  # trailing whitespace
    assert "Greifer öffnen" in raw.decode("utf-8")


def test_latin1_file_really_is_latin1() -> None:
    raw = (LEGACY / "latin1_cookie.py").read_bytes()
    encoding, _ = tokenize.detect_encoding(io.BytesIO(raw).readline)
    assert encoding == "iso-8859-1"
    assert any(b >= 0x80 for b in raw)
    with pytest.raises(UnicodeDecodeError):
        raw.decode("utf-8")
    assert "°C" in raw.decode("latin-1")


def test_already_migrated_file_is_in_ezskiros_form() -> None:
    text = _decode(LEGACY / "already_migrated.py")
    assert "addParam" not in text and "getRelationCond" not in text
    tree = ast.parse(text)
    methods = {f.name for c in tree.body if isinstance(c, ast.ClassDef)
               for f in c.body if isinstance(f, ast.FunctionDef)}
    assert "description" in methods


# --------------------------------------------------------------------------------------
# fixtures/broken and fixtures/isolation
# --------------------------------------------------------------------------------------


@pytest.mark.parametrize("path", _files(BROKEN), ids=lambda p: p.name)
def test_broken_file_does_not_compile_on_311(path: Path) -> None:
    with pytest.raises(SyntaxError):
        compile(path.read_bytes(), str(path), "exec", dont_inherit=True)


def test_pep701_fstring_file_parses_with_libcst() -> None:
    raw = (BROKEN / "fstring_pep701.py").read_bytes()
    assert libcst.parse_module(raw).bytes == raw


def test_invalid_utf8_file_has_no_cookie() -> None:
    raw = (BROKEN / "invalid_utf8_no_cookie.py").read_bytes()
    assert b"coding" not in raw.split(b"\n", 2)[0] + raw.split(b"\n", 2)[1]
    with pytest.raises(UnicodeDecodeError):
        raw.decode("utf-8")


def test_truncated_file_stops_mid_call() -> None:
    raw = (BROKEN / "truncated_mid_call.py").read_bytes()
    assert raw.rstrip().endswith(b",") and not raw.endswith(b"\n")


@pytest.mark.parametrize("path", _files(ISOLATION), ids=lambda p: p.name)
def test_isolation_file_parses_and_has_a_description(path: Path) -> None:
    text = _decode(path)
    compile(text, str(path), "exec", dont_inherit=True)
    assert description_class_names(text)


def test_marker_file_is_created_first_thing_at_import(tmp_path: Path) -> None:
    shutil.copy(ISOLATION / "creates_marker.py", tmp_path / "creates_marker.py")
    (tmp_path / ".markers").mkdir()
    marker = tmp_path / ".markers" / "imported"
    # no stand-ins: the import of rospy fails, but only after the marker is written
    proc = subprocess.run([sys.executable, str(tmp_path / "creates_marker.py")],
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode != 0
    assert marker.read_text().startswith("imported")


def test_readme_lists_every_fixture() -> None:
    readme = (FIXTURES / "README.md").read_text(encoding="utf-8")
    for folder in (LEGACY, BROKEN, ISOLATION):
        for path in _files(folder):
            assert f"| `{path.name}` |" in readme, f"{path.name} missing in fixtures/README.md"


# --------------------------------------------------------------------------------------
# tests/strategies/legacy_source.py
# --------------------------------------------------------------------------------------

_FAST = settings(max_examples=50, deadline=None, database=None,
                 suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])


@_FAST
@given(legacy_modules_with_names())
def test_generated_modules_are_valid_python_311(module: GeneratedModule) -> None:
    text, names = module
    tree = ast.parse(text)
    compile(tree, "<generated>", "exec", dont_inherit=True)
    assert 1 <= len(names) <= 3
    assert description_class_names(text) == list(names)
    assert libcst.parse_module(text).code == text


@settings(_FAST, max_examples=20)
@given(legacy_module_texts)
def test_default_text_strategy_gives_parseable_text(text: str) -> None:
    ast.parse(text)


@_FAST
@given(legacy_modules(file_quirks=False, comments=False, implementations=False,
                      max_classes=1))
def test_knobs_switch_constructs_off(text: str) -> None:
    assert "\r" not in text and "\t" not in text and text.endswith("\n")
    assert "PrimitiveBase" not in text
    tokens = tokenize.generate_tokens(io.StringIO(text).readline)
    assert not [t.string for t in tokens if t.type == tokenize.COMMENT]
    assert len(description_class_names(text)) == 1


def test_strategy_covers_the_construct_table() -> None:
    seen: list[str] = []

    @settings(max_examples=200, deadline=None, database=None, derandomize=True,
              suppress_health_check=list(HealthCheck))
    @given(legacy_module_texts)
    def collect(text: str) -> None:
        seen.append(text)

    collect()
    corpus = "\n".join(seen)
    expected = [
        "getRelationCond(", "getAbstractRelationCond(", "getPropCond(", "getHasPropCond(",
        "getIsSpecifiedCond(", "getGenerateCond(", "getOnTypeCond(", "getOrCond(",
        ".addCondition(", "ConditionRelation(", "ConditionProperty(", "ConditionHasProperty(",
        "addPreCondition(", "addHoldCondition(", "addPostCondition(",
        ".Lock", ".Consume", ".Unspecify", ".RespectType", ".Output",
        "key=", "value=", "param_type=", "options=", "description=",
        "Element()", "E(", "we.Element(", "PT.", "params.ParamTypes.",
        '":Location"', '"Location"', "float,", "dict,", "{}", "-", "True", "False",
        '">="', '"<"', "#=======", "PrimitiveBase", "SkillBase", "remap=", "\r\n", "\t",
        "# -*- coding: utf-8 -*-", "#!/usr/bin/env python", '"Robot"',
    ]
    missing = [token for token in expected if token not in corpus]
    if not any(f'"{key}"' in corpus for key in ("On/Off", "Target Location", "Speed (m/s)",
                                                "grip-force", "tool.frame", "2nd Object")):
        missing.append("a key that is no identifier")
    assert not missing, f"never generated: {missing}"
    assert any(not text.endswith("\n") for text in seen)
    assert re.search(r'addParam\("[^"]*", [^,]+, [^,]+, "', corpus), "4th-positional quirk"
    assert re.search(r"addParam\([^)]*, [012]\)", corpus), "kinds as ints"


# --------------------------------------------------------------------------------------
# bench/generate_repo.py
# --------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def generator() -> ModuleType:
    return load_generator()


def _tree(root: Path) -> dict[str, bytes]:
    return {p.relative_to(root).as_posix(): p.read_bytes()
            for p in sorted(root.rglob("*")) if p.is_file()}


def test_generator_is_deterministic(generator: ModuleType, tmp_path: Path) -> None:
    generator.generate(tmp_path / "a", 40, 0.25, seed=7)
    generator.generate(tmp_path / "b", 40, 0.25, seed=7)
    generator.generate(tmp_path / "c", 40, 0.25, seed=8)
    assert _tree(tmp_path / "a") == _tree(tmp_path / "b")
    assert _tree(tmp_path / "a") != _tree(tmp_path / "c")


def test_generator_produces_the_requested_counts(generator: ModuleType, tmp_path: Path) -> None:
    out = tmp_path / "repo"
    summary = generator.generate(out, 80, 0.25, seed=1)
    modules = [p for p in out.rglob("*.py") if p.name != "__init__.py"]
    assert len(modules) == summary.files == 80
    assert summary.skill_files == len(summary.manifest) == 20
    assert summary.init_files == len(list(out.rglob("__init__.py")))
    skill_paths = {e["path"]: e["classes"] for e in summary.manifest}
    total_lines = 0
    for path in modules:
        text = path.read_text(encoding="utf-8")
        total_lines += len(text.splitlines())
        rel = path.relative_to(out)
        assert 1 <= len(rel.parts) - 1 <= 4  # nested 1-4 packages deep
        for depth in range(1, len(rel.parts)):
            assert (out.joinpath(*rel.parts[:depth]) / "__init__.py").is_file()
        names = description_class_names(text)  # ast.parse inside: every file is valid
        if rel.as_posix() in skill_paths:
            assert names == skill_paths[rel.as_posix()]
            assert 1 <= len(names) <= 4
            assert 60 <= len(text.splitlines()) <= 450
        else:
            assert names == []
            assert 90 <= len(text.splitlines()) <= 650
    assert summary.skills == sum(len(c) for c in skill_paths.values())
    assert summary.lines == total_lines


def test_generator_optional_py2_files_do_not_compile(generator: ModuleType,
                                                     tmp_path: Path) -> None:
    out = tmp_path / "repo"
    summary = generator.generate(out, 20, 1.0, seed=2, py2_share=1.0)
    assert summary.python2_files == 20
    for entry in summary.manifest:
        with pytest.raises(SyntaxError):
            compile((out / entry["path"]).read_bytes(), entry["path"], "exec")


def test_generator_cli(tmp_path: Path) -> None:
    out = tmp_path / "repo"
    cmd = [sys.executable, str(GENERATOR), str(out), "--files", "30", "--skill-share", "0.1",
           "--seed", "0"]
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=120, check=True)
    fields = dict(item.split("=", 1) for item in proc.stdout.split())
    assert proc.stdout.count("\n") == 1
    assert (fields["files"], fields["skill_files"]) == ("30", "3")
    assert int(fields["skills"]) >= 3 and int(fields["lines"]) > 30 * 80
    manifest = json.loads((out / ".generated-repo.json").read_text())
    assert manifest["summary"]["files"] == 30
    again = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    assert again.returncode != 0 and "not empty" in again.stderr
    cleaned = subprocess.run([*cmd, "--clean"], capture_output=True, text=True, timeout=120)
    assert cleaned.returncode == 0
    foreign = tmp_path / "foreign"
    foreign.mkdir()
    (foreign / "keep.txt").write_text("x")
    refused = subprocess.run([sys.executable, str(GENERATOR), str(foreign), "--clean"],
                             capture_output=True, text=True, timeout=120)
    assert refused.returncode != 0 and (foreign / "keep.txt").exists()
