"""Wrong uses of the DSL fail at once with a ``DescriptionError`` that says what to write."""

from __future__ import annotations

import re

import pytest
from dsl_support import paper  # noqa: F401 - paper is a fixture

from ezskiros_runtime import (
    INFERRED,
    KEY,
    OPTIONAL,
    DescriptionError,
    Lock,
    SkillDescription,
    abstract,
    any_of,
    check,
)
from ezskiros_runtime.ontology import skiros

pytestmark = pytest.mark.usefixtures("paper")


def build(body: str) -> type:
    """A skill over A: Location, B: Product whose description body is ``body``."""
    namespace = {"SkillDescription": SkillDescription, "skiros": skiros, "abstract": abstract,
                 "any_of": any_of}
    exec("class Skill(SkillDescription):\n"
         "    def description(self, A: skiros.Location, B: skiros.Product):\n"
         f"        {body}\n", namespace)
    return namespace["Skill"]  # type: ignore[return-value]


@pytest.mark.parametrize(("body", "message"), [
    ("self.pre_conditions += ~ B.is_a(skiros.Product)", "~ on is_a"),
    ("self.pre_conditions += (A.contain(B) | A.contain(B)).named('x')",
     'or-conditions are always labelled "or"'),
    ("self.pre_conditions += A.PositionX != 1.0", "write ~ (A.prop == value)"),
    ("self.pre_conditions += A.contain('B')", "needs a parameter as its object"),
    ("self.pre_conditions += A.PositionX == B", "compare with a literal value"),
    ("self.pre_conditions += A.PositionX.ne(1.0)", "write ~ A.prop.eq(value)"),
    ("self.pre_conditions += A.PositionX.gt(B)", "compare with a literal value"),
    ("self.pre_conditions += A.PositionX", "takes conditions (A.contain(B)"),
    ("self.pre_conditions += abstract(B.is_specified())", "abstract(...) needs a relation"),
    ("self.pre_conditions += any_of(A.contain(B), 'x')", "any_of(...) takes conditions"),
    ("self.pre_conditions += A.has(3)", "has(...) needs a vocabulary name"),
    ("self.pre_conditions += 'A contains B'", "takes conditions"),
    ("self.pre_conditions = [A.contain(B)]", "cannot be assigned"),
    ("self.pre_conditions += A.contain(B) if A.contain(B) else B.generated()",
     "no truth value"),
    ("self.pre_conditions += A.contain(B) if A else B.generated()", "no truth value"),
    ("A.x = 1", "cannot be assigned"),
    ("self.pre_conditions += A.named('x')", ".named(...) applies to conditions"),
])
def test_misuse_in_the_body_is_a_description_error(body, message):
    with pytest.raises(DescriptionError, match=re.escape(message)):
        build(body)()


@pytest.mark.parametrize(("make", "message"), [
    (lambda: OPTIONAL["m/s"], "the first item must be the type"),
    (lambda: OPTIONAL[float, "a", "b"], "two descriptions"),
    (lambda: OPTIONAL[float, KEY("a"), KEY("b")], "two KEY"),
    (lambda: INFERRED[skiros.Product, 3], "unexpected item 3"),
    (lambda: INFERRED[Lock], "the first item must be the type"),
    (lambda: KEY(3), "KEY(...) needs a str"),
])
def test_malformed_markers_fail_where_they_are_written(make, message):
    with pytest.raises(DescriptionError, match=re.escape(message)):
        make()


def test_a_bare_marker_without_default_and_a_non_type_are_rejected():
    class Bare(SkillDescription):
        def description(self, S: OPTIONAL):
            pass

    class NotAType(SkillDescription):
        def description(self, S: OPTIONAL[3.5]):
            pass

    with pytest.raises(DescriptionError, match="needs a default value"):
        Bare()
    with pytest.raises(DescriptionError, match=r"3\.5 is not a type"):
        NotAType()
    (finding,) = check(Bare)
    assert (finding.kind, finding.severity, finding.skill) == ("description", "error", "Bare")
    assert "OPTIONAL[float]" in finding.message
