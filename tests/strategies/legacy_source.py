"""Hypothesis strategies that write legacy SkiROS2 description modules as *source text*.

The text covers the construct table of ``legacy-skiros2-api.md`` §1-§5 and the mess of §7:

* import styles: plain, re-exported from ``skiros2_skill.core.skill``, aliased names
  (``ParamTypes as PT``), aliased modules (``import ...params as params``);
* parameter keys: identifiers, lower case, keys differing only in case, Python keywords,
  keys that are no identifiers (``"On/Off"``, ``"Speed (m/s)"``), random text, an explicit
  ``Robot``, and (rarely) a key declared twice;
* values: ``Element("prefix:C")``, ``Element(":C")``, ``Element("C")``, ``Element()``, type
  objects, literals of every type (negative numbers, ``1e-3``, float lists, ``{}``, ``""``)
  and module-level constants;
* kinds as ``ParamTypes.X`` or the ints 0/1/2; options ``Lock``/``Consume``/``Unspecify``/
  ``RespectType``/``Output`` on Element parameters; descriptions by keyword, as 5th
  positional argument, or in the options slot (the silent-drop quirk); keyword spellings;
* every condition factory, the three condition classes, conventional and free labels,
  desired True/False, every property operator with bool/str/int/float values,
  or-conditions with 2-3 children, conditions stored in locals first;
* comments, banners, commented-out calls, blank lines, multi-line calls with trailing
  commas, docstrings; file quirks (shebang, coding cookie, no final newline, trailing
  whitespace, CRLF, tab or 2-space indentation); optional implementation classes.

Only declarative constructs are generated, so every description class is convertible in
principle. In particular all ``addParam`` calls come before the conditions: options expand
at the ``addParam`` call while EzSkiROS lowers every parameter before any condition, so a
condition written *before* an option-expanding parameter could not keep its position.

Public API::

    legacy_modules(**knobs)             -> SearchStrategy[str]
    legacy_module_texts                 =  legacy_modules()
    legacy_modules_with_names(**knobs)  -> SearchStrategy[GeneratedModule(text, class_names)]
    description_class_names(text)       -> list[str]   (recovered from the text with ast)
"""

from __future__ import annotations

import ast
import functools
import json
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any, NamedTuple

from hypothesis import strategies as st

from ezskiros_runtime.labels import conventional_label

# --------------------------------------------------------------------------------------
# Vocabulary
# --------------------------------------------------------------------------------------

IDENTIFIER_KEYS: tuple[str, ...] = (
    "Object", "Gripper", "Arm", "Location", "ObjectLocation", "TargetLocation", "Container",
    "Camera", "GraspingPose", "Target", "Tool", "Drawer", "Handle", "Station", "Speed",
    "Timeout", "Force", "Offset", "Frame", "Enabled", "Retries", "Joints", "Settings",
    "X", "x", "Y", "y", "object", "gripper", "volume", "target", "Höhe",
)
"""CamelCase identifiers, lower-case keys, keys differing only in case, a non-ASCII one."""

UNUSUAL_KEYS: tuple[str, ...] = (
    "On/Off", "Target Location", "Speed (m/s)", "2nd Object", "grip-force", "tool.frame",
    "Operator's note", 'say "hi"', "back\\slash", "from", "class", "lambda", "in", "None",
    "self", "",
)
"""Keys that are no (usable) Python identifiers: spaces, punctuation, keywords, ``self``."""

ELEMENT_TYPES: tuple[str, ...] = (
    "skiros:Product", "skiros:Location", ":Location", "Location", ":Product", "Product",
    "skiros:TransformationPose", "skiros:GraspingPose", "skiros:Container", "skiros:Drawer",
    "rparts:GripperEffector", "rparts:ArmDevice", "rparts:DepthCamera", "cora:Robot",
    "sumo:Agent", "scalable:Ur5", "turtlebot:Turtle", "skiros;:Workstation", "lab:Widget",
)
"""Element type strings with and without prefix; a third are unknown to the core ontology."""

RELATIONS: tuple[str, ...] = (
    "skiros:contain", "skiros:contain", "skiros:contain", "skiros:hasA", "skiros:at",
    ":contain", "cora:robotPart", "skiros:spatiallyRelated", "turtlebot:Docked",
    "lab:attachedTo", "contain",
)

CONSISTENT_RELATIONS: tuple[str, ...] = tuple(
    r for r in RELATIONS if r not in ("skiros:hasA", "cora:robotPart"))
