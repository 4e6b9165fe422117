"""``recover_classes`` reads the classes of a module ``ast`` cannot parse from its tokens;
under Python 3.11 from the C tokenizer (``c_tokens``) where it stands in for ``tokenize``,
else from ``tokenize`` (``python_tokens``). Whichever reads a module, the classes are the
same: held on every Python file of the fixtures and the tests, and on Python 2 shapes on
both sides of where the C tokenizer gives up."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from ezmigrate.compound import repository
from ezmigrate.compound.repository import c_tokens, python_tokens, recover_classes

ROOT = Path(__file__).resolve().parents[2]
MODULES = sorted(p for folder in ("fixtures", "tests") for p in (ROOT / folder).rglob("*.py"))

PYTHON2 = {
    "print statements": 'class Pick(SkillDescription):\n    def createDescription(self):\n'
                        '        print "x"\n',
    "except with a comma": "class pick(SkillBase):\n    def createDescription(self):\n"
                           "        self.setDescription(Pick(), 'pick')\n"
                           "    def run(self):\n        try:\n            pass\n"
                           "        except Exception, e:\n            pass\n",
    "a backtick": "class A(SkillDescription):\n    def createDescription(self):\n"
                  "        x = `1`\n",
    "an octal literal": "class A(SkillDescription):\n    def createDescription(self):\n"
                        "        os.chmod(p, 0755)\n",
    "a long literal": "class A(SkillDescription):\n    def createDescription(self):\n"
                      "        n = 10L\n",
    "a bracket open at the end": "class A(SkillDescription):\n"
                                 "    def createDescription(self):\n        f(\n",
    "a bracket open at the end, no class": "print 'x'\nf(\n",
    "a string open at the end": 'class A(SkillDescription):\n    """never closed\n',
    "a dedent to nowhere": "class A(SkillDescription):\n        def createDescription(self):\n"
                           "            pass\n      print 1\nclass B(SkillDescription):\n"
                           "    def createDescription(self):\n        pass\n",
    "a dedent to nowhere, a class after": "x = 1\nif x:\n        y = 2\n    z = 3\n"
                                          "class B(SkillDescription):\n"
                                          "    def createDescription(self):\n"
                                          "        pass\n",
    "a dollar sign, a class after": "x = $y\nclass B(SkillDescription):\n"
                                    "    def createDescription(self):\n        pass\n",
    "a dollar sign": "class A(SkillDescription):\n    def createDescription(self):\n"
                     "        x = $y\n",
    "a class named in a string": "s = '''\nclass Fake(SkillDescription):\n'''\nprint s\n",
    "latin-1 with its cookie": "# -*- coding: latin-1 -*-\nclass A(SkillDescription):\n"
                               "    def createDescription(self):\n        print 'caf\xe9'\n",
}


def _by_tokenize(data: bytes, monkeypatch: pytest.MonkeyPatch) -> object:
    monkeypatch.setattr(repository, "c_tokens", lambda _data: None)
    try:
        return recover_classes(data)
    finally:
        monkeypatch.undo()


@pytest.mark.parametrize("name", PYTHON2)
def test_python2_shapes_are_read_alike(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    encoding = "latin-1" if "latin-1" in name else "utf-8"
    data = PYTHON2[name].encode(encoding)
    assert recover_classes(data) == _by_tokenize(data, monkeypatch)


def test_every_module_of_the_project_is_read_alike(monkeypatch: pytest.MonkeyPatch) -> None:
    assert len(MODULES) > 200
    differ = [p for p in MODULES if recover_classes(p.read_bytes())
              != _by_tokenize(p.read_bytes(), monkeypatch)]
    assert differ == []


@pytest.mark.skipif(sys.version_info[:2] != (3, 11), reason="the C tokenizer's API is 3.11's")
def test_the_c_tokenizer_reads_most_modules_and_gives_way_where_it_must() -> None:
    read = [p for p in MODULES if c_tokens(p.read_bytes()) is not None]
    assert len(read) > len(MODULES) * 0.9  # else the fast path would be dead code
    for name in ("an octal literal", "a long literal", "a bracket open at the end",
                 "a string open at the end", "a dedent to nowhere",
                 "a dedent to nowhere, a class after"):  # refused, or read short
        assert c_tokens(PYTHON2[name].encode()) is None, name
    assert recover_classes(PYTHON2["a dedent to nowhere, a class after"].encode()) is None
    assert recover_classes(PYTHON2["a dollar sign, a class after"].encode()) == [
        ("B", 2, None)]  # read on past the error token, as tokenize does
    names = [s for s, kind, _, _ in c_tokens(PYTHON2["print statements"].encode()) or ()
             if kind == 1]
    assert names == [s for s, kind, _, _ in python_tokens(PYTHON2["print statements"].encode())
                     if kind == 1]
    assert recover_classes(PYTHON2["except with a comma"].encode()) == [("pick", 1, "Pick")]
