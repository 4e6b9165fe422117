"""Property: outside the migrated code, every line of a generated module survives.

Modules mix legacy descriptions (some sharing a name, some decorated, with methods of
their own) with the shapes that once lost bytes (issue 20): functions and methods with
nested defs, decorators and form feeds at the start of their lines, implementation classes, ``class X(*SkillDescription)``, coding
cookies (latin-1, and utf-7 / raw-unicode-escape with escaped newlines inside a helper),
and tails after the last statement (blank and whitespace-only lines, form feeds,
commented-out code, no final newline).

The oracle is the generator's own: it knows which lines are the import statements, the
converted classes' headers and their ``createDescription`` with its trailing comments;
every other line, decoded as Python decodes the file, must be in the output in order.
Every description converts in one run, and a second run finds nothing left to do. The
test uses ``migrate`` alone, so it runs on the code from before issue 20 too (it failed
there on the end-of-file tails, the starred bases, the cookies and the repeated names).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from codemod_case import settings
from hypothesis import HealthCheck, given
from hypothesis import settings as hypothesis_settings
from hypothesis import strategies as st

from ezmigrate.codemod.migrate import migrate

EXAMPLES = 500
ESCAPED = "\u23ce"
"""Stands for a newline a utf-7 or raw-unicode-escape file writes as an escape."""
ESCAPES = {"utf-7": b"+AAo-", "raw_unicode_escape": b"\\u000a"}
COOKIES = (None, "utf-8", "latin-1", "utf-7", "raw_unicode_escape")
IMPORTS = ("from skiros2_common.core.abstract_skill import SkillDescription\n",
           "from skiros2_common.core.params import ParamTypes\n")
_LINE = re.compile(r"[^\r\n]*(?:\r\n|\n|\r)?")


@dataclass
class Module:
    """A generated module: its lines (decoded) and which of them a migration may change."""

    lines: list[str] = field(default_factory=list)
    protected: set[int] = field(default_factory=set)
    descriptions: int = 0
    cookie: str | None = None

    def add(self, text: str, protected: bool = False) -> None:
        for line in _LINE.findall(text):
            if not line:
                continue
            if self.lines and not self.lines[-1].endswith("\n"):
                self.lines[-1] += line  # "\f" and "def ...\n" make one line
            else:
                self.lines.append(line)
            if protected:
                self.protected.add(len(self.lines) - 1)

    def source(self) -> bytes:
        text = "".join(self.lines)
        if self.cookie in ESCAPES:
            # the decoded text has a newline where the file has an escape for one
            parts = text.split(f"{ESCAPED}\n")
            return ESCAPES[self.cookie].join(part.encode(self.cookie) for part in parts)
        return text.encode(self.cookie or "utf-8")

    def kept(self) -> list[str]:
        return [line.replace(ESCAPED, "") for n, line in enumerate(self.lines)
                if n not in self.protected]


SEPARATORS = st.sampled_from(["\n", "\n\n", "# note\n", "\f\n", "    \n", "\n\f\n\n",
                              "\n    \n    # a comment block\n    # of two lines\n"])
TAILS = st.lists(st.sampled_from(["\n", "    \n", "\f\n", "    # commented_out()\n",
                                  "# end\n", "\t\n"]), max_size=4)


@st.composite
def _description(draw: st.DrawFn, module: Module) -> bool:
    """A description class; True when its ``createDescription`` is its last statement
    (the lines after it, up to the next statement, are its trailing comments)."""
    name = draw(st.sampled_from(["Pick", "Place", "Pick"]))
    if draw(st.booleans()):
        module.add("@register\n")
    module.add(f"class {name}(SkillDescription):\n", protected=True)
    if draw(st.booleans()):
        module.add('    """A skill."""\n')
    if draw(st.booleans()):
        module.add(draw(st.sampled_from(["    ", "\f    "])) + "def helper(self):\n"
                   + draw(st.sampled_from(["        ", "\f        "])) + "return 1\n"
                   + draw(SEPARATORS).replace("# note", "    # note"))
    params = draw(st.integers(0, 3))
    body = "".join(f'        self.addParam("P{i}", {i}, ParamTypes.Required)\n'
                   for i in range(params)) or "        pass\n"
    trailing = draw(st.sampled_from(["", "        # trailing\n", "\n    # after\n"]))
    module.add("    def createDescription(self):\n" + body + trailing, protected=True)
    module.descriptions += 1
    if draw(st.booleans()):
        module.add(draw(st.sampled_from(["", "    @property\n", "    @property\n\f"]))
                   + "    def other(self):\n        x = 1\n\n"
                   + draw(st.sampled_from(["        ", "\f        "])) + "return x\n")
        return False
    return True


@st.composite
def _helper(draw: st.DrawFn, module: Module) -> None:
    escaped = ESCAPED if module.cookie in ESCAPES and draw(st.booleans()) else ""
    if draw(st.booleans()):
        module.add("@decorate\n" + draw(st.sampled_from(["", "\f"])))
    module.add(draw(st.sampled_from(["def", "async def"])) + " helper(a):" + escaped + "\n")
    if draw(st.booleans()):
        module.add("    def inner(b):\n        return b\n")
    module.add(draw(st.sampled_from(["    x = a\n", "\f    x = a\n", "    x = a\n\f\n"])))
    if draw(st.booleans()):
        module.add("    if x:\n" + draw(st.sampled_from(["        ", "\f        "]))
                   + "return 1\n")
    module.add("    return x" + draw(st.sampled_from(["\n", " \\\n# continued\n"])))


@st.composite
def _other(draw: st.DrawFn, module: Module) -> None:
    kind = draw(st.sampled_from(["implementation", "starred", "constant"]))
    if kind == "implementation":
        module.add("class Impl(PrimitiveBase):\n    def execute(self):\n"
                   + draw(st.sampled_from(["", "\f"])) + "        def inner():\n"
                   "            return 1\n\n        return inner()\n")
    elif kind == "starred":
        module.add("class Starred(*SkillDescription):\n    def createDescription(self):\n"
                   '        self.addParam("Q", 1, ParamTypes.Required)\n')
    else:
        module.add("CONSTANT = 1\n")


@st.composite
def modules(draw: st.DrawFn) -> Module:
    module = Module(cookie=draw(st.sampled_from(COOKIES)))
    if module.cookie is not None:
        module.add(f"# -*- coding: {module.cookie} -*-\n")
    if module.cookie == "latin-1":
        module.add("# Größe und Gewicht\n")
    for line in IMPORTS:
        module.add(line, protected=True)
    pieces = draw(st.lists(st.sampled_from(["description", "helper", "other"]),
                           min_size=1, max_size=6))
    if "description" not in pieces:
        pieces.append("description")
    create_last = False
    for piece in pieces:
        module.add(draw(SEPARATORS))
        if piece == "description":
            create_last = draw(_description(module))
        else:
            draw(_helper(module) if piece == "helper" else _other(module))
            create_last = False
    start = len(module.lines)
    for line in draw(TAILS):
        module.add(line, protected=create_last)  # a trailing comment of createDescription
    if draw(st.booleans()) and len(module.lines) > start \
            and module.lines[-1].endswith("\n") and module.lines[-1].strip():
        module.lines[-1] = module.lines[-1][:-1]  # no final newline
    return module


def _in_order(kept: list[str], lines: list[str]) -> str | None:
    """The first of ``kept`` not found in ``lines`` after the ones before it."""
    at = 0
    for line in kept:
        try:
            at = lines.index(line, at) + 1
        except ValueError:
            return line
    return None


@hypothesis_settings(max_examples=EXAMPLES, deadline=None, database=None,
                     suppress_health_check=[HealthCheck.too_slow])
@given(modules())
def test_every_line_outside_the_migration_survives(module: Module) -> None:
    source = module.source()
    result = migrate(source, settings(), "generated.py")
    assert result.error is None, result.error
    assert result.count("converted") == module.descriptions, [
        (s.name, s.status, s.reason) for s in result.skills]
    assert isinstance(result.new_source, bytes)
    encoding = module.cookie or "utf-8"
    new_lines = [line for line in _LINE.findall(result.new_source.decode(encoding)) if line]
    lost = _in_order(module.kept(), new_lines)
    assert lost is None, f"lost or moved: {lost!r}"
    again = migrate(result.new_source, settings(), "generated.py")
    assert again.new_source is None and not again.skills, [
        (s.name, s.status) for s in again.skills]