"""Relations without domain/range in the bundled ontology: any subject/object type-checks."""

PROPERTIES: tuple[str, ...] = (
    "skiros:ContainerState", "skiros:StateProperty", "skiros:Open", "skiros:Position",
    "skiros:Size", "skiros:FrameId", ":Open", "turtlebot:BatteryLevel", "lab:Temperature",
)

OPERATORS: tuple[str, ...] = ("=", "=", "=", ">", "<", ">=", "<=")

FREE_LABELS: tuple[str, ...] = (
    "Holding", "EmptyHanded", "IsOpen", "Ready", "AtHome", "SafeToMove", "Docked",
    "Not holding", "precondition 1",
)

CLASS_VERBS: tuple[str, ...] = (
    "Pick", "Place", "Open", "Close", "Move", "Navigate", "Inspect", "Scan", "Grasp",
    "Release", "Push", "Pour", "Charge", "Dock", "Wait", "Fetch", "Screw", "Sort", "Stack",
)
CLASS_NOUNS: tuple[str, ...] = (
    "", "Object", "Part", "Drawer", "Door", "Box", "Tray", "Bin", "Cup", "Lid", "Shelf",
    "Tool", "Arm", "Base", "Sample",
)

FLOAT_SPELLINGS: tuple[str, ...] = (
    "0.0", "0.5", "-0.5", "1e-3", "0.1", "2.0", "-1.57", "3.14159", "100.0", ".25", "1.",
    "0.085", "-12.75", "1e6",
)
INT_SPELLINGS: tuple[str, ...] = ("0", "1", "-1", "3", "10", "-42", "255", "1000")
STR_VALUES: tuple[str, ...] = (
    "", "skiros:contain", "base_link", "Idle", "map", "tool0", "Greifer öffnen", "m/s",
)
DESCRIPTIONS: tuple[str, ...] = (
    "speed in m/s", "the object to pick", "seconds", "1 forward, -1 backward", "Öffnungsweite",
    "camera above the belt", "", "frame of the target",
)
CONSTANT_NAMES: tuple[str, ...] = (
    "DEFAULT_SPEED", "APPROACH_OFFSET", "HOME_FRAME", "MAX_RETRIES", "FORCE_LIMIT",
)
LOCAL_NAMES: tuple[str, ...] = (
    "cond", "c", "holding", "not_holding", "in_container", "pre", "post", "is_open",
    "at_target", "either", "open_or_tray",
)
COMMENTS: tuple[str, ...] = (
    "TODO: check this on the real robot", "NOTE: order matters for the planner",
    "the gripper must be empty", "FIXME(jk) remove after the demo", "see issue #42",
    "Greifer öffnen", "----",
)
BANNERS: tuple[str, ...] = (
    "#=======Params=========", "#=======PreConditions=========",
    "#=======HoldConditions=========", "#=======PostConditions=========",
    "##########################################", "# ---- conditions ----",
)
OPTIONS: tuple[str, ...] = ("Lock", "Lock", "Lock", "Consume", "Unspecify", "RespectType", "Output")
ROS_IMPORTS: tuple[str, ...] = (
    "import rospy", "import numpy as np", "from geometry_msgs.msg import Pose",
    "import moveit_commander", "import tf", "from std_msgs.msg import Bool",
)

_TEXT = st.text(
    alphabet=st.characters(categories=("L", "N", "P", "Zs", "S"), exclude_characters="\x7f"),
    min_size=1,
    max_size=12,
)
"""Free text for keys, labels, strings and comments: printable, no line breaks."""


def _q(text: str) -> str:
    """A double-quoted Python string literal for ``text`` (legacy code uses double quotes)."""
    return json.dumps(text, ensure_ascii=False)


@functools.cache
def _weighted(*pairs: tuple[int, Any]) -> st.SearchStrategy[Any]:
    """``sampled_from`` with integer weights: ``_weighted((3, "a"), (1, "b"))``.

    Cached, like ``_choice``: a strategy object is validated on its first draw, and
    building fresh ones for every draw made generation several times slower.
    """
    return st.sampled_from(tuple(value for weight, value in pairs for _ in range(weight)))


@functools.lru_cache(maxsize=4096)
def _choice(options: tuple[Any, ...]) -> st.SearchStrategy[Any]:
    return st.sampled_from(options)


