"""Read a compound skill's tree by running its ``expand`` against recording stand-ins.

About one ``expand`` in four computes its tree (``specify={"Duration":
self.params["Wait"].value}``, a loop over parameters, a type name built with ``format``);
reading its syntax cannot tell the tree, running it can. ``trace`` calls the class's own
``expand`` with a ``self`` whose ``skill(...)`` records a node instead of asking a skill
manager and whose ``params[...]`` are symbols (``{"param": "X"}``), and with a root node
that records ``setProcessor`` and its children. It works on the legacy backend and on real
SkiROS2 alike: only ``skill``, ``params`` and the root are replaced.

A body that needs more (the world model, a branch on a parameter's value, a helper that
fails on symbols) raises; ``trace`` reports that as ``Unanalysable`` with the error, never
as a clean tree. Run it in a child process when the code is not trusted (``ezmigrate``
does, in its verification sandbox).
"""

from __future__ import annotations

import difflib
import sys
from dataclasses import dataclass
from typing import Any

from ..legacy.skill import SkillWrapper
from .model import CallProblem, CompoundModel, Node, ProcessorNode, SkillNode
from .stable_ids import stable_ids

ARGUMENTS = ("stype", "slabel", "remap", "specify", "preconditions")
PARAMETER_OBJECT = "parameter_object"
"""A ``specify`` value that is the parameter object ``self.params["X"]``, not its value:
``{"parameter_object": "X"}`` in a tree's JSON."""


@dataclass(frozen=True)
class Unanalysable:
    """Neither reading nor running ``expand`` gave its tree; ``reason`` says why."""

    implementation: str
    reason: str
    line: int = 0


class ParamRef:
    """``self.params["X"].value`` while tracing: the value is not known, its source is.

    Attributes and calls on it (``.value.label``, ``.value.getProperty("p")``) give further
    symbols, as an element's properties would; branching or iterating on one raises, since
    only the running skill knows it. Its ``repr`` is the expression the user wrote: no
    message ever shows the name of this class."""

    def __init__(self, key: str, path: str = ".value") -> None:
        self.key = key
        self.path = path

    def __repr__(self) -> str:
        return f"self.params[{self.key!r}]{self.path}"

    def __getattr__(self, name: str) -> ParamRef:
        if name.startswith("__"):
            raise AttributeError(name)
        return ParamRef(self.key, f"{self.path}.{name}")

    def __call__(self, *args: Any, **kwargs: Any) -> ParamRef:
        return ParamRef(self.key, f"{self.path}(...)")

    def __getitem__(self, index: Any) -> ParamRef:
        return ParamRef(self.key, f"{self.path}[{index!r}]")

    def __bool__(self) -> bool:
        raise TypeError(f"expand branches on {self!r}, which is known only when the skill "
                        "runs")

    def __iter__(self) -> Any:
        raise TypeError(f"expand iterates over {self!r}, which is known only at run time")


class _Param:
    """``self.params["X"]``: the parameter object (``.value``, ``.values``, ``.key``)."""

    def __init__(self, key: str) -> None:
        self.key = key
        self.value = ParamRef(key)
        self.values = ParamRef(key, ".values")

    def __repr__(self) -> str:
        return f"self.params[{self.key!r}]"

    def getValue(self) -> ParamRef:
        return self.value

    def getValues(self) -> ParamRef:
        return self.values


class _Params:
    """``self.params``: every key gives a symbolic parameter."""

    def __getitem__(self, key: str) -> _Param:
        return _Param(str(key))

    def get(self, key: str, default: Any = None) -> _Param:
        return _Param(str(key))


class _WorldModel:
    """``self.wmi`` while tracing: any query ends the trace with a readable reason (what
    the world model holds is known only on the robot)."""

    def __getattr__(self, name: str) -> Any:
        if name.startswith("__"):
            raise AttributeError(name)
        raise TypeError(f"expand queries the world model (self.wmi.{name}), which is known "
                        "only when the skill runs")


