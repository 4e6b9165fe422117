"""Build the EzSkiROS ``description`` method that replaces a legacy ``createDescription``.

Layout follows the paper (one parameter per line, aligned under the opening parenthesis).
The method is assembled from libcst nodes around the original ones: the original ``def``
keeps its leading comments and header, kept statements and the docstring are the original
nodes, and the comments of each legacy statement move with what replaces it (onto the
parameter in the signature, or onto the ``+=`` line). Text that SkiROS2 drops (a string in
``addParam``'s options slot) becomes a comment on its parameter's line (``kept_text``).
"""

from __future__ import annotations

import functools
import itertools
import keyword
import re
import unicodedata
from dataclasses import replace
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import libcst as cst
else:
    from .lazy_cst import cst

from .emit import EmitContext
from .ir import (
    AddCondition,
    CommentOnly,
    Comments,
    CondSpec,
    ElementValue,
    ExtractedSkill,
    KeptStatement,
    ParamOp,
)

ALIGN = " " * len("def description(")
HANGING_TABS = "\t\t"
"""In a file indented with tabs, the parameters hang two tabs deeper than ``def``, from the
line after ``def description(``: aligning them with the ``(`` needs spaces after the tabs,
which pycodestyle reports on every line (E101, mixed spaces and tabs), and tabs alone
cannot line up with it (E128). Two tabs keep them apart from the body (one would be E125);
pycodestyle's E126 for it is one flake8 ignores by default."""
ROBOT = "Robot"


def referenced_keys(spec: CondSpec) -> list[str]:
    """Every key a condition (and its children) mentions."""
    keys = [k for k in (spec.subject, spec.object) if k is not None]
    for child in spec.children:
        keys += referenced_keys(child)
    return keys


def _expands_options(op: ParamOp) -> bool:
    return bool(op.options) and isinstance(op.value, ElementValue) and not op.value.is_class


def emitted_params(skill: ExtractedSkill, comments: bool = True) -> list[ParamOp]:
    """The signature's parameters, in order (``comments`` False: without the comments the
    signature would carry, for a reader that writes nothing, ``lint/plain_reader.py``).

    A key declared again replaces the first declaration in its position (§8.3), so when
    the first one expanded no options the second is simply written in the first's place,
    unless the second expands options after others did (its conditions would move ahead
    of theirs); otherwise both are kept (the second with a ``KEY``), as SkiROS2 would run
    them.
    SkiROS2's automatic ``Robot`` is written as ``Robot: INFERRED[sumo.Agent]`` last when
    conditions use it undeclared: exactly what ``generateDefParams`` appends (§8.1).
    The caller replays the result to prove the model is unchanged.
    """
    params: list[ParamOp] = []
    for declared_op in skill.params():
        op = replace(declared_op, comments=kept_text(declared_op.comments,
                                                     declared_op.options_text)) \
            if comments else declared_op
        earlier = next((i for i, p in enumerate(params) if p.key == op.key), None)
        between = params[earlier + 1:] if earlier is not None else []
        if earlier is not None and not _expands_options(params[earlier]) \
                and not any(p.key == op.key for p in between) \
                and not (_expands_options(op) and any(_expands_options(p) for p in between)):
            params[earlier] = replace(op, comments=_merged(params[earlier].comments,
                                                           op.comments))
        else:
            params.append(op)
    declared = {op.key for op in params}
    used = {k for add in skill.conditions() for k in referenced_keys(add.condition)}
    if ROBOT in used and ROBOT not in declared:
        params = [*params, ParamOp(ROBOT, ElementValue("sumo:Agent"), "Inferred", [], None, 0)]
    return params


def kept_text(comments: Comments, text: str | None) -> Comments:
    """``comments`` with the text of the options slot added as the parameter line's comment.

    Why: SkiROS2 drops a string passed there (the description stays empty), so the signature
    must not declare it either, but it is the author's words: losing them in a migration is
    a surprise, a comment keeps them with the meaning unchanged. A comment already at the end
    of the line follows it; text that cannot sit on one comment line is shown as a literal.
    """
    if not text or not text.strip():
        return comments
    shown = text.strip() if text.isprintable() else repr(text)
    after = f"  {comments.trailing.value}" if comments.trailing is not None else ""
    return replace(comments, trailing=cst.Comment(f"# {shown}{after}"))


def _merged(first: Comments, second: Comments) -> Comments:
    """Both declarations' comments for the one parameter that replaces them."""
    carried = [first.trailing.value] if first.trailing is not None else []
    return Comments(leading=[*first.leading, *second.leading],
                    inner=[*first.inner, *carried, *second.inner], trailing=second.trailing)


