"""Permissive stand-ins for modules a legacy skill file imports but this machine lacks.

Skill files import ROS (``rospy``, ``tf``, ``geometry_msgs.msg``, ``moveit_commander``), numpy
and their project's own modules (legacy-skiros2-api.md §1). Loading a file only to read its
*descriptions* must not need any of that, but the module body still runs: classes derive from
``smach.State``, decorators wrap functions, constants are computed with ``np.array``. A
:class:`Stub` therefore survives every ordinary use -- attribute access, calls, subclassing
(``__mro_entries__``, PEP 560), iteration (empty), indexing, arithmetic, comparisons, use as a
decorator or context manager -- and a stub module answers any attribute with a stub.
"""

from __future__ import annotations

import contextlib
import inspect
from collections.abc import Iterator
from types import ModuleType
from typing import Any

__all__ = ["Stub", "StubBase", "is_stub", "make_stub_module"]


def _is_dunder(name: str) -> bool:
    # Protocol look-ups (copy, pickle, inspect, typing) must see "absent", not a stub.
    return len(name) > 4 and name.startswith("__") and name.endswith("__")


class StubBase:
    """What ``class X(stub.Thing)`` really derives from: a plain class, so that it combines
    with real bases (several stub bases, a ``SkillDescription``, an ``ABCMeta`` class)."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        # Cooperative: a real base later in the MRO (``class X(smach.State,
        # SkillDescription)``) still initializes. The arguments were meant for the stub, so
        # they are not passed on; a real base that needs its own is called by user code.
        with contextlib.suppress(TypeError):
            super().__init__()

    def __init_subclass__(cls, **kwargs: Any) -> None:
        super().__init_subclass__()

    def __getattr__(self, name: str) -> Any:
        if _is_dunder(name):
            raise AttributeError(name)
        return Stub(f"{type(self).__qualname__}.{name}")


class Stub:
    """A permissive object named after the dotted path it was reached by (for messages)."""

    def __init__(self, name: str) -> None:
        object.__setattr__(self, "_stub_name", name)
        object.__setattr__(self, "_stub_attrs", {})
        object.__setattr__(self, "_stub_class", None)

    def _child(self, suffix: str) -> Stub:
        return Stub(self._stub_name + suffix)

    # attributes: created once per name, assignable
    def __getattr__(self, name: str) -> Any:
        if _is_dunder(name) or name.startswith("_stub_"):
            raise AttributeError(name)
        attrs: dict[str, Any] = self._stub_attrs
        if name not in attrs:
            attrs[name] = self._child("." + name)
        return attrs[name]

    def __setattr__(self, name: str, value: Any) -> None:
        self._stub_attrs[name] = value

    def __delattr__(self, name: str) -> None:
        self._stub_attrs.pop(name, None)

    # calls and decorators: ``@stub.deco`` keeps the decorated function or class
    def __call__(self, *args: Any, **kwargs: Any) -> Any:
        if len(args) == 1 and not kwargs and (inspect.isfunction(args[0])
                                             or inspect.isclass(args[0])):
            return args[0]
        return self._child("()")

    # subclassing: ``class X(stub.Thing)`` derives from a real class made once per stub
    def __mro_entries__(self, bases: tuple[Any, ...]) -> tuple[type, ...]:
        if self._stub_class is None:
            module, _, name = self._stub_name.rpartition(".")
            cls = type(name or "Stub", (StubBase,), {"__module__": module or "stub",
                                                     "__qualname__": name or "Stub"})
            object.__setattr__(self, "_stub_class", cls)
        return (self._stub_class,)

    def __instancecheck__(self, instance: Any) -> bool:
        return False

    def __subclasscheck__(self, subclass: Any) -> bool:
        return False

    # containers: empty, but indexable and assignable
    def __iter__(self) -> Iterator[Any]:
        return iter(())

    def __reversed__(self) -> Iterator[Any]:
        return iter(())

    def __len__(self) -> int:
        return 0

    def __contains__(self, item: Any) -> bool:
        return False

    def __getitem__(self, key: Any) -> Any:
        return self._child("[]")

    def __setitem__(self, key: Any, value: Any) -> None:
        pass

    def __delitem__(self, key: Any) -> None:
        pass

    # context manager
    def __enter__(self) -> Stub:
        return self

    def __exit__(self, *exc: Any) -> None:
        return None

    # truth, numbers, text: usable values. Truthy, so ``while not rospy.is_shutdown()`` ends.
    def __bool__(self) -> bool:
        return True

    def __int__(self) -> int:
        return 0

    def __index__(self) -> int:
        return 0

    def __float__(self) -> float:
        return 0.0

    def __complex__(self) -> complex:
        return 0j

    def __str__(self) -> str:
        return self._stub_name

    def __format__(self, spec: str) -> str:
        return self._stub_name

    def __repr__(self) -> str:
        return f"<stub {self._stub_name}>"

    # comparisons: plain bools (a stub equals only itself)
    def __eq__(self, other: object) -> bool:
        return self is other

    def __ne__(self, other: object) -> bool:
        return self is not other

    def __lt__(self, other: Any) -> bool:
        return False

    __le__ = __gt__ = __ge__ = __lt__
    __hash__ = object.__hash__


def _operator(self: Stub, *args: Any) -> Stub:
    return self._child("<op>")


for _name in ("add", "sub", "mul", "matmul", "truediv", "floordiv", "mod", "divmod", "pow",
              "lshift", "rshift", "and", "xor", "or"):
    setattr(Stub, f"__{_name}__", _operator)
    setattr(Stub, f"__r{_name}__", _operator)
for _name in ("neg", "pos", "abs", "invert", "round", "trunc", "floor", "ceil"):
    setattr(Stub, f"__{_name}__", _operator)


_MARK = "__ezmigrate_stub__"
STUB_VERSION = "0.0.0"
"""A stub module's ``__version__``: a string every version parser and comparison accepts."""


def is_stub(value: Any) -> bool:
    """True for stub modules, stub objects and classes derived from a stub."""
    if isinstance(value, ModuleType):
        return value.__dict__.get(_MARK) is True
    return isinstance(value, Stub) or (isinstance(value, type) and issubclass(value, StubBase))


def make_stub_module(module: ModuleType) -> None:
    """Turn an empty module object into a permissive one: any attribute is a stub (made once
    and kept), ``from m import *`` imports nothing. Submodules (``import a.b.c``) resolve
    because the finder creates the module as a package."""
    name = module.__name__

    def __getattr__(attr: str) -> Any:
        if _is_dunder(attr):
            raise AttributeError(f"module {name!r} has no attribute {attr!r}")
        value = Stub(f"{name}.{attr}")
        setattr(module, attr, value)
        return value

    module.__dict__["__getattr__"] = __getattr__
    module.__dict__["__all__"] = []
    module.__dict__["__version__"] = STUB_VERSION  # `if np.__version__ >= "1.20":` runs
    module.__dict__[_MARK] = True
