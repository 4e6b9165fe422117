"""``ezmigrate server`` end to end: a real client (pytest-lsp) over the server's stdio.

Each test opens a workspace made in a temporary folder, as an editor would, and checks what
comes back against what ``check`` says of the same text.
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
import pytest_lsp
from lsprotocol import types as lsp
from pytest_lsp import ClientServerConfig, LanguageClient, client_capabilities

LEGACY = '''\
from skiros2_skill.core.skill import SkillDescription
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


class Pick(SkillDescription):
    def createDescription(self):
        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)
        self.addParam("Place", Element("skiros:Lcoation"), ParamTypes.Required)
        self.addParam("Speed", 0.5, ParamTypes.Optional, "how fast")
        self.addPreCondition(self.getRelationCond("PlaceHolds", "skiros:contain", "Place",
                                                  "Object", True))
'''
MARKER_MODULE = '''\
import pathlib
pathlib.Path(__file__).with_name("imported.marker").write_text("ran")
from ezskiros_runtime import SkillDescription
from ezskiros_runtime.ontology import skiros


class Place(SkillDescription):
    def description(self, Where: skiros.Location):
        pass
'''


COMPOUND = '''\
from skiros2_skill.core.skill import SkillDescription, SkillBase, Sequential
from skiros2_common.core.params import ParamTypes
from skiros2_common.core.world_element import Element


class Fetch(SkillDescription):
    def createDescription(self):
        self.addParam("Object", Element("skiros:Product"), ParamTypes.Required)


class fetch(SkillBase):
    def createDescription(self):
        self.setDescription(Fetch(), self.__class__.__name__)

    def expand(self, skill):
        skill.setProcessor(Sequential())
        skill(
            self.skill("Pick", "pick", specify={"Speed": 0.2}),
        )


class pick(SkillBase):
    def createDescription(self):
        self.setDescription(Pick(), self.__class__.__name__)
'''


def _workspace(root: Path) -> Path:
    (root / "pkg").mkdir(parents=True)
    (root / "package.xml").write_text("<package><name>ws</name></package>\n")
    (root / "pkg" / "pick.py").write_text(LEGACY)
    (root / "pkg" / "place.py").write_text(MARKER_MODULE)
    (root / "pkg" / "fetch.py").write_text(COMPOUND)
    return root / "pkg" / "pick.py"


@pytest_lsp.fixture(config=ClientServerConfig(
    server_command=[sys.executable, "-m", "ezmigrate", "server"]))
async def client(lsp_client: LanguageClient, tmp_path: Path):  # type: ignore[no-untyped-def]
    _workspace(tmp_path / "ws")
    await lsp_client.initialize_session(lsp.InitializeParams(
        capabilities=client_capabilities("visual-studio-code"),
        root_uri=(tmp_path / "ws").as_uri()))
    yield
    await lsp_client.shutdown_session()


async def _open(client: LanguageClient, path: Path, text: str) -> list[lsp.Diagnostic]:
    uri = path.as_uri()
    client.text_document_did_open(lsp.DidOpenTextDocumentParams(
        lsp.TextDocumentItem(uri=uri, language_id="python", version=1, text=text)))
    await client.wait_for_notification(lsp.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
    return list(client.diagnostics[uri])


def _applied(text: str, edits: list[lsp.TextEdit]) -> str:
    """``edits`` made on ``text`` as an editor makes them (positions in the text before
    any edit; the last first)."""
    lines = text.splitlines(keepends=True)

    def offset(at: lsp.Position) -> int:
        return sum(len(row) for row in lines[:at.line]) + at.character

    for edit in sorted(edits, key=lambda e: offset(e.range.start), reverse=True):
        text = text[:offset(edit.range.start)] + edit.new_text + text[offset(edit.range.end):]
    return text


@pytest.mark.asyncio
async def test_open_change_and_save_publish_check_findings(client: LanguageClient,
                                                           tmp_path: Path) -> None:
    path = tmp_path / "ws" / "pkg" / "pick.py"
    found = await _open(client, path, LEGACY)
    assert [(d.code, d.range.start.line) for d in found if d.code == "EZ209"] == [("EZ209", 8)]
    assert any(d.code == "EZ101" for d in found)
    # typed, not saved: the buffer is checked as it stands, the file on disk unchanged
    fixed = LEGACY.replace("skiros:Lcoation", "skiros:Location")
    client.text_document_did_change(lsp.DidChangeTextDocumentParams(
        lsp.VersionedTextDocumentIdentifier(uri=path.as_uri(), version=2),
        [lsp.TextDocumentContentChangeWholeDocument(text=fixed)]))
    await client.wait_for_notification(lsp.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
    assert not any(d.code == "EZ209" for d in client.diagnostics[path.as_uri()])
    assert path.read_text() == LEGACY
    client.text_document_did_save(lsp.DidSaveTextDocumentParams(
        lsp.TextDocumentIdentifier(uri=path.as_uri())))
    await client.wait_for_notification(lsp.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
    assert not any(d.code == "EZ209" for d in client.diagnostics[path.as_uri()])


@pytest.mark.asyncio
async def test_a_buffer_mid_typing_with_a_syntax_error_gets_a_finding_not_a_crash(
        client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "ws" / "pkg" / "pick.py"
    broken = LEGACY.replace('ParamTypes.Required)\n        self.addParam("Place"',
                            'ParamTypes.Required\n        self.addParam("Place"')
    found = await _open(client, path, broken)
    assert found, "a file that does not parse says so"
    again = await _open(client, path, LEGACY)  # the session goes on
    assert any(d.code == "EZ209" for d in again)


@pytest.mark.asyncio
async def test_hover_and_definition_of_a_legacy_string_and_an_ezskiros_attribute(
        client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "ws" / "pkg" / "pick.py"
    await _open(client, path, LEGACY)
    legacy = await client.text_document_hover_async(lsp.HoverParams(
        lsp.TextDocumentIdentifier(path.as_uri()), lsp.Position(7, 44)))
    assert legacy is not None and "**skiros:Product**" in legacy.contents.value  # type: ignore[union-attr]
    assert "defined at" in legacy.contents.value  # type: ignore[union-attr]
    place = tmp_path / "ws" / "pkg" / "place.py"
    await _open(client, place, MARKER_MODULE)
    line = MARKER_MODULE.splitlines()[7]
    hover = await client.text_document_hover_async(lsp.HoverParams(
        lsp.TextDocumentIdentifier(place.as_uri()),
        lsp.Position(7, line.index("Location") + 2)))
    assert hover is not None and "**skiros:Location**" in hover.contents.value  # type: ignore[union-attr]
    where = await client.text_document_definition_async(lsp.DefinitionParams(
        lsp.TextDocumentIdentifier(place.as_uri()),
        lsp.Position(7, line.index("Location") + 2)))
    assert isinstance(where, lsp.Location)
    defined = Path(where.uri.removeprefix("file://")).read_text().splitlines()
    assert "Location" in defined[where.range.start.line]


@pytest.mark.asyncio
async def test_completion_offers_the_classes_of_a_prefix_in_both_forms(
        client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "ws" / "pkg" / "new.py"
    text = 'x = Element("skiros:Loc\ny: skiros.Loc\n'
    await _open(client, path, text)
    for line, character in ((0, len('x = Element("skiros:Loc')), (1, len("y: skiros.Loc"))):
        found = await client.text_document_completion_async(lsp.CompletionParams(
            lsp.TextDocumentIdentifier(path.as_uri()), lsp.Position(line, character)))
        assert found is not None
        labels = [i.label for i in (found.items if isinstance(found, lsp.CompletionList)
                                    else found)]
        assert "Location" in labels and all(label.startswith("Loc") for label in labels)


@pytest.mark.asyncio
async def test_code_actions_fix_and_suppress_and_their_edits_pass_check(
        client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "ws" / "pkg" / "pick.py"
    found = await _open(client, path, LEGACY)
    actions = await client.text_document_code_action_async(lsp.CodeActionParams(
        lsp.TextDocumentIdentifier(path.as_uri()),
        lsp.Range(lsp.Position(0, 0), lsp.Position(12, 0)),
        lsp.CodeActionContext(diagnostics=found)))
    assert actions is not None
    titles = [a.title for a in actions if isinstance(a, lsp.CodeAction)]
    assert "Apply the safe fixes (check --fix)" in titles
    assert "Suppress EZ209 on this line" in titles
    text = LEGACY
    for action in actions:
        assert isinstance(action, lsp.CodeAction) and action.edit is not None
        if action.title in ("Apply the safe fixes (check --fix)", "Suppress EZ209 on this line"):
            text = _applied(text, list(action.edit.changes[path.as_uri()]))  # type: ignore[index]
            again = await _open(client, path, text)
    assert 'description="how fast"' in text and "# noqa: EZ209" in text
    assert not [d for d in again if d.code in ("EZ101", "EZ209")]


@pytest.mark.asyncio
async def test_a_session_of_edits_never_runs_the_workspace_code(client: LanguageClient,
                                                                tmp_path: Path) -> None:
    place = tmp_path / "ws" / "pkg" / "place.py"
    await _open(client, place, MARKER_MODULE)
    for version in range(2, 5):
        client.text_document_did_change(lsp.DidChangeTextDocumentParams(
            lsp.VersionedTextDocumentIdentifier(uri=place.as_uri(), version=version),
            [lsp.TextDocumentContentChangeWholeDocument(
                text=MARKER_MODULE + f"# edit {version}\n")]))
        await client.wait_for_notification(lsp.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
    client.text_document_did_save(lsp.DidSaveTextDocumentParams(
        lsp.TextDocumentIdentifier(uri=place.as_uri())))
    await client.wait_for_notification(lsp.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
    assert not (tmp_path / "ws" / "pkg" / "imported.marker").exists()


def _message(payload: dict[str, object]) -> bytes:
    import json

    body = json.dumps(payload).encode()
    return b"Content-Length: %d\r\n\r\n" % len(body) + body


def test_a_client_that_hangs_up_abruptly_leaves_no_server_behind(tmp_path: Path) -> None:
    """The editor dies mid-session (its end of the pipes closes, no shutdown, no exit):
    the server sees its input end and exits with everything it started."""
    import subprocess

    _workspace(tmp_path / "ws")
    server = subprocess.Popen([sys.executable, "-m", "ezmigrate", "server"],
                              stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                              stderr=subprocess.DEVNULL, cwd=tmp_path)
    assert server.stdin is not None and server.stdout is not None
    server.stdin.write(_message({"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {
        "processId": None, "rootUri": (tmp_path / "ws").as_uri(), "capabilities": {}}}))
    server.stdin.flush()
    assert server.stdout.readline().startswith(b"Content-Length:")  # it answered: it runs
    server.stdin.close()
    server.stdout.close()
    try:
        assert server.wait(timeout=60) is not None
    finally:
        if server.poll() is None:
            server.kill()


@pytest.mark.asyncio
async def test_a_child_skill_has_hover_completion_and_a_definition(
        client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "ws" / "pkg" / "fetch.py"
    await _open(client, path, COMPOUND)
    row = next(n for n, text in enumerate(COMPOUND.splitlines()) if '"Pick"' in text)
    line = COMPOUND.splitlines()[row]
    at = lsp.Position(row, line.index('"Pick"') + 2)
    hover = await client.text_document_hover_async(lsp.HoverParams(
        lsp.TextDocumentIdentifier(path.as_uri()), at))
    assert hover is not None
    shown = hover.contents.value  # type: ignore[union-attr]
    assert "**Pick**" in shown and "`Place`" in shown and "`Speed`" in shown
    assert "pre-conditions" in shown and "'skiros:contain'" in shown
    where = await client.text_document_definition_async(lsp.DefinitionParams(
        lsp.TextDocumentIdentifier(path.as_uri()), at))
    assert isinstance(where, lsp.Location) and where.uri.endswith("/pkg/pick.py")
    assert "class Pick" in LEGACY.splitlines()[where.range.start.line]
    typed = line.index('"Pick"') + 3  # in "Pi|ck"
    found = await client.text_document_completion_async(lsp.CompletionParams(
        lsp.TextDocumentIdentifier(path.as_uri()), lsp.Position(row, typed)))
    assert found is not None
    labels = [i.label for i in (found.items if isinstance(found, lsp.CompletionList) else found)]
    assert "Pick" in labels and all(label.startswith("Pi") for label in labels)
    key = line.index('"Speed"') + 2  # in "Sp|eed"
    found = await client.text_document_completion_async(lsp.CompletionParams(
        lsp.TextDocumentIdentifier(path.as_uri()), lsp.Position(row, key)))
    assert found is not None
    keys = [i.label for i in (found.items if isinstance(found, lsp.CompletionList) else found)]
    assert keys == ["Speed"]


@pytest.mark.asyncio
async def test_migrate_this_skill_rewrites_the_class_under_the_cursor_and_passes_check(
        client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "ws" / "pkg" / "pick.py"
    text = LEGACY.replace("skiros:Lcoation", "skiros:Location").replace(
        'ParamTypes.Optional, "how fast"', 'ParamTypes.Optional, [], "how fast"')
    await _open(client, path, text)
    actions = await client.text_document_code_action_async(lsp.CodeActionParams(
        lsp.TextDocumentIdentifier(path.as_uri()),
        lsp.Range(lsp.Position(8, 0), lsp.Position(8, 0)), lsp.CodeActionContext([])))
    assert actions is not None
    [migrate] = [a for a in actions if isinstance(a, lsp.CodeAction)
                 and a.title == "Migrate Pick to EzSkiROS"]
    assert migrate.disabled is None and migrate.edit is not None
    migrated = _applied(text, list(migrate.edit.changes[path.as_uri()]))  # type: ignore[index]
    assert "createDescription" not in migrated and "skiros.Location" in migrated
    after = await _open(client, path, migrated)
    assert not [d for d in after if d.severity == lsp.DiagnosticSeverity.Error]
    assert path.read_text() == LEGACY  # the editor applies it; nothing was written


@pytest.mark.asyncio
async def test_a_save_refreshes_what_crosses_files_in_every_open_document(
        client: LanguageClient, tmp_path: Path) -> None:
    """The repository around a file is read once until a save: renaming the description
    a tree names, on disk, changes nothing until that file is saved; then the tree's
    file, open beside it, is checked again and names the missing type."""
    fetch = tmp_path / "ws" / "pkg" / "fetch.py"
    before = await _open(client, fetch, COMPOUND)
    assert not [d for d in before if d.code == "EZ301"]
    pick = tmp_path / "ws" / "pkg" / "pick.py"
    renamed = LEGACY.replace("class Pick(", "class Grab(")
    pick.write_text(renamed)
    client.text_document_did_change(lsp.DidChangeTextDocumentParams(
        lsp.VersionedTextDocumentIdentifier(uri=fetch.as_uri(), version=2),
        [lsp.TextDocumentContentChangeWholeDocument(text=COMPOUND + "\n")]))
    await client.wait_for_notification(lsp.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
    assert not [d for d in client.diagnostics[fetch.as_uri()] if d.code == "EZ301"]
    await _open(client, pick, renamed)
    client.text_document_did_save(lsp.DidSaveTextDocumentParams(
        lsp.TextDocumentIdentifier(uri=pick.as_uri())))
    while not [d for d in client.diagnostics.get(fetch.as_uri(), []) if d.code == "EZ301"]:
        await client.wait_for_notification(lsp.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
    [missing] = [d for d in client.diagnostics[fetch.as_uri()] if d.code == "EZ301"]
    assert "Pick" in missing.message
