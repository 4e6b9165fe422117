"""Each command's dataclass (``cli.arguments``) has a field for exactly the options click
parses for it: one missing, or one left over after an option is renamed, would otherwise
surface only as an internal error on that command's first run."""

from __future__ import annotations

import dataclasses

import pytest

from ezmigrate.cli.arguments import CheckArguments, RewriteArguments, VerifyArguments
from ezmigrate.cli.commands import main


@pytest.mark.parametrize(("command", "arguments"), [
    ("rewrite", RewriteArguments), ("verify", VerifyArguments), ("check", CheckArguments)])
def test_a_field_for_every_option_and_an_option_for_every_field(command: str,
                                                                 arguments: type) -> None:
    parsed = {param.name for param in main.commands[command].params}
    assert parsed == {field.name for field in dataclasses.fields(arguments)}


def test_check_without_select_keeps_the_projects_selection() -> None:
    """An empty ``--select`` (not given) must not replace the project's selection with no
    codes at all: ``CommandLine.select`` is then None."""
    given = {field.name: None for field in dataclasses.fields(CheckArguments)}
    given.update(select=(), ignore=("EZ2",), extend_select=(), exclude=())
    line = CheckArguments(**given).command_line()
    assert line.select is None
    assert line.ignore == ("EZ2",)
