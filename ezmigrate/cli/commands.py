"""The ``ezmigrate`` command line. It parses options and prints; decisions live elsewhere.

Conventions of black and ruff: diffs and reports go to stdout only when asked, progress and
the summary to stderr; exit 0 when the run did its work (skills skipped with a reason
included), 1 when something needs attention (``--check`` found changes, a verification
failed, a file could not be processed; with ``--strict`` also a skipped skill), 2 for usage
or internal errors.
"""

from __future__ import annotations

import contextlib
import os
import sys
import threading
from collections.abc import Sequence
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING, Any, NoReturn

import click

from .. import __version__
from ..files.discover import excluded_under
from ..files.paths import from_repository, in_report, scrub
from ..files.paths import shown as shown_path
from ..project import interrupt
from ..project.exit_codes import EXIT_ATTENTION, EXIT_ERROR, EXIT_OK
from ..verify.interpreters import never_search
from .arguments import CheckArguments, RewriteArguments, VerifyArguments
from .config import ConfigError, load_project_config
from .options import CommandLine, Options
from .output_formats import printable
from .shared_options import (
    DEBUG,
    EXCLUDE,
    IGNORE_LABELS,
    IGNORE_ORDER,
    INCLUDE_VENDORED,
    JOBS,
    ONTOLOGY,
    PYTHON,
    STDIN_FILENAME,
    TIMEOUT,
    report_option,
)
from .terminal import coloured_text, echo_diff, wants_colour

if TYPE_CHECKING:
    from ezskiros_runtime.ontology.config import SettledSource

    from ..checking.command import Subject
    from ..checking.run import CheckSettings
    from ..files.discover import Discovery
    from ..lint.select import Selection

EXIT_BROKEN_PIPE = 128 + 13  # as a shell reports a process ended by SIGPIPE


def _fail(message: str, debug: bool) -> NoReturn:
    click.echo(f"ezmigrate: error: {printable(message)}", err=True)
    if debug:
        import traceback

        traceback.print_exc()
    else:
        click.echo("ezmigrate: rerun with --debug for details", err=True)
    sys.exit(EXIT_ERROR)


class _Main(click.Group):
    """Stops cleanly on SIGINT/SIGTERM/SIGHUP (says what was done, exits 128 + signal); an
    internal error anywhere, a worker thread included, is one line and a ``--debug`` hint."""

    def invoke(self, ctx: click.Context) -> Any:
        debug = "--debug" in sys.argv[1:]
        previous_hook = threading.excepthook
        threading.excepthook = lambda args: _thread_failed(args, debug)
        interrupt.install()  # for the life of the process
        try:
            return super().invoke(ctx)
        except interrupt.Interrupted as stop:
            interrupt.ignore_further()
            with contextlib.suppress(OSError):  # the terminal may be gone (SIGHUP)
                for line in stop.report():
                    click.echo(f"ezmigrate: {printable(line)}", err=True)
            sys.exit(stop.exit_code)
        except (click.exceptions.ClickException, click.exceptions.Exit,
                click.exceptions.Abort):
            raise
        except ConfigError as error:
            click.echo(f"ezmigrate: error: {printable(str(error))}", err=True)
            sys.exit(EXIT_ERROR)
        except BrokenPipeError:  # `ezmigrate rewrite --dry-run . | head`: the reader left
            _quiet_stdout()
            sys.exit(EXIT_BROKEN_PIPE)
        except Exception as error:  # never a raw traceback for the user
            _fail(f"internal error: {error}", debug)
        finally:
            threading.excepthook = previous_hook


def _quiet_stdout() -> None:
    """Point stdout at /dev/null so that flushing it at exit raises nothing more."""
    with contextlib.suppress(OSError, ValueError):
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())


def _thread_failed(args: Any, debug: bool) -> None:
    if args.exc_type is SystemExit:
        return
    click.echo(f"ezmigrate: internal error in a worker thread: {args.exc_type.__name__}: "
               f"{args.exc_value}", err=True)
    if debug:
        import traceback

        traceback.print_exception(args.exc_type, args.exc_value, args.exc_traceback)
    else:
        click.echo("ezmigrate: rerun with --debug for details", err=True)


