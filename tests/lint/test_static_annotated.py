"""``check``'s static reading of EzSkiROS files reads ``Annotated[...]`` (issue 43) as
loading the module does: the codemod writes it, so the reader must take it."""

from __future__ import annotations

import ast
import json
from pathlib import Path

import pytest

from ezmigrate.lint.ezskiros_static import read_ezskiros_statically
from ezskiros_runtime.dsl.policy import collecting
from ezskiros_runtime.legacy.loader import load_bytes

MODULE = '''\
from ezskiros_runtime import SkillDescription, Annotated, INFERRED, OPTIONAL, REQUIRED, ELEMENT
from ezskiros_runtime import KEY, DESC, Lock
from ezskiros_runtime.ontology import skiros

HELP = "where to put it"


class Place(SkillDescription):
    def description(self,
                    Target: Annotated[REQUIRED, ELEMENT("scalable:Workstation")],
                    Object: Annotated[skiros.Product, DESC("The position of the prompt object")],
                    Cam: Annotated[INFERRED, ELEMENT(":Cam"), Lock, DESC("camera")],
                    Where: Annotated[REQUIRED[skiros.Location, Lock], DESC(HELP)],
                    On_Off: Annotated[OPTIONAL[bool], KEY("On/Off")] = True,
                    Mode: Annotated[str, DESC("compliant|joint_config")] = ""):
        self.pre_conditions += Where.contain(Object)
'''

BROKEN = '''
class Broken(SkillDescription):
    def description(self, X: Annotated[OPTIONAL, DESC("a"), DESC("b")] = 1):
        pass
'''


pytestmark = pytest.mark.usefixtures("core_ontology")


def test_the_annotated_form_reads_as_it_loads(tmp_path: Path) -> None:
    path = tmp_path / "place.py"
    path.write_text(MODULE, encoding="utf-8")
    read = read_ezskiros_statically(ast.parse(path.read_bytes()), str(path))
    with collecting():
        loaded = load_bytes(path.read_bytes(), path)
    assert read.status == "ok", read.message
    assert read.unread == [] and read.maybe == []
    models = [json.dumps({**m.to_json(), "source": ""}, sort_keys=True) for m in loaded.models]
    assert [json.dumps({**m, "source": ""}, sort_keys=True) for m in read.models] == models
    assert [m["name"] for m in read.models] == ["Place"]
    params = {p["key"]: p for p in read.models[0]["params"]}
    assert params["Object"]["description"] == "The position of the prompt object"
    assert "On/Off" in params
    assert read.errors == [] and loaded.errors == []
    assert sorted((f.skill, f.kind, f.line, f.message) for f in read.findings) == \
        sorted((f.skill, f.kind, f.line, f.message) for f in loaded.findings)


@pytest.mark.parametrize("future", [False, True], ids=["at-import", "at-instantiation"])
def test_a_misused_annotated_fails_where_loading_fails(tmp_path: Path, future: bool) -> None:
    """Evaluated when ``def`` runs, the error fails the import; as a string annotation, it
    fails the class when it is instantiated: the reading says the same in both cases."""
    path = tmp_path / "broken.py"
    path.write_text(("from __future__ import annotations\n" if future else "") + MODULE + BROKEN,
                    encoding="utf-8")
    read = read_ezskiros_statically(ast.parse(path.read_bytes()), str(path))
    if not future:
        assert read.status == "import-error"
        assert "two descriptions" in (read.message or "")
        return
    with collecting():
        loaded = load_bytes(path.read_bytes(), path)
    assert read.status == "ok", read.message
    assert [(e.skill, e.message) for e in read.errors] == \
        [(e.skill, e.message) for e in loaded.errors]
    assert [e.skill for e in read.errors] == ["Broken"]
    assert "two descriptions" in read.errors[0].message