def _pick(draw: st.DrawFn, options: Sequence[Any]) -> Any:
    """One element of ``options`` (a cached ``sampled_from``)."""
    return draw(_choice(tuple(options)))


# --------------------------------------------------------------------------------------
# Import styles
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class ImportStyle:
    """How a module imports the SkiROS2 names, and how the code then spells them."""

    lines: tuple[str, ...]
    base: str
    element: str
    param_types: str
    param_options: str
    has_skill_base: bool = False


IMPORT_STYLES: tuple[ImportStyle, ...] = (
    ImportStyle(
        ("from skiros2_common.core.abstract_skill import SkillDescription, ParamOptions",
         "from skiros2_common.core.params import ParamTypes",
         "from skiros2_common.core.world_element import Element"),
        "SkillDescription", "Element", "ParamTypes", "ParamOptions"),
    ImportStyle(
        ("from skiros2_skill.core.skill import SkillDescription, ParamOptions, SkillBase, "
         "Sequential",
         "from skiros2_common.core.params import ParamTypes",
         "from skiros2_common.core.world_element import Element"),
        "SkillDescription", "Element", "ParamTypes", "ParamOptions", has_skill_base=True),
    ImportStyle(
        ("from skiros2_common.core.abstract_skill import SkillDescription as Description",
         "from skiros2_common.core.abstract_skill import ParamOptions as Opt",
         "from skiros2_common.core.params import ParamTypes as PT",
         "from skiros2_common.core.world_element import Element as E"),
        "Description", "E", "PT", "Opt"),
    ImportStyle(
        ("import skiros2_common.core.abstract_skill as abstract_skill",
         "import skiros2_common.core.params as params",
         "import skiros2_common.core.world_element as we"),
        "abstract_skill.SkillDescription", "we.Element", "params.ParamTypes",
        "abstract_skill.ParamOptions"),
)

CONDITION_CLASS_IMPORTS: tuple[tuple[str, str], ...] = (
    ("from skiros2_common.core.conditions import ConditionRelation, ConditionProperty, "
     "ConditionHasProperty", ""),
    ("import skiros2_common.core.conditions as cond", "cond."),
)


# --------------------------------------------------------------------------------------
# Small pieces
# --------------------------------------------------------------------------------------


# Source text of literals (module-level strategies, built once).
_FLOAT_SRC = st.one_of(st.sampled_from(FLOAT_SPELLINGS),
                       st.floats(allow_nan=False, allow_infinity=False).map(repr))
_INT_SRC = st.one_of(st.sampled_from(INT_SPELLINGS), st.integers(-10**6, 10**6).map(str))
_BOOL_SRC = st.sampled_from(("True", "False"))
_STR_SRC = st.one_of(st.sampled_from(STR_VALUES), _TEXT).map(_q)
_FLOAT_LIST_SRC = st.lists(_FLOAT_SRC, min_size=1, max_size=6).map(
    lambda items: "[" + ", ".join(items) + "]")
_LITERAL_SRC = st.one_of(_FLOAT_SRC, _INT_SRC, _STR_SRC, _BOOL_SRC, _FLOAT_LIST_SRC,
                         st.just("{}"))
"""A literal default of any legacy type (never ``[]`` or a mixed list: those raise)."""
_PROPERTY_VALUE_SRC = st.one_of(_BOOL_SRC, _STR_SRC, _INT_SRC, _FLOAT_SRC)
_DESCRIPTION_SRC = st.one_of(st.sampled_from(DESCRIPTIONS), _TEXT).map(_q)
_LABEL_TEXT = st.one_of(_TEXT, st.just(""))
_KEY_SOURCES = (st.sampled_from(IDENTIFIER_KEYS), st.sampled_from(UNUSUAL_KEYS), _TEXT)
_KEY = st.sampled_from((0,) * 14 + (1, 1, 2)).flatmap(lambda i: _KEY_SOURCES[i])
"""Mostly identifier keys, sometimes unusual ones, rarely random text."""
_OPTION_NAMES = st.lists(st.sampled_from(OPTIONS), min_size=1, max_size=3, unique=True)


