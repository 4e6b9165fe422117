"""Generate a synthetic repository of Python files for benchmarking ezmigrate.

    python bench/generate_repo.py OUT --files 20000 --skill-share 0.1 --seed 0

writes ``--files`` modules into nested packages under OUT (folders with ``__init__.py``,
depth 1-4; the ``__init__.py`` files come on top of ``--files``). A share of the modules are
legacy SkiROS2 skill files (80-400 lines, 1-4 descriptions with 3-8 parameters and 2-6
conditions each, implementations alongside) whose construct mix follows the survey in
legacy-skiros2-api.md §7; the rest are ordinary modules (100-600 lines of classes, functions,
docstrings and comments) without descriptions, about 2% of which mention
``SkillDescription`` in a comment or string to defeat naive text prefilters.

Output is a pure function of the arguments: the same seed gives byte-identical trees.
OUT must be empty or absent; ``--clean`` first removes an OUT that this script generated
(recognised by its ``.generated-repo.json``, which also lists every skill file and its
description classes). Standard library only; one line of ``key=value`` summary on stdout.
"""

from __future__ import annotations

import argparse
import functools
import json
import random
import re
import shutil
import sys
import time
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

MANIFEST = ".generated-repo.json"

# --------------------------------------------------------------------------------------
# Word lists
# --------------------------------------------------------------------------------------

NOUNS = (
    "pose", "frame", "target", "buffer", "config", "sensor", "camera", "joint", "cloud", "map",
    "path", "goal", "state", "result", "message", "record", "entry", "item", "value", "batch",
    "request", "response", "cache", "queue", "model", "layer", "point", "image", "grid",
    "signal", "report", "event", "handler", "client", "session", "token", "table", "column",
)
VERBS = (
    "load", "save", "parse", "build", "update", "compute", "filter", "merge", "split", "sort",
    "convert", "validate", "check", "find", "collect", "publish", "read", "write", "send",
    "reset", "scale", "normalize", "resolve", "render", "apply", "extract", "format", "open",
)
PACKAGES = (
    "core", "utils", "perception", "planning", "control", "drivers", "io", "models", "tools",
    "config", "nodes", "skills", "msgs", "geometry", "vision", "hw", "sim", "common", "api",
    "web", "storage", "analysis", "calibration", "navigation", "manipulation", "tasks",
)
PROJECTS = ("lab", "cell", "robot", "demo", "ur5", "turtle", "kitting", "assembly")
SENTENCES = (
    "The caller owns the returned object.",
    "Values outside the valid range are clipped silently.",
    "This is called from the ROS callback thread; keep it cheap.",
    "Kept for backwards compatibility with the 2019 launch files.",
    "See the design notes in docs/architecture.md.",
    "Raises ValueError when the input is empty.",
    "The result is cached per process.",
    "Units are SI unless stated otherwise.",
)
COMMENTS = (
    "TODO: remove once the new driver is deployed", "NOTE: order matters here",
    "keep in sync with the config schema", "FIXME: this is O(n^2)", "fast path",
    "guard against division by zero", "legacy behaviour, do not change", "see issue #128",
)
TRAPS = (
    "    # unlike a SkillDescription subclass, this helper declares nothing\n",
    '    hint = "SkillDescription classes live in the skills package"\n',
    "    # (we used to subclass SkillDescription here; addParam moved to skills/)\n",
)

STDLIB_IMPORTS = (
    "import itertools", "import re", "import sys", "import time", "import functools",
    "from collections import defaultdict, OrderedDict", "from pathlib import Path",
    "from typing import Any, Dict, List, Optional", "import dataclasses",
)
THIRD_PARTY_IMPORTS = ("import numpy as np", "import yaml", "import requests", "import rospy")

# --------------------------------------------------------------------------------------
# Ordinary modules
# --------------------------------------------------------------------------------------

