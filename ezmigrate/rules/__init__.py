"""One module per legacy construct family; importing this package registers them all.

Order matters for statement rules: the first rule that claims a statement handles it, and
``unsupported`` (the catch-all that explains why a statement cannot be translated) is last.
"""

from . import (  # noqa: F401  (imported for registration)
    add_param,
    condition_factories,
    or_conditions,
    condition_lists,
    local_variables,
    parent_calls,
    kept_statements,
    unsupported,
)