def _identifier(key: str) -> str:
    """A Python name made from ``key``, as Python reads it back: ``\\w`` is wider than what
    an identifier may hold (``"¼"``, ``"²"``), and Python NFKC-normalizes every name it
    parses (``ℌ`` is ``H``), so keep only characters valid in an identifier, normalize, and
    check the result."""
    kept = "".join(c if ("_" + c).isidentifier() else "_" for c in key)
    name = re.sub(r"_+", "_", unicodedata.normalize("NFKC", kept)).strip("_") or "param"
    if not name.isidentifier():
        name = "_" + name if ("_" + name).isidentifier() else "param"
    return name + "_" if keyword.iskeyword(name) else name


def _usable_as_is(key: str) -> bool:
    """A key Python keeps exactly as written when it is a parameter name (inside a class,
    ``__tool`` is mangled to ``_Skill__tool``)."""
    return key.isidentifier() and not keyword.iskeyword(key) and not key.startswith("__") \
        and unicodedata.normalize("NFKC", key) == key


def assign_names(params: list[ParamOp], ctx: EmitContext) -> list[str]:
    """One Python name per parameter; the first declaration of a key names the key.

    Keys usable as names are served first, so that ``"Target_Location"`` keeps its own name
    even when an earlier ``"Target Location"`` would be spelt the same; the others get a
    made-up name (with a ``KEY(...)``) from what is left.
    """
    taken = set(ctx.reserved)
    names: list[str | None] = [None] * len(params)
    for index, op in enumerate(params):
        if _usable_as_is(op.key) and op.key not in taken:
            names[index] = op.key
            taken.add(op.key)
    for index, op in enumerate(params):
        if names[index] is None:
            name = base = _identifier(op.key)
            counter = 2
            while name in taken:
                name = f"{base}_{counter}"
                counter += 1
            taken.add(name)
            names[index] = name
    assigned = [name for name in names if name is not None]
    for op, name in zip(params, assigned, strict=True):
        ctx.param_names.setdefault(op.key, name)
    return assigned


def _comment_lines(comments: Comments, indent_ws: str) -> list[cst.EmptyLine]:
    texts = [line.comment.value for line in comments.leading if line.comment is not None]
    return [cst.EmptyLine(indent=True, whitespace=cst.SimpleWhitespace(indent_ws),
                          comment=cst.Comment(text)) for text in texts + comments.inner]


def _line_break(comment: cst.Comment | None, lines: list[cst.EmptyLine],
                align: str = ALIGN) -> cst.ParenthesizedWhitespace:
    return cst.ParenthesizedWhitespace(
        first_line=cst.TrailingWhitespace(
            whitespace=cst.SimpleWhitespace("  " if comment else ""), comment=comment),
        empty_lines=lines, indent=True, last_line=cst.SimpleWhitespace(align))


@functools.lru_cache(maxsize=4096)
def expression(text: str) -> cst.BaseExpression:
    """``text`` parsed as an expression, once per text: a repository repeats the same few
    annotations and defaults in every description, and libcst nodes are immutable, so one
    node can stand in every signature that needs it."""
    return cst.parse_expression(text)


def build_parameters(func: cst.FunctionDef, params: list[ParamOp], names: list[str],
                     ctx: EmitContext, align: str = ALIGN
                     ) -> tuple[cst.Parameters, cst.Comment | None]:
    """The signature; also returns the last parameter's end-of-line comment (for the header).

    Each comma carries the line break before the next item together with that item's
    comments, and the end-of-line comment of the item it follows.
    """
    self_param = func.params.params[0].with_changes(comma=cst.MaybeSentinel.DEFAULT)
    header = func.body.header if isinstance(func.body, cst.IndentedBlock) else None
    def_comment = header.comment if header is not None and params else None
    entries: list[tuple[cst.Param, Comments]] = []
    for op, name in zip(params, names, strict=True):
        annotation_text, default = ctx.rules.param_annotation(op, name, ctx)
        entries.append((cst.Param(
            name=cst.Name(name),
            annotation=cst.Annotation(expression(annotation_text)),
            equal=cst.AssignEqual() if default is not None else cst.MaybeSentinel.DEFAULT,
            default=expression(default) if default is not None else None),
            op.comments))
    star_at = _keyword_only_from([param for param, _ in entries])
    # the ``def`` line's own comment stays at the end of the ``def`` line: after ``self,``
    items: list[tuple[cst.Param | cst.ParamStar, Comments]] = [
        (self_param, Comments(trailing=def_comment))]
    for index, entry in enumerate(entries):
        if index == star_at:
            items.append((cst.ParamStar(), Comments()))
        items.append(entry)
    linked: list[cst.Param | cst.ParamStar] = []
    for (item, own), (_, following) in itertools.pairwise(items):
        comma = cst.Comma(whitespace_after=_line_break(
            own.trailing, _comment_lines(following, align), align))
        linked.append(item.with_changes(comma=comma))
    linked.append(items[-1][0])
    star = next((i for i, item in enumerate(linked) if isinstance(item, cst.ParamStar)), None)
    positional = [p for p in linked[:star] if isinstance(p, cst.Param)]
    if star is None:
        return cst.Parameters(params=positional), items[-1][1].trailing
    star_node = linked[star]
    assert isinstance(star_node, cst.ParamStar)
    kwonly = [p for p in linked[star + 1:] if isinstance(p, cst.Param)]
    return (cst.Parameters(params=positional, star_arg=star_node, kwonly_params=kwonly),
            items[-1][1].trailing)