FUNCTION_TEMPLATES = (
    '''def {verb}_{noun}({a}, {b}=None):
    """{Verb} the {noun} from ``{a}``.

    {sentence}
    """
    if {b} is None:
        {b} = {CONST}
    result = []
    for item in {a}:
        # {comment}
        if item is None:
            continue
        result.append(item * {b})
    return result
''',
    '''def {verb}_{noun}_map({a}):
    """Group ``{a}`` by key. {sentence}"""
    groups = {{}}
    for key, value in {a}:
        groups.setdefault(key, []).append(value)
    return {{key: sorted(values) for key, values in groups.items()}}
''',
    '''def _{verb}_{noun}({a}, {b}):
    try:
        with open({a}) as fh:
            data = json.load(fh)
    except (OSError, ValueError) as exc:  # {comment}
        logger.warning("could not {verb} %s: %s", {a}, exc)
        return {b}
    return data.get("{noun}", {b})
''',
    '''def {verb}_{noun}_norm({a}, {b}):
    """Euclidean distance between two {noun}s."""
    return math.sqrt(sum((x - y) ** 2 for x, y in zip({a}, {b})))
''',
    '''def {verb}_all_{noun}s({a}, {b}=10, *, strict=False):
    """{Verb} at most ``{b}`` {noun}s.

    {sentence}
    {sentence2}
    """
    count = 0
    out = []
    while count < {b} and {a}:
        current = {a}.pop()
        if strict and not current:
            raise ValueError("empty {noun}")
        out.append(current)
        count += 1
    logger.debug("{verb}: %d {noun}s", count)
    return out
''',
    '''def {verb}_{noun}_path({a}):
    # {comment}
    base = os.environ.get("{ENV}", "/tmp")
    return os.path.join(base, "{noun}", str({a}))
''',
)

CLASS_TEMPLATES = (
    '''class {Noun}{Role}(object):
    """{Role} for {noun} objects.

    {sentence}
    """

    def __init__(self, {a}, {b}={CONST}):
        self.{a} = {a}
        self.{b} = {b}
        self._{noun}s = []

    def {verb}(self, {noun}):
        """{Verb} one {noun}."""
        if {noun} is None:
            raise ValueError("no {noun}")
        self._{noun}s.append({noun})
        return len(self._{noun}s)

    def {verb2}(self):
        # {comment}
        out = list(self._{noun}s)
        self._{noun}s = []
        return out

    def __len__(self):
        return len(self._{noun}s)

    def __repr__(self):
        return "{Noun}{Role}(%r, %r)" % (self.{a}, self.{b})
''',
    '''class {Noun}Error(Exception):
    """Raised when a {noun} cannot be {verb}ed."""

    def __init__(self, {noun}, reason=""):
        super().__init__("cannot {verb} %s: %s" % ({noun}, reason))
        self.{noun} = {noun}
        self.reason = reason
''',
    '''class {Noun}{Role}:
    """{sentence}"""

    {CONST2} = {number}

    def __init__(self):
        self._{a} = {{}}
        self._hits = 0

    def get(self, key, default=None):
        self._hits += 1
        return self._{a}.get(key, default)

    def put(self, key, value):
        # {comment}
        if len(self._{a}) > self.{CONST2}:
            self._{a}.pop(next(iter(self._{a})))
        self._{a}[key] = value

    @property
    def hits(self):
        return self._hits

    @classmethod
    def {verb}_from(cls, items):
        obj = cls()
        for key, value in items:
            obj.put(key, value)
        return obj
''',
)
ROLES = ("Manager", "Cache", "Buffer", "Registry", "Handler", "Tracker", "Pool", "Filter")


def _pick(seq: tuple[str, ...], r: float) -> str:
    """``seq[r * len]``: a cheaper ``rng.choice`` (the generator makes millions of picks)."""
    return seq[int(r * len(seq))]


_CONSTS = ("DEFAULT_SCALE", "MAX_ITEMS", "None")


def _fill(template: str, rng: random.Random) -> str:
    r = rng.random
    noun, verb = _pick(NOUNS, r()), _pick(VERBS, r())
    return template.format(
        noun=noun, Noun=noun.capitalize(), verb=verb, Verb=verb.capitalize(),
        verb2=_pick(VERBS, r()) + "_all", a=_pick(NOUNS, r()), b=_pick(NOUNS, r()) + "_arg",
        Role=_pick(ROLES, r()), sentence=_pick(SENTENCES, r()), sentence2=_pick(SENTENCES, r()),
        comment=_pick(COMMENTS, r()), CONST=_pick(_CONSTS, r()), CONST2="LIMIT",
        number=8 + int(r() * 4088), ENV=noun.upper() + "_DIR",
    )


@functools.cache
def _block_pool(kind: str) -> tuple[tuple[str, int], ...]:
    """Pre-filled blocks ``("\\n\\n" + code, line count)``: 512 variants per template.

    Filling templates per block would dominate the run time; picking from a fixed pool (built
    from a constant seed, so the output still depends only on the arguments) keeps 20,000
    files at a few seconds of CPU.
    """
    rng = random.Random(f"ezmigrate-bench-{kind}")
    templates = CLASS_TEMPLATES if kind == "class" else FUNCTION_TEMPLATES
    blocks = []
    for template in templates:
        for _ in range(512):
            text = "\n\n" + _fill(template, rng)
            blocks.append((text, text.count("\n")))
    return tuple(blocks)