def _label(draw: st.DrawFn, kind: str, subject: str, vocabulary: str | None,
           obj: str | None, desired: bool) -> str:
    which = draw(_weighted((8, "conventional"), (3, "free"), (1, "text"), (1, "flip")))
    if which == "free":
        return _pick(draw, FREE_LABELS)
    if which == "text":
        return draw(_LABEL_TEXT)
    # "flip": the label of the opposite desired state (a real copy-paste mistake)
    state = (not desired) if which == "flip" and kind != "on_type" else desired
    return conventional_label(kind, subject=subject, vocabulary=vocabulary, object=obj,
                              desired_state=state)


# --------------------------------------------------------------------------------------
# Statements: a statement is a list of (relative indent level, text) lines
# --------------------------------------------------------------------------------------

Line = tuple[int, str]


def _call(prefix: str, args: Sequence[str], multiline: bool, trailing_comma: bool) -> list[Line]:
    if not multiline:
        return [(0, f"{prefix}({', '.join(args)})")]
    lines = [(0, f"{prefix}(")]
    for i, arg in enumerate(args):
        last = i == len(args) - 1
        lines.append((1, arg + ("," if not last or trailing_comma else "")))
    lines.append((0, ")"))
    return lines


@dataclass
class _Param:
    key: str
    value: str
    kind: str
    is_element: bool
    """An ``Element`` instance (typed or ``Element()``): a sensible condition subject."""


@dataclass
class _ClassState:
    """What one description class has declared so far while it is being drawn."""

    style: ImportStyle
    cond_prefix: str | None
    relations: tuple[str, ...] = RELATIONS
    comments: bool = True
    keys: list[str] = field(default_factory=list)
    locals_used: set[str] = field(default_factory=set)

    def __post_init__(self) -> None:
        # a local named like the module alias (``cond``) would shadow it in the whole body
        if self.cond_prefix:
            self.locals_used.add(self.cond_prefix.rstrip("."))

    def local(self, base: str) -> str:
        name, n = base, 1
        while name in self.locals_used:
            n += 1
            name = f"{base}{n}"
        self.locals_used.add(name)
        return name


def _value(draw: st.DrawFn, style: ImportStyle, constants: Sequence[str],
           key: str) -> tuple[str, bool]:
    """(value source, is an Element instance with a type string: options may apply)."""
    if key == "Robot":  # an explicit Robot is always an agent element in real code
        robot = _pick(draw, ["cora:Robot", "sumo:Agent", "rparts:ArmDevice"])
        return f"{style.element}({_q(robot)})", True
    which = draw(_weighted((12, "element"), (1, "element()"), (4, "type"), (5, "literal"),
                           (1 if constants else 0, "constant")))
    if which == "element":
        return f"{style.element}({_q(_pick(draw, ELEMENT_TYPES))})", True
    if which == "element()":
        return f"{style.element}()", False
    if which == "type":
        return _pick(draw, ["float", "str", "dict", "int", "bool", "list"]), False
    if which == "constant":
        return _pick(draw, constants), False
    return draw(_LITERAL_SRC), False


def _add_param(draw: st.DrawFn, state: _ClassState, key: str,
               constants: Sequence[str]) -> tuple[_Param, list[Line]]:
    style = state.style
    value, is_element = _value(draw, style, constants, key)
    kinds = ["Required", "Optional"] + (["Inferred"] if is_element else [])
    kind_name = _pick(draw, kinds)
    if draw(_weighted((6, False), (1, True))):
        kind = str(("Required", "Optional", "Inferred").index(kind_name))
    else:
        kind = f"{style.param_types}.{kind_name}"
    options: str | None = None
    if is_element and draw(_weighted((3, False), (1, True))):
        names = draw(_OPTION_NAMES)
        options = "[" + ", ".join(f"{style.param_options}.{o}" for o in names) + "]"
    desc_style = draw(_weighted((10, "none"), (1, "keyword"), (1, "fifth"), (2, "quirk")))
    if desc_style == "quirk" and options is not None:
        desc_style = "fifth"
    description = draw(_DESCRIPTION_SRC)
    if desc_style == "quirk" and description == '""':
        description = _q("speed in m/s")
    spelling = draw(_weighted((8, "positional"), (1, "keywords"), (1, "mixed")))

    positional = [_q(key), value, kind]
    keyword: list[str] = []
    if spelling == "keywords":
        keyword = draw(st.permutations([f"key={_q(key)}", f"value={value}",
                                        f"param_type={kind}"]))
        positional = []
    elif spelling == "mixed":
        positional = [_q(key)]
        keyword = [f"value={value}", f"param_type={kind}"]
    if desc_style == "quirk":
        if positional and len(positional) == 3:
            positional.append(description)
        else:  # a keyword came first: the quirk needs position 4, fall back to options=
            keyword.append(f"options={description}")
    else:
        opt_kw = draw(st.booleans()) or bool(keyword)
        if options is not None or desc_style == "fifth":
            opts = options or "[]"
            if opt_kw:
                keyword.append(f"options={opts}")
            else:
                positional.append(opts)
        if desc_style == "fifth":
            if keyword:
                keyword.append(f"description={description}")
            else:
                positional.append(description)
        elif desc_style == "keyword":
            keyword.append(f"description={description}")
    multiline = draw(_weighted((9, False), (1, True)))
    lines = _call("self.addParam", positional + keyword, multiline, draw(st.booleans()))
    element = is_element or value == f"{style.element}()"
    return _Param(key, value, kind, element), lines


