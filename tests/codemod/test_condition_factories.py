"""Every condition factory and condition class, both desired states, both label kinds."""

from codemod_case import HEADER, assert_migrates, assert_skipped


def case(conditions: str, extra_imports: str = "") -> str:
    return extra_imports + HEADER + (
        "\n\nclass S(SkillDescription):\n    def createDescription(self):\n"
        '        self.addParam("A", Element("skiros:Location"), ParamTypes.Required)\n'
        '        self.addParam("B", Element("skiros:Product"), ParamTypes.Required)\n'
        + conditions)


OUT = '''\
from ezskiros_runtime import SkillDescription{imports}
from ezskiros_runtime.ontology import skiros{spaces}


class S(SkillDescription):
    def description(self,
                    A: skiros.Location,
                    B: skiros.Product{robot}):
{body}'''


def expected(body: str, imports: str = "", spaces: str = "", robot: str = "") -> str:
    return OUT.format(body=body, imports=imports, spaces=spaces, robot=robot)


def test_relation_conventional_labels_both_states():
    assert_migrates(case(
        '        self.addPreCondition(self.getRelationCond("AContainB", "skiros:contain", "A", "B", True))\n'
        '        self.addPostCondition(self.getRelationCond("NotAContainB", "skiros:contain", "A", "B", False))\n'
    ), expected('        self.pre_conditions += A.contain(B)\n'
                '        self.post_conditions += ~ A.contain(B)\n'))


def test_relation_unconventional_label_is_named():
    assert_migrates(case(
        '        self.addPreCondition(self.getRelationCond("Holding", "skiros:contain", "A", "B", True))\n'
        '        self.addPreCondition(self.getRelationCond("EmptyHanded", "skiros:contain", "A", "B", False))\n'
    ), expected('        self.pre_conditions += A.contain(B).named("Holding")\n'
                '        self.pre_conditions += ~ A.contain(B).named("EmptyHanded")\n'))


def test_verbatim_relation_for_unknown_or_unprefixed_vocabulary():
    assert_migrates(case(
        '        self.addPreCondition(self.getRelationCond("AContainB", ":contain", "A", "B", True))\n'
        '        self.addPreCondition(self.getRelationCond("ADockedB", "turtlebot:docked", "A", "B", True))\n'
    ), expected('        self.pre_conditions += A.relation(":contain", B)\n'
                '        self.pre_conditions += A.relation("turtlebot:docked", B)\n'))


def test_abstract_relation():
    assert_migrates(case(
        '        self.addPreCondition(self.getAbstractRelationCond("AContainB", "skiros:contain", "A", "B", True))\n'
        '        self.addPreCondition(self.getAbstractRelationCond("X", "skiros:contain", "A", "B", False))\n'
    ), expected('        self.pre_conditions += abstract(A.contain(B))\n'
                '        self.pre_conditions += ~ abstract(A.contain(B).named("X"))\n',
                imports=", abstract"))


def test_property_operators_values_and_verbatim_form():
    assert_migrates(case(
        '        self.addPreCondition(self.getPropCond("APositionX", "skiros:PositionX", "A", ">", 0.5, True))\n'
        '        self.addPreCondition(self.getPropCond("APositionX", "skiros:PositionX", "A", "<=", 1, True))\n'
        '        self.addPreCondition(self.getPropCond("NotAPositionX", "skiros:PositionX", "A", "=", 0.0, False))\n'
        '        self.addPreCondition(self.getPropCond("Open", "skiros:Open", "A", "=", False, True))\n'
        '        self.addPreCondition(self.getPropCond("APositionX", "skiros:PositionX", "A", "!=", 2.0, True))\n'
        '        self.addPreCondition(self.getPropCond("APositionX", "skiros:PositionX", "A", ">=", 0.25, True))\n'
        '        self.addPreCondition(self.getPropCond("APositionX", "skiros:PositionX", "A", "<", 3, True))\n'
        '        self.addPreCondition(self.getPropCond("APositionX", "skiros:PositionX", "A", "=", True, True))\n'
    ), expected('        self.pre_conditions += A.PositionX.gt(0.5)\n'
                '        self.pre_conditions += A.PositionX.le(1)\n'
                '        self.pre_conditions += ~ A.PositionX.eq(0.0)\n'
                '        self.pre_conditions += A.property("skiros:Open", "=", False).named("Open")\n'
                '        self.pre_conditions += A.property("skiros:PositionX", "!=", 2.0)\n'
                '        self.pre_conditions += A.PositionX.ge(0.25)\n'
                '        self.pre_conditions += A.PositionX.lt(3)\n'
                '        self.pre_conditions += A.PositionX.eq(True)\n'))


