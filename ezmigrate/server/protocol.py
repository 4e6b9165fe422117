"""``ezmigrate server``: the Language Server Protocol over stdio, on pygls.

Diagnostics are ``check``'s findings from ``check``'s pipeline (``workspace``), published
when a document opens, after it changes (debounced: one check per pause in typing) and
when it is saved. Hover, completion and go-to-definition answer from the ontology
(``terms``). Code actions: suppressing a finding with ``# noqa: CODE`` on its
line, and the safe fixes ``check --fix`` applies (EZ101). Nothing is written to disk:
every edit goes back to the editor as a workspace edit, and no code of the repository
runs.
"""

from __future__ import annotations

import asyncio
import gc
import os
from collections.abc import Callable
from pathlib import Path
from typing import Any

from lsprotocol import types as lsp
from pygls.lsp.server import LanguageServer
from pygls.uris import to_fs_path

from .. import __version__
from ..lint.diagnostic import Diagnostic
from . import skills, terms
from .workspace import Workspace

DEBOUNCE = float(os.environ.get("EZMIGRATE_SERVER_DEBOUNCE", "0.25"))
"""Seconds of quiet after a change before the buffer is checked (``bench_server.py`` sets
0 to time the check itself)."""
SEVERITY = {"error": lsp.DiagnosticSeverity.Error, "warning": lsp.DiagnosticSeverity.Warning,
            "info": lsp.DiagnosticSeverity.Information}


class EzServer(LanguageServer):
    """The server and the one workspace it serves (made on ``initialize``)."""

    def __init__(self, open_workspace: Callable[[Path], Workspace]) -> None:
        super().__init__("ezmigrate", __version__)
        self.open_workspace = open_workspace
        self.ws: Workspace | None = None
        self.notes: terms.Notes | None = None
        self.pending: dict[str, asyncio.TimerHandle] = {}
        self.found: dict[str, list[Diagnostic]] = {}

    def forget_finished(self) -> None:
        """Drop the finished handler futures pygls keeps. pygls 2.1 files the future of a
        notification whose built-in handler is a generator (``didOpen``, ``didChange``,
        ``didSave``, ``didClose``) under a fresh id that nothing ever removes: one future,
        a lock and a condition per keystroke, for the whole session. A finished one has
        nothing left to answer or cancel."""
        futures = getattr(self.protocol, "_request_futures", None)
        if isinstance(futures, dict):
            for key in [key for key, future in futures.items() if future.done()]:
                del futures[key]

    def cancel_waiting(self, uri: str) -> None:
        """Drop the debounced check a change of ``uri`` left waiting, if any."""
        waiting = self.pending.pop(uri, None)
        if waiting is not None:
            waiting.cancel()

    def term_notes(self) -> terms.Notes:
        if self.notes is None:
            assert self.ws is not None and self.ws.index is not None
            self.notes = terms.read_notes(self.ws.index)
        return self.notes


def _range(d: Diagnostic) -> lsp.Range:
    line = max(d.line - 1, 0)
    end_line = max((d.end_line or d.line) - 1, line)
    start = max(d.column - 1, 0)
    end = d.end_column - 1 if d.end_column else start + 1
    if end_line == line and end <= start:
        end = start + 1
    return lsp.Range(lsp.Position(line, start), lsp.Position(end_line, max(end, 0)))


def _lsp_diagnostic(d: Diagnostic) -> lsp.Diagnostic:
    return lsp.Diagnostic(range=_range(d), message=d.text, code=d.code, source="ezmigrate",
                          severity=SEVERITY.get(d.severity, lsp.DiagnosticSeverity.Hint),
                          data={"fix": d.fix} if d.fix else None)


def publish(server: EzServer, uri: str) -> None:
    """Check the document at ``uri`` as it stands in the editor and publish the findings."""
    server.cancel_waiting(uri)  # a save or an open while a change waits: check once
    server.forget_finished()
    if server.ws is None:
        return
    document = server.workspace.get_text_document(uri)
    path = Path(to_fs_path(uri) or document.path)
    if path.suffix != ".py":
        return
    try:
        found = server.ws.diagnose(path, document.source)
    except Exception as error:  # a buffer mid-typing must not end the session
        server.window_log_message(lsp.LogMessageParams(
            lsp.MessageType.Error, f"ezmigrate: {path}: {error}"))
        found = []
    server.found[uri] = found
    server.text_document_publish_diagnostics(lsp.PublishDiagnosticsParams(
        uri=uri, version=document.version, diagnostics=[_lsp_diagnostic(d) for d in found]))