def _module_header(rng: random.Random, title: str) -> list[str]:
    lines = [f'"""{title}.\n', "\n", f"{rng.choice(SENTENCES)}\n", '"""\n']
    if rng.random() < 0.3:
        lines.append("from __future__ import annotations\n\n")
    lines += ["import json\n", "import logging\n", "import math\n", "import os\n"]
    lines += [line + "\n" for line in rng.sample(STDLIB_IMPORTS, rng.randint(0, 3))]
    if rng.random() < 0.5:
        lines += ["\n", rng.choice(THIRD_PARTY_IMPORTS) + "\n"]
    lines += ["\n", "logger = logging.getLogger(__name__)\n", "\n",
              f"DEFAULT_SCALE = {rng.choice((0.5, 1.0, 2.0, 1e-3))}\n",
              f"MAX_ITEMS = {rng.randint(10, 1000)}\n"]
    return lines


def ordinary_module(rng: random.Random, trap: bool) -> str:
    """An ordinary module of 100-600 lines with no legacy description in it."""
    target = rng.randint(100, 570)  # the last block may overshoot by up to ~30 lines
    lines = _module_header(rng, f"{rng.choice(VERBS).capitalize()} {rng.choice(NOUNS)}s")
    count = sum(line.count("\n") for line in lines)
    trap_at = rng.randint(0, 3) if trap else -1
    block = 0
    classes, functions = _block_pool("class"), _block_pool("function")
    r = rng.random
    while count < target:
        pool = classes if r() < 0.3 else functions
        text, n = pool[int(r() * len(pool))]
        if block == trap_at:  # insert the trap as the first body line of this block
            head, _, rest = text.partition(":\n")
            text = head + ":\n" + rng.choice(TRAPS) + rest
            n += 1
        lines.append(text)
        count += n
        block += 1
    if trap and trap_at >= block:
        lines.append("\n\n# SkillDescription: none here (see skills/)\n")
    if rng.random() < 0.2:
        lines.append('\n\nif __name__ == "__main__":\n    logging.basicConfig()\n')
    return "".join(lines)


# --------------------------------------------------------------------------------------
# Legacy skill modules
# --------------------------------------------------------------------------------------

ELEMENT_TYPES = (
    ("skiros:Product", 10), ("skiros:Location", 8), ("rparts:GripperEffector", 6),
    ("skiros:TransformationPose", 3), ("skiros:GraspingPose", 3), ("skiros:Container", 3),
    ("skiros:DepthCamera", 3), ("rparts:ArmDevice", 3), ("cora:Robot", 2), ("sumo:Agent", 1),
    ("skiros:ApproachPose", 2), ("skiros:LargeBox", 1), (":Location", 1), ("Product", 1),
    ("scalable:Ur5", 2), ("scalable:Workstation", 2), ("turtlebot:Turtle", 2),
    ("skiros:Drawer", 2), ("skiros:Tray", 1), ("lab:Fixture", 1),
)
_ELEMENT_POOL = tuple(t for t, w in ELEMENT_TYPES for _ in range(w))
KEY_WORDS = (
    "Object", "Gripper", "Arm", "Location", "Target", "Container", "Camera", "Pose", "Tool",
    "Station", "Fixture", "Tray", "Drawer", "Handle", "Part", "Base", "Sensor", "Goal",
)
KEY_PREFIXES = ("", "", "", "Target", "Start", "Object", "Placing", "Grasping", "Approach")
LITERAL_KEYS = (
    "Speed", "Timeout", "Force", "Offset", "Frame", "Enabled", "Retries", "Distance",
    "Tolerance", "Duration", "Height", "Width", "Velocity", "Mode", "Topic", "Joints",
)
UNUSUAL_KEYS = ("On/Off", "Target Location", "Speed (m/s)", "grip-force", "2nd Object", "x")
RELATIONS = (("skiros:contain", 12), ("skiros:at", 4), ("skiros:hasA", 1),
             ("cora:robotPart", 1), ("skiros:spatiallyRelated", 1), ("turtlebot:Docked", 1))
