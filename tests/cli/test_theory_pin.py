"""``chainbench theory pin`` against the hand-worked 16B example.

See docs/models/paper-004-pin-criterion.md.
"""

from __future__ import annotations

import json

import pytest
from typer.testing import CliRunner

from pipeline.cli import app

runner = CliRunner()
EXAMPLE = ["--chain", "16B", "--f-max-kn", "12", "--sigma-t-mpa", "800", "--teeth", "40"]


def run_json(*arguments: str) -> dict:
    result = runner.invoke(app, ["theory", "pin", *arguments, "--json"])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def test_16b_example():
    rows = {row["support"]: row for row in run_json(*EXAMPLE)["rows"]}
    # Hand values rounded to 0.01 mm (0.001 mm for delta_t1, delta_d): half a unit.
    for row in rows.values():
        assert row["z"] == 40
        assert row["delta_t1_mm"] == pytest.approx(1.168, abs=5e-4)
        assert row["delta_d_mm"] == pytest.approx(0.584, abs=5e-4)
        assert row["pin_mm"] == pytest.approx(8.28, abs=1e-9)  # ISO 606 16B
    assert rows["pinned"]["K"] == 1 and rows["clamped"]["K"] == 3
    assert rows["pinned"]["d_k_mm"] == pytest.approx(8.67, abs=5e-3)
    assert rows["clamped"]["d_k_mm"] == pytest.approx(6.01, abs=5e-3)
    # Required = d_k + delta_d; the example's 9.25 and 6.60 add rounded terms: 0.01 mm.
    assert rows["pinned"]["required_mm"] == pytest.approx(9.25, abs=1e-2)
    assert rows["clamped"]["required_mm"] == pytest.approx(6.60, abs=1e-2)
    assert rows["pinned"]["passes"] is False
    assert rows["clamped"]["passes"] is True


def test_several_teeth_and_wear_coefficient():
    rows = run_json(*EXAMPLE, "20", "--wear-coefficient", "0.5")["rows"]
    assert [(row["z"], row["support"]) for row in rows] == [
        (40, "pinned"), (40, "clamped"), (20, "pinned"), (20, "clamped"),
    ]  # fmt: skip
    # z = 20: delta_t1 = 25.4 (2/20 - 0.004) = 2.4384 mm; K_e = 0.5: delta_d = 0.6096 mm.
    assert rows[2]["delta_t1_mm"] == pytest.approx(2.4384, rel=1e-9)
    assert rows[2]["delta_d_mm"] == pytest.approx(0.6096, rel=1e-9)


def test_chain_without_pin_geometry_names_the_option():
    result = runner.invoke(
        app, ["theory", "pin", "--chain", "20B", "--f-max-kn", "12", "--sigma-t-mpa", "800",
              "--teeth", "40"],
    )  # fmt: skip
    assert result.exit_code != 0
    assert "--bush-length-mm" in result.output
