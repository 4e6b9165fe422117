"""``recover_classes`` reads the classes of a module ``ast`` cannot parse from its tokens
(``tokenize``): the classes of every Python file of the fixtures and the tests are those
``ast`` finds at the top level, and Python 2 shapes give their classes, or None where the
tokens stop short of the end."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from ezmigrate.compound.repository import recover_classes

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


EXPECTED: dict[str, list[tuple[str, int, str | None]] | None] = {
    "print statements": [("Pick", 1, None)],
    "except with a comma": [("pick", 1, "Pick")],
    "a backtick": [("A", 1, None)],
    "a dedent to nowhere, a class after": None,
    "a dollar sign, a class after": [("B", 2, None)],
    "a class named in a string": [],
    "latin-1 with its cookie": [("A", 2, None)],
}
"""What tokenize's tokens give (None: they stop short of the end, so nothing is known)."""


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_python2_shapes_give_their_classes(name: str) -> None:
    encoding = "latin-1" if "latin-1" in name else "utf-8"
    assert recover_classes(PYTHON2[name].encode(encoding)) == EXPECTED[name]


@pytest.mark.parametrize("name", sorted(set(PYTHON2) - set(EXPECTED)))
def test_every_python2_shape_is_read_without_an_error(name: str) -> None:
    found = recover_classes(PYTHON2[name].encode())
    assert found is None or all(isinstance(c[0], str) for c in found)


def _described(node: ast.ClassDef) -> bool:
    """A class ``recover_classes`` keeps: one naming ``createDescription`` or
    ``setDescription`` (a description or an implementation)."""
    return any((isinstance(n, ast.FunctionDef) and n.name == "createDescription")
               or (isinstance(n, ast.Attribute) and n.attr in ("createDescription",
                                                                "setDescription"))
               for n in ast.walk(node))


def test_every_module_of_the_project_gives_its_top_level_classes() -> None:
    assert len(MODULES) > 200
    differ = []
    for path in MODULES:
        data = path.read_bytes()
        try:
            tree = ast.parse(data)
        except (SyntaxError, ValueError):
            continue
        found = recover_classes(data)
        names = [node.name for node in tree.body
                 if isinstance(node, ast.ClassDef) and _described(node)]
        if found is not None and [c[0] for c in found] != names:
            differ.append(path)
    assert differ == []