def build(open_workspace: Callable[[Path], Workspace]) -> EzServer:
    """The server, its features registered."""
    server = EzServer(open_workspace)

    @server.feature(lsp.INITIALIZED)
    def initialized(ls: EzServer, _params: lsp.InitializedParams) -> None:
        root = ls.workspace.root_path or str(Path.cwd())
        ls.ws = ls.open_workspace(Path(root))
        # What the session holds for good (the modules, the ontology's index) is frozen out
        # of the collector's reach once, for the whole session: a check then finds the
        # heap frozen and leaves it so (``frozen_heap``), and what each check leaves is
        # collected as usual. Freezing and thawing around every check would move the
        # previous check's garbage out of reach each time, where no collection finds it.
        gc.collect()
        gc.freeze()

    @server.feature(lsp.TEXT_DOCUMENT_DID_OPEN)
    def did_open(ls: EzServer, params: lsp.DidOpenTextDocumentParams) -> None:
        publish(ls, params.text_document.uri)

    @server.feature(lsp.TEXT_DOCUMENT_DID_SAVE)
    def did_save(ls: EzServer, params: lsp.DidSaveTextDocumentParams) -> None:
        """The saved file, then every other open one: a save may change what crosses
        files (a description a tree names, an implementation's label)."""
        if ls.ws is not None:
            ls.ws.saved()
        publish(ls, params.text_document.uri)
        for uri in list(ls.found):
            if uri != params.text_document.uri:
                publish(ls, uri)

    @server.feature(lsp.TEXT_DOCUMENT_DID_CHANGE)
    def did_change(ls: EzServer, params: lsp.DidChangeTextDocumentParams) -> None:
        uri = params.text_document.uri
        ls.cancel_waiting(uri)
        ls.pending[uri] = asyncio.get_running_loop().call_later(DEBOUNCE, publish, ls, uri)

    @server.feature(lsp.TEXT_DOCUMENT_DID_CLOSE)
    def did_close(ls: EzServer, params: lsp.DidCloseTextDocumentParams) -> None:
        uri = params.text_document.uri
        ls.cancel_waiting(uri)
        ls.found.pop(uri, None)
        ls.text_document_publish_diagnostics(lsp.PublishDiagnosticsParams(uri, []))

    @server.feature(lsp.TEXT_DOCUMENT_HOVER)
    def hover(ls: EzServer, params: lsp.HoverParams) -> lsp.Hover | None:
        child = _child(ls, params.text_document.uri, params.position)
        if child is not None and ls.ws is not None and ls.ws.skills is not None:
            said = skills.hover_text(ls.ws.skills, child)
            if said is not None:
                return lsp.Hover(lsp.MarkupContent(lsp.MarkupKind.Markdown, said),
                                 lsp.Range(lsp.Position(params.position.line, child.start),
                                           lsp.Position(params.position.line, child.end)))
        term = _term(ls, params.text_document.uri, params.position)
        if term is None or ls.ws is None or ls.ws.index is None:
            return None
        text = terms.hover_text(ls.ws.index, ls.term_notes(), term)
        return lsp.Hover(lsp.MarkupContent(lsp.MarkupKind.Markdown, text),
                         lsp.Range(lsp.Position(term.line, term.start),
                                   lsp.Position(term.line, term.end)))

    @server.feature(lsp.TEXT_DOCUMENT_DEFINITION)
    def definition(ls: EzServer, params: lsp.DefinitionParams) -> lsp.Location | None:
        child = _child(ls, params.text_document.uri, params.position)
        if child is not None and ls.ws is not None and ls.ws.skills is not None:
            declared = skills.definition(ls.ws.skills, child, ls.ws.root)
            if declared is not None:
                at = lsp.Position(max(declared[1] - 1, 0), 0)
                return lsp.Location(Path(declared[0]).resolve().as_uri(), lsp.Range(at, at))
        term = _term(ls, params.text_document.uri, params.position)
        where = None if term is None else terms.definition(ls.term_notes(), term)
        if where is None:
            return None
        at = lsp.Position(where.line, 0)
        return lsp.Location(Path(where.path).as_uri(), lsp.Range(at, at))

    @server.feature(lsp.TEXT_DOCUMENT_COMPLETION,
                    lsp.CompletionOptions(trigger_characters=[".", ":", '"', "'"]))
    def completion(ls: EzServer, params: lsp.CompletionParams) -> lsp.CompletionList:
        if ls.ws is None or ls.ws.index is None:
            return lsp.CompletionList(is_incomplete=False, items=[])
        document = ls.workspace.get_text_document(params.text_document.uri)
        child = skills.child_at(document.source, params.position.line,
                                params.position.character)
        if child is not None and ls.ws.skills is not None:
            return lsp.CompletionList(is_incomplete=False, items=[
                lsp.CompletionItem(label=label, detail=detail,
                                   kind=lsp.CompletionItemKind.Module if child.kind == "type"
                                   else lsp.CompletionItemKind.Value)
                for label, detail in skills.completions(ls.ws.skills, child)])
        found = terms.completions(ls.ws.index, document.source, params.position.line,
                                  params.position.character)
        return lsp.CompletionList(is_incomplete=False, items=[
            lsp.CompletionItem(label=c.label, detail=c.detail,
                               kind=lsp.CompletionItemKind.Class if c.detail == "class"
                               else lsp.CompletionItemKind.Property) for c in found])

    @server.feature(lsp.TEXT_DOCUMENT_CODE_ACTION)
    def code_action(ls: EzServer, params: lsp.CodeActionParams) -> list[lsp.CodeAction]:
        return _actions(ls, params)

    return server


