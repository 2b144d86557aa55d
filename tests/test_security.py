"""Nothing from an input is executed or trusted; nothing leaves its folder."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from pipeline.runsheet import load_run_sheet

PACKAGE = Path(__file__).parents[1] / "pipeline"

#: Calls that would execute or unpickle data; none may appear in the package. (Tasks that
#: the package's own processes send one another on a dask cluster are pickled by dask's
#: serializer, :mod:`pipeline.tasks` too: bytes made by the package, never read from a file.)
FORBIDDEN_CALLS = {"eval", "exec", "compile", "__import__"}
FORBIDDEN_MODULES = {"pickle", "marshal", "shelve", "dill", "cloudpickle", "yaml"}


def test_package_never_executes_or_unpickles():
    found = []
    for path in sorted(PACKAGE.rglob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, ast.Call) and getattr(node.func, "id", None) in FORBIDDEN_CALLS:
                found.append(f"{path.name}:{node.lineno} {node.func.id}()")
            if isinstance(node, ast.Import | ast.ImportFrom):
                names = [alias.name for alias in node.names] + [getattr(node, "module", "")]
                if any((name or "").split(".")[0] in FORBIDDEN_MODULES for name in names):
                    found.append(f"{path.name}:{node.lineno} imports {names}")
    assert found == []


HEAD = """
[campaign]
id = "c"
[chains.c18]
catalog = "18x64"
[wheels.w8]
teeth = 8
apex_angle_deg = 40
"""


def engagement(**fields: str) -> str:
    entry = {"id": '"E1"', "kind": '"engagement"', "file": '"e.csv"', "chain": '"c18"',
             "wheel": '"w8"', "branch_length_m": "2", "omega_per_s": "20", **fields}
    return "\n[[runs]]\n" + "\n".join(f"{key} = {value}" for key, value in entry.items()) + "\n"


@pytest.mark.parametrize("reference", ['"../../etc/c18"', '"../c18"', '"a/b/c"', '"/abs/c18"',
                                       '"campaign"'])
def test_stiffness_reference_cannot_leave_the_processed_folder(tmp_path, reference):
    (tmp_path / "campaign.toml").write_text(HEAD + engagement(stiffness_from=reference))
    sheet = load_run_sheet(tmp_path)
    (error,) = sheet.invalid_runs
    assert error.column == "runs[0].stiffness_from"


def test_stiffness_reference_of_safe_names_is_accepted(tmp_path):
    (tmp_path / "campaign.toml").write_text(HEAD + engagement(stiffness_from='"demo-1/c18x64"'))
    assert load_run_sheet(tmp_path).runs[0].stiffness_from == "demo-1/c18x64"


@pytest.mark.parametrize("run_id", ['".."', '"."', '"a/b"', '"..\\\\x"', '"x y"'])
def test_run_ids_cannot_name_a_path(tmp_path, run_id):
    (tmp_path / "campaign.toml").write_text(HEAD + engagement(id=run_id, E0_N="2.26e7"))
    (error,) = load_run_sheet(tmp_path).invalid_runs
    assert error.column == "runs[0].id"
