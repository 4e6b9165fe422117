"""The one catalogue of findings: a stable code (``EZ`` + 3 digits) for every finding kind.

Codes are what users select, ignore and suppress (``# ezskiros: ignore[EZ201]``), so they
never change meaning once published; kinds are the internal identifiers the checks emit
(``"range"``, ``"description-in-options"``). Several kinds may share a code when they are
the same problem found by two passes (the runtime's ``undeclared-parameter`` and the
codemod's ``undeclared-key``); a kind never has two codes.

Groups, by the hundreds digit: EZ1xx the description itself, EZ2xx vocabulary and ontology,
EZ3xx compound skills, EZ4xx the world model (scenes, and what conditions do to it), EZ9xx
migration state.

Like ``diagnostics``, this module imports nothing from the rest of the runtime.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

CODE_PATTERN = re.compile(r"EZ\d{3}\Z")
GROUPS: dict[str, str] = {
    "EZ1": "description",
    "EZ2": "vocabulary and ontology",
    "EZ3": "compound skills",
    "EZ4": "world model",
    "EZ9": "migration state",
}


@dataclass(frozen=True)
class Rule:
    """One finding code: what it means, how bad it is by default, and how to fix it.

    ``enabled`` is False for rules that run only when selected (``--select EZ901``):
    "not migrated yet" is news only for a repository that finished migrating.

    This is the one place a rule lives: the runtime's policy (``dsl/policy.py``), the
    findings of every pass, docs/rules.md and the README's tables take its severity from
    here, and tests hold them to it.
    """

    code: str
    name: str
    severity: str
    rationale: str
    fix: str
    kinds: tuple[str, ...] = ()
    enabled: bool = True
    skiros2: str = ""
    """What SkiROS2 does when the finding's mistake runs (the function that raises, drops
    or misbehaves): every error names one, since an error in CI must mean SkiROS2 will
    certainly fail or misbehave."""

    @property
    def group(self) -> str:
        return GROUPS[self.code[:3]]


RULES: tuple[Rule, ...] = (
    # EZ1xx: the description itself
    Rule("EZ100", "unused-suppression", "warning",
         "An `# ezskiros: ignore[...]` comment that suppresses nothing hides future findings.",
         "Delete the comment, or the codes in it that no longer fire.",
         ("unused-suppression",)),
    Rule("EZ101", "description-in-options", "warning",
         "A string passed 4th to addParam lands in the options slot; SkiROS2 drops it and the "
         "parameter's description stays empty.",
         "Pass it as description=\"...\" (5th argument): `ezmigrate check --fix` does it on "
         "the legacy file, so run it before `rewrite`, which keeps the text as a comment on "
         "the parameter's line (nothing is left to fix after it).",
         ("description-in-options",)),
    Rule("EZ102", "options-ignored", "warning",
         "SkiROS2 expands ParamOptions only for Element values; on any other value they do "
         "nothing.",
         "Remove the options, or make the parameter an Element.",
         ("options-ignored",)),
    Rule("EZ103", "duplicate-key", "warning",
         "A second addParam with the same key replaces the first one silently.",
         "Rename one of the parameters or delete the duplicate.",
         ("duplicate-key",)),
    Rule("EZ104", "undeclared-parameter", "warning",
         "A condition refers to a key no addParam declares; SkiROS2 accepts it and the "
         "condition can never be grounded.",
         "Declare the parameter, or fix the key's spelling in the condition.",
         ("undeclared-parameter", "undeclared-key")),
    Rule("EZ105", "uninferable", "warning",
         "An Inferred Element parameter that no pre-condition mentions: SkiROS2 grounds it "
         "by its type alone, to the first matching element of the world model, which is "
         "arbitrary when several elements fit.",
         "Add a pre-condition that relates it to a known parameter, or make it Required.",
         ("uninferable",)),
    Rule("EZ106", "default-type", "error",
         "The default value does not fit the parameter's declared type.",
         "Change the default or the annotation so that they agree.",
         ("default-type",),
         skiros2="ezskiros_runtime raises SkillTypeError when the skill manager instantiates the "
         "description (SkillManager.add_skill), so the skill is not loaded"),
    Rule("EZ107", "contradiction", "error",
         "One condition list wants the same fact true and false (or two different values), "
         "so it can never hold.",
         "Delete one of the two conditions.",
         ("contradiction",),
         skiros2="SkillCore.checkPreCond can never pass (NodeExecutor._ground fails the skill "
         "every time); in post-conditions, SkillCore.checkPostCond turns every success "
         "into a failure (NodeExecutor.postExecute)"),
    Rule("EZ108", "description-error", "error",
         "The EzSkiROS DSL is used in a way that cannot be lowered (`*args`, `~` on is_a, a "
         "malformed marker).",
         "Follow the message; docs/dsl.md lists the accepted forms.",
         ("description", "not-upstream-api", "not-declarative"),
         skiros2="ezskiros_runtime raises SkillTypeError when the skill manager instantiates the "
         "description (SkillManager.add_skill), so the skill is not loaded"),
    Rule("EZ109", "implementation-unknown-key", "error",
         "An implementation reads self.params[\"Key\"] with a key its description does not "
         "declare (nor its modifyDescription, nor the automatic Robot).",
         "Use a declared key (see the suggestion), or declare the parameter.",
         ("implementation-unknown-key",),
         skiros2="ParamHandler.__getitem__ logs \"Param ... is not in the map\" and returns "
         "None, so the .value after it raises AttributeError when the line runs"),
    Rule("EZ110", "no-set-description", "error",
         "An implementation (a class deriving from SkillBase, PrimitiveBase or a lab base "
         "of them) that no class derives from, whose createDescription never calls "
         "setDescription: it keeps SkillCore's empty type and label, and the skill "
         "manager cannot add it to the world model (SkiROS2 issue #109). Reported only "
         "where createDescription is read in full (no super() call, no helper that might "
         "set the description); info when the launch file's skill_list does not load it.",
         "Call self.setDescription(TheDescription(), self.__class__.__name__) in "
         "createDescription.",
         ("no-set-description",),
         skiros2="SkillManager.add_skill builds the skill's element from its empty type "
         "(SkillCore._type \"\") and WorldModel.add_element cannot store it "
         "(_element2statements: lightstring2uri(\"\") is None), so the skill is not "
         "loaded"),
    # EZ2xx: vocabulary and ontology
    Rule("EZ201", "domain", "error",
         "The subject's class is outside the relation's or property's domain.",
         "Use a relation whose domain contains the parameter's class, or change its type.",
         ("domain",),
         skiros2="no element of the parameter's class can take part in the relation: "
         "ezskiros_runtime refuses the description when SkillManager.add_skill "
         "instantiates it, and a legacy pre-condition never holds in "
         "SkillCore.checkPreCond"),
    Rule("EZ202", "range", "error",
         "The object's class is outside the relation's range.",
         "Use a relation whose range contains the parameter's class, or change its type.",
         ("range",),
         skiros2="no element of the parameter's class can take part in the relation: "
         "ezskiros_runtime refuses the description when SkillManager.add_skill "
         "instantiates it, and a legacy pre-condition never holds in "
         "SkillCore.checkPreCond"),
    Rule("EZ203", "domain-unproven", "info",
         "The subject's class is wider than the domain: the relation may not hold for it. "
         "Modelling advice (info): SkiROS2 grounds whatever the world model holds, and labs "
         "set such properties on classes outside the declared domain on purpose.",
         "Narrow the parameter's type to a class inside the domain.",
         ("domain-unproven",)),
    Rule("EZ204", "range-unproven", "info",
         "The object's class is wider than the range: the relation may not hold for it. "
         "Modelling advice (info), as EZ203.",
         "Narrow the parameter's type to a class inside the range.",
         ("range-unproven",)),
    Rule("EZ205", "property-kind", "error",
         "A relation over a datatype property, or a property condition over an object "
         "property.",
         "Use a relation condition for object properties and a property condition for "
         "datatype properties.",
         ("property-kind",),
         skiros2="ConditionRelation looks the name up among relations (Element.getRelations) and "
         "ConditionProperty among properties (Element.hasProperty): the condition never "
         "holds, so SkillCore.checkPreCond fails the skill"),
    Rule("EZ206", "value-type", "error",
         "A property condition compares with a value of the wrong Python type for the "
         "property's datatype.",
         "Write the value with the type the property's range asks for.",
         ("value-type",),
         skiros2="ConditionProperty compares with a value no element holds (Property.isSpecified "
         "and == across types): the condition never holds in SkillCore.checkPreCond"),
    Rule("EZ207", "operator", "error",
         "An ordering operator (> < >= <=) on a property whose values are not numbers.",
         "Compare with = or use a numeric property.",
         ("operator",),
         skiros2="ConditionProperty orders values with Python's > and <, which raises TypeError on "
         "strings and booleans of other types, or never holds"),
    Rule("EZ208", "unknown-operator", "warning",
         "An operator outside = > < >= <=, which SkiROS2's world model does not evaluate.",
         "Use one of = > < >= <=.",
         ("unknown-operator",)),
    Rule("EZ209", "unknown-vocabulary", "warning",
         "A class or property the loaded ontology does not define (SkiROS2 accepts it; the "
         "world model never matches it).",
         "Fix the name (see the suggestion), or load the ontology that defines it "
         "(--ontology, [tool.ezmigrate] ontology).",
         ("unknown-vocabulary",)),
    Rule("EZ210", "ambiguous-vocabulary", "error",
         "A local name that several prefixes define cannot be resolved to one IRI.",
         "Write the name with its prefix (A.relation(\"skiros:name\", B)).",
         ("ambiguous-vocabulary",),
         skiros2="ezskiros_runtime cannot choose the IRI and raises SkillTypeError when "
         "SkillManager.add_skill instantiates the description"),
    Rule("EZ211", "element-type-unqualified", "warning",
         "An Element type not written as prefix:Name; SkiROS2 stores it verbatim and it "
         "matches no class.",
         "Write the type with its prefix, e.g. Element(\"skiros:Gripper\").",
         ("element-type-spelling",)),
    Rule("EZ212", "prefix-typo", "error",
         "A prefix that the ontology does not define but that is a typo of one it does "
         "(\"skiros;:Parameter\", \"skirso:Product\").",
         "Correct the prefix.",
         ("prefix-typo",),
         skiros2="the world model stores the type verbatim: WorldModelInterface.resolve_elements "
         "matches no element of the misspelt class, so grounding the parameter fails "
         '(NodeExecutor._autoParametrizeWm: "Can t autoparametrize param")'),
    Rule("EZ213", "class-spelling", "error",
         "An Element type that differs from a class of the ontology only in case or "
         "separators (\"skiros:largebox\" for skiros:LargeBox).",
         "Spell the class exactly as the ontology does.",
         ("class-spelling",),
         skiros2="the world model stores the type verbatim: WorldModelInterface.resolve_elements "
         "matches no element of the misspelt class, so grounding the parameter fails "
         '(NodeExecutor._autoParametrizeWm: "Can t autoparametrize param")'),
    Rule("EZ214", "implementation-element-typo", "warning",
         "An Element(\"p:Class\") in implementation code (a world-model query, a new "
         "element) names a class that no loaded ontology, owl file or scene defines and "
         "that is one edit away from one that is: the world model matches types "
         "verbatim, so the query finds nothing or the element gets the wrong type.",
         "Use the class the suggestion names.",
         ("implementation-element-typo",)),
    Rule("EZ215", "implementation-unknown-property", "info",
         "Implementation code reads a property (getProperty, hasProperty) that nothing in "
         "the repository sets and no loaded ontology or scene declares. Info: SkiROS2 "
         "makes property names at run time (setProperty adds any name), so another "
         "package may set it.",
         "Check the name against the code that sets the property, or declare it in the "
         "lab's ontology.",
         ("implementation-unknown-property",)),
    # EZ3xx: compound skills (the behaviour trees built in expand)
    Rule("EZ301", "unknown-child-type", "error",
         "A child type that no loadable description matches; the compound skill fails when "
         "it runs (\"No plugin with name ... found\").",
         "Fix the type name (see the suggestion), or add the library that defines it to "
         "[tool.ezmigrate] skill-libraries.",
         ("unknown-child-type",),
         skiros2="SkillInstanciator finds no description or instance of the type: PluginLoader.get "
         'raises "No plugin with name ... found!", or NodeExecutor.init raises "Skill ... '
         'is not available" when the compound skill runs'),
    Rule("EZ302", "regex-child-type", "error",
         "A child type that matches a description only as a regular expression (\"Pick()\"). "
         "SkiROS2 finds the description that way, but looks its instances up under the "
         "literal type: a node without a label fails; one with a label loads the "
         "implementation by name and works (info).",
         "Write the description's class name exactly.",
         ("regex-child-type",),
         skiros2="SkillInstanciator.assign_instance finds no instance under the literal type "
         "and, with no label to load one by, NodeExecutor.init raises \"Skill ... is not "
         "available\""),
    Rule("EZ303", "label-other-type", "error",
         "The label names an implementation of another description type; SkiROS2 runs it "
         "without a check (upstream issue #80).",
         "Use a label that implements the child's type, or change the type.",
         ("label-other-type",),
         skiros2="SkillInstanciator.assign_instance takes the labelled implementation of the other "
         "type without a check (upstream issue #80): the child runs another skill's code"),
    Rule("EZ304", "remap-key-unknown", "error",
         "A remap key that neither the child nor anything below it declares: the remap does "
         "nothing (often a key renamed on one side only).",
         "Use the child's parameter name (see the suggestion), or delete the remap.",
         ("remap-key-unknown",),
         skiros2="SkillInterface.remap renames only keys the node and its children hold "
         "(ParamHandler.remap): nothing is renamed, so the value never reaches the child"),
    Rule("EZ305", "remap-key-descendant", "info",
         "A remap key declared only below the child (by a grandchild): SkiROS2 passes the "
         "remap down, which is easy to miss when reading the tree.",
         "Nothing to fix if intended.",
         ("remap-key-descendant",)),
    Rule("EZ306", "remap-onto-declared", "error",
         "A remap onto a key the child already declares; SkiROS2 rejects it and renames "
         "nothing.",
         "Remap onto another key, or drop one of the child's parameters.",
         ("remap-onto-declared",),
         skiros2='SkillInterface.remap logs "Invalid remapping ... target key is already present" '
         "and returns without renaming"),
    Rule("EZ307", "specify-key-unknown", "error",
         "A specify key the child does not declare after remapping; SkiROS2 drops the value "
         "(Wait given Time instead of Duration).",
         "Use the child's parameter name after remapping (see the suggestion).",
         ("specify-key-unknown",),
         skiros2='SkillCore.specifyParamDefault logs "No param ... found" and '
         "ParamHandler.specifyDefault drops the value"),
    Rule("EZ308", "remap-dangling", "info",
         "A remap value that no parameter of the compound skill and no other node of its "
         "tree declares: the child's parameter connects to nothing, unless something "
         "outside the tree writes that blackboard key (info: skills inserted at run time "
         "and BbUnsetParam of an absent key do exactly that).",
         "Remap onto a parameter of the compound skill (see the suggestion) or one that "
         "another child writes.",
         ("remap-dangling",)),
    Rule("EZ309", "compound-call-shape", "error",
         "A call SkiROS2 cannot use: self.skill(self.skill(...), ...), a first argument "
         "that is neither a type name nor a processor (nothing is attached), or a call that "
         "raises a TypeError when expand runs (a keyword typo such as specfiy=, a "
         "non-empty string as remap). Checked from the syntax even when the tree cannot "
         "be traced.",
         "Call a node with its children (self.skill(...)(child, ...)); spell the keywords "
         "as SkiROS2's self.skill(stype, slabel, remap, specify, preconditions).",
         ("compound-call-shape",),
         skiros2="SkillBase.skill raises TypeError (an unknown keyword, a node as type) or "
         "attaches nothing when expand runs, and the compound skill fails"),
    Rule("EZ310", "processor-not-upstream", "info",
         "A processor that SkiROS2's master and ros2 branches do not have (RetryOnFail is "
         "the ros2_roscon24_workshop branch's; Loop, InferInvalid are forks'). Reported "
         "once per project, naming where it exists.",
         "Use an upstream processor, or accept the dependency on the fork.",
         ("processor-not-upstream",)),
    Rule("EZ311", "remap-disjoint", "info",
         "A remap between element parameters whose classes share no subclass in the loaded "
         "ontology. Info: OWL does not make them disjoint without an axiom, and passing an "
         "element between parameters of different classes is a blackboard idiom real trees "
         "use on purpose.",
         "Remap onto a parameter of a compatible class, or fix one of the two types.",
         ("remap-disjoint",)),
    Rule("EZ312", "remap-narrower", "info",
         "A remap whose child parameter wants a narrower class than the parent's: some "
         "elements the parent accepts do not fit the child.",
         "Narrow the parent's parameter if every use fits the child.",
         ("remap-narrower",)),
    Rule("EZ313", "compound-unanalysable", "info",
         "A compound skill whose tree could be neither read statically nor traced (the world "
         "model, a branch on a value): it is not checked, not clean.",
         "Nothing to fix; simplify expand if you want it checked.",
         ("compound-unanalysable",)),
    Rule("EZ314", "remap-key-remapped-below", "error",
         "A remap key that the node below declaring it already remapped: SkiROS2 refuses "
         "the second remap there (\"Key K already remapped\") and does not pass it "
         "further, so the value never reaches that node.",
         "Remap the key's new name (the one the node below gave it), or drop one of the two "
         "remaps.",
         ("remap-key-remapped-below",),
         skiros2='SkillInterface.remap logs "Key ... already remapped ... Can t remap" on the node '
         "below and returns, so the value never reaches it"),
    Rule("EZ317", "processor-undefined", "error",
         "A processor class the module neither defines nor imports (Sqeuential() for "
         "Sequential()): expand raises NameError when it runs, and the compound skill "
         "fails.",
         "Fix the name, or import the processor (from skiros2_skill.core.skill import ...).",
         ("processor-undefined",),
         skiros2="SkillWrapper.expand runs the implementation's expand, where the name is "
         "looked up: NameError, and the skill fails when it runs"),
    Rule("EZ318", "unknown-label", "warning",
         "A child label that no implementation of the child's type the run knows has "
         "(the repository, skiros2_std_lib, [tool.ezmigrate] skill-libraries): "
         "SkillInstanciator.assign_instance finds no instance with that label, and "
         "add_instance asks PluginLoader.getPluginByName for it, which raises. Info when the "
         "run knows no implementation of the type at all (it may come from another "
         "library).",
         "Use the label of an implementation of the type (see the suggestion), or leave it "
         "empty to let the skill manager pick one.",
         ("unknown-label",),
         skiros2="SkillInstanciator.add_instance -> PluginLoader.getPluginByName raises "
         "\"No plugin with name ... found\" when the compound skill expands"),
    Rule("EZ319", "specify-modified-key", "warning",
         "A specify of a parameter that only the implementation's modifyDescription adds: "
         "self.skill(...) applies specify to a wrapper filled from the description class "
         "alone, and modifyDescription runs later (SkillWrapper.setInstance), so the value "
         "is dropped and the child runs with modifyDescription's default.",
         "Declare the parameter in the description class, or set it another way (remap "
         "onto a key the parent sets).",
         ("specify-modified-key",),
         skiros2="SkillWrapper.specifyParamDefault logs \"No param ... found\" and drops the "
         "value"),
    Rule("EZ320", "required-unset", "error",
         "A child's parameter that must have a value (not Optional, not an Element, "
         "declared with a type instead of a value: addParam(\"Relation\", str, "
         "ParamTypes.Required)) that nothing in the tree sets: no parameter of the "
         "compound skill, no remap onto it, no specify, no other node that writes it on the "
         "blackboard, nor any known tree around the compound (SkiROS2 issue #91). Reported "
         "only where the whole tree and the child's description are known; info when a "
         "tree of the run could not be read (it may hold the compound and set the key).",
         "Give the child the value (specify={\"Relation\": \"skiros:contain\"}), or "
         "declare the key in the compound's description so that its caller sets it.",
         ("required-unset",),
         skiros2="NodeExecutor._autoParametrizeBB (skill_utils.py) raises \"Missing required "
         "parameter(s)\" when the child is grounded and the compound skill fails (develop, "
         "ros2 branches); master's leaves the value None and the child runs without it"),
    Rule("EZ315", "specify-parameter-object", "error",
         "A specify value that is the parameter object self.params[\"X\"] rather than "
         "its value: SkiROS2 logs an error and leaves the child's parameter unset.",
         "Write self.params[\"X\"].value.",
         ("specify-parameter-object",),
         skiros2="ParamHandler.specifyDefault is given a Param where it wants values: "
         "Param.setValues logs an error and the child's parameter stays unset"),
    Rule("EZ316", "child-not-launched", "info",
         "A child type whose implementations the launch file's skill_list does not load "
         "(the launch file may not be the one the robot uses: info).",
         "Add an implementation of the type to skill_list, or pass the launch file the "
         "robot starts with (--launch).",
         ("child-not-launched",)),
    # EZ4xx: the world model (scenes, and what post-conditions leave in it)
    Rule("EZ401", "double-place", "warning",
         "The pre-conditions require a single-valued relation (a spatial parent, skiros:at) "
         "to one element, the post-conditions assert it to another and never retract the "
         "first: SkiROS2's planner takes post-conditions as effects and then believes both "
         "(an object in the container and in the gripper).",
         "Add the retraction the message suggests (`~ Container.contain(Object)` or "
         "getRelationCond(..., False)); not applied automatically, it changes what the "
         "planner believes. [tool.ezmigrate] single-valued sets the relations.",
         ("double-place",)),
    Rule("EZ402", "scene-syntax", "error",
         "A world-model scene that is not valid Turtle: the world model cannot load it.",
         "Fix the Turtle at the line named.",
         ("scene-syntax",),
         skiros2="WorldModel.load_context cannot parse the file (rdflib raises), so the world "
         "model does not start with the scene"),
    Rule("EZ403", "scene-two-parents", "warning",
         "An element with two spatial parents (sub-properties of skiros:spatiallyRelated: "
         "contain, hasA) whose parent something reads: its pose, in a frame of its own, is "
         "expressed in whichever parent comes first. An element without a pose of its own "
         "only shows twice in the GUI's tree (info), and a property declared a "
         "sub-property of spatiallyRelated that gives many elements a second parent is one "
         "finding at its declaration.",
         "Keep one of the two relations.",
         ("scene-two-parents", "scene-spatial-declaration"),
         skiros2="AauSpatialReasoner._getParentFrame takes the first spatial relation "
         "(Element.getRelation) as the parent frame of the element's pose"),
    Rule("EZ404", "scene-dangling", "warning",
         "A relation whose object is defined nowhere in the scene: the world model holds a "
         "reference to nothing.",
         "Define the element in the scene, or fix the name.",
         ("scene-dangling",)),
    Rule("EZ405", "scene-domain-range", "info",
         "A relation between elements whose classes lie outside its domain or range (with "
         "the subclass closure, as in the description checks). Modelling (info): the world "
         "model stores the triple and grounding uses it as any other.",
         "Relate elements of the right classes, or fix an element's type.",
         ("scene-domain", "scene-range")),
    Rule("EZ406", "scene-datatype", "warning",
         "A data-property value that does not fit the property's datatype (a float written "
         "as text, a boolean as a number): a property condition comparing it with a value "
         "of the right type never holds.",
         "Write the value with the property's datatype (\"0.5\"^^xsd:float).",
         ("scene-datatype",)),
    Rule("EZ407", "scene-unknown-type", "info",
         "An individual of a class the loaded ontology does not define; the scene may be "
         "its only declaration.",
         "Load the ontology that defines the class, or fix the name.",
         ("scene-unknown-type",)),
    Rule("EZ408", "scene-unattached", "info",
         "An element outside the scene's spatial tree (no contain/hasA chain from the "
         "scene): SkiROS2's GUI, which reads the scene as a tree, does not show it. What "
         "SkiROS2 saves about itself (skills, parameters, conditions) is not counted.",
         "Relate it to a parent in the tree.",
         ("scene-unattached",)),
    Rule("EZ409", "cannot-start", "info",
         "With --scene, a skill that cannot be grounded in the scene the way the skill "
         "manager grounds it: no choice of elements satisfies the pre-condition named. Not "
         "a bug in itself: skills often run after others changed the world.",
         "Nothing to fix if the skill runs later; else add the elements or relations the "
         "pre-condition needs to the scene.",
         ("cannot-start",)),
    Rule("EZ410", "ontology-undefined-reference", "warning",
         "An rdfs:subClassOf, rdfs:subPropertyOf, rdfs:domain or rdfs:range in the lab's "
         "ontology names a term that no loaded ontology defines, in a namespace that "
         "defines others (a typo): the lab's class falls outside get_sub_classes of its "
         "intended parent, and parameters typed by that parent never match its elements.",
         "Name the defined term the suggestion gives, or define the term.",
         ("ontology-undefined-reference",),
         skiros2="WorldModel.get_sub_classes (and get_sub_properties) follow only the "
                 "axioms as written: the misspelt parent has no sub-classes, the intended "
                 "one lacks the lab's class"),
    Rule("EZ411", "scene-unknown-predicate", "warning",
         "A scene uses a predicate that no loaded ontology declares: the world model drops "
         "the value or relation when it loads the scene.",
         "Fix the predicate's name (see the suggestion), or declare the property in the "
         "lab's ontology.",
         ("scene-unknown-predicate",),
         skiros2="WorldModel.get_individual logs \"Predicate is not defined in the "
                 "ontology\" and skips the triple"),
    Rule("EZ412", "ontology-property-is-class", "warning",
         "A property declared with the IRI of a class (an owl:DatatypeProperty written "
         "rdf:about=\"...#Skill\", SkiROS2 pull request #114): the one IRI is then both a "
         "class and a predicate in the world model.",
         "Give the property its own IRI.",
         ("ontology-property-is-class",),
         skiros2="WorldModel.get_sub_classes and get_sub_properties both answer for the "
                 "IRI: elements typed by the class and values of the property mix"),
    # EZ9xx: migration state
    Rule("EZ901", "not-migrated", "error",
         "A legacy description that `ezmigrate rewrite` would convert is still in the "
         "repository (off by default: select it once the migration is finished).",
         "Run `ezmigrate rewrite PATH`.",
         ("not-migrated",), enabled=False,
         skiros2="none: kept off by default; selected, it is the repository's own rule that every "
         "description is migrated"),
    Rule("EZ902", "kept-legacy", "info",
         "A legacy description that cannot be migrated automatically (a loop, a computed "
         "key...) is kept; its description is not statically checked.",
         "Migrate it by hand following the reason, or accept it.",
         ("kept-legacy", "skipped")),
    Rule("EZ903", "not-equivalent", "error",
         "Verification found that the migrated description means something else than the "
         "legacy one.",
         "Read the difference in the report; rewrite the description or keep the legacy "
         "form.",
         ("not-equivalent", "failed"),
         skiros2="none: the migrated skill means something else than the legacy one, so SkiROS2 "
         "would run a different skill; rewrite never writes it"),
    Rule("EZ904", "unloadable", "error",
         "The module could not be loaded to run the early checks (an exception while "
         "importing it). A load stopped by the sandbox's limits (a timeout, the memory "
         "limit, a crash) says nothing certain about the module: it is reported as info.",
         "Fix the error in the message; run `python -c 'import MODULE'` to reproduce.",
         ("unloadable",),
         skiros2="the module raises when the skill manager imports it (SkillManager.load_skills "
         "through PluginLoader), so none of its skills is loaded"),
    Rule("EZ905", "unreadable", "error",
         "The file could not be parsed or decoded (Python 2 syntax, an empty or truncated "
         "file), so it was skipped and nothing in it was checked; the class names in it "
         "still count as defined for compound skills. An error in a module of a skill "
         "library the skill manager imports (a Python package under a ROS package's src/, "
         "of an ament_python package, or named in the launch file's libraries_list). Info "
         "elsewhere (scripts/, a loose module: the skill manager does not import it), and "
         "for Python 2 syntax where nothing says the package runs on Python 3 (a Python 2 "
         "ROS imports it). `rewrite` reports the same file as not processed.",
         "Fix the syntax or encoding error (port Python 2 code to Python 3).",
         ("unreadable", "syntax-error"),
         skiros2="PluginLoader.__import_plugins imports every module of the library and "
         "catches only ImportError: the SyntaxError stops SkillManager.load_skills and the "
         "skill manager does not start (in a sub-package's __init__.py, "
         "pkgutil.walk_packages ignores it and none of the sub-package's skills is "
         "loaded)"),
    Rule("EZ906", "lossy-rewrite", "error",
         "The migrated text would have changed or lost a line outside the migrated code (a "
         "comment, a blank line, a helper), so the file was not written: outside the "
         "converted methods, their class headers and import statements every byte must "
         "stay as it was.",
         "A bug of ezmigrate: report it with the file. Meanwhile migrate that file by hand, "
         "or move the line named out of the way and run again.",
         ("lossy-rewrite",),
         skiros2="none: ezmigrate refused to write the file, which stays as it was"),
    Rule("EZ907", "not-read-statically", "info",
         "An EzSkiROS description whose signature or body uses a construct `check` does not "
         "evaluate without running the module (a loop, a helper call, a base class of "
         "another module): `check` runs no repository code, so the description is not "
         "checked, not clean. Info: it says nothing of the robot.",
         "Write the description in the forms of docs/dsl.md, or run `check --trace` (which "
         "loads the module in the sandbox) on code you trust.",
         ("not-read-statically",)),
)

BY_CODE: dict[str, Rule] = {rule.code: rule for rule in RULES}
_BY_KIND: dict[str, Rule] = {kind: rule for rule in RULES for kind in rule.kinds}


class UnknownKind(KeyError):
    """A finding kind no rule lists: a bug of the pass that emitted it, never filed under
    some other code (it used to become EZ108, an error, silently)."""


def rule_for(kind: str) -> Rule:
    """The rule of a finding kind, spelt as the catalogue spells it (``range-unproven``:
    one spelling from the runtime to the reports); ``UnknownKind`` for a kind no rule
    lists."""
    try:
        return _BY_KIND[kind]
    except KeyError:
        raise UnknownKind(f"finding kind {kind!r} is listed by no rule of "
                          "ezskiros_runtime/codes.py") from None


def code_for(kind: str) -> str:
    """The code of a finding kind (``"range"`` -> ``"EZ202"``)."""
    return rule_for(kind).code


def known_kind(kind: str) -> bool:
    """Whether the catalogue lists the kind explicitly (tests demand it for every kind)."""
    return kind in _BY_KIND


def matches(code: str, selector: str) -> bool:
    """``EZ2`` selects EZ201..EZ299, ``EZ201`` only itself, ``ALL`` everything (as ruff)."""
    return selector == "ALL" or code.startswith(selector)


def valid_selector(selector: str) -> bool:
    """A code, a prefix of one (``EZ``, ``EZ2``, ``EZ20``), or ``ALL``."""
    if selector == "ALL" or selector in GROUPS:  # EZ3 is reserved but already valid
        return True
    return (re.fullmatch(r"EZ\d{0,3}", selector) is not None
            and any(matches(r.code, selector) for r in RULES))


__all__ = ["BY_CODE", "CODE_PATTERN", "GROUPS", "RULES", "Rule", "UnknownKind", "code_for",
           "known_kind", "matches", "rule_for", "valid_selector"]