def test_has_property_is_specified_generate_on_type():
    assert_migrates(case(
        '        self.addPreCondition(self.getHasPropCond("AHasPosition", "skiros:Position", "A", True))\n'
        '        self.addPreCondition(self.getHasPropCond("NotBHasFoo", "skiros:Foo", "B", False))\n'
        '        self.addPreCondition(self.getIsSpecifiedCond("ASpecified", "A", True))\n'
        '        self.addPreCondition(self.getIsSpecifiedCond("Unset", "A", False))\n'
        '        self.addPostCondition(self.getGenerateCond("BGenerated", "B", True))\n'
        '        self.addPostCondition(self.getGenerateCond("NotBGenerated", "B", False))\n'
        '        self.addPreCondition(self.getOnTypeCond("BOfType", "B", "skiros:Product"))\n'
        '        self.addPreCondition(self.getOnTypeCond("IsProduct", "B", ":Product"))\n'
    ), expected('        self.pre_conditions += A.has(skiros.Position)\n'
                '        self.pre_conditions += ~ B.has("skiros:Foo")\n'
                '        self.pre_conditions += A.is_specified()\n'
                '        self.pre_conditions += ~ A.is_specified().named("Unset")\n'
                '        self.post_conditions += B.generated()\n'
                '        self.post_conditions += ~ B.generated()\n'
                '        self.pre_conditions += B.is_a(skiros.Product)\n'
                '        self.pre_conditions += B.is_a(":Product").named("IsProduct")\n'))


def test_condition_classes_from_the_conditions_module():
    """ConditionProperty was never used: it stays (the migration did not make it unused)."""
    imports = ("from skiros2_common.core.conditions import ConditionRelation, ConditionProperty\n"
               "import skiros2_common.core.conditions as cond\n")
    assert_migrates(case(
        '        self.addPreCondition(ConditionRelation("AContainB", "skiros:contain", "A", "B", True))\n'
        '        self.addPreCondition(cond.ConditionHasProperty("AHasPosition", "skiros:Position", "A", True))\n',
        imports), "from skiros2_common.core.conditions import ConditionProperty\n"
        + expected('        self.pre_conditions += A.contain(B)\n'
                   '        self.pre_conditions += A.has(skiros.Position)\n'))


def test_automatic_robot_and_undeclared_keys():
    result = assert_migrates(case(
        '        self.addPreCondition(self.getRelationCond("RobotAtA", "skiros:at", "Robot", "A", True))\n'
        '        self.addPreCondition(self.getRelationCond("ToolContainB", "skiros:contain", "Tool", "B", True))\n'
    ), expected('        self.pre_conditions += Robot.at(A)\n'
                '        self.pre_conditions += self.param("Tool").contain(B)\n',
                imports=", INFERRED", spaces=", sumo",
                robot=",\n                    Robot: INFERRED[sumo.Agent]"))
    assert [f.kind for f in result.skills[0].findings] == ["undeclared-key"]


def test_condition_function_and_odd_desired_states_are_skipped():
    assert_skipped(case("        self.addPreCondition(ConditionFunction('x', lambda: True))\n",
                        "from skiros2_common.core.conditions import ConditionFunction\n"),
                   "ConditionFunction", "not declarative")
    assert_skipped(case('        self.addPreCondition(self.getRelationCond("x", "skiros:at", "A", "B", 1))\n'),
                   "desired state")
    assert_skipped(case('        self.addPreCondition(self.getRelationCond(self.l, "skiros:at", "A", "B", True))\n'),
                   "computed at run time")


def test_short_forms_only_for_the_default_prefix_other_prefixes_stay_qualified():
    """``A.hasPart(B)`` would resolve by local name in whatever ontology the robot loads
    (``skiros:hasPart`` when it lacks ``sumo:hasPart``): only ``skiros`` vocabulary, the
    prefix a short name falls back to, gets the short form."""
    assert_migrates(case(
        '        self.addPreCondition(self.getRelationCond("AHasPartB", "sumo:hasPart", "A", "B", True))\n'
        '        self.addPreCondition(self.getPropCond("AMeasure", "sumo:measure", "A", "=", 1, True))\n'
        '        self.addPreCondition(self.getRelationCond("AContainB", "skiros:contain", "A", "B", True))\n'
    ), expected('        self.pre_conditions += A.relation("sumo:hasPart", B)\n'
                '        self.pre_conditions += A.property("sumo:measure", "=", 1)\n'
                '        self.pre_conditions += A.contain(B)\n'))
