"""``lint/newer_fstrings.py``: Python 3.12's f-strings respelt for an older ``ast``.

Three oracles: Python 3.12 itself (the respelt bytes give it the tree the original gives
it, node for node and position for position: the swap changed nothing it reads), this
Python (it parses the respelt bytes), and the codemod (libcst, on the original bytes):
``check`` reports of such a file exactly what the codemod's reading makes it report.
"""

from __future__ import annotations

import ast
import json
import random
import subprocess
import sys
from pathlib import Path

import pytest

from ezmigrate.checking import file_facts
from ezmigrate.checking.pipeline import run_check
from ezmigrate.files.discover import Candidate
from ezmigrate.lint.newer_fstrings import older_spelling
from ezmigrate.lint.plain_reader import Declined
from ezmigrate.report.results import FileResult
from ezmigrate.verify.interpreters import find_python
from ezmigrate.verify.pool import PoolConfig
from ezskiros_runtime.ontology.index import bundled_ontology_path
from ezskiros_runtime.ontology.load import load_index

PAIRS = [
    (b'x = f"{d["k"]}"\n', b"x = f\"{d['k']}\"\n"),
    (b"x = f'{d['k']}'\n", b"x = f'{d[\"k\"]}'\n"),
    (b'x = f"a {d["k"]!r:>{w}} b"\n', b"x = f\"a {d['k']!r:>{w}} b\"\n"),
    (b'x = rf"{d["k"]}\\d"\n', b"x = rf\"{d['k']}\\d\"\n"),
    (b'x = F"{"-".join(xs)}"\n', b"x = F\"{'-'.join(xs)}\"\n"),
    (b'x = f"""{d["k"]}\n{e["q"]}"""\n', b"x = f\"\"\"{d['k']}\n{e['q']}\"\"\"\n"),
    (b'x = f"{ {"a": 1}["a"] }"\n', b"x = f\"{ {'a': 1}['a'] }\"\n"),
    (b'# f"{d["k"]}" in a comment\nx = f"{d["k"]}"\n',
     b'# f"{d["k"]}" in a comment\nx = f"{d[\'k\']}"\n'),
    (b's = "f{"\nx = f"{d["k"]}"  # \xc3\xa9\n', b's = "f{"\nx = f"{d[\'k\']}"  # \xc3\xa9\n'),
]

NOTHING_TO_DO = [
    b'x = f"{d[\'k\']}"\n',  # any Python reads it
    b"x = 1\n",
    b'x = "{d["k"]}"\n',  # not an f-string: no swap makes it Python
]

MORE_THAN_A_SWAP = [
    b'x = f"{d["it\'s"]}"\n',  # the other quote inside
    b'x = f"{d["a\\tb"]}"\n',  # a backslash in a field
    b'x = f"{f"{y}"}"\n',  # an f-string reusing the quote
    b'x = f"{d["k"]  # why\n}"\n',  # a comment in a field
    b'x = f"{d["""k"""]}"\n',  # a triple-quoted string reusing the quote
    b"x = f'{d[\"k\"] + f\"{e['q']}\"}'\n",  # both quotes around
    b'# -*- coding: latin-1 -*-\nx = f"{d["\xe9"]}"\n',  # bytes are not the text
    b'x = f"{d["k"]\n',  # unterminated
]


@pytest.mark.parametrize(("before", "after"), PAIRS)
def test_nested_strings_reusing_the_quote_are_swapped(before: bytes, after: bytes) -> None:
    assert older_spelling(before) == after
    ast.parse(after)


@pytest.mark.parametrize("data", NOTHING_TO_DO + MORE_THAN_A_SWAP)
def test_anything_else_is_left_alone(data: bytes) -> None:
    assert older_spelling(data) is None


KEYS = ['"k"', "'k'", '"a b"', "0", '"x:y"']
FIELDS = ["d[{key}]", "d.get({key}, {key})", "{key}.join(xs)", "f(a={key})[0]",
          " {{{key}: 1}}[{key}]", "xs[{key}]!r", "v:>{{w}}", "v!s:^10", "m[{key}]:{{w}}.2f",
          "(lambda q: q)({key})", "a if b else {key}"]


