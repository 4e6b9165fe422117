"""The rule table: explicit order, the catch-all last, every rule module in it, and the core
never importing a rule (the table reaches it through the contexts)."""

from __future__ import annotations

import ast
import inspect
import pkgutil
from pathlib import Path

import pytest

import ezmigrate.codemod.rules
from ezmigrate.codemod.core.registry import CONDITION_EMITTERS, CONDITION_REPLAYERS, RuleTable
from ezmigrate.codemod.migrate import migrate
from ezmigrate.codemod.rules import CONSTRUCTS, unsupported

CORE = Path(ezmigrate.codemod.rules.__file__).parents[1] / "core"


def _functions(table: RuleTable) -> set[object]:
    return {*table.statement_rules, *table.conditions, *table.compound_rules, *table.read_passes,
            table.param_annotation, table.condition_statement,
            *table.condition_emitters.values(), *table.condition_replayers.values()}


def test_the_catch_all_is_asked_last_whatever_the_statements_are() -> None:
    assert CONSTRUCTS.statement_rules[-1] is unsupported.unsupported
    assert unsupported.unsupported not in CONSTRUCTS.statements
    shuffled = RuleTable(**{**vars(CONSTRUCTS), "statements": tuple(reversed(CONSTRUCTS.statements))})
    assert shuffled.statement_rules[-1] is unsupported.unsupported


def test_every_rule_module_has_its_rules_in_the_table() -> None:
    table = _functions(CONSTRUCTS)
    modules = [name for _, name, _ in pkgutil.iter_modules(ezmigrate.codemod.rules.__path__)]
    assert len(modules) >= 8
    for name in modules:
        module = getattr(ezmigrate.codemod.rules, name)
        own = {f for f in vars(module).values()
               if inspect.isfunction(f) and f.__module__ == module.__name__}
        assert own & table, f"rules/{name}.py contributes nothing to the rule table"


def test_every_condition_kind_is_written_and_replayed() -> None:
    assert set(CONDITION_EMITTERS) == set(CONDITION_REPLAYERS)
    assert {"relation", "property", "has_property", "is_specified", "generate", "on_type",
            "abstract_relation", "or"} <= set(CONDITION_REPLAYERS)


@pytest.mark.parametrize("path", sorted(CORE.glob("*.py")), ids=lambda p: p.name)
def test_the_core_never_imports_a_rule(path: Path) -> None:
    for node in ast.walk(ast.parse(path.read_bytes())):
        if isinstance(node, ast.ImportFrom):
            source = "." * node.level + (node.module or "")
            assert not source.startswith("..rules") and "ezmigrate.codemod.rules" not in source, (
                f"{path.name}:{node.lineno} imports {source}")


def test_the_table_is_what_the_migration_asks(monkeypatch: pytest.MonkeyPatch) -> None:
    source = """\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_common.core.params import ParamTypes


class S(SkillDescription):
    def createDescription(self):
        self.addParam("A", 1.0, ParamTypes.Optional)
"""
    assert migrate(source).skills[0].status == "converted"
    without_params = RuleTable(**{**vars(CONSTRUCTS), "statements": tuple(
        rule for rule in CONSTRUCTS.statements if rule.__name__ != "add_param")})
    monkeypatch.setattr("ezmigrate.codemod.migrate.CONSTRUCTS", without_params)
    [skill] = migrate(source).skills
    assert skill.status == "skipped"
    assert skill.reason is not None and "self.addParam(...) at line 7" in skill.reason