def _simple_condition(draw: st.DrawFn, state: _ClassState, subjects: Sequence[str]) -> str:
    """The source of one non-or condition expression."""
    kind = draw(_weighted((12, "relation"), (5, "property"), (2, "has_property"),
                          (1, "abstract_relation"), (1, "is_specified"), (1, "generate"),
                          (1, "on_type")))
    subj = _pick(draw, subjects)
    desired = draw(_weighted((3, True), (2, False)))
    klass = state.cond_prefix is not None and draw(st.booleans())
    cls = state.cond_prefix or ""
    if kind in ("relation", "abstract_relation"):
        rel = _pick(draw, state.relations)
        obj = _pick(draw, subjects)
        label = _label(draw, kind, subj, rel, obj, desired)
        args = [_q(label), _q(rel), _q(subj), _q(obj), str(desired)]
        if kind == "relation" and klass:
            return f"{cls}ConditionRelation({', '.join(args)})"
        factory = "getRelationCond" if kind == "relation" else "getAbstractRelationCond"
        return f"self.{factory}({', '.join(args)})"
    if kind == "property":
        prop = _pick(draw, PROPERTIES)
        op = _pick(draw, OPERATORS)
        value = draw(_PROPERTY_VALUE_SRC)
        label = _label(draw, kind, subj, prop, None, desired)
        args = [_q(label), _q(prop), _q(subj), _q(op), value, str(desired)]
        if klass:
            return f"{cls}ConditionProperty({', '.join(args)})"
        return f"self.getPropCond({', '.join(args)})"
    if kind == "has_property":
        prop = _pick(draw, PROPERTIES)
        label = _label(draw, kind, subj, prop, None, desired)
        args = [_q(label), _q(prop), _q(subj), str(desired)]
        if klass:
            return f"{cls}ConditionHasProperty({', '.join(args)})"
        return f"self.getHasPropCond({', '.join(args)})"
    if kind in ("is_specified", "generate"):
        label = _label(draw, kind, subj, None, None, desired)
        factory = "getIsSpecifiedCond" if kind == "is_specified" else "getGenerateCond"
        return f"self.{factory}({_q(label)}, {_q(subj)}, {desired})"
    type_ = _pick(draw, ELEMENT_TYPES)
    label = _label(draw, "on_type", subj, None, None, True)
    return f"self.getOnTypeCond({_q(label)}, {_q(subj)}, {_q(type_)})"


def _condition_statement(draw: st.DrawFn, state: _ClassState,
                         subjects: Sequence[str]) -> list[Line]:
    """One condition added to a list, possibly built in locals first, possibly an or."""
    target = draw(_weighted((5, "Pre"), (1, "Hold"), (4, "Post")))
    adder = f"self.add{target}Condition"
    lines: list[Line] = []
    if draw(_weighted((12, False), (1, True))):
        name = state.local(_pick(draw, ["either", "open_or_tray", "alternatives", "alt"]))
        lines.append((0, f"{name} = self.getOrCond({draw(_weighted((3, True), (1, False)))})"))
        for _ in range(draw(st.integers(2, 3))):
            child = _simple_condition(draw, state, subjects)
            if draw(_weighted((4, False), (1, True))):
                local = state.local(_pick(draw, LOCAL_NAMES))
                lines.append((0, f"{local} = {child}"))
                child = local
            lines.append((0, f"{name}.addCondition({child})"))
        lines.append((0, f"{adder}({name})"))
        return lines
    expr = _simple_condition(draw, state, subjects)
    if draw(_weighted((5, False), (1, True))):
        local = state.local(_pick(draw, LOCAL_NAMES))
        lines.append((0, f"{local} = {expr}"))
        if state.comments and draw(_weighted((3, False), (1, True))):
            lines.append((0, f"# {_pick(draw, COMMENTS)}"))
        lines.append((0, f"{adder}({local})"))
        return lines
    if draw(_weighted((12, False), (1, True))):
        return [(0, f"{adder}("), (1, expr + ("," if draw(st.booleans()) else "")), (0, ")")]
    return [(0, f"{adder}({expr})")]


