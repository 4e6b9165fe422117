"""addParam: every value spelling, kind, option, description and key form."""

from codemod_case import HEADER, assert_migrates, assert_skipped


def case(body: str) -> str:
    return HEADER + "\n\nclass S(SkillDescription):\n    def createDescription(self):\n" + body


def test_element_kinds_use_ontology_classes():
    assert_migrates(case(
        '        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)\n'
        '        self.addParam("Place", Element("skiros:Location"), ParamTypes.Inferred)\n'
        '        self.addParam("Hand", Element("rparts:GripperEffector"), ParamTypes.Optional)\n'
    ), '''\
from ezskiros_runtime import SkillDescription, INFERRED, OPTIONAL
from ezskiros_runtime.ontology import rparts, skiros


class S(SkillDescription):
    def description(self,
                    Object: skiros.Product,
                    Place: INFERRED[skiros.Location],
                    Hand: OPTIONAL[rparts.GripperEffector]):
        pass
''')


def test_verbatim_element_strings_and_unknown_vocabulary():
    result = assert_migrates(case(
        '        self.addParam("A", Element(":Location"), ParamTypes.Required)\n'
        '        self.addParam("B", Element("Location"), ParamTypes.Required)\n'
        '        self.addParam("C", Element(), ParamTypes.Required)\n'
        '        self.addParam("D", Element("scalable:Ur5"), ParamTypes.Required)\n'
    ), '''\
from ezskiros_runtime import SkillDescription, Annotated, REQUIRED, ELEMENT


class S(SkillDescription):
    def description(self,
                    A: Annotated[REQUIRED, ELEMENT(":Location")],
                    B: Annotated[REQUIRED, ELEMENT("Location")],
                    C: ELEMENT(),
                    D: Annotated[REQUIRED, ELEMENT("scalable:Ur5")]):
        pass
''')
    spelled = [f.message for f in result.skills[0].findings if f.kind == "element-type-spelling"]
    assert len(spelled) == 2 and "':Location'" in spelled[0] and "'Location'" in spelled[1]
    assert not any("Unknown" in f.message for f in result.skills[0].findings)  # Element()


def test_type_objects_and_literal_defaults_keep_exact_types():
    assert_migrates(case(
        '        self.addParam("F", float, ParamTypes.Required)\n'
        '        self.addParam("D", dict, ParamTypes.Optional)\n'
        '        self.addParam("I", 0, ParamTypes.Required)\n'
        '        self.addParam("X", 0.0, ParamTypes.Optional)\n'
        '        self.addParam("B", True, ParamTypes.Optional)\n'
        '        self.addParam("N", -1, 1)\n'
        '        self.addParam("E", 1e-3, ParamTypes.Optional)\n'
        '        self.addParam("L", [2.0, 8.0], ParamTypes.Optional)\n'
        '        self.addParam("S", "", ParamTypes.Optional)\n'
    ), '''\
from ezskiros_runtime import SkillDescription, OPTIONAL


class S(SkillDescription):
    def description(self,
                    F: float,
                    D: OPTIONAL[dict],
                    I: int = 0,
                    X: OPTIONAL[float] = 0.0,
                    B: OPTIONAL[bool] = True,
                    N: OPTIONAL[int] = -1,
                    E: OPTIONAL[float] = 1e-3,
                    L: OPTIONAL[list[float]] = [2.0, 8.0],
                    S: OPTIONAL[str] = ""):
        pass
''')


def test_keyword_only_marker_only_when_python_needs_it():
    result = assert_migrates(case(
        '        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)\n'
        '        self.addParam("Speed", 0.5, ParamTypes.Optional)\n'
    ), '''\
from ezskiros_runtime import SkillDescription, OPTIONAL
from ezskiros_runtime.ontology import skiros


class S(SkillDescription):
    def description(self,
                    Object: skiros.Product,
                    Speed: OPTIONAL[float] = 0.5):
        pass
''')
    assert result.skills[0].status == "converted"


