"""``chainbench simulate roller-engagement``: logs with known xi that the campaign reads back."""

from __future__ import annotations

import json

import pytest
from typer.testing import CliRunner

from pipeline.cli import app
from pipeline.campaign import process_campaign


def test_simulated_campaign_processes_to_its_truth(tmp_path):
    out = tmp_path / "raw" / "sim"
    result = CliRunner().invoke(app, ["simulate", "roller-engagement", "--out", str(out),
                                      "--xi", "0.5", "--module-mm", "0", "--rpm", "100", "250",
                                      "--format", "tdms", "--seed", "3"])
    assert result.exit_code == 0, result.output
    truth = json.loads((out / "truth.json").read_text())["runs"]
    assert sorted(truth) == ["R18-100", "R18-250"] and truth["R18-100"]["xi"] == 0.5
    summary = process_campaign(out, tmp_path / "processed").summary
    assert float(summary["xi_fit"][0]) == pytest.approx(0.5, rel=0.03)


def test_odd_teeth_without_xi_or_geometry_is_refused(tmp_path):
    result = CliRunner().invoke(app, ["simulate", "roller-engagement", "--out",
                                      str(tmp_path / "x"), "--module-mm", "0"])
    assert result.exit_code != 0 and "--xi" in result.output