def _options(start: Path, cli: CommandLine, checked: Sequence[Path] = ()) -> Options:
    """The settings a command runs with: ``cli`` over the project ``start`` belongs to.
    ``start`` and ``checked`` (the paths given) are the repository at work: no interpreter
    is looked for there, ``--python`` named on the command line included."""
    never_search([start, *checked])
    project = load_project_config(start)
    for warning in project.warnings:  # once per run: a typo'd key otherwise does nothing
        click.echo(f"ezmigrate: {printable(warning)}", err=True)
    return Options.resolve(cli, project)


def _load_index(ontology: tuple[Path, ...], start: Path, roots: Sequence[Path],
                options: Options) -> tuple[Any, tuple[str, ...], str]:
    """The ontology index by the configuration rules, the files it came from, and a line
    saying which files and why (``_settle_ontology``, loaded)."""
    settled, described = _settle_ontology(ontology, start, roots, options)
    return settled.index(), tuple(str(p) for p in settled.source.paths), described


def _settle_ontology(ontology: tuple[Path, ...], start: Path, roots: Sequence[Path],
                     options: Options) -> tuple[Any, str]:
    """The ontology by the configuration rules, its files known to load
    (``SettledSource``: the index decoded when asked for), and a line saying which files
    and why.

    Says once on stderr which files are used and why (the report header says it again):
    with nothing configured, the owl/ folders of the repository of ``roots`` count (less
    what ``options.exclude`` names, relative to the project)."""
    from ezskiros_runtime.ontology.config import resolve_ontology_paths, settle_source
    from ezskiros_runtime.ontology.errors import OntologyError

    try:
        skip = excluded_under(options.project or Path.cwd(), options.exclude)
        source = resolve_ontology_paths(list(ontology) or None, start=start, roots=roots,
                                        skip=skip)
        settled = settle_source(source)
        for warning in settled.source.warnings():  # paths relative, as the next line's
            click.echo(f"ezmigrate: {printable(scrub(warning, report=False))}", err=True)
        described = scrub(settled.source.describe(), report=False)  # as other lines say
        click.echo(f"ezmigrate: {printable(described)}", err=True)
        return settled, described
    except OntologyError as error:
        click.echo(f"ezmigrate: error: {printable(str(error))}", err=True)
        sys.exit(EXIT_ERROR)


def _report_path(path: Path | None) -> Path | None:
    """The report's format comes from its name: refuse a name that says neither."""
    if path is not None and str(path) != "-" and path.suffix.lower() not in (".md", ".json"):
        raise click.BadParameter(f"{path}: name it *.md for Markdown or *.json for JSON "
                                 "(or - for JSON on stdout)", param_hint="'--report'")
    return path


REPORT: Any = report_option(_report_path)


@click.group(cls=_Main, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, "-V", "--version", prog_name="ezmigrate")
def main() -> None:
    """Migrate SkiROS2 skill descriptions to EzSkiROS, and prove nothing changed."""


@main.command()
@click.argument("paths", nargs=-1, required=True,
                type=click.Path(path_type=Path, allow_dash=True, exists=True))
@click.option("--dry-run", is_flag=True, help="Write nothing; print a unified diff per file.")
@click.option("--check", is_flag=True, help="Write nothing; exit 1 if any file would change.")
@REPORT
@EXCLUDE
@INCLUDE_VENDORED
@ONTOLOGY
@JOBS
@click.option("--output-dir", type=click.Path(path_type=Path, file_okay=False),
              help="Write migrated copies here instead of in place, each at its path "
                   "relative to the PATH it was found under; a second file with the same "
                   "relative path (c1/x.py and c2/x.py) is refused, and the run exits 1.")
@click.option("--verify/--no-verify", default=True, show_default=True,
              help="Load both versions and demand equivalence before writing.")
@TIMEOUT
@PYTHON
@IGNORE_ORDER
@IGNORE_LABELS
@click.option("--color/--no-color", default=None, help="Colour diffs (default: on a terminal).")
@STDIN_FILENAME
@click.option("--strict", is_flag=True,
              help="Exit 1 also when a skill was skipped with a reason (default: only for "
                   "--check with changes, failed verification, or unprocessable files).")
