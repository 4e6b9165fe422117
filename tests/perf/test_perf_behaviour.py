"""Behaviour of the speed-ups of issue 5 (no timing here: bench/bench_repo.py measures).

- the prefilter never rules out a file that holds a description (checked against the
  migrate core, on generated repositories and on hand-written corner cases);
- the runner gives the same results with and without worker processes, migrates a single
  candidate without a pool, survives a dying worker, keeps no bytes of files it never
  parsed (and still hands them out when asked), and leaves libcst unimported when nothing
  needs parsing;
- discovery asks git once per checkout, not once per folder, and still honours each
  checkout's ``.gitignore``;
- the verification worker's warm-up loads its two built-in descriptions, equivalently.
"""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
from concurrent.futures import wait
from concurrent.futures.process import BrokenProcessPool
from pathlib import Path

import pytest
from bench_generator import generator

from ezmigrate.codemod.migrate import migrate
from ezmigrate.files import git_ignored
from ezmigrate.files.discover import Candidate, discover
from ezmigrate.files.prefilter import MARKERS, by_text, may_hold_descriptions
from ezmigrate.project import runner
from ezmigrate.project.runner import Migrated, migrate_all

REPO = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def generated_with_manifest(tmp_path_factory) -> tuple[Path, set[str]]:
    """A generated repository (skill files, some messy; ordinary modules; prefilter traps)
    and the relative paths of its skill files."""
    out = tmp_path_factory.mktemp("repo") / "tree"
    summary = generator().generate(out, 400, 0.1, seed=5, messy_share=0.2)
    return out, {entry["path"] for entry in summary.manifest}


@pytest.fixture(scope="module")
def generated(generated_with_manifest) -> Path:
    return generated_with_manifest[0]


def _named(data: bytes) -> bool:
    return any(marker in data for marker in MARKERS)


# -- prefilter -----------------------------------------------------------------------------

def test_prefilter_keeps_every_generated_skill_file_and_rules_out_the_traps(
        generated_with_manifest):
    generated, skill_files = generated_with_manifest
    assert len(skill_files) == 40
    traps = []
    for path in sorted(generated.rglob("*.py")):
        relative = path.relative_to(generated).as_posix()
        data = path.read_bytes()
        if relative in skill_files:
            assert may_hold_descriptions(data), relative
        elif _named(data):
            traps.append(path)
    assert traps, "the generator makes files that mention SkillDescription in text"
    assert not any(may_hold_descriptions(p.read_bytes()) for p in traps)


def test_every_generated_file_the_prefilter_rules_out_has_nothing_to_migrate(generated):
    """The core itself, on every rejected file that mentions a marker, plus a sample of
    the others: no description, no change, no base from a sibling file."""
    rejected = [p for p in sorted(generated.rglob("*.py"))
                if not may_hold_descriptions(p.read_bytes())]
    named = [p for p in rejected if _named(p.read_bytes())]
    sample = named + [p for p in rejected if p not in named][::25]
    assert named and len(sample) > len(named)
    for path in sample:
        result = migrate(path.read_bytes(), path=str(path))
        assert result.skills == [] and result.new_source is None, path
        assert result.error is None and result.foreign_bases == [], path


LEGACY_IMPORTS = ("from skiros2_common.core.abstract_skill import SkillDescription\n"
                  "from skiros2_common.core.params import ParamTypes\n")
BODY = ("    def createDescription(self):\n"
        '        self.addParam("Speed", 0.5, ParamTypes.Optional)\n')