_RELATION_POOL = tuple(r for r, w in RELATIONS for _ in range(w))
PROPERTIES = ("skiros:ContainerState", "skiros:StateProperty", "skiros:Open", "skiros:FrameId",
              "skiros:Size", "skiros:Position", "turtlebot:BatteryLevel")
FREE_LABELS = ("Holding", "EmptyHanded", "IsOpen", "Ready", "AtHome", "SafeToMove")
SKILL_VERBS = ("Pick", "Place", "Open", "Close", "Move", "Navigate", "Inspect", "Scan", "Grasp",
               "Release", "Push", "Pour", "Charge", "Dock", "Fetch", "Screw", "Sort", "Stack",
               "Insert", "Align", "Measure", "Wipe", "Turn", "Press")
SKILL_NOUNS = ("", "Object", "Part", "Drawer", "Door", "Box", "Tray", "Bin", "Cup", "Lid",
               "Shelf", "Tool", "Screw", "Valve", "Button", "Sample", "Kit", "Pallet")

IMPORT_STYLES = (
    # (import lines, base, Element, ParamTypes, ParamOptions), weights by repetition
    (("from skiros2_common.core.abstract_skill import SkillDescription, ParamOptions",
      "from skiros2_common.core.params import ParamTypes",
      "from skiros2_common.core.world_element import Element"),
     "SkillDescription", "Element", "ParamTypes", "ParamOptions"),
) * 6 + (
    (("from skiros2_skill.core.skill import SkillDescription, ParamOptions",
      "from skiros2_common.core.params import ParamTypes",
      "from skiros2_common.core.world_element import Element"),
     "SkillDescription", "Element", "ParamTypes", "ParamOptions"),
    (("from skiros2_common.core.abstract_skill import SkillDescription, ParamOptions",
      "from skiros2_common.core.params import ParamTypes as PT",
      "from skiros2_common.core.world_element import Element as E"),
     "SkillDescription", "E", "PT", "ParamOptions"),
    (("import skiros2_common.core.abstract_skill as sk",
      "import skiros2_common.core.params as params",
      "from skiros2_common.core.world_element import Element"),
     "sk.SkillDescription", "Element", "params.ParamTypes", "sk.ParamOptions"),
)
ROS_IMPORTS = ("import rospy", "import numpy as np", "from geometry_msgs.msg import Pose",
               "import moveit_commander", "import tf", "from std_msgs.msg import Bool")


def _q(text: str) -> str:
    return json.dumps(text, ensure_ascii=False)


def _conventional(kind: str, subject: str, vocab: str, obj: str, desired: bool) -> str:
    local = vocab.rsplit(":", 1)[-1]
    local = local[:1].upper() + local[1:]
    label = {"relation": f"{subject}{local}{obj}", "property": f"{subject}{local}",
             "has_property": f"{subject}Has{local}"}[kind]
    return label if desired else "Not" + label


@dataclass
class SkillFile:
    """What one generated skill module contains (for the summary and the manifest)."""

    text: str = ""
    classes: list[str] = field(default_factory=list)
    convertible: list[bool] = field(default_factory=list)
    python2: bool = False


def _param_line(rng: random.Random, key: str, category: str, style: tuple,
                consts: list[str]) -> str:
    _, _, element, ptypes, poptions = style
    options = ""
    if category == "element":
        value = f"{element}({_q(rng.choice(_ELEMENT_POOL))})"
        kind = rng.choice(("Required", "Required", "Inferred", "Inferred", "Optional"))
        if rng.random() < 0.08:
            options = f"[{poptions}.Lock]"
    elif category == "type":
        value = rng.choice(("float", "float", "str", "dict", "int", "bool"))
        kind = rng.choice(("Required", "Optional"))
    else:
        value = rng.choice((
            "0.0", "0.1", "0.5", "-0.5", "1.0", "2.5", "10.0", "True", "False", '""',
            '"base_link"', '"skiros:contain"', "0", "1", "3", "-1", "[0.0, 0.0, 0.0]",
            "[2.0, 8.0]", *consts))
        kind = rng.choice(("Optional", "Optional", "Optional", "Required"))
    kind_src = f"{ptypes}.{kind}" if rng.random() > 0.01 else str(
        ("Required", "Optional", "Inferred").index(kind))
    args = [_q(key), value, kind_src]
    d = rng.random()
    if options:
        args.append(options)
    elif d < 0.04:  # the silent-drop quirk: description in the options slot
        args.append(_q(rng.choice(("speed in m/s", "in seconds", "the target", "optional"))))
    elif d < 0.05:
        args.append(f"description={_q('set by the planner')}")
    return f"self.addParam({', '.join(args)})"