@click.option("--package-xml/--no-package-xml", default=True, show_default=True,
              help="Declare the runtime (<exec_depend>) in the package.xml of each ROS "
                   "package whose files were migrated.")
@DEBUG
def rewrite(**given: Any) -> None:
    """Rewrite legacy descriptions under PATHS into EzSkiROS (`-` reads stdin).

    Temporary files (.NAME.XXXXXXXX.ezmigrate) that a killed run left beside PATHS are
    listed; a run that writes removes them (they never hold the only copy of anything).
    """
    args = RewriteArguments(**given)
    start = (args.stdin_filename or Path.cwd()) if args.reads_stdin else args.paths[0]
    options = _options(start, args.command_line(), args.paths)
    if args.reads_stdin:
        _rewrite_stdin(args, start, options)
    from ..project.session import RewriteOptions, run_rewrite  # heavy (libcst): after the handlers
    from ..project.target import robot_python, target_for, verified_with
    from ..report.reports import MarkdownOptions, newer_python_lines
    from ..verify.interpreters import version_of
    from .rewrite_output import finish, print_result, results_as_written, show_manifests

    index, ontology_files, used = _load_index(args.ontology, start, args.paths, options)
    robot = target_for(args.paths, options.target_version,
                       f"{options.source}: target-version")
    python = robot_python(robot, options.python, args.verify)
    verifier = verified_with(python, robot) if args.verify else ""
    if verifier:
        click.echo(f"ezmigrate: {printable(verifier)}", err=True)
    pool = replace(options.pool(ontology_files), python=python)  # verification and tracing
    request = RewriteOptions(
        paths=list(args.paths), dry_run=args.dry_run, check=args.check,
        exclude=options.exclude, jobs=options.jobs, output_dir=args.output_dir,
        verify=args.verify, pool=pool, ignore_order=args.ignore_order,
        ignore_labels=args.ignore_labels, project=options.project, target=robot.version,
        include_vendored=args.include_vendored, package_xml=args.package_xml)
    from ..project.earlier import whole_tree

    outcome = run_rewrite(request, index)
    for note in outcome.notes:
        click.echo(f"ezmigrate: {printable(note)}", err=True)
    # earlier runs' descriptions count too: stderr and the report say one count of the tree
    results = results_as_written(outcome.migrated, whole_tree(outcome.migrated))
    for item, result in zip(outcome.migrated, results, strict=True):  # unchanged: bytes stay
        if result.error or result.changed or any(
                s.status in ("skipped", "failed") for s in result.skills):  # else nothing to say
            print_result(shown_path(item.candidate.path),
                          from_repository(item.candidate.path, item.candidate.relative),
                          item.original if result.changed else b"", result, args)
    for refused in outcome.refused:
        click.echo(f"ezmigrate: {printable(refused)}", err=True)
    declared = show_manifests(outcome, request, args.color)
    newer = newer_python_lines(results, python, version_of(python)) if args.verify else []
    for line in newer:
        click.echo(f"ezmigrate: {printable(line)}", err=True)
    compounds: list[str] = []
    scenes: list[str] = []
    if args.report is not None and args.report.suffix.lower() == ".md":
        from ..checking.compound import compound_report
        from ..checking.pipeline import scene_report
        from ..checking.run import CheckSettings

        compounds = compound_report(
            [(m.candidate, m.original, m.result) for m in outcome.migrated], index, pool,
            CheckSettings(exclude=options.exclude, skill_libraries=options.skill_libraries),
            args.paths)
        scenes = scene_report(args.paths, options.exclude, index)
    finish(args, results, outcome.refused,
            MarkdownOptions(args.verify, args.ignore_order, args.ignore_labels, ontology=used,
                            compounds=compounds, verifier=verifier, scenes=scenes,
                            notes=[*newer, *declared]),
            reported=results if args.report else None)


