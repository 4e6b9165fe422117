"""Exceptions of the ontology layer.

They live in their own tiny module so that callers (the CLI, the DSL checks) can catch
them without importing rdflib or the index machinery.
"""

from __future__ import annotations


class OntologyError(Exception):
    """Base of every ontology problem, so a caller can report them all in one place."""


class OntologyLoadError(OntologyError):
    """An ontology file or folder could not be read or parsed.

    The message always names the file (and the line when the parser reports one), because
    the user has to go and fix that file.
    """

    def __init__(self, message: str, *, path: str | None = None, line: int | None = None):
        super().__init__(message)
        self.path = path
        self.line = line


class OntologyLimitError(OntologyLoadError):
    """A file is over one of the loader's limits (``limits``): too large, too many triples,
    too slow to parse, too many or too large entity expansions.

    Apart from other load errors so that the parser's own error handling lets it through
    unchanged (it is not "the file does not parse"); ``variable`` names the environment
    variable that raises the limit.
    """

    def __init__(self, message: str, *, path: str | None = None, line: int | None = None,
                 variable: str = ""):
        super().__init__(message, path=path, line=line)
        self.variable = variable


class OntologyConfigError(OntologyError):
    """The configuration points at something unusable (a missing path, a bad pyproject).

    The message names where the setting came from (argument, environment variable or the
    pyproject.toml file), since that is what the user has to correct.
    """