@functools.cache
def _index() -> Any:
    from ezskiros_runtime.ontology.load import load_index

    return load_index()


def _can_hold(relation: str, subject_type: str, object_type: str) -> bool:
    """Whether the bundled ontology lets ``relation`` hold between elements of these types.

    Real skills relate a device to a robot with ``cora:robotPart`` and a product to a pose
    with ``skiros:hasA``; random pairs would be type errors that EzSkiROS (rightly) refuses,
    which no real repository is made of.
    """
    from ezskiros_runtime.ontology.expressions import every

    index = _index()
    info = index.property(index.expand(relation) or "")
    for type_string, exprs in ((subject_type, info.domains if info else ()),
                               (object_type, info.ranges if info else ())):
        iri = index.expand(type_string)
        if iri is not None and exprs and index.can_satisfy(iri, every(exprs)) is False:
            return False  # the early checks' own rule for an error (check_types.py)
    return True


_CONDITION = re.compile(r'add(\w+)Condition\(.*\("([^"]*)", "([^"]*)", "([^"]*)", '
                        r'"([^"]*)", (True|False)\)')
"""list, label, relation, subject, object, desired of a generated relation condition."""


def _condition_line(rng: random.Random, subjects: list[str], cond_classes: bool,
                    types: dict[str, str]) -> str:
    target = rng.choice(("Pre", "Pre", "Pre", "Pre", "Post", "Post", "Post", "Hold"))
    r = rng.random()
    desired = rng.random() < 0.7
    subj = "Robot" if rng.random() < 0.25 else rng.choice(subjects)
    if r < 0.66:
        rel = rng.choice(_RELATION_POOL)
        others = [k for k in subjects if k != subj]
        obj = rng.choice(others or subjects)
        if not _can_hold(rel, types.get(subj, "sumo:Agent"), types.get(obj, "sumo:Agent")):
            rel = "skiros:contain"
        label = _conventional("relation", subj, rel, obj, desired)
        if rng.random() < 0.2:
            label = rng.choice(FREE_LABELS)
        args = f"{_q(label)}, {_q(rel)}, {_q(subj)}, {_q(obj)}, {desired}"
        call = f"ConditionRelation({args})" if cond_classes else f"self.getRelationCond({args})"
    elif r < 0.91:
        prop = rng.choice(PROPERTIES)
        value = rng.choice(("True", "True", "False", '"Idle"', '"Open"', "0.5", "1"))
        numeric = value[0].isdigit()
        op = rng.choice((">", "<", ">=", "<=", "=")) if numeric else "="
        label = _conventional("property", subj, prop, "", desired)
        call = (f"self.getPropCond({_q(label)}, {_q(prop)}, {_q(subj)}, {_q(op)}, {value}, "
                f"{desired})")
    elif r < 0.98:
        prop = rng.choice(PROPERTIES)
        label = _conventional("has_property", subj, prop, "", desired)
        call = f"self.getHasPropCond({_q(label)}, {_q(prop)}, {_q(subj)}, {desired})"
    else:
        factory = rng.choice(("getIsSpecifiedCond", "getGenerateCond"))
        call = f"self.{factory}({_q(subj + 'Specified')}, {_q(subj)}, {desired})"
    return f"self.add{target}Condition({call})"