def _rewrite_stdin(args: RewriteArguments, start: Path, options: Options) -> NoReturn:
    """``rewrite -``: stdin's file migrated (and verified) to stdout, whole whatever
    happened, problems and the summary on stderr as for a file."""
    from ..project.stdin import rewrite_stdin, stdin_roots
    from ..report.reports import MarkdownOptions
    from ..report.written_lines import as_written
    from ..verify.verdicts import Comparison
    from .rewrite_output import finish, print_result

    index, ontology_files, used = _load_index(args.ontology, start,
                                              stdin_roots(args.stdin_filename), options)
    data = sys.stdin.buffer.read()
    result = rewrite_stdin(data, index, options.pool(ontology_files), options.target_version,
                           Comparison(args.ignore_order, args.ignore_labels) if args.verify
                           else None, args.stdin_filename)
    shown = str(args.stdin_filename) if args.stdin_filename else "-"
    print_result(shown, shown, data, result, args)
    if args.writes:  # whatever happened, stdout gets a whole file
        new = result.new_source
        sys.stdout.buffer.write(new if isinstance(new, bytes) else data)
    finish(args, [as_written(replace(result, path=in_report(result.path)), data)], [],
            MarkdownOptions(args.verify, args.ignore_order, args.ignore_labels, ontology=used))


def _cache_dir(paths: Sequence[Path], options: Options, named: Path | None) -> Path:
    """The folder of this project's entries in the user's cache (``cache_folder``): the
    project is the ``pyproject.toml`` folder, else the git checkout or ROS package of the
    first path, else the working directory."""
    from ezskiros_runtime.ontology.discovery import enclosing_project

    from ..cache.cache_folder import ENVIRONMENT, cache_root, project_folder

    if named is not None:  # the sandbox hides it from loaded code (``hidden_folders``)
        os.environ[ENVIRONMENT] = str(named.resolve())
    base = options.project or enclosing_project(paths[0]) or Path.cwd()
    return project_folder(cache_root(named), base)


@main.command()
@click.argument("before", type=click.Path(path_type=Path, exists=True))
@click.argument("after", type=click.Path(path_type=Path, exists=True))
@REPORT
@ONTOLOGY
@JOBS
@TIMEOUT
@PYTHON
@EXCLUDE
@IGNORE_ORDER
@IGNORE_LABELS
@DEBUG
def verify(**given: Any) -> None:
    """Prove AFTER means what BEFORE meant (two files, or two folders by relative path)."""
    from ..project.target import robot_python, target_for, verified_with
    from ..report.reports import MarkdownOptions, relaxed
    from ..verify.command import PathsMismatch, VerifyOptions, run_verify
    from .rewrite_output import said, write_report

    args = VerifyArguments(**given)
    options = _options(args.before, args.command_line(), (args.after,))
    _, ontology_files, used = _load_index(args.ontology, args.before, [args.before], options)
    robot = target_for([args.after], options.target_version,
                       f"{options.source}: target-version")
    python = robot_python(robot, options.python, True)
    verifier = verified_with(python, robot)
    click.echo(f"ezmigrate: {printable(verifier)}", err=True)
    pool = replace(options.pool(ontology_files), python=python)
    try:
        results, unloadable = run_verify(VerifyOptions(
            args.before, args.after, pool, args.ignore_order, args.ignore_labels,
            options.exclude))
    except PathsMismatch as error:
        raise click.UsageError(str(error)) from None
    for result in results:
        where = printable(result.path, path=True)
        if result.error:
            click.echo(f"{where}: {said(result.error, args.debug)}", err=True)
        for note in result.notes:  # an unchanged file that cannot load; captured output
            click.echo(f"{where}: {said(note, args.debug)}", err=True)
        for skill in result.skills:
            if skill.status == "failed":
                click.echo(f"{where}:{skill.line}: {printable(skill.name)}: "
                           f"{said(skill.reason or '', args.debug)}", err=True)
                for d in skill.diff or ():
                    click.echo(f"    {d['where']}: {d['message']}", err=True)
                    if d.get("before") is not None:
                        click.echo(f"      - {d['before']}", err=True)
                    if d.get("after") is not None:
                        click.echo(f"      + {d['after']}", err=True)
    if args.report is not None:
        write_report(args.report, results,
                      MarkdownOptions(True, args.ignore_order, args.ignore_labels,
                                      ontology=used, verifier=verifier))
    total = sum(len(r.skills) for r in results)
    bad = sum(1 for r in results for s in r.skills if s.status == "failed")
    relax = relaxed(args.ignore_order, args.ignore_labels)
    click.echo(f"ezmigrate: {len(results)} files compared, {total} classes, "
               f"{total - bad} equivalent, {bad} not equivalent"
               + (f" ({relax})" if relax else "")
               + (", some files could not be loaded" if unloadable else ""), err=True)
    sys.exit(EXIT_ERROR if unloadable else EXIT_ATTENTION if bad else EXIT_OK)