HOLDING = {
    "plain": LEGACY_IMPORTS + "\n\nclass A(SkillDescription):\n" + BODY,
    "alias": "from skiros2_common.core.abstract_skill import SkillDescription as SD\n"
             "from skiros2_common.core.params import ParamTypes\n\n\nclass A(SD):\n" + BODY,
    "module alias": "import skiros2_common.core.abstract_skill as a\n"
                    "from skiros2_common.core.params import ParamTypes\n\n\n"
                    "class A(a.SkillDescription):\n" + BODY,
    "base on its own line": LEGACY_IMPORTS + "\n\nclass A(\n        SkillDescription):\n"
                            + BODY,
    "alias inside parentheses under if 0": "if 0:\n"
        "    from skiros2_common.core.abstract_skill import (\n"
        "        SkillDescription as SD)\n"
        "from skiros2_common.core.abstract_skill import SkillDescription as SD\n"
        "from skiros2_common.core.params import ParamTypes\n\n\nclass A(SD):\n" + BODY,
    "star import": "from skiros2_skill.core.skill import *\n"
                   "ParamTypes = ParamTypes\n\n\nclass A(\n    SkillDescription,\n):\n" + BODY,
    "comment before the code": "# a SkillDescription follows\n" + LEGACY_IMPORTS
                               + "\n\nclass A(SkillDescription):\n" + BODY,
    "carriage returns only": (LEGACY_IMPORTS + "# SkillDescription\n\n\nclass A(\n"
                              "    SkillDescription):\n" + BODY).replace("\n", "\r"),
}

NOT_HOLDING = {
    "comment": "# unlike a SkillDescription subclass, this helper declares nothing\nx = 1\n",
    "indented comment": "def f():\n    # we used to subclass SkillDescription here\n"
                        "    return 1\n",
    "docstring": '"""Geometry helpers.\n\nNo SkillDescription lives here -- the skills\n'
                 'import these helpers.\n"""\nimport math\n',
    "string": 'def f():\n    hint = "SkillDescription classes live in skills/"\n'
              '    return hint\n',
    "hash line in a string": 's = """\n# createDescription is not here\n"""\n',
    "attribute-like text": "x = 'self.createDescription()'\n",
}

MAYBE = {  # the prefilter cannot tell without the core: it must say "maybe"
    "syntax error": "def broken(:\n    x = SkillDescription\n",
    "undecodable": b"x = '\xff\xfe'\ny = SkillDescription\n",
    "code mention, no class": "from somewhere import thing\nprint(SkillDescription)\n",
}


@pytest.mark.parametrize("name", sorted(HOLDING))
def test_files_with_descriptions_are_kept(name):
    source = HOLDING[name].encode()
    assert migrate(source).skills, "the case must really hold a description"
    assert may_hold_descriptions(source)


@pytest.mark.parametrize("name", sorted(NOT_HOLDING))
def test_files_that_only_mention_a_marker_in_text_are_ruled_out(name):
    source = NOT_HOLDING[name].encode()
    assert _named(source)
    assert migrate(source).skills == []
    assert not may_hold_descriptions(source)


@pytest.mark.parametrize("name", sorted(MAYBE))
def test_doubtful_files_go_to_the_core(name):
    source = MAYBE[name]
    assert may_hold_descriptions(source if isinstance(source, bytes) else source.encode())


@pytest.mark.parametrize("jobs", [1, 2])
def test_the_parse_the_text_cannot_spare_is_taken_in_the_workers(tmp_path, jobs):
    """A file whose text mentions a marker in code (a string, a print) needs a parse to be
    ruled out (``by_text`` is None): the migration's workers take it, and give the empty
    result the prefilter gives; a file the text rules out never reaches them."""
    files = {f"not_{i}.py": source for i, source in enumerate(NOT_HOLDING.values())}
    files["skill.py"] = HOLDING["plain"]
    for name, source in files.items():
        (tmp_path / name).write_text(source)
    asked = [name for name, source in files.items() if by_text(source.encode()) is None]
    assert len(asked) >= 2  # the strings and the attribute-like text
    items = {m.candidate.relative: m for m in migrate_all(_candidates(tmp_path), None, jobs)}
    assert [n for n, m in items.items() if m.result.skills] == ["skill.py"]
    assert all(items[n].result == runner.FileResult(n) for n in files if n != "skill.py")
    assert {n for n, m in items.items() if m._original is not None} == {*asked, "skill.py"}


