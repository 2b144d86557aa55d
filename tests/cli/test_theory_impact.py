"""``chainbench theory impact`` against Paper 000's example (docs/published-values.md).

Expectations are typed here from the paper and docs/published-values.md, or from the
closed forms of docs/models/paper-000-wheel-impact.md, never copied from the code's
output.
"""

from __future__ import annotations

import json
import math

import pytest
from typer.testing import CliRunner

from pipeline.cli import _options, app
from pipeline.theory import wheel_impact as wi

runner = CliRunner()

COMMAND = (
    "theory impact --chain 18x64 --teeth 6 8 10 --apex 20 30 40 50 60 --omega 20 --branch-length 2"
).split()
TEETH = [6, 8, 10]
APEX_DEG = [20, 30, 40, 50, 60]
T, D, OMEGA = 0.064, 0.018, 20.0  # [m], [m], [1/s]
# docs/published-values.md, Paper 000: the model's grid (N, q = 6.6 kg/m).
GRID_N_U1 = [494, 736, 972, 1201, 1421]
GRID_N_U2 = {
    6: [3257, 3583, 3882, 4151, 4388],
    8: [2723, 3085, 3423, 3736, 4020],
    10: [2379, 2760, 3120, 3456, 3766],
}


def run_json(arguments: list[str]) -> dict:
    result = runner.invoke(app, [*arguments, "--json"])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def test_paper_case_grid():
    document = run_json(COMMAND)
    rows = document["rows"]
    assert [(row["z"], row["psi_deg"]) for row in rows] == [
        (z, psi) for z in TEETH for psi in APEX_DEG
    ]
    for row in rows:
        z, column = row["z"], APEX_DEG.index(row["psi_deg"])
        psi = math.radians(row["psi_deg"])
        # reference grid printed to whole newtons: +-0.5 N
        assert row["N_u1"] == pytest.approx(GRID_N_U1[column], abs=0.5)
        assert row["N_u2"] == pytest.approx(GRID_N_U2[z][column], abs=0.5)
        assert row["N_u2/N_u1"] == pytest.approx(row["N_u2"] / row["N_u1"], rel=1e-12)
        # closed forms of Paper 000 and tau = pi / (z omega), exact up to round-off
        assert row["v_u1"] == pytest.approx(OMEGA * (T - D) * math.sin(psi / 2), rel=1e-12)
        v_u2 = OMEGA * (T + D) * math.sin(math.pi / z + psi / 2)
        assert row["v_u2"] == pytest.approx(v_u2, rel=1e-12)
        assert row["tau"] == pytest.approx(math.pi / (z * OMEGA), rel=1e-12)


def test_paper_case_inputs_and_published_numbers():
    document = run_json(COMMAND)
    inputs = document["inputs"]
    # Paper 000: E0 = 2.26e7 N by default; q/g = 6.6 kg/m from the catalogue (DIN 22252).
    assert inputs["E0"] == 2.26e7
    assert inputs["mass_per_length"] == pytest.approx(6.6, rel=1e-12)
    assert inputs["k"] == 2
    ratio_row = next(row for row in document["rows"] if (row["z"], row["psi_deg"]) == (8, 40))
    assert ratio_row["N_u2/N_u1"] == pytest.approx(3.521, abs=0.005)
    notes = document["notes"]
    for row in wi.compare_published().itertuples():
        (line,) = [note for note in notes if note.strip().startswith(f"{row.quantity} = ")]
        assert f"= {row.published:g}" in line
        assert ("NOT REPRODUCED" in line) is not row.reproduced
    assert "N_u2_over_N_u1_z8_psi40 = 2.54, model 3.521: NOT REPRODUCED" in " ".join(notes)


@pytest.mark.parametrize(
    "spelling",
    [
        ["--teeth", "6,8,10", "--apex", "20,30,40,50,60"],
        ["--teeth=6,8", "10", "--apex", "20 30 40", "50,60"],
        ["--teeth", "6", "--teeth", "8", "--teeth", "10", "--apex", "20", "30", "40", "50", "60"],
    ],
)
def test_other_spellings_of_the_lists(spelling):
    common = ["theory", "impact", "--chain", "18x64", "--omega", "20", "--branch-length", "2"]
    assert run_json([*common, *spelling])["rows"] == run_json(COMMAND)["rows"]


def test_table_output():
    result = runner.invoke(app, COMMAND)
    assert result.exit_code == 0, result.output
    assert "N_u2/N_u1" in result.stdout
    assert "NOT REPRODUCED" in result.stdout


def test_options_override_catalogue_and_paper():
    # N_u ~ sqrt(q E0 k / L) (eq. (16)): q x 4, E0 x 9 give N_u x 6.
    base = run_json(COMMAND)["rows"][0]
    scaled = run_json([*COMMAND, "--mass-per-m", "26.4", "--E0", "2.034e8"])["rows"][0]
    assert scaled["N_u1"] == pytest.approx(6 * base["N_u1"], rel=1e-12)
    assert scaled["N_u2"] == pytest.approx(6 * base["N_u2"], rel=1e-12)


@pytest.mark.parametrize(
    ("replace", "option"),
    [
        (("18x64", "99x99"), "--chain"),
        (("18x64", "16B"), "--chain"),  # a roller chain
        (("18x64", "22x86"), "--E0"),  # no published E0 for it
        (("60", "200"), "--apex"),
        (("--teeth 6", "--teeth 2"), "--teeth"),
        (("--omega 20", "--omega -3"), "--omega"),
    ],
)
def test_bad_input_names_the_option(replace, option):
    arguments = " ".join(COMMAND).replace(*replace).split()
    result = runner.invoke(app, arguments)
    assert result.exit_code == 2
    assert option in result.output


@pytest.mark.parametrize(
    ("args", "expected"),
    [
        (["--apex", "-5", "10", "--k", "2"], ["--apex", "-5", "--apex", "10", "--k", "2"]),
        (["--teeth", "--json"], ["--teeth", "--json"]),  # no value: left for click to report
        (["--teeth=6", "--", "8"], ["--teeth", "6", "--", "8"]),
        (["--chain", "6", "8"], ["--chain", "6", "8"]),  # not a list option
    ],
)
def test_spread_values(args, expected):
    assert _options.spread_values(args, {"--teeth", "--apex"}) == expected
