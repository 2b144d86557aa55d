"""``chainbench simulate tensile``: a campaign folder whose logs carry the stated truth."""

from __future__ import annotations

import json
import tomllib

import numpy as np
import pandas as pd
import pytest
from typer.testing import CliRunner

from pipeline.cli import app
from pipeline.condition.tensile import condition_tensile
from pipeline.fit.stiffness import fit_stiffness, specimen_stiffness

runner = CliRunner()


def simulate(tmp_path, *arguments: str) -> dict:
    result = runner.invoke(app, ["simulate", "tensile", "--out", str(tmp_path), *arguments,
                                 "--json"])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def test_writes_logs_run_sheet_and_truth(tmp_path):
    printed = simulate(tmp_path, "--chain", "18x64", "--specimens", "2", "--sample-rate", "2",
                       "--seed", "5")
    assert [row["file"] for row in printed["rows"]] == ["T18-1.csv", "T18-2.csv"]
    sheet = tomllib.loads((tmp_path / "campaign.toml").read_text(encoding="utf-8"))
    assert sheet["chains"]["c18x64"]["catalog"] == "18x64"
    assert [run["file"] for run in sheet["runs"]] == ["T18-1.csv", "T18-2.csv"]
    assert all(run["kind"] == "tensile" and run["gauge_length_mm"] == 900 and run["cycles"] == 3
               for run in sheet["runs"])
    truth = json.loads((tmp_path / "truth.json").read_text(encoding="utf-8"))
    assert set(truth["runs"]) == {"T18-1", "T18-2"}
    first = pd.read_csv(tmp_path / "T18-1.csv")
    assert list(first.columns) == ["time [s]", "force [kN]", "gauge1 [mm]", "gauge2 [mm]"]
    # the same seed writes the same campaign
    again = tmp_path / "again"
    simulate(again, "--chain", "18x64", "--specimens", "2", "--sample-rate", "2", "--seed", "5")
    assert (again / "T18-1.csv").read_bytes() == (tmp_path / "T18-1.csv").read_bytes()


def test_written_log_gives_back_its_E0(tmp_path):
    simulate(tmp_path, "--specimens", "1", "--e0-kn", "20000", "--layout", "european",
             "--language", "de", "--force-unit", "kgf", "--length-unit", "um")
    truth = json.loads((tmp_path / "truth.json").read_text(encoding="utf-8"))["runs"]["T18-1"]
    table = pd.read_csv(tmp_path / "T18-1.csv", sep=";", decimal=",", encoding="latin-1")
    assert list(table.columns) == ["Zeit [s]", "Kraft [kgf]", "Weg 1 [um]", "Weg 2 [um]"]
    canonical = pd.DataFrame({"time": table.iloc[:, 0], "force": table.iloc[:, 1] * 9.80665,
                              "gauge_1": table.iloc[:, 2] * 1e-6,
                              "gauge_2": table.iloc[:, 3] * 1e-6})
    run = condition_tensile(canonical, 0.9, preload=truth["truth"]["preload"], n_cycles=3)
    result = specimen_stiffness(fit_stiffness(run))
    assert result.E0 == pytest.approx(truth["truth"]["E0"], rel=0.005)
    # the set is read to the gauges' division, 0.01 mm
    np.testing.assert_allclose(run.cycles["permanent_set"], truth["permanent_set_m"], atol=1e-5)


@pytest.mark.parametrize(("layout", "name"), [("machine", "T13-1.csv"), ("xlsx", "T13-1.xlsx")])
def test_other_layouts(tmp_path, layout, name):
    simulate(tmp_path, "--chain", "13x50", "--specimens", "1", "--layout", layout,
             "--sample-rate", "1")
    assert (tmp_path / name).exists()


@pytest.mark.parametrize(
    ("arguments", "words"),
    [(["--force-unit", "kp"], "--force-unit"), (["--chain", "99x9"], "unknown chain"),
     (["--chain", "34x126"], "give E0"), (["--campaign", "a/b"], "--campaign")],
)
def test_bad_options_exit_non_zero(tmp_path, arguments, words):
    result = runner.invoke(app, ["simulate", "tensile", "--out", str(tmp_path), *arguments])
    assert result.exit_code != 0
    assert words in result.output