def test_a_latin1_file_is_judged_by_its_code():
    cookie = "# -*- coding: latin-1 -*-\n"
    comment_only = (cookie + "# Grüße: no SkillDescription here\nx = 'ü'\n").encode("latin-1")
    in_code = (cookie + "x = 'ü'\ny = [\n    SkillDescription]\n").encode("latin-1")
    assert not may_hold_descriptions(comment_only)
    assert may_hold_descriptions(in_code)


# -- runner --------------------------------------------------------------------------------

def _candidates(root: Path) -> list[Candidate]:
    candidates, _ = discover([root], respect_gitignore=False)
    return candidates


def _summary(items: list[Migrated]) -> list[tuple]:
    return [(m.candidate.relative, m.result.new_source, m.result.error,
             [(s.name, s.status, s.reason) for s in m.result.skills]) for m in items]


def test_workers_give_the_same_results_as_one_process(generated):
    candidates = _candidates(generated)[:160]
    alone = migrate_all(candidates, None, 1)
    pooled = migrate_all(candidates, None, 2)
    assert _summary(pooled) == _summary(alone)
    assert sum(m.result.changed for m in pooled) >= 3


def test_unparsed_files_keep_no_bytes_but_hand_them_out(tmp_path):
    (tmp_path / "plain.py").write_text("x = 1\n")
    (tmp_path / "skill.py").write_text(HOLDING["plain"])
    items = {m.candidate.relative: m for m in migrate_all(_candidates(tmp_path), None, 2)}
    plain, skill = items["plain.py"], items["skill.py"]
    assert plain._original is None and skill._original == HOLDING["plain"].encode()
    assert skill.result.changed and len(skill.digest) == 64
    (tmp_path / "plain.py").write_text("x = 2\n")
    assert plain.original == b"x = 2\n"  # read when asked, as the file is then
    assert plain.digest == runner.content_digest(b"x = 2\n")


def test_a_single_candidate_is_migrated_without_a_pool(tmp_path, monkeypatch):
    (tmp_path / "skill.py").write_text(HOLDING["plain"])
    (tmp_path / "plain.py").write_text("x = 1\n")

    def no_pool(self):
        raise AssertionError("no pool for a single file")

    monkeypatch.setattr(runner._Workers, "_start", no_pool)
    items = migrate_all(_candidates(tmp_path), None, 4)
    assert [m.result.changed for m in items] == [False, True]


def _dies_on_boom(relative: str, data: bytes, ambiguous: bool = False):
    if relative == "boom.py":
        os._exit(3)
    return ORIGINAL_MIGRATE_ONE(relative, data, ambiguous)


ORIGINAL_MIGRATE_ONE = runner._migrate_one


def test_a_dying_worker_costs_an_error_result_not_the_run(tmp_path, monkeypatch):
    for name in ("a.py", "boom.py", "c.py"):
        (tmp_path / name).write_text(HOLDING["plain"])
    monkeypatch.setattr(runner, "_migrate_one", _dies_on_boom)
    items = {m.candidate.relative: m for m in migrate_all(_candidates(tmp_path), None, 2)}
    assert "worker died" in (items["boom.py"].result.error or "")
    assert all(m.result.changed or m.result.error for m in items.values())


def test_a_file_read_after_a_worker_died_gets_an_error_result_too(tmp_path, monkeypatch):
    """The pool breaks while the main process still reads files: the next submit must not
    raise (it did: the whole run stopped). Held by construction: the third file is added
    only once the dying file's future has failed, which the executor does after marking
    itself broken."""
    monkeypatch.setattr(runner, "_migrate_one", _dies_on_boom)
    workers = runner._Workers(None, 2)
    items = []
    for name in ("a.py", "boom.py", "c.py"):
        path = tmp_path / name
        path.write_text(HOLDING["plain"])
        item = Migrated(Candidate(path, tmp_path), path.read_bytes(), None,
                        runner.FileResult(name))
        if name == "c.py":
            died = next(future for done, future in workers.futures if done.candidate.relative
                        == "boom.py")
            wait([died])
            assert isinstance(died.exception(), BrokenProcessPool)
        workers.add(item, item.original)
        items.append(item)
    workers.finish()
    assert all("worker died" in (m.result.error or "") or m.result.changed for m in items)
    assert "worker died" in (items[2].result.error or "")