class Recorded(SkillWrapper):
    """A node while ``expand`` builds it: the call's arguments, then its children, and the
    line of the call (the backend's wrapper records the rest)."""

    def __init__(self, args: tuple[Any, ...], kwargs: dict[str, Any], line: int) -> None:
        super().__init__(*args, **kwargs)
        self.line = line

    def __repr__(self) -> str:
        return f"the node of self.skill(...) at line {self.line}"


def _record(_self: Any, *args: Any, **kwargs: Any) -> Recorded:
    return Recorded(args, kwargs, sys._getframe(1).f_lineno)


def processor_name(processor: Any) -> str:
    """``SerialStar`` for ``SerialStar()``; ``NoFail(Sequential)`` for a wrapping one."""
    if isinstance(processor, (ParamRef, _Param)):
        raise TypeError(f"the processor is {processor!r}, known only when the skill runs")
    name = type(processor).__name__
    inner = [a for a in getattr(processor, "args", ()) if not isinstance(a, (str, int, float))]
    return f"{name}({processor_name(inner[0])})" if inner else name


def _is_processor(value: Any) -> bool:
    return not isinstance(value, (str, bytes, int, float, bool, dict, list, tuple, Recorded,
                                  type(None), ParamRef, _Param))


def _plain(value: Any) -> Any:
    """A ``specify`` value as JSON-ready data (symbols as ``{"param": key}``)."""
    if isinstance(value, ParamRef):
        return {"param": value.key} if value.path == ".value" else repr(value)
    if isinstance(value, _Param):
        return {PARAMETER_OBJECT: value.key}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, dict):
        return {str(k): _plain(v) for k, v in value.items()}
    if value is None or isinstance(value, (str, int, float, bool)):
        return value
    return repr(value)


def _pairs(value: Any, what: str) -> tuple[tuple[str, Any], ...]:
    """``remap``/``specify`` as SkiROS2 reads them (``for k in remap: remap[k]``): any
    empty iterable, ``""`` included, is none."""
    if value is None or (isinstance(value, (str, list, tuple, set, frozenset)) and not value):
        return ()
    if not isinstance(value, dict):
        raise TypeError(f"{what} is {type(value).__name__}, not a dict")
    return tuple((str(k), _plain(v)) for k, v in value.items())


def call_problem(kwargs: Any, bound: dict[str, Any], positional: int) -> str | None:
    """What makes a ``self.skill(...)`` call raise when ``expand`` runs, or None: a keyword
    SkiROS2's ``skill(stype, slabel, remap, specify, preconditions)`` does not take
    (``specfiy=``), too many arguments, a non-empty string as ``remap``/``specify``
    (``for k in remap: remap[k]`` indexes a string with a string)."""
    unknown = sorted(k for k in kwargs if k not in ARGUMENTS)
    if unknown:
        close = [difflib.get_close_matches(k, ARGUMENTS, 1, 0.6) for k in unknown]
        hint = "".join(f" (did you mean {c[0]}=?)" for c in close if c)
        return (f"self.skill(...) takes no keyword {unknown[0]}={hint}: the call raises a "
                "TypeError when expand runs, and the compound skill fails")
    if positional > len(ARGUMENTS):
        return (f"self.skill(...) is given {positional} positional arguments, at most "
                f"{len(ARGUMENTS)}: the call raises a TypeError when expand runs")
    for what in ("remap", "specify"):
        if isinstance(bound.get(what), str) and bound[what]:
            return (f"{what} is the string {bound[what]!r}, not a dict: SkiROS2 iterates it "
                    "and raises a TypeError when expand runs")
    return None


def parameter_object_message(key: str) -> str:
    """The message of a ``specify`` value that is a parameter object (read or traced)."""
    return (f"specify value self.params[{key!r}] is the parameter object, not its value: "
            "SkiROS2 logs an error and leaves the child's parameter unset (write "
            f"self.params[{key!r}].value)")


