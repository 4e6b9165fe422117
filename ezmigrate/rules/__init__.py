"""One module per legacy construct family; importing this package registers them all.

Order matters for statement rules: the first rule that claims a statement handles it, and
``unsupported`` (the catch-all that explains why a statement cannot be translated) is last.
"""

from . import (  # noqa: F401  (imported for registration)
    add_param,
    condition_factories,
    condition_lists,
    kept_statements,
    local_variables,
    or_conditions,
    parent_calls,
    unsupported,
)