def _filler(draw: st.DrawFn, state: _ClassState, constants: Sequence[str]) -> list[Line]:
    """Comments, banners, blank lines or commented-out calls between statements."""
    which = draw(_weighted((4, "blank"), (3, "comment"), (2, "banner"), (2, "commented-out"),
                           (1, "text")))
    if which == "blank":
        return [(0, "")]
    if which == "comment":
        return [(0, "# " + _pick(draw, COMMENTS))]
    if which == "banner":
        return [(0, _pick(draw, BANNERS))]
    if which == "text":
        return [(0, "#" + draw(_TEXT))]
    if draw(st.booleans()):
        _, call = _add_param(draw, state, draw(_KEY), constants)
    else:
        call = _condition_statement(draw, state, [*state.keys, "Robot"])
    sep = _pick(draw, ["# ", "#", "#  "])
    return [(0, sep + "    " * level + text) for level, text in call]


# --------------------------------------------------------------------------------------
# Classes and modules
# --------------------------------------------------------------------------------------


@dataclass
class _Knobs:
    """The families of constructs a generated module may use (``legacy_modules_with_names``
    takes them as keywords: one object here, not nine parameters down every helper)."""

    max_params: int = 8
    max_conditions: int = 8
    implementations: bool = True
    comments: bool = True
    condition_classes: bool = True
    duplicate_keys: bool = True
    undeclared_keys: bool = False
    file_quirks: bool = True
    consistent_vocabulary: bool = False


def _description_class(draw: st.DrawFn, name: str, style: ImportStyle, cond_prefix: str | None,
                       constants: Sequence[str], knobs: _Knobs) -> tuple[list[Line], list[str]]:
    """(source lines of one description class, its declared keys in order)."""
    relations = CONSISTENT_RELATIONS if knobs.consistent_vocabulary else RELATIONS
    state = _ClassState(style, cond_prefix, relations, knobs.comments)
    body: list[list[Line]] = []

    def maybe_filler() -> None:
        if knobs.comments and draw(_weighted((4, False), (1, True))):
            body.append(_filler(draw, state, constants))

    keys = [k for k in draw(st.lists(_KEY, max_size=knobs.max_params, unique=True))
            if k != "Robot"]
    if draw(_weighted((8, False), (1, True))):
        # Robot declared explicitly (usually first): changes the parameter order
        at = 0 if draw(_weighted((3, True), (1, False))) else draw(st.integers(0, len(keys)))
        keys.insert(at, "Robot")
    if keys and knobs.duplicate_keys and draw(_weighted((15, False), (1, True))):
        keys.append(_pick(draw, keys))  # declared twice: the second replaces
    if knobs.comments and keys and draw(st.booleans()):
        body.append([(0, "#=======Params=========")])
    element_keys: dict[str, bool] = {}
    for key in keys:
        param, lines = _add_param(draw, state, key, constants)
        element_keys[key] = param.is_element  # a second declaration replaces the first
        if knobs.comments and draw(_weighted((8, False), (1, True))):
            last_level, last_text = lines[-1]
            lines[-1] = (last_level, f"{last_text}  # {_pick(draw, COMMENTS)}")
        body.append(lines)
        state.keys.append(key)
        maybe_filler()
    if draw(_weighted((12, False), (1, True))):
        body.append([(0, f"self._note = {draw(_STR_SRC)}")])  # a plain attribute
    # conditions name Element parameters (or the automatic Robot), as real code does
    subjects = [k for k, element in element_keys.items() if element and k != "Robot"]
    subjects.append("Robot")
    if knobs.undeclared_keys and draw(_weighted((10, False), (1, True))):
        subjects.append(_pick(draw, ["Tool", "Fixture", "Base"]))
    for _ in range(draw(st.integers(0, knobs.max_conditions))):
        body.append(_condition_statement(draw, state, subjects))
        maybe_filler()

    lines: list[Line] = [(0, f"class {name}({style.base}):")]
    if draw(_weighted((5, False), (1, True))):
        lines.append((1, f'"""{name}: generated description."""'))
        if draw(st.booleans()):
            lines.append((1, ""))
    lines.append((1, "def createDescription(self):"))
    if draw(_weighted((8, False), (1, True))):
        lines.append((2, '"""Parameters and conditions."""'))
    statements = [line for chunk in body for line in chunk]
    if not any(text and not text.startswith("#") for _, text in statements):
        statements.append((0, "pass"))
    while statements and statements[-1][1] == "":
        statements.pop()
    lines.extend((2 + level, text) for level, text in statements)
    return lines, list(dict.fromkeys(keys))