def _description(rng: random.Random, name: str, style: tuple, consts: list[str],
                 comments: bool, cond_classes: bool, messy: bool) -> tuple[list[str], list[str]]:
    """(source lines of one description class, its Element keys)."""
    out = [f"class {name}({style[1]}):\n", "    def createDescription(self):\n"]
    body: list[str] = []
    keys: list[str] = []
    element_keys: list[str] = []
    types: dict[str, str] = {}
    for _ in range(rng.randint(3, 8)):
        # §7: Element values ~59%, type objects ~18%, literal defaults ~23%
        r = rng.random()
        category = "element" if r < 0.59 else "type" if r < 0.77 else "literal"
        for _attempt in range(5):
            if rng.random() < 0.06:
                key = rng.choice(UNUSUAL_KEYS)
            elif category == "element":
                prefix, word = rng.choice(KEY_PREFIXES), rng.choice(KEY_WORDS)
                key = word if prefix == word else prefix + word
            else:
                key = rng.choice(LITERAL_KEYS)
            if key not in keys:
                break
        else:
            continue
        keys.append(key)
        if category == "element":
            element_keys.append(key)
        body.append(_param_line(rng, key, category, style, consts))
        if category == "element":
            types[key] = re.findall(r'\("([^"]*)"\)', body[-1])[0]
    if comments:
        body.insert(0, "#=======Params=========")
        if rng.random() < 0.3:
            body.insert(rng.randint(1, len(body)), "# self.addParam(\"Debug\", False, 1)")
    subjects = element_keys or ["Robot"]
    if comments:
        body.append("#=======Conditions=========")
    wanted: dict[tuple[str, ...], str] = {}
    for _ in range(rng.randint(2, 6)):
        for _attempt in range(5):  # a real skill never wants one fact true and false at once
            line = _condition_line(rng, subjects, cond_classes, types)
            fact = _CONDITION.search(line)
            if fact is None or wanted.setdefault(fact.group(1, 3, 4, 5), fact[6]) == fact[6]:
                break
        body.append(line)
    if messy:  # not declarative: keys from a loop, or a lambda condition
        if rng.random() < 0.5:
            body += ["for i in range(3):",
                     f"    self.addParam(\"Waypoint%d\" % i, {style[2]}(\"skiros:Location\"), "
                     f"{style[3]}.Optional)"]
        else:
            body.append("self.addPreCondition(ConditionFunction(\"Ready\", lambda: True, True))")
    out += [f"        {line}\n" for line in body]
    return out, element_keys


def _primitive(rng: random.Random, desc: str, keys: list[str]) -> list[str]:
    key = _q(rng.choice(keys or ["Robot"]))
    lines = [
        f"class {desc[:1].lower()}{desc[1:]}_primitive(PrimitiveBase):\n",
        "    def createDescription(self):\n",
        f"        self.setDescription({desc}(), self.__class__.__name__)\n",
        "\n",
        "    def onStart(self):\n",
        "        self._ticks = 0\n",
        "        return True\n",
        "\n",
        "    def execute(self):\n",
        "        self._ticks += 1\n",
        f"        target = self.params[{key}].value\n",
        f"        if self._ticks < {rng.randint(2, 20)}:\n",
        "            return self.step(\"working on {}\".format(target))\n",
    ]
    lines.append(f"        return self.success(\"{desc} done\")\n")
    if rng.random() < 0.5:
        lines += ["\n", "    def onPreempt(self):\n",
                  "        return self.fail(\"Preempted\", -2)\n"]
    return lines


def _compound(rng: random.Random, desc: str, others: list[str]) -> list[str]:
    children = rng.sample(others, min(len(others), rng.randint(1, 3))) or [desc]
    lines = [
        f"class {desc[:1].lower()}{desc[1:]}_compound(SkillBase):\n",
        "    def createDescription(self):\n",
        f"        self.setDescription({desc}(), self.__class__.__name__)\n",
        "\n",
        "    def expand(self, skill):\n",
        "        skill.setProcessor(Sequential())\n",
        "        skill(\n",
    ]
    lines += [f"            self.skill({_q(c)}, \"\"),\n" for c in children]
    lines.append("        )\n")
    return lines


