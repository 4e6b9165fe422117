"""Static reading and tracing give the same model of any tree (hypothesis).

Random trees (skill nodes with labels, remaps and specifies, literal or read from
``self.params``; processor nodes, wrapped ones; nodes called with children; now and then a
``self.setProcessor`` line, which sets the instance's processor and not the tree's) are
written as the ``expand`` of a real legacy module. The static reader (``ezmigrate.compound.static``)
reads the syntax; the tracer runs the same module through the real legacy loader with
``trace=`` (as the sandbox child does). Both must equal the generated model, and each
other. A second spelling builds the same tree through a local list, which only tracing can
read, so that the tracer is held to the generated model on its own as well.
"""

from __future__ import annotations

import ast
from pathlib import Path
from typing import Any

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from ezmigrate.compound.static import NeedsTrace, read_compounds
from ezskiros_runtime.compound.model import (
    CompoundModel,
    ProcessorNode,
    SkillNode,
    model_from_json,
)
from ezskiros_runtime.legacy.loader import load_bytes

HEADER = """\
from skiros2_common.core.abstract_skill import SkillDescription
from skiros2_skill.core.skill import (NoFail, ParallelFf, ParallelFs, Selector, SelectorStar,
                                      Sequential, Serial, SerialStar, SkillBase)


class Task(SkillDescription):
    def createDescription(self):
        pass


class task_tree(SkillBase):
    def createDescription(self):
        self.setDescription(Task(), self.__class__.__name__)

    def expand(self, skill):
"""
PROCESSORS = ["Sequential", "SerialStar", "Serial", "Selector", "SelectorStar", "ParallelFf",
              "ParallelFs", "NoFail(Sequential)", "NoFail(ParallelFs)"]
KEYS = st.sampled_from(["Target", "Object", "Arm", "Duration", "Gripper", "On/Off", "x"])
VALUES = st.one_of(st.integers(-5, 5), st.floats(-2, 2, allow_nan=False).map(lambda f: round(f, 3)),
                   st.booleans(), st.text("abc:", max_size=6), st.none(),
                   st.sampled_from(["P1", "P2"]).map(lambda k: {"param": k}))


def _pairs(values: st.SearchStrategy[Any]) -> st.SearchStrategy[tuple[tuple[str, Any], ...]]:
    return st.dictionaries(KEYS, values, max_size=3).map(lambda d: tuple(d.items()))


skill_nodes = st.builds(
    SkillNode, st.sampled_from(["Navigate", "Pick", "skiros:Wait", "Place.*", "Locate"]),
    st.sampled_from(["", "impl_a", "impl_b"]), _pairs(KEYS), _pairs(VALUES))


def _trees(leaves: st.SearchStrategy[Any]) -> st.SearchStrategy[Any]:
    return st.one_of(
        st.builds(ProcessorNode, st.sampled_from(PROCESSORS),
                  st.lists(leaves, max_size=3).map(tuple), _pairs(KEYS)),
        st.builds(lambda n, c: SkillNode(n.type, n.label, n.remap, n.specify, (), tuple(c)),
                  skill_nodes, st.lists(leaves, min_size=1, max_size=2)))


trees = st.recursive(skill_nodes, _trees, max_leaves=8)
models = st.builds(lambda p, c: CompoundModel("task_tree", "Task", "task_tree", p, tuple(c)),
                   st.sampled_from(PROCESSORS), st.lists(trees, max_size=4))


def _value(value: Any) -> str:
    if isinstance(value, dict):
        return f"self.params[{value['param']!r}].value"
    return repr(value)


def _processor(name: str) -> str:
    outer, _, inner = name.partition("(")
    return f"{outer}({inner.rstrip(')')}())" if inner else f"{outer}()"


def _node(node: Any) -> str:
    if isinstance(node, ProcessorNode):
        head = f"self.skill({_processor(node.processor)}"
        head += f", remap={dict(node.remap)!r})" if node.remap else ")"
    else:
        args = [repr(node.type), repr(node.label)]
        if node.remap:
            args.append(f"remap={dict(node.remap)!r}")
        if node.specify:
            args.append("specify={" + ", ".join(f"{k!r}: {_value(v)}" for k, v in node.specify)
                        + "}")
        head = f"self.skill({', '.join(args)})"
    if node.children:
        return head + "(" + ", ".join(_node(c) for c in node.children) + ")"
    return head


def source_of(model: CompoundModel, through_a_list: bool = False,
              instance: tuple[int, str] | None = None) -> str:
    """``expand`` building ``model``; ``instance``: where a ``self.setProcessor`` line goes
    and what it sets (the skill instance's processor, which the tree does not take)."""
    lines = [f"skill.setProcessor({_processor(model.processor)})"]
    children = [_node(c) for c in model.children]
    if through_a_list:  # static reading gives up on this; only tracing reads it
        lines += ["nodes = []"] + [f"nodes.append({c})" for c in children] + ["skill(*nodes)"]
    else:
        lines += [f"skill({c})" for c in children]
    if instance is not None:
        at, processor = instance
        lines.insert(min(at, len(lines)), f"self.setProcessor({_processor(processor)})")
    return HEADER + "".join(f"        {line}\n" for line in lines)


def _traced(source: str, folder: Path) -> CompoundModel:
    path = folder / "tree.py"
    path.write_text(source, encoding="utf-8")
    [data] = load_bytes(source.encode(), path, trace=["task_tree"]).compounds
    assert "unanalysable" not in data, data
    return model_from_json(data)


@settings(max_examples=150, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(model=models, instance=st.one_of(st.none(), st.tuples(st.integers(0, 5),
                                                           st.sampled_from(PROCESSORS))))
def test_static_and_traced_models_are_the_generated_one(
        model: CompoundModel, instance: tuple[int, str] | None, tmp_path: Path) -> None:
    source = source_of(model, instance=instance)
    [static] = read_compounds(ast.parse(source), "tree.py")
    assert isinstance(static, CompoundModel), static
    traced = _traced(source, tmp_path)
    assert static.canonical_json() == model.canonical_json()
    assert traced.canonical_json() == model.canonical_json()
    assert static == traced == model
    assert (static.obtained, traced.obtained) == ("static", "traced")


@settings(max_examples=60, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(model=models.filter(lambda m: bool(m.children)))
def test_a_tree_only_tracing_can_read_is_traced_right(model: CompoundModel,
                                                      tmp_path: Path) -> None:
    source = source_of(model, through_a_list=True)
    [static] = read_compounds(ast.parse(source), "tree.py")
    assert isinstance(static, NeedsTrace)
    assert _traced(source, tmp_path) == model


def test_the_json_form_round_trips_and_ignores_positions() -> None:
    model = CompoundModel("t", "Task", "t", "SerialStar", (
        SkillNode("Wait", "", (), (("Duration", {"param": "Pause"}),), line=4),
        ProcessorNode("ParallelFs", (SkillNode("Pick", "impl", (("Object", "Part"),), line=6),),
                      line=5)), path="a.py", line=2, expand_line=3)
    assert model_from_json(model.to_json()) == model
    moved = model_from_json({**model.to_json(), "line": 40, "path": "b.py"})
    assert moved == model and moved.canonical_json() == model.canonical_json()
    other = CompoundModel("t", "Task", "t", "Serial", model.children)
    assert other != model and other.canonical_json() != model.canonical_json()
