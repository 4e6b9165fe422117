"""EZ105 (an Inferred parameter no pre-condition mentions) judged by what the repository says.

SkiROS2 grounds such a parameter by its type alone (``NodeExecutor._autoParametrizeWm`` takes
the first match), and only when the blackboard left it unset (``skill_utils._ground``). That
grounds the wrong element only when three things hold, so the finding is a warning only
then, and info otherwise, saying which one failed (issue 30):

- something reads the parameter: an implementation of the description names the key (its
  ``self.params[...]``, a child it passes the key to);
- a run can leave it unset: not every parent tree that runs the skill passes a value
  (``specify``, a ``remap`` of the key, or a parameter of the same key on the parent,
  which shares the blackboard);
- the choice is real: the run's scenes, when there are any, hold two or more elements of
  the parameter's class (a robot's one gripper is the right one).

The same facts judge EZ209 on a parameter's class: a class no ontology defines matters only
when SkiROS2 grounds the parameter, which it never does when every tree passes a value.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from dataclasses import replace
from typing import TYPE_CHECKING

from ezskiros_runtime.codes import code_for

from ..lint.diagnostic import Diagnostic

if TYPE_CHECKING:  # the compound library: not for the codes alone (``check.needs_trees``)
    from ezskiros_runtime.compound.library import SkillIndex
    from ezskiros_runtime.compound.model import CompoundModel

    from .implementation_code import ModuleFacts

UNINFERABLE = code_for("uninferable")
UNKNOWN = code_for("unknown-vocabulary")


def keys_read(modules: Iterable[ModuleFacts]) -> dict[str, set[str]]:
    """``{description: every string literal in its implementations' bodies}``: a superset
    of the keys they read or pass on, enough to tell a key nothing names."""
    found: dict[str, set[str]] = {}
    for module in modules:
        for cls in module.classes:
            found.setdefault(cls.description, set()).update(cls.strings)
    return found


def keys_passed(models: Iterable[CompoundModel], skills: SkillIndex
                ) -> dict[str, dict[str, bool]]:
    """``{child description: {key: whether every node of it passes a value}}`` over the
    compound trees: a node passes ``key`` when it specifies or remaps it, or when its
    parent's description declares it (the blackboard hands it down)."""
    from ezskiros_runtime.compound.library import type_name
    from ezskiros_runtime.compound.model import ProcessorNode, SkillNode

    passed: dict[str, dict[str, bool]] = {}

    def visit(nodes: Iterable[object], parent_keys: set[str]) -> None:
        for node in nodes:
            if isinstance(node, SkillNode):
                child = skills.descriptions.get(type_name(node.type))
                if child is not None:
                    given = {k for k, _ in node.specify} | {k for k, _ in node.remap}
                    mine = passed.setdefault(child.name, {})
                    for key in child.params:
                        mine[key] = mine.get(key, True) and (key in given
                                                            or key in parent_keys)
                visit(node.children, parent_keys)
            elif isinstance(node, ProcessorNode):
                visit(node.children, parent_keys)

    for model in models:
        parent = skills.descriptions.get(model.description or "")
        visit(model.children, set(parent.params) if parent is not None else set())
    return passed


def judge(diagnostics: Sequence[Diagnostic], read: dict[str, set[str]],
          passed: dict[str, dict[str, bool]],
          elements_of: Callable[[str], int | None],
          misspelt: Callable[[str], bool] = lambda _term: False) -> list[Diagnostic]:
    """``diagnostics`` with each EZ105 kept a warning or lowered to info, as the module
    doc says; ``elements_of(class)`` is the number of elements of that class the run's
    scenes hold (None: no scene); ``misspelt(term)``: the unknown class is one edit from a
    known one of its loaded namespace, a typo, which stays a warning even where every tree
    passes a value (the task planner types the parameter by its class, and the GUI lists
    no element for it)."""
    out = []
    for d in diagnostics:
        if d.code == UNKNOWN and d.term_is_class and d.param and d.severity == "warning" \
                and passed.get(d.skill, {}).get(d.param, False) \
                and not (d.term is not None and misspelt(d.term)):
            # SkiROS2 matches a class only to ground a parameter; one every tree passes a
            # value to is never grounded, so its unknown class changes nothing at run time
            out.append(replace(d, severity="info", message=f"{d.message}; info: every tree "
                                                           "that runs it passes a value"))
            continue
        if d.code != UNINFERABLE or d.severity != "warning" or not d.param:
            out.append(d)
            continue
        why = None
        if d.param not in read.get(d.skill, set()):
            why = "no implementation of it in the repository reads it"
        elif passed.get(d.skill, {}).get(d.param, False):
            why = "every tree that runs it passes a value"
        elif d.term is not None:
            count = elements_of(d.term)
            if count is not None and count < 2:
                why = f"the scenes hold {count} element(s) of {d.term}"
        out.append(d if why is None else
                   replace(d, severity="info", message=f"{d.message}; info: {why}"))
    return out