def skill_module(rng: random.Random, py2: bool, messy_share: float) -> SkillFile:
    """A legacy SkiROS2 skill module of 80-400 lines."""
    result = SkillFile()
    target = rng.randint(80, 380)
    style = rng.choice(IMPORT_STYLES)
    cond_classes = rng.random() < 0.03
    comments = rng.random() < 0.5
    descriptions_only = rng.random() < 0.07
    lines: list[str] = []
    if rng.random() < 0.3:
        lines.append("#!/usr/bin/env python\n")
    if rng.random() < 0.2:
        lines.append("# -*- coding: utf-8 -*-\n")
    lines.append(f'"""{rng.choice(SKILL_VERBS)} skills of the {rng.choice(PACKAGES)} cell."""\n')
    lines += [line + "\n" for line in rng.sample(ROS_IMPORTS, rng.randint(1, 4))]
    helpers_at = len(lines)  # imports for the padding helpers go here, if any
    lines.append("\n")
    lines += [line + "\n" for line in style[0]]
    if cond_classes:
        lines.append("from skiros2_common.core.conditions import ConditionRelation\n")
    if not descriptions_only:
        lines.append("from skiros2_common.core.primitive import PrimitiveBase\n")
        lines.append("from skiros2_skill.core.skill import SkillBase, Sequential\n")
    messy_any = messy_share > 0 and rng.random() < messy_share * 3
    if messy_any:
        lines.append("from skiros2_common.core.conditions import ConditionFunction\n")
    consts = []
    if rng.random() < 0.4:
        consts = ["DEFAULT_SPEED"]
        lines += ["\n", f"DEFAULT_SPEED = {rng.choice(('0.1', '0.25', '0.5'))}\n"]
    names: list[str] = []
    n_descriptions = rng.randint(1, 4)
    while len(names) < n_descriptions:
        name = rng.choice(SKILL_VERBS) + rng.choice(SKILL_NOUNS)
        if name not in names:
            names.append(name)
    impls: list[list[str]] = []
    for name in names:
        messy = messy_any and rng.random() < 1 / 3
        block, keys = _description(rng, name, style, consts, comments, cond_classes, messy)
        lines += ["\n", "\n", *block]
        result.classes.append(name)
        result.convertible.append(not messy)
        if descriptions_only:
            continue
        if rng.random() < 0.15 and len(names) > 1:
            impls.append(_compound(rng, name, [n for n in names if n != name]))
        else:
            impls.append(_primitive(rng, name, keys))
    for block in impls:
        lines += ["\n", "\n", *block]
    count = sum(line.count("\n") for line in lines)
    if count < target:  # pad with helper functions, which need a few imports
        helper_header = ["import json\n", "import logging\n", "import math\n", "import os\n"]
        lines[helpers_at:helpers_at] = helper_header
        lines += ["\n\n", "logger = logging.getLogger(__name__)\n", "DEFAULT_SCALE = 1.0\n",
                  "MAX_ITEMS = 100\n"]
        count += len(helper_header) + 5
    functions = _block_pool("function")
    while count < target:
        block, n = functions[int(rng.random() * len(functions))]
        lines.append(block)
        count += n
    if py2:  # a Python-2 print statement: the file no longer compiles on Python 3
        lines.append('\n\nprint "%s skills loaded" % __name__\n')
        result.python2 = True
    text = "".join(lines)
    if rng.random() < 0.25:
        text = text.rstrip("\n")  # about a quarter of real files lack the final newline
    result.text = text
    return result


# --------------------------------------------------------------------------------------
# Repository layout
# --------------------------------------------------------------------------------------


