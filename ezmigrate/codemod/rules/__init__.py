"""One module per legacy construct family, and the table that puts their rules in order.

The first statement rule that claims a statement handles it, so the order below is part of
the meaning: a condition added to a list before a parameter, a kept statement before a
local, and ``unsupported`` (the catch-all that explains why a statement cannot be
translated) asked last by construction. A new construct is a module here, its entries in
``CONSTRUCTS``, and a test module in ``tests/codemod``. Emitters and replayers of condition kinds
register themselves with decorators next to the rule that reads the kind: order does not
matter there.
"""

from ..core.registry import CONDITION_EMITTERS, CONDITION_REPLAYERS, RuleTable
from . import (
    add_param,
    condition_factories,
    condition_lists,
    condition_statements,
    constant_loops,
    kept_statements,
    local_variables,
    or_conditions,
    parent_calls,
    unsupported,
)

CONSTRUCTS = RuleTable(
    statements=(
        condition_lists.add_condition,
        add_param.add_param,
        kept_statements.kept_statement,
        local_variables.local_assignment,
        or_conditions.add_child,
        parent_calls.parent_call,
    ),
    fallback=unsupported.unsupported,
    conditions=(condition_factories.factory_condition, or_conditions.or_condition),
    compound_rules=(constant_loops.constant_loop,),
    read_passes=(local_variables.drop_dead_literal_locals,),
    param_annotation=add_param.annotation,
    condition_statement=condition_statements.condition_statement,
    condition_emitters=CONDITION_EMITTERS,
    condition_replayers=CONDITION_REPLAYERS,
)

__all__ = ["CONSTRUCTS"]