def _remapped(value: Any) -> str:
    if not isinstance(value, str):
        raise TypeError(f"a remap value is {value!r}, known only when the skill runs")
    return value


def node_of(recorded: Any) -> Node | CallProblem:
    """The model node of one recorded call (or the problem SkiROS2 would have with it)."""
    if not isinstance(recorded, Recorded):
        return CallProblem(f"{recorded!r} is added as a child, but it is not a node made "
                           "by self.skill(...)")
    bound = dict(zip(ARGUMENTS, recorded.args))
    bound.update(recorded.kwargs)
    problem = call_problem(recorded.kwargs, bound, len(recorded.args))
    if problem is not None:
        return CallProblem(problem, recorded.line)
    first = bound.get("stype")
    if isinstance(first, (ParamRef, _Param)):
        raise TypeError(f"the child type is {first!r}, known only when the skill runs")
    children = tuple(node_of(c) for c in recorded.children)
    if isinstance(first, Recorded):
        return CallProblem("self.skill(self.skill(...), ...) passes a node where SkiROS2 "
                           "wants a type name or a processor; call the node instead: "
                           "self.skill(...)(child, ...)", recorded.line)
    remap = tuple((k, _remapped(v)) for k, v in _pairs(bound.get("remap"), "remap"))
    specify = _pairs(bound.get("specify"), "specify")
    if isinstance(first, str):
        label = bound.get("slabel", "")
        preconditions = tuple(str(getattr(c, "label", c))
                              for c in bound.get("preconditions") or ())
        return SkillNode(first, label if isinstance(label, str) else repr(label), remap,
                         specify, preconditions, children, recorded.line)
    if first is not None and _is_processor(first):
        return ProcessorNode(processor_name(first), children, remap, specify, recorded.line)
    return CallProblem(f"self.skill({first!r}) is neither a type name nor a processor",
                       recorded.line)


def described(stand_in: Any, cls: type) -> tuple[str | None, str]:
    """(description class, label) that ``createDescription`` passes to ``setDescription``."""
    seen: list[tuple[str | None, str]] = []

    def set_description(_self: Any, description: Any, label: Any = "") -> None:
        kind = description if isinstance(description, type) else type(description)
        seen.append((kind.__name__, label if isinstance(label, str) else cls.__name__))

    stand_in.setDescription = set_description.__get__(stand_in)
    try:
        cls.createDescription(stand_in)  # type: ignore[attr-defined]
    except Exception:  # the tree can still be read; the description stays unknown
        return None, cls.__name__
    return seen[-1] if seen else (None, cls.__name__)


def trace(cls: type, path: str = "", line: int = 0) -> CompoundModel | Unanalysable:
    """The tree ``cls.expand`` builds, by running it with recording stand-ins."""
    name = cls.__name__
    expand = getattr(cls, "expand", None)
    if expand is None:
        return Unanalysable(name, "the class has no expand method", line)
    stand_in = type(name, (cls,), {"skill": _record, "params": _Params(),
                                   "wmi": _WorldModel(), "__init__": lambda self: None})
    with stable_ids():  # a label made with id(self) is the same on every run
        description, label = described(stand_in(), cls)
    root = Recorded((), {}, 0)
    try:
        with stable_ids():
            expand(stand_in(), root)
        children = tuple(node_of(c) for c in root.children)
    except Exception as error:
        frame = error.__traceback__
        where = 0
        while frame is not None:
            if frame.tb_frame.f_code is getattr(expand, "__code__", None):
                where = frame.tb_lineno
            frame = frame.tb_next
        return Unanalysable(name, f"running expand raised {type(error).__name__}: {error}",
                            where or line)
    code = getattr(expand, "__code__", None)
    return CompoundModel(
        name, description, label,
        processor_name(root.processor) if root.processor is not None else "Sequential",
        children, path, line, code.co_firstlineno if code is not None else 0, "traced")
