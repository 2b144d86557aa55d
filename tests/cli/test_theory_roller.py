"""``chainbench theory roller-impact`` against Paper 002 and hand-worked values."""

from __future__ import annotations

import json
import math

import pytest
from typer.testing import CliRunner

from pipeline.cli import app
from pipeline.theory import roller_impact as ri

runner = CliRunner()

# The hand-worked example of docs/published-values.md (Paper 002) with 20B-like rollers [mm].
EXAMPLE = ["--pitch-mm", "31.75", "--mass-per-m", "3.8", "--xi", "0.8", "--rpm", "500",
           "--roller-diameter-mm", "19.05", "--inner-width-mm", "19.56"]  # fmt: skip


def run_json(*arguments: str) -> dict:
    result = runner.invoke(app, ["theory", "roller-impact", *arguments, "--json"])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def test_example_energy_velocity_and_n_max():
    (row,) = run_json(*EXAMPLE, "--teeth", "10")["rows"]
    omega = 2 * math.pi * 500 / 60
    v = omega * 0.03175 * 0.8
    # Hand-worked: V_y = omega t xi; E = (1/2)(q t) V_y^2 = 0.1067 J (spec: 0.1066 J with
    # the paper's rounded constant; 0.1 %).
    assert row["v_y_m_per_s"] == pytest.approx(v, rel=1e-9)
    assert row["energy_J"] == pytest.approx(0.5 * 3.8 * 0.03175 * v**2, rel=1e-9)
    assert row["energy_J"] == pytest.approx(0.1066, rel=1e-3)
    # G = E / (D L) in J/mm^2.
    assert row["G_J_per_mm2"] == pytest.approx(row["energy_J"] / (19.05 * 19.56), rel=1e-9)
    # eq. (8): 7400 / (xi t) sqrt(D B / (q t)); 7400 is the rounded 7397: 0.1 %.
    paper = 7400 / (0.8 * 31.75) * math.sqrt(19.05 * 19.56 / (3.8 * 31.75))
    assert row["n_max_rpm"] == pytest.approx(paper, rel=1e-3)
    assert row["below_n_max"] is (500 <= paper)
    assert row["xi"] == 0.8


def test_xi_bounds_and_involute_xi_for_a_catalogue_chain():
    document = run_json("--chain", "16B", "--teeth", "10", "15", "20", "--rpm", "500")
    rows = document["rows"]
    assert [row["z"] for row in rows] == [10, 15, 20]
    for row in rows:
        z = row["z"]
        assert row["xi_min"] == pytest.approx(math.sin(math.pi / z), rel=1e-12)
        assert row["xi_max"] == pytest.approx(math.cos(math.pi / z), rel=1e-12)
        assert row["xi_min"] <= row["xi"] <= row["xi_max"]
    # Default module t / pi, alpha = 20 deg: xi = sin(pi/z + acos(z sin(pi/z) cos(20)/pi)).
    z = 10
    expected = math.sin(
        math.pi / z + math.acos(z * math.sin(math.pi / z) * math.cos(math.radians(20)) / math.pi)
    )
    assert rows[0]["xi"] == pytest.approx(expected, rel=1e-12)
    assert rows[0]["xi"] > rows[1]["xi"] > rows[2]["xi"]
    assert document["inputs"]["pitch_mm"] == pytest.approx(25.4, abs=1e-9)  # ISO 606 16B


def test_g_lim_4e_4_raises_n_max_by_sqrt_4_over_3():
    low = run_json(*EXAMPLE, "--teeth", "10")["rows"][0]["n_max_rpm"]
    high = run_json(*EXAMPLE, "--teeth", "10", "--g-lim-j-per-mm2", "4e-4")["rows"][0]["n_max_rpm"]
    assert high / low == pytest.approx(math.sqrt(4 / 3), rel=1e-12)


def test_published_constants_in_json_and_notes():
    document = run_json(*EXAMPLE)
    assert document["published"] == ri.compare_published().to_dict("records")
    notes = [note for note in document["notes"] if note.startswith("Paper 002, eq. (")]
    assert len(notes) == len(document["published"])
    (misprint,) = [note for note in notes if "not reproduced" in note]
    assert misprint.startswith("Paper 002, eq. (7)") and "1.8e+12" in misprint


def test_missing_chain_data_names_the_option():
    result = runner.invoke(app, ["theory", "roller-impact", "--teeth", "10"])
    assert result.exit_code != 0
    assert "--pitch-mm" in result.output


def test_round_link_chain_is_refused():
    result = runner.invoke(app, ["theory", "roller-impact", "--chain", "18x64"])
    assert result.exit_code != 0
    assert "not a roller chain" in result.output