@main.command()
@click.argument("paths", nargs=-1,
                type=click.Path(path_type=Path, allow_dash=True, exists=True))
@STDIN_FILENAME
@ONTOLOGY
@click.option("--select", multiple=True, metavar="CODES",
              help="Report only these codes or prefixes (EZ2,EZ901; replaces the default).")
@click.option("--ignore", multiple=True, metavar="CODES", help="Do not report these codes.")
@click.option("--extend-select", multiple=True, metavar="CODES",
              help="Report these codes as well as the selected ones.")
@click.option("--output-format", type=click.Choice(["text", "json", "sarif", "github",
                                                     "junit"]), default="text",
              show_default=True, help="How findings are written to stdout.")
@click.option("--statistics", is_flag=True, help="Print the count of findings per code.")
@click.option("--fix", is_flag=True,
              help="Apply the fixes that are safe and explicit (EZ101), then report the rest.")
@click.option("--diff", "show_diff", is_flag=True,
              help="Print the diff --fix would apply and write nothing (exit 1 if any).")
@click.option("--exit-zero", is_flag=True, help="Exit 0 even when errors were found.")
@JOBS
@TIMEOUT
@PYTHON
@EXCLUDE
@INCLUDE_VENDORED
@click.option("--trace/--no-trace", "trace", default=False,
              help="Run repository code, for repositories you trust: load EzSkiROS files "
                   "whose descriptions the syntax cannot give, and trace compound skills "
                   "whose tree it cannot give, in the sandbox. By default check runs no "
                   "code of the repository and says what it could not read (info).")
@click.option("--no-cache", is_flag=True,
              help="Read every file again instead of reusing what an earlier run kept in "
                   "the cache.")
@click.option("--cache-dir", "cache_folder", type=click.Path(path_type=Path, file_okay=False),
              help="The cache folder (default: $EZMIGRATE_CACHE_DIR, else "
                   "$XDG_CACHE_HOME/ezmigrate or ~/.cache/ezmigrate).")
@click.option("--quiet", "-q", is_flag=True, help="Only errors; no summary.")
@click.option("--scene", type=click.Path(path_type=Path, exists=True, dir_okay=False),
              help="A world-model scene (*.turtle): say which skills cannot start from it "
                   "(EZ409, info).")
@click.option("--launch", "launch_file",
              type=click.Path(path_type=Path, exists=True, dir_okay=False),
              help="The SkiROS2 launch file the robot starts with (.launch or .launch.py): "
                   "its workspace_dir, init_scene and skill_list are used (default: the "
                   "only one in the repository).")