def _random_module(chance: random.Random) -> bytes:
    lines = []
    for number in range(chance.randint(1, 6)):
        quote = chance.choice(['"', "'", '"""'])
        prefix = chance.choice(["f", "F", "rf", "fR"])
        parts = []
        for _ in range(chance.randint(1, 3)):
            piece = chance.choice(FIELDS).format(key=chance.choice(KEYS))
            parts.append(chance.choice(["", "text ", "{{braces}} ", "\\N{EM DASH} "]) +
                         "{" + piece + "}")
        body = "".join(parts)
        if "\\N" in body and "r" in prefix.lower():
            body = body.replace("\\N{EM DASH} ", "")
        lines.append(f"v{number} = {prefix}{quote}{body}{quote}")
    return ("\n".join(lines) + "\n").encode()


def _cases() -> list[bytes]:
    chance = random.Random(31)
    return [before for before, _ in PAIRS] + [_random_module(chance) for _ in range(400)]


def test_python_3_12_reads_the_respelt_bytes_as_it_reads_the_original() -> None:
    python = find_python("3.12")
    if python is None:
        pytest.skip("no Python 3.12 on PATH or in pyenv's versions folder")
    pairs = [(before, older_spelling(before)) for before in _cases()]
    respelt = [(b.decode(), a.decode()) for b, a in pairs if a is not None]
    script = ("import ast, json, sys\n"
              "dump = lambda s: ast.dump(ast.parse(s), include_attributes=True)\n"
              "for old, new in json.load(sys.stdin):\n"
              "    try:\n"
              "        ast.parse(old)\n"
              "    except SyntaxError:\n"
              "        print('invalid')  # the generator's mistake, not Python 3.12\n"
              "        continue\n"
              "    print('same' if dump(old) == dump(new) else 'differs')\n")
    answers = subprocess.run([python, "-c", script], input=json.dumps(respelt), text=True,
                             capture_output=True, check=True).stdout.split()
    assert len(answers) == len(respelt)
    assert [r for r, a in zip(respelt, answers, strict=True) if a == "differs"] == []
    same = [new for (_, new), a in zip(respelt, answers, strict=True) if a == "same"]
    assert len(same) >= 250  # the generator reaches the swaps, not only the give-ups
    for new in same:
        ast.parse(new)  # and this Python reads them


HEADER = """\
from skiros2_common.core.abstract_skill import SkillDescription, SkillBase
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element

LABELS = {"speed": "m/s"}
BANNER = f"speed in {LABELS["speed"]}"
"""

SKILLS = HEADER + """
class Pick(SkillDescription):
    def createDescription(self):
        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)
        self.addParam("Speed", 0.5, ParamTypes.Optional)
        self.addParam("Place", Element("skiros:Location"), ParamTypes.Required)
        self.addParam("Place", Element("skiros:Location"), ParamTypes.Optional)


class pick(SkillBase):
    def createDescription(self):
        self.setDescription(Pick(), "pick")

    def execute(self):
        return self.success(f"Picked {self.params["Object"].value.label}")
"""

IN_THE_DESCRIPTION = SKILLS.replace('self.addParam("Speed", 0.5',
                                    'self.addParam(f"{LABELS["speed"]}", 0.5')


@pytest.mark.parametrize(("source", "plain"), [(SKILLS, True), (IN_THE_DESCRIPTION, False)])
def test_check_reports_of_such_a_file_what_the_codemod_makes_it_report(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch, source: str, plain: bool) -> None:
    path = tmp_path / "skills.py"
    path.write_text(source)
    data = path.read_bytes()
    if sys.version_info < (3, 12):  # this Python refuses the file: the respelling reads it
        facts = file_facts.file_facts(Candidate(path, tmp_path), data, True)
        assert isinstance(facts.static, FileResult) is plain
    index = load_index([bundled_ontology_path()])
    fast = run_check([tmp_path], index, PoolConfig(workers=1))
    monkeypatch.setattr(file_facts, "read_plain", lambda data, path, tree=None: Declined())
    slow = run_check([tmp_path], index, PoolConfig(workers=1))
    assert [str(d) for d in fast.diagnostics] == [str(d) for d in slow.diagnostics]
    assert fast.skills == slow.skills == 1
    said = "addParam('Place')" if plain else "Pick"  # a duplicate parameter, or the kept skill
    assert any(said in str(d) for d in fast.diagnostics), [str(d) for d in fast.diagnostics]