def test_no_libcst_import_when_nothing_needs_parsing(tmp_path):
    (tmp_path / "a.py").write_text("# SkillDescription: not here\nx = 1\n")
    (tmp_path / "b.py").write_text("y = 2\n")
    code = textwrap.dedent(f"""
        import sys
        from pathlib import Path
        from ezmigrate.files.discover import discover
        from ezmigrate.project.runner import migrate_all
        items = migrate_all(discover([Path({str(tmp_path)!r})])[0], None, 2)
        assert len(items) == 2 and not any(m.result.changed for m in items)
        print("libcst" in sys.modules)
    """)
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True)
    assert run.stdout.strip() == "False"


def test_the_command_line_starts_without_libcst():
    """``--version``, ``--help`` and the start of every command import no libcst (issue 31:
    a tenth of a second of every run); the codemod's settings live apart (``settings``)."""
    code = textwrap.dedent("""
        import sys
        import ezmigrate.cli.commands, ezmigrate.project.session, ezmigrate.project.settle
        from ezmigrate.codemod.settings import Settings
        Settings()
        print("libcst" in sys.modules)
    """)
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True)
    assert run.stdout.strip() == "False"


# -- discovery -----------------------------------------------------------------------------

def _git(*args: str | Path) -> None:
    subprocess.run(["git", *map(str, args)], check=True, capture_output=True)


def _git_calls(monkeypatch: pytest.MonkeyPatch) -> list[list[str]]:
    """The command lines of every process started from now on (discovery's git calls):
    the shell that asks every checkout at once (``git_ignored``) counts as the gits it
    starts, one per ``(top, input, output)`` triple of its arguments."""
    calls: list[list[str]] = []
    real_popen = subprocess.Popen

    class Counting(real_popen):  # type: ignore[misc, valid-type]
        def __init__(self, args, *rest, **kwargs):  # type: ignore[no-untyped-def]
            args = [str(a) for a in args]
            if args[:2] == [git_ignored.SHELL, "-c"]:
                triples = args[4:]
                calls.extend(["git", "-C", triples[i], "check-ignore", "--stdin", "-z"]
                             for i in range(0, len(triples), 3))
            else:
                calls.append(args)
            super().__init__(args, *rest, **kwargs)

    monkeypatch.setattr(subprocess, "Popen", Counting)
    return calls


def test_git_is_asked_once_per_checkout_and_each_gitignore_holds(tmp_path, monkeypatch):
    outer = tmp_path / "outer"
    for folder in ("a", "a/b", "c", "nested", "nested/d"):
        (outer / folder).mkdir(parents=True)
        (outer / folder / "keep.py").write_text("")
        (outer / folder / "ignored.py").write_text("")
        (outer / folder / "local.py").write_text("")
    _git("init", "-q", outer)
    _git("init", "-q", outer / "nested")
    (outer / ".gitignore").write_text("ignored.py\n")
    (outer / "nested" / ".gitignore").write_text("local.py\n")
    calls = _git_calls(monkeypatch)
    found = {c.relative for c in discover([outer])[0]}
    assert found == {"a/keep.py", "a/local.py", "a/b/keep.py", "a/b/local.py", "c/keep.py",
                     "c/local.py", "nested/keep.py", "nested/ignored.py", "nested/d/keep.py",
                     "nested/d/ignored.py"}
    assert sum("check-ignore" in call for call in calls) == 2  # one per checkout
    assert len(calls) == 2