def _packages(rng: random.Random, n_files: int) -> list[tuple[str, ...]]:
    """Package paths (tuples of folder names, depth 1-4), about 25 modules per package."""
    wanted = max(1, n_files // 25)
    packages: list[tuple[str, ...]] = []
    top = max(1, min(len(PACKAGES), wanted // 6 or 1))
    for name in rng.sample(PACKAGES, top):  # prefixed: never shadows a stdlib module (io)
        packages.append((f"{rng.choice(PROJECTS)}_{name}",))
    serial = 0
    while len(packages) < wanted:
        depth = rng.choice((2, 2, 2, 3, 3, 3, 4, 4))  # nesting of the new package
        parents = [p for p in packages if len(p) == depth - 1]
        if not parents:
            continue
        serial += 1
        packages.append((*rng.choice(parents), f"{rng.choice(PACKAGES)}_{serial}"))
    return packages


@dataclass
class Summary:
    files: int = 0
    init_files: int = 0
    skill_files: int = 0
    skills: int = 0
    convertible: int = 0
    python2_files: int = 0
    lines: int = 0
    manifest: list[dict] = field(default_factory=list)


def _write(path: Path, text: str) -> None:
    with open(path, "w", encoding="utf-8", newline="") as fh:
        fh.write(text)


def generate(out: Path, files: int, skill_share: float = 0.1, seed: int = 0, *,
             py2_share: float = 0.0, messy_share: float = 0.0) -> Summary:
    """Write the repository into ``out`` (which must not exist or be empty)."""
    if files < 0 or not 0.0 <= skill_share <= 1.0:
        raise ValueError("need files >= 0 and 0 <= skill_share <= 1")
    rng = random.Random(seed)
    packages = _packages(rng, files)
    n_skill = round(files * skill_share)
    skill_indices = set(rng.sample(range(files), n_skill))
    trap_indices = {i for i in range(files) if i not in skill_indices and rng.random() < 0.02}
    assignment = [rng.randrange(len(packages)) for _ in range(files)]
    for i in range(min(files, len(packages))):
        assignment[i] = i  # every package gets at least one module
    summary = Summary()
    out.mkdir(parents=True, exist_ok=True)
    for pkg in packages:
        folder = out.joinpath(*pkg)
        for depth in range(1, len(pkg) + 1):
            init = out.joinpath(*pkg[:depth], "__init__.py")
            if not init.exists():
                init.parent.mkdir(parents=True, exist_ok=True)
                doc = f'"""{pkg[depth - 1]} package."""\n' if rng.random() < 0.3 else ""
                init.write_text(doc, encoding="utf-8")
                summary.init_files += 1
        folder.mkdir(parents=True, exist_ok=True)
    layout = _Layout(packages, assignment, skill_indices, trap_indices)
    for path, text in _modules(out, layout, seed, py2_share, messy_share, summary):
        _write(path, text)
    return summary


@dataclass(frozen=True)
class _Layout:
    """Where each module goes (``assignment``: its package's index, one per module) and
    which modules are skill files or traps, as ``generate`` drew them."""

    packages: list[tuple[str, ...]]
    assignment: list[int]
    skill_indices: set[int]
    trap_indices: set[int]


def _modules(out: Path, layout: _Layout, seed: int, py2_share: float, messy_share: float,
             summary: Summary) -> Iterator[tuple[Path, str]]:
    """Each module's path and text, counted into ``summary`` as it is made."""
    used: dict[int, set[str]] = {}
    for index, pkg_index in enumerate(layout.assignment):
        file_rng = random.Random(seed * 1_000_003 + index)
        taken = used.setdefault(pkg_index, set())
        stem = f"{file_rng.choice(VERBS)}_{file_rng.choice(NOUNS)}"
        if stem in taken:
            stem = f"{stem}_{index}"
        taken.add(stem)
        path = out.joinpath(*layout.packages[pkg_index], stem + ".py")
        if index in layout.skill_indices:
            skill = skill_module(file_rng, file_rng.random() < py2_share, messy_share)
            text = skill.text
            summary.skill_files += 1
            summary.skills += len(skill.classes)
            summary.convertible += sum(skill.convertible)
            summary.python2_files += skill.python2
            summary.manifest.append({
                "path": path.relative_to(out).as_posix(), "classes": skill.classes,
                "convertible": skill.convertible, "python2": skill.python2,
            })
        else:
            text = ordinary_module(file_rng, index in layout.trap_indices)
        summary.files += 1
        summary.lines += text.count("\n") + (0 if text.endswith("\n") or not text else 1)
        yield path, text


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out", type=Path, help="output folder (created; must be empty)")
    parser.add_argument("--files", type=int, default=1000,
                        help="number of modules, not counting __init__.py (default 1000)")
    parser.add_argument("--skill-share", type=float, default=0.1,
                        help="share of modules that are legacy skill files (default 0.1)")
    parser.add_argument("--seed", type=int, default=0, help="random seed (default 0)")
    parser.add_argument("--py2-share", type=float, default=0.0,
                        help="share of skill files ending in a Python-2 print statement, which "
                             "then do not compile (default 0)")
    parser.add_argument("--messy-share", type=float, default=0.0,
                        help="approximate share of descriptions with non-declarative code "
                             "(default 0)")
    parser.add_argument("--clean", action="store_true",
                        help=f"first remove OUT if it holds a {MANIFEST} from this script")
    args = parser.parse_args(argv)
    out: Path = args.out
    if args.clean and out.exists():
        if not (out / MANIFEST).is_file():
            parser.error(f"--clean: {out} has no {MANIFEST}; refusing to delete it")
        shutil.rmtree(out)
    if out.exists() and any(out.iterdir()):
        parser.error(f"{out} is not empty (use --clean to regenerate)")
    start = time.perf_counter()
    summary = generate(out, args.files, args.skill_share, args.seed,
                       py2_share=args.py2_share, messy_share=args.messy_share)
    seconds = time.perf_counter() - start
    fields = {"files": summary.files, "init_files": summary.init_files,
              "skill_files": summary.skill_files, "skills": summary.skills,
              "convertible_skills": summary.convertible,
              "python2_skill_files": summary.python2_files, "lines": summary.lines,
              "seed": args.seed}
    manifest = {"arguments": {"files": args.files, "skill_share": args.skill_share,
                              "seed": args.seed, "py2_share": args.py2_share,
                              "messy_share": args.messy_share},
                "summary": fields, "skill_files": summary.manifest}
    (out / MANIFEST).write_text(json.dumps(manifest, indent=1) + "\n", encoding="utf-8")
    print(" ".join(f"{k}={v}" for k, v in fields.items()) + f" seconds={seconds:.2f} out={out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