def _child(ls: EzServer, uri: str, position: lsp.Position) -> skills.ChildAt | None:
    document = ls.workspace.get_text_document(uri)
    return skills.child_at(document.source, position.line, position.character)


def _term(ls: EzServer, uri: str, position: lsp.Position) -> terms.Term | None:
    if ls.ws is None or ls.ws.index is None:
        return None
    document = ls.workspace.get_text_document(uri)
    return terms.term_at(ls.ws.index, document.source, position.line, position.character)


def _actions(ls: EzServer, params: lsp.CodeActionParams) -> list[lsp.CodeAction]:
    """Suppress each finding on the asked lines; apply the safe fixes of ``check --fix``."""
    from ..checking.fixes import fixed_text

    uri = params.text_document.uri
    document = ls.workspace.get_text_document(uri)
    lines = document.source.splitlines(keepends=True)
    first, last = params.range.start.line, params.range.end.line
    actions: list[lsp.CodeAction] = []
    here = [d for d in ls.found.get(uri, []) if first <= d.line - 1 <= last]
    for d in here:
        row = lines[d.line - 1] if d.line - 1 < len(lines) else ""
        body = row.rstrip("\r\n")
        end = lsp.Position(d.line - 1, len(body))
        actions.append(lsp.CodeAction(
            title=f"Suppress {d.code} on this line", kind=lsp.CodeActionKind.QuickFix,
            diagnostics=[_lsp_diagnostic(d)],
            edit=lsp.WorkspaceEdit(changes={uri: [lsp.TextEdit(
                lsp.Range(end, end), f"  # noqa: {d.code}")]})))
    actions += _migration(ls, uri, document.source, params.range.start.line)
    after = fixed_text(document.source, here)
    if after is not None and after != document.source:
        whole = lsp.Range(lsp.Position(0, 0), lsp.Position(len(lines), 0))
        actions.insert(0, lsp.CodeAction(
            title="Apply the safe fixes (check --fix)", kind=lsp.CodeActionKind.QuickFix,
            is_preferred=True, diagnostics=[_lsp_diagnostic(d) for d in here],
            edit=lsp.WorkspaceEdit(changes={uri: [lsp.TextEdit(whole, after)]})))
    return actions


def _migration(ls: EzServer, uri: str, text: str, line: int) -> list[lsp.CodeAction]:
    """"Migrate NAME to EzSkiROS" for the description class under the cursor: an edit of
    the whole module, or disabled with the reason ``rewrite`` gives."""
    from .migration import class_at, migrate_class

    name = class_at(text, line)
    if name is None or ls.ws is None:
        return []
    path = to_fs_path(uri) or uri
    done = migrate_class(text, name, str(path), ls.ws.index)
    title = f"Migrate {name} to EzSkiROS"
    if done.text is None:
        return [lsp.CodeAction(title=title, kind=lsp.CodeActionKind.RefactorRewrite,
                               disabled=lsp.CodeActionDisabled(done.refused or "refused"))]
    whole = lsp.Range(lsp.Position(0, 0), lsp.Position(len(text.splitlines()) + 1, 0))
    return [lsp.CodeAction(title=title, kind=lsp.CodeActionKind.RefactorRewrite,
                           edit=lsp.WorkspaceEdit(changes={uri: [lsp.TextEdit(whole,
                                                                              done.text)]}))]


def serve(open_workspace: Callable[[Path], Workspace], **_: Any) -> None:
    """Serve one editor over stdin and stdout until it hangs up."""
    build(open_workspace).start_io()