@DEBUG
def check(**given: Any) -> None:
    """Lint SkiROS2 and EzSkiROS descriptions under PATHS, the working directory when none
    is given, as ruff does (codes: docs/rules.md).

    Suppress a finding on its line with `# ezskiros: ignore[EZ209]` (or `ignore[EZ209,EZ201]`).
    Exit 0 when no finding at error severity remains, 1 when one does, 2 on usage errors.
    """
    from ezskiros_runtime.ontology.vendored import shared_rules

    from ..checking.command import Conclusion, conclude, subject
    from ..checking.discover import checked_files
    from ..checking.pipeline import run_check
    from .output_formats import STATISTICS

    args = CheckArguments(**given)
    if args.statistics and args.output_format not in STATISTICS:
        raise click.UsageError(f"--statistics has no {args.output_format} form (it has "
                               f"{' and '.join(STATISTICS)}): drop one of the two options")
    if args.reads_stdin and (args.fix or args.show_diff):
        raise click.UsageError("--fix and --diff work on files, not on stdin")
    of = subject(args.paths, sys.stdin.buffer.read() if args.reads_stdin else None,
                 args.stdin_filename)
    options = _options(of.anchor, args.command_line(), of.roots)
    selection = _selection(options)
    with shared_rules():  # the four searches of the repository share their answers
        discovered = checked_files(list(of.paths), options.exclude, args.include_vendored)
        ontology, _ = _settle_ontology(args.ontology, of.anchor, of.roots, options)
        outcome = run_check(list(of.paths), None,
                            options.pool(tuple(str(p) for p in ontology.source.paths)),
                            _check_settings(args, of, options, selection, discovered,
                                            ontology))
    done = conclude(outcome, of, Conclusion(
        selection, "diff" if args.show_diff else "fix" if args.fix else None, args.quiet,
        args.exit_zero))
    for diff in done.diffs:
        echo_diff(diff)
    for message in done.messages:
        click.echo(f"ezmigrate: {printable(message)}", err=True)
    if done.findings:
        _echo_findings(done.shown, args.output_format, args.statistics)
    if done.summary is not None:
        click.echo(f"ezmigrate: {done.summary}", err=True)
    sys.exit(done.exit_code)


def _check_settings(args: CheckArguments, of: Subject, options: Options,
                    selection: Selection, discovered: Discovery,
                    ontology: SettledSource) -> CheckSettings:
    """The ``CheckSettings`` of a ``check`` run, the one place its command line, the
    resolved ``options`` and the codes of ``selection`` become them; says the launch file
    on stderr (``_launch``). ``discovered``: the paths' files, already being found;
    ``ontology``: loaded when the run must read."""
    from ..checking.pipeline import needs_trees
    from ..checking.run import CheckSettings

    return CheckSettings(
        exclude=options.exclude, include_vendored=args.include_vendored,
        skill_libraries=options.skill_libraries, compounds=needs_trees(selection.codes()),
        trace=args.trace,
        cache_dir=None if args.no_cache else _cache_dir(of.paths, options, args.cache_folder),
        world=_world_run(of.paths, options, args.scene),
        launch=_launch(of.anchor, args.launch_file, args.quiet),
        progress=sys.stderr.isatty() and not args.quiet,
        discovered=discovered, ontology=ontology)


def _selection(options: Options) -> Any:
    """The codes a run reports (``lint/select.py``), from the resolved settings; a
    selector that names no code is a usage error."""
    from ..lint.select import Selection, SelectorError, parse_selectors

    try:
        return Selection(
            select=None if options.select is None else parse_selectors(options.select,
                                                                       options.select_from),
            ignore=parse_selectors(options.ignore, "--ignore"),
            extend_select=parse_selectors(options.extend_select, "--extend-select"))
    except SelectorError as error:
        raise click.UsageError(str(error)) from None


def _echo_findings(found: list[Any], output_format: str, statistics: bool) -> None:
    """``check``'s findings on stdout in ``output_format``; the text format coloured by
    severity on a terminal (``terminal.wants_colour``), every machine format never."""
    from .output_formats import FORMATS, STATISTICS

    if output_format == "text" and not statistics and wants_colour(sys.stdout):
        click.echo(coloured_text(found), nl=False, color=True)
    else:
        click.echo((STATISTICS if statistics else FORMATS)[output_format](found), nl=False)


