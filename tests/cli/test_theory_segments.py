"""``chainbench theory tooth-segments`` against Paper 003 (chain 34x126).

The published values are read from the packaged ``paper_003.csv``
(``compare_published()``); the model's values are typed here.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from typer.testing import CliRunner

from pipeline.cli import app
from pipeline.theory import tooth_segments as ts
from pipeline.theory._published import parse_inputs
from pipeline.units import from_si

runner = CliRunner()

#: The column of the command's rows that gives each quantity of paper_003.csv.
COLUMN = {"contact_radius": "k_mm", "opening_angle": "psi_deg", "contact_force_ratio": "F_K/F"}


def run_json(*arguments: str) -> dict:
    result = runner.invoke(app, ["theory", "tooth-segments", *arguments, "--json"])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def row_at(rows: list[dict], inputs: dict) -> dict:
    """The command's row at the SI `inputs` of a published value (s = 45 mm if it has none)."""
    point = (from_si(inputs["beta"], "deg"), from_si(inputs["eps_n"], "deg"),
             from_si(inputs.get("s", 0.045), "mm"))  # fmt: skip
    (row,) = [row for row in rows
              if np.allclose((row["beta_deg"], row["eps_n_deg"], row["s_mm"]), point)]
    return row


def test_default_grid_reproduces_the_papers_cases():
    document = run_json()
    rows = {(r["beta_deg"], r["eps_n_deg"], r["s_mm"]): r for r in document["rows"]}
    assert len(rows) == 8  # beta 50 80 x eps_n 0 6 x s 45 70
    for published in ts.compare_published().itertuples():
        row = row_at(document["rows"], parse_inputs(published.inputs))
        (column,) = [column for quantity, column in COLUMN.items()
                     if published.quantity.startswith(f"{quantity}_")]
        # Every published value of the paper's cases, as the command gives it.
        assert row[column] == pytest.approx(published.model, rel=1e-12)
        # Within the published value's tolerance where the paper is reproduced; the
        # 0.3 % and the model's 128.45 pinned where not (docs/published-values.md, Paper 003).
        tolerance = published.tolerance if published.reproduced else 3e-3
        assert row[column] == pytest.approx(published.published, rel=tolerance)
    assert rows[(80, 0, 45)]["psi_deg"] == pytest.approx(128.45, abs=5e-3)
    # Friction increase at s 70, beta 50: 46.0 % (eps_n 0) and 50.6 % (eps_n 6).
    assert rows[(50, 0, 70)]["friction_increase_pct"] == pytest.approx(46.0, abs=0.05)
    assert rows[(50, 6, 70)]["friction_increase_pct"] == pytest.approx(50.6, abs=0.05)
    # F_P / F: above 0.5 at s 70 (above 67.9 mm), below at 45 (beta 50, eps_n 0).
    assert rows[(50, 0, 70)]["F_P/F"] > 0.5 > rows[(50, 0, 45)]["F_P/F"]


def test_the_not_reproduced_value_is_flagged():
    document = run_json()
    flagged = [n for n in document["notes"] if "NOT reproduced" in n]
    assert len(flagged) == 1
    assert "128.7" in flagged[0] and "128.45" in flagged[0]
    assert "11 of 12" in document["notes"][0]


def test_s_below_the_groove_width_is_refused():
    result = runner.invoke(app, ["theory", "tooth-segments", "--s", "40"])
    assert result.exit_code != 0
    assert "groove width" in result.output


def test_other_chain_dimensions_give_no_paper_notes():
    document = run_json("--r-outer-mm", "60", "--s", "50", "--beta", "60", "--eps-n", "0")
    assert document["notes"] == []
    (row,) = document["rows"]
    # k = 60 - 17 (1 - cos 30 deg) = 57.722 mm (hand-worked).
    assert row["k_mm"] == pytest.approx(57.722, abs=5e-4)