def test_options_description_and_the_fourth_positional_quirk():
    result = assert_migrates(case(
        '        self.addParam("Cam", Element("skiros:Location"), ParamTypes.Required, [ParamOptions.Lock, ParamOptions.Consume])\n'
        '        self.addParam("Speed", 0.5, ParamTypes.Optional, [], "m/s")\n'
        '        self.addParam("Mass", float, ParamTypes.Required, description="kg")\n'
        '        self.addParam("Force", 1.0, ParamTypes.Optional, "newton")\n'
    ), '''\
from ezskiros_runtime import SkillDescription, Annotated, OPTIONAL, REQUIRED, DESC, Lock, Consume
from ezskiros_runtime.ontology import skiros


class S(SkillDescription):
    def description(self,
                    Cam: REQUIRED[skiros.Location, Lock, Consume],
                    *,
                    Speed: Annotated[OPTIONAL[float], DESC("m/s")] = 0.5,
                    Mass: Annotated[float, DESC("kg")],
                    Force: OPTIONAL[float] = 1.0):  # newton
        pass
''')
    kinds = [f.kind for f in result.skills[0].findings]
    assert "description-in-options" in kinds


def test_text_in_the_options_slot_stays_as_a_comment_on_the_parameters_line():
    """Issue 22: SkiROS2 drops it (so no DESC), but the author's words are not lost; a
    comment already on the line follows, and text no comment line can hold is a literal."""
    result = assert_migrates(case(
        '        self.addParam("Linear", float, ParamTypes.Required, "Linear velocity")\n'
        '        self.addParam("Turn", 0.5, ParamTypes.Optional, "rad/s")  # measured\n'
        '        self.addParam("Note", "", ParamTypes.Optional, "two\\nlines")\n'
        '        self.addParam("Mass", 1.0, ParamTypes.Optional, "")\n'
    ), '''\
from ezskiros_runtime import SkillDescription, OPTIONAL


class S(SkillDescription):
    def description(self,
                    Linear: float,  # Linear velocity
                    Turn: OPTIONAL[float] = 0.5,  # rad/s  # measured
                    Note: OPTIONAL[str] = "",  # 'two\\nlines'
                    Mass: OPTIONAL[float] = 1.0):
        pass
''')
    messages = [f.message for f in result.skills[0].findings]
    assert all("as a comment on the parameter's line, meaning unchanged" in m
               for m in messages[:3]), messages


def test_options_on_non_element_values_are_dropped_with_a_finding():
    result = assert_migrates(case(
        '        self.addParam("T", 0.5, ParamTypes.Optional, [ParamOptions.Lock])\n'
    ), '''\
from ezskiros_runtime import SkillDescription, OPTIONAL


class S(SkillDescription):
    def description(self,
                    T: OPTIONAL[float] = 0.5):
        pass
''')
    assert [f.kind for f in result.skills[0].findings] == ["options-ignored"]


def test_keys_that_are_not_identifiers_get_a_key_escape():
    assert_migrates(case(
        '        self.addParam("On/Off", True, ParamTypes.Required)\n'
        '        self.addParam("from", Element("skiros:Location"), ParamTypes.Required)\n'
        '        self.addParam("2nd", 1, ParamTypes.Optional)\n'
        '        self.addPreCondition(self.getRelationCond("fromContain2nd", "skiros:contain", "from", "2nd", True))\n'
    ), '''\
from ezskiros_runtime import SkillDescription, Annotated, OPTIONAL, KEY
from ezskiros_runtime.ontology import skiros


class S(SkillDescription):
    def description(self,
                    *,
                    On_Off: Annotated[bool, KEY("On/Off")] = True,
                    from_: Annotated[skiros.Location, KEY("from")],
                    _2nd: Annotated[OPTIONAL[int], KEY("2nd")] = 1):
        self.pre_conditions += from_.contain(_2nd)
''')


def test_keys_python_would_mangle_in_a_class_get_a_key_escape():
    """Inside a class body ``__tool`` becomes ``_S__tool``: the key would silently change."""
    assert_migrates(case(
        '        self.addParam("__tool", Element("skiros:Product"), ParamTypes.Required)\n'
    ), '''\
from ezskiros_runtime import SkillDescription, Annotated, KEY
from ezskiros_runtime.ontology import skiros


class S(SkillDescription):
    def description(self,
                    tool: Annotated[skiros.Product, KEY("__tool")]):
        pass
''')