def _launch(anchor: Path, chosen: Path | None, quiet: bool) -> Any:
    """The SkiROS2 launch file of the run's repository (``launch.project_launch``), said
    on stderr with what it sets."""
    from ezskiros_runtime.ontology.discovery import enclosing_project

    from ..checking.launch import project_launch

    root = anchor if anchor.is_dir() else enclosing_project(anchor)
    if root is None:  # a file alone: no launch file around it is its robot's, unless named
        launch, note = project_launch(anchor, chosen) if chosen else (None, None)
    else:
        launch, note = project_launch(root, chosen)
    if not quiet and note is not None:
        click.echo(f"ezmigrate: {printable(note)}", err=True)
    if not quiet and launch is not None and launch.values:
        said = ", ".join(f"{k}={v}" for k, v in sorted(launch.values.items()))
        click.echo(f"ezmigrate: launch: {printable(shown_path(str(launch.path)))} "
                   f"({printable(said)})", err=True)
        scene = launch.values.get("init_scene", "").strip()
        if scene and launch.scene() is None:
            click.echo(f"ezmigrate: init_scene {scene!r} is neither beside the launch file "
                       "nor in the workspace_dir: not checked", err=True)
    return launch


def _world_run(paths: tuple[Path, ...], options: Options, scene: Path | None) -> Any:
    """``check``'s world-model settings: the project's ``single-valued`` (resolved once in
    ``options``), the scenes under ``paths``, and the ``--scene`` skills must start from
    (which must parse: exit 2)."""
    from ..lint.scene_search import WorldRun, scene_files

    if scene is not None:
        from ezskiros_runtime.world.scene import SceneError, read_scene

        try:
            read_scene(scene)
        except SceneError as error:
            raise click.BadParameter(str(error), param_hint="'--scene'") from None
    return WorldRun(single_valued=options.single_valued,
                    scenes=tuple(scene_files(list(paths), options.exclude)), start_scene=scene)


@main.command()
@ONTOLOGY
@click.option("--stdio", is_flag=True, help="Talk over stdin and stdout (the default).")
def server(ontology: tuple[Path, ...], stdio: bool) -> None:
    """Serve an editor over the Language Server Protocol: check's findings as you type,
    hover, completion and go-to-definition on ontology terms, and quick fixes.

    No code of the workspace runs; an unsaved buffer is checked as typed, never written.
    """
    from ..checking.pipeline import needs_trees
    from ..checking.run import CheckSettings
    from ..server.protocol import serve
    from ..server.workspace import Workspace

    def open_workspace(root: Path) -> Workspace:
        options = _options(root, CommandLine(), [root])
        index, files, _ = _load_index(ontology, root, [root], options)
        selection = _selection(options)
        return Workspace(root, index, replace(options.pool(files), workers=1), CheckSettings(
            exclude=options.exclude, skill_libraries=options.skill_libraries,
            compounds=needs_trees(selection.codes()),
            world=_world_run((root,), options, None),
            launch=_launch(root, None, quiet=False)), selection)

    serve(open_workspace)


@main.command()
@click.argument("file", type=click.Path(path_type=Path, exists=True, dir_okay=False))
@ONTOLOGY
@click.option("--markdown", is_flag=True,
              help="Print the Markdown section (findings and a fenced diagram) instead.")
@DEBUG
def scene(file: Path, ontology: tuple[Path, ...], markdown: bool, debug: bool) -> None:
    """Draw the spatial tree of the world-model scene FILE as a Mermaid flowchart.

    Elements with their class, contain/hasA edges, and the elements a finding (EZ4xx) is
    about highlighted. Exit 0 when the scene has no finding at error severity, 1 when it
    has, 2 when it cannot be parsed.
    """
    from ..lint.scene_diagram import markdown_section, mermaid
    from ..lint.world_model import read_scenes

    options = _options(file, CommandLine())
    index, _, _ = _load_index(ontology, file, [file], options)
    read = read_scenes([file], index)[0]
    if read.scene is None:
        for f in read.findings:
            click.echo(f"{f.file}:{f.line}: {f.code} {f.message}", err=True)
        sys.exit(EXIT_ERROR)
    if markdown:
        click.echo("\n".join(markdown_section([file], index)), nl=False)
    else:
        click.echo(mermaid(read.scene, read.findings, index), nl=False)
        for f in read.findings:
            click.echo(f"{f.file}:{f.line}: {f.code} {f.message}", err=True)
    sys.exit(EXIT_ATTENTION if any(f.severity == "error" for f in read.findings) else EXIT_OK)