def _keyword_only_from(params: list[cst.Param]) -> int | None:
    """Index of the first defaulted parameter when a non-defaulted one follows it."""
    first_default = None
    for index, param in enumerate(params):
        if param.default is not None and first_default is None:
            first_default = index
        elif param.default is None and first_default is not None:
            return first_default
    return None


def build_body(func: cst.FunctionDef, skill: ExtractedSkill, ctx: EmitContext,
               config: cst.PartialParserConfig, header_comment: cst.Comment | None,
               moved_def_comment: bool = False) -> cst.IndentedBlock:
    """The method body: docstring, then conditions and kept statements in legacy order."""
    statements: list[cst.BaseStatement] = []
    if skill.docstring is not None:
        statements.append(skill.docstring)
    pending: list[cst.EmptyLine] = []
    for op in skill.operations:
        if isinstance(op, ParamOp):
            continue
        lines = pending + list(op.comments.leading) + [
            cst.EmptyLine(comment=cst.Comment(text)) for text in op.comments.inner]
        if isinstance(op, CommentOnly):
            trailing = [cst.EmptyLine(comment=op.comments.trailing)] if op.comments.trailing \
                else []
            pending = lines + trailing
            continue
        pending = []
        trailing_ws = cst.TrailingWhitespace(
            whitespace=cst.SimpleWhitespace("  " if op.comments.trailing else ""),
            comment=op.comments.trailing)
        if isinstance(op, AddCondition):
            parsed = cst.parse_statement(ctx.rules.condition_statement(op, ctx) + "\n",
                                         config=config)
            assert isinstance(parsed, cst.SimpleStatementLine)
            node: cst.SimpleStatementLine = parsed
        else:
            assert isinstance(op, KeptStatement)
            node = cst.SimpleStatementLine(body=[op.node])
        statements.append(node.with_changes(leading_lines=lines, trailing_whitespace=trailing_ws))
    footer = pending + list(skill.footer)
    if not statements:
        statements.append(cst.SimpleStatementLine(body=[cst.Pass()], leading_lines=footer))
        footer = []
    first = statements[0]
    if isinstance(first, cst.SimpleStatementLine):
        leading = list(first.leading_lines)
        while leading and leading[0].comment is None:
            leading.pop(0)
        statements[0] = first.with_changes(leading_lines=leading)
    original = func.body
    indent = original.indent if isinstance(original, cst.IndentedBlock) else None
    header = original.header if isinstance(original, cst.IndentedBlock) else \
        cst.TrailingWhitespace()
    if moved_def_comment:  # build_parameters wrote it after ``self,``
        header = header.with_changes(whitespace=cst.SimpleWhitespace(""), comment=None)
    if header_comment is not None:
        header = header.with_changes(whitespace=cst.SimpleWhitespace("  "),
                                     comment=header_comment)
    return cst.IndentedBlock(body=statements, header=header, indent=indent, footer=footer)


def build_description(func: cst.FunctionDef, skill: ExtractedSkill, params: list[ParamOp],
                      ctx: EmitContext, config: cst.PartialParserConfig) -> cst.FunctionDef:
    """The complete ``description`` method for ``skill`` with the signature ``params``."""
    names = assign_names(params, ctx)
    indent = config.default_indent
    hanging = bool(params) and isinstance(indent, str) and set(indent) == {"\t"}
    parameters, last_comment = build_parameters(func, params, names, ctx,
                                                HANGING_TABS if hanging else ALIGN)
    body = build_body(func, skill, ctx, config, last_comment, moved_def_comment=bool(params))
    before_params: cst.BaseParenthesizableWhitespace = cst.ParenthesizedWhitespace(
        indent=True, last_line=cst.SimpleWhitespace(HANGING_TABS)) if hanging \
        else cst.SimpleWhitespace("")
    return func.with_changes(name=cst.Name("description"), params=parameters, body=body,
                             whitespace_before_params=before_params)