def test_redeclared_key_takes_the_first_position():
    assert_migrates(case(
        '        self.addParam("Speed", 0.1, ParamTypes.Optional)\n'
        '        self.addParam("Other", 1, ParamTypes.Optional)\n'
        '        self.addParam("Speed", 0.02, ParamTypes.Optional)\n'
    ), '''\
from ezskiros_runtime import SkillDescription, OPTIONAL


class S(SkillDescription):
    def description(self,
                    Speed: OPTIONAL[float] = 0.02,
                    Other: OPTIONAL[int] = 1):
        pass
''')


def test_redeclared_key_with_options_keeps_both_declarations():
    assert_migrates(case(
        '        self.addParam("Arm", Element("skiros:Location"), ParamTypes.Required, [ParamOptions.Lock])\n'
        '        self.addParam("Arm", Element("skiros:Product"), ParamTypes.Required)\n'
    ), '''\
from ezskiros_runtime import SkillDescription, Annotated, REQUIRED, KEY, Lock
from ezskiros_runtime.ontology import skiros


class S(SkillDescription):
    def description(self,
                    Arm: REQUIRED[skiros.Location, Lock],
                    Arm_2: Annotated[skiros.Product, KEY("Arm")]):
        pass
''')


def test_module_constants_keep_their_name_and_get_their_type():
    assert_migrates('SPEED = 0.5\nUNKNOWN = compute()\n' + case(
        '        self.addParam("Speed", SPEED, ParamTypes.Optional, [], "m/s")\n'
        '        self.addParam("Other", UNKNOWN, ParamTypes.Optional)\n'
    ), '''\
SPEED = 0.5
UNKNOWN = compute()
from ezskiros_runtime import SkillDescription, Annotated, OPTIONAL, DESC  # noqa: E402


class S(SkillDescription):
    def description(self,
                    Speed: Annotated[OPTIONAL[float], DESC("m/s")] = SPEED,
                    Other: OPTIONAL = UNKNOWN):
        pass
''')


def test_fork_api_and_runtime_keys_are_skipped_with_reasons():
    assert_skipped(case('        self.addParam("A", float, ParamTypes.SharedInput)\n'),
                   "ParamTypes.SharedInput", "not upstream")
    assert_skipped(case('        self.addParam("A", float, ParamTypes.Required, remap="B")\n'),
                   "remap=", "not upstream")
    assert_skipped(case('        key = self.name()\n        self.addParam(key, float, 0)\n'),
                   "computed at run time")
    assert_skipped(case('        self.addParam("A", [], ParamTypes.Optional)\n'), "reject")


def test_defaults_the_class_body_would_read_differently_block_the_skill():
    """In ``createDescription`` ``SPEED`` is the module's; as a signature default it is read
    in the class body, which may bind its own, or name the class before it exists."""
    module = HEADER + "\nSPEED = 0.5\n\n\nclass Move(SkillDescription):\n"
    assert_skipped(module + "    SPEED = 2.0\n\n    def createDescription(self):\n"
                   '        self.addParam("Speed", SPEED, ParamTypes.Optional)\n',
                   "`SPEED`", "binds its own `SPEED`")
    assert_skipped(module + "    LIMIT = 2.0\n\n    def createDescription(self):\n"
                   '        self.addParam("Speed", Move.LIMIT, ParamTypes.Optional)\n',
                   "`Move.LIMIT`", "Move is not defined yet")


def test_identifier_keys_keep_their_own_name_before_made_up_ones_take_it():
    """``"Target Location"`` would be spelt ``Target_Location``, but that is the real key
    declared after it: the real key keeps its name, the made-up one moves aside."""
    assert_migrates(case(
        '        self.addParam("Target Location", Element("skiros:Location"), ParamTypes.Required)\n'
        '        self.addParam("Target_Location", Element("skiros:Location"), ParamTypes.Required)\n'
    ), '''\
from ezskiros_runtime import SkillDescription, Annotated, KEY
from ezskiros_runtime.ontology import skiros


class S(SkillDescription):
    def description(self,
                    Target_Location_2: Annotated[skiros.Location, KEY("Target Location")],
                    Target_Location: skiros.Location):
        pass
''')