def test_a_worktree_whose_git_is_a_file_is_asked_from_its_own_folder(tmp_path, monkeypatch):
    """A linked worktree (or a submodule) holds a ``.git`` file, not a folder: git is asked
    from there, and the checkout's ``.gitignore`` holds."""
    main = tmp_path / "main"
    main.mkdir()
    _git("init", "-q", main)
    (main / ".gitignore").write_text("ignored.py\n")
    _git("-C", main, "add", ".gitignore")
    _git("-C", main, "-c", "user.name=t", "-c", "user.email=t@t", "commit", "-q", "-m", "i")
    _git("-C", main, "worktree", "add", "-q", "-b", "side", tmp_path / "side")
    assert (tmp_path / "side" / ".git").is_file()
    for name in ("keep.py", "ignored.py"):
        (tmp_path / "side" / "pkg").mkdir(exist_ok=True)
        (tmp_path / "side" / "pkg" / name).write_text("")
    calls = _git_calls(monkeypatch)
    assert {c.relative for c in discover([tmp_path / "side"])[0]} == {"pkg/keep.py"}
    assert len(calls) == 1


def test_with_gits_own_variables_each_folder_asks_for_its_checkout(tmp_path, monkeypatch):
    """``GIT_CEILING_DIRECTORIES`` and friends change where git finds a checkout: then
    each folder asks git for its top level, and the answers are those git gives."""
    outer = tmp_path / "outer"
    for folder in ("a", "nested/d"):
        (outer / folder).mkdir(parents=True)
        (outer / folder / "keep.py").write_text("")
        (outer / folder / "ignored.py").write_text("")
    _git("init", "-q", outer)
    _git("init", "-q", outer / "nested")
    (outer / ".gitignore").write_text("ignored.py\n")
    monkeypatch.setenv("GIT_CEILING_DIRECTORIES", str(tmp_path))
    calls = _git_calls(monkeypatch)
    found = {c.relative for c in discover([outer])[0]}
    assert found == {"a/keep.py", "nested/d/keep.py", "nested/d/ignored.py"}
    assert sum("rev-parse" in call for call in calls) == 2  # one per folder
    assert sum("check-ignore" in call for call in calls) == 2  # one per checkout


def test_outside_any_checkout_git_is_never_asked(tmp_path, monkeypatch):
    for index in range(12):
        folder = tmp_path / f"p{index}" / "q"
        folder.mkdir(parents=True)
        (folder / "m.py").write_text("")
    if subprocess.run(["git", "-C", str(tmp_path), "rev-parse"], capture_output=True,
                      check=False).returncode == 0:
        pytest.skip("the temporary folder lies inside a git checkout")
    calls = _git_calls(monkeypatch)
    assert len(discover([tmp_path])[0]) == 12
    assert calls == []  # no .git above any folder: nothing to ask


# -- verification worker warm-up -----------------------------------------------------------

def test_the_warm_up_descriptions_load_and_agree():
    code = textwrap.dedent("""
        import json, os, sys
        os.environ["EZSKIROS_BACKEND"] = "legacy"
        from ezmigrate.verify.zygote import warm_up
        from ezskiros_runtime.compare import compare
        from ezskiros_runtime.model import SkillModel
        before = (list(sys.path), list(sys.meta_path))
        legacy, migrated = warm_up()
        assert (list(sys.path), list(sys.meta_path)) == before
        assert not [n for n in sys.modules if "warm_up" in n or n.startswith("skiros2")]
        models = [SkillModel.from_json(o.models[0]) for o in (legacy, migrated)]
        print(json.dumps([legacy.status, migrated.status, len(legacy.models),
                          len(migrated.models), [str(d) for d in compare(*models)],
                          [c.obtained for c in legacy.compounds]]))
    """)
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=False)
    assert run.returncode == 0, run.stderr
    import json

    assert json.loads(run.stdout.strip().splitlines()[-1]) == ["ok", "ok", 1, 1, [], ["traced"]]