def _snake(name: str) -> str:
    out = "".join("_" + ch.lower() if ch.isupper() else ch for ch in name)
    return out.lstrip("_")


def _implementation_class(draw: st.DrawFn, description: str, keys: Sequence[str],
                          others: Sequence[str]) -> list[Line]:
    impl = _snake(description) + _pick(draw, ["", "_impl", "_fake"])
    set_desc = f"self.setDescription({description}(), self.__class__.__name__)"
    if draw(st.booleans()) or not others:
        key = _q(_pick(draw, list(keys) or ["Robot"]))
        return [
            (0, f"class {impl}(PrimitiveBase):"),
            (1, "def createDescription(self):"), (2, set_desc), (0, ""),
            (1, "def onStart(self):"), (2, "self._ticks = 0"), (2, "return True"), (0, ""),
            (1, "def execute(self):"), (2, "self._ticks += 1"),
            (2, f"value = self.params[{key}].value"),
            (2, "if self._ticks < 3:"), (3, 'return self.step("working on {}".format(value))'),
            (2, 'return self.success("Done")'),
        ]
    children = draw(st.lists(st.sampled_from(list(others)), min_size=1, max_size=3))
    lines: list[Line] = [
        (0, f"class {impl}(SkillBase):"),
        (1, "def createDescription(self):"), (2, set_desc), (0, ""),
        (1, "def expand(self, skill):"), (2, "skill.setProcessor(Sequential())"),
        (2, "skill("),
    ]
    for child in children:
        remap = ""
        if keys and draw(st.booleans()):
            remap = f", remap={{{_q(_pick(draw, list(keys)))}: {_q('Target')}}}"
        lines.append((3, f"self.skill({_q(child)}, {_q('')}{remap}),"))
    lines.append((2, ")"))
    return lines


class GeneratedModule(NamedTuple):
    """A generated legacy module and the names of its description classes, in order."""

    text: str
    class_names: tuple[str, ...]