def test_module_constants_as_keys_and_descriptions_resolve_like_constant_values():
    assert_migrates('KEY_NAME = "Target"\nWHERE = "where to go"\n' + case(
        '        self.addParam(KEY_NAME, Element("skiros:Location"), ParamTypes.Required,\n'
        '                      description=WHERE)\n'
        '        self.addPreCondition(self.getRelationCond("c", "skiros:contain", KEY_NAME, "B", True))\n'
    ), '''\
KEY_NAME = "Target"
WHERE = "where to go"
from ezskiros_runtime import SkillDescription, Annotated, DESC  # noqa: E402
from ezskiros_runtime.ontology import skiros  # noqa: E402


class S(SkillDescription):
    def description(self,
                    Target: Annotated[skiros.Location, DESC(WHERE)]):
        self.pre_conditions += Target.contain(self.param("B")).named("c")
''')


def test_module_constants_a_local_or_the_class_shadows_are_not_used_as_such():
    """``createDescription`` binding the name makes it local throughout (legacy fails there
    too); a name bound twice (here also by the class) is no constant."""
    assert_skipped('KEY_NAME = "Target"\n' + case(
        '        self.addParam(KEY_NAME, float, ParamTypes.Required)\n'
        '        KEY_NAME = compute()\n'), "`KEY_NAME`", "computed at run time")
    assert_skipped(HEADER + ('\nWHERE = "there"\n\n\nclass S(SkillDescription):\n'
                             '    WHERE = "here"\n\n    def createDescription(self):\n'
                             '        self.addParam("A", float, ParamTypes.Required, [], WHERE)\n'),
                   "`WHERE`", "computed at run time")


def test_a_description_held_in_a_local_is_written_as_its_value():
    """The signature is read in the class body, where ``createDescription``'s locals do not
    exist: ``DESC(unit)`` would be a NameError."""
    assert_migrates(case(
        '        unit = "m/s"\n'
        '        self.addParam("Speed", 0.5, ParamTypes.Optional, [], unit)\n'
    ), '''\
from ezskiros_runtime import SkillDescription, Annotated, OPTIONAL, DESC


class S(SkillDescription):
    def description(self,
                    Speed: Annotated[OPTIONAL[float], DESC("m/s")] = 0.5):
        pass
''')


def test_an_element_label_has_no_place_in_the_signature_and_says_so():
    assert_skipped(case(
        '        self.addParam("A", Element("skiros:Product", "cup"), ParamTypes.Required)\n'),
        "line 8", "passes a label", 'Element(etype, label="", eid=-1) accepts that',
        "pass only the type")


def test_findings_point_at_the_add_param_or_condition_that_causes_them():
    result = assert_migrates(case(
        '        self.addParam("A", Element("Location"), ParamTypes.Required)\n'
        '        self.addParam("B", Element("skiros:Nope"), ParamTypes.Required)\n'
        '        self.addPreCondition(self.getRelationCond("c", "skiros:nothere", "A", "W", True))\n'
    ), '''\
from ezskiros_runtime import SkillDescription, Annotated, REQUIRED, ELEMENT


class S(SkillDescription):
    def description(self,
                    A: Annotated[REQUIRED, ELEMENT("Location")],
                    B: Annotated[REQUIRED, ELEMENT("skiros:Nope")]):
        self.pre_conditions += A.relation("skiros:nothere", self.param("W")).named("c")
''')
    lines = {(f.kind, f.message.split("'")[-2]): f.line for f in result.skills[0].findings}
    assert lines == {("undeclared-key", "W"): 10, ("element-type-spelling", "Location"): 8,
                     ("unknown-vocabulary", "skiros:Nope"): 9,
                     ("unknown-vocabulary", "skiros:nothere"): 10}, lines