@st.composite
def _module(draw: st.DrawFn, min_classes: int, max_classes: int, knobs: _Knobs) -> GeneratedModule:
    style = _pick(draw, IMPORT_STYLES)
    cond_import, cond_prefix = (None, None)
    if knobs.condition_classes and draw(_weighted((3, False), (1, True))):
        cond_import, cond_prefix = _pick(draw, CONDITION_CLASS_IMPORTS)
    n = draw(st.integers(min_classes, max_classes))
    names = draw(st.lists(
        st.tuples(st.sampled_from(CLASS_VERBS), st.sampled_from(CLASS_NOUNS)).map("".join),
        min_size=n, max_size=n, unique=True))
    constant_names = draw(st.lists(st.sampled_from(CONSTANT_NAMES), max_size=2, unique=True))
    constants = [(c, draw(_LITERAL_SRC)) for c in constant_names]

    header: list[Line] = []
    quirks = knobs.file_quirks
    if quirks and draw(_weighted((3, False), (1, True))):
        header.append((0, "#!/usr/bin/env python"))
    if quirks and draw(_weighted((3, False), (1, True))):
        header.append((0, "# -*- coding: utf-8 -*-"))
    if draw(st.booleans()):
        header.append((0, '"""Generated legacy SkiROS2 skills."""'))
    header.extend((0, line) for line in draw(st.lists(st.sampled_from(ROS_IMPORTS),
                                                      max_size=3, unique=True)))
    header.append((0, ""))
    header.extend((0, line) for line in style.lines)
    if cond_import:
        header.append((0, cond_import))
    constant_refs = [c for c, _ in constants]
    classes = [_description_class(draw, name, style, cond_prefix, constant_refs, knobs)
               for name in names]
    impls: dict[str, list[Line]] = {}
    if knobs.implementations:
        for name, (_, keys) in zip(names, classes, strict=True):
            if draw(st.booleans()):
                others = [x for x in names if x != name]
                impls[name] = _implementation_class(draw, name, keys, others)
    if impls:
        header.append((0, "from skiros2_common.core.primitive import PrimitiveBase"))
        if not style.has_skill_base:
            header.append((0, "from skiros2_skill.core.skill import SkillBase, Sequential"))
    if constants:
        header.append((0, ""))
        header.extend((0, f"{c} = {v}") for c, v in constants)

    if draw(st.booleans()):  # all descriptions first, then the implementations
        blocks = [cls for cls, _ in classes] + list(impls.values())
    else:  # each implementation right after its description
        blocks = [b for name, (cls, _) in zip(names, classes, strict=True)
                  for b in (cls, impls.get(name)) if b]
    lines = list(header)
    for block in blocks:
        lines.extend([(0, ""), (0, "")])
        lines.extend(block)

    indent = draw(_weighted((8, "    "), (1, "  "), (1, "\t"))) if quirks else "    "
    rendered = [indent * level + text if text else "" for level, text in lines]
    if quirks and draw(_weighted((4, False), (1, True))):
        for i in draw(st.lists(st.integers(0, len(rendered) - 1), max_size=4)):
            rendered[i] += _pick(draw, [" ", "  ", "\t"])
    newline = "\r\n" if quirks and draw(_weighted((8, False), (1, True))) else "\n"
    text = newline.join(rendered)
    if not (quirks and draw(_weighted((3, False), (1, True)))):
        text += newline  # about a quarter of real files have no final newline
    return GeneratedModule(text, tuple(names))


def legacy_modules_with_names(
    *, min_classes: int = 1, max_classes: int = 3, **knobs: Any
) -> st.SearchStrategy[GeneratedModule]:
    """Legacy modules as ``GeneratedModule(text, class_names)``.

    ``class_names`` are the description classes in source order. Knobs (the fields of
    ``_Knobs``, by name; an unknown one is a ``TypeError``) switch off whole families of
    constructs (e.g. ``file_quirks=False`` gives ``\\n`` line endings, 4-space
    indentation and a final newline; ``undeclared_keys=True`` lets conditions name keys no
    ``addParam`` declares, a latent bug SkiROS2 accepts and EzSkiROS keeps via
    ``self.param(...)``).

    Vocabulary is drawn without regard to the ontology, so ``skiros:hasA`` or
    ``cora:robotPart`` may link parameters whose classes violate their domain/range: SkiROS2
    loads that, the EzSkiROS early checks report it. ``consistent_vocabulary=True`` uses
    only relations without domain/range, so the migrated side passes the type checks
    (unknown vocabulary still gives warnings).
    """
    if not 1 <= min_classes <= max_classes:
        raise ValueError("need 1 <= min_classes <= max_classes")
    return _module(min_classes, max_classes, _Knobs(**knobs))


def legacy_modules(**knobs: Any) -> st.SearchStrategy[str]:
    """Legacy module source text with 1-3 description classes (see the module docstring)."""
    return legacy_modules_with_names(**knobs).map(lambda m: m.text)


legacy_module_texts: st.SearchStrategy[str] = legacy_modules()
"""The default strategy: ``@given(legacy_module_texts)``."""


# --------------------------------------------------------------------------------------
# Reading generated text back
# --------------------------------------------------------------------------------------

_BASE_NAMES = frozenset({"SkillDescription"})


def _base_name(node: ast.expr) -> str | None:
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        return node.attr
    return None


def description_class_names(text: str) -> list[str]:
    """Names of the classes in ``text`` that derive from ``SkillDescription`` (any alias).

    Works for generated modules and for simple hand-written ones; a class deriving from
    another description class of the same module counts too.
    """
    tree = ast.parse(text)
    aliases = set(_BASE_NAMES)
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            aliases.update(a.asname for a in node.names if a.name in _BASE_NAMES and a.asname)
    found: list[str] = []

    def is_description(base: ast.expr) -> bool:
        name = _base_name(base)
        return name in aliases or (isinstance(base, ast.Name) and name in found)

    for node in tree.body:
        if isinstance(node, ast.ClassDef) and any(is_description(b) for b in node.bases):
            found.append(node.name)
    return found
