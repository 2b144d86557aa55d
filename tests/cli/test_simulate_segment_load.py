"""``chainbench simulate segment-load``: drum logs of known geometry, read back by a campaign."""

from __future__ import annotations

import io
import json
import math
import re
import tomllib

import pytest
from rich.console import Console
from typer.testing import CliRunner

from pipeline.campaign import process_campaign
from pipeline.cli import app
from pipeline.cli.run import _print_result
from pipeline.store.netcdf import read_dataset

runner = CliRunner()


def test_simulated_campaign_processes_to_its_truth(tmp_path):
    out = tmp_path / "raw" / "sim"
    result = runner.invoke(app, [
        "simulate", "segment-load", "--out", str(out), "--levels-kn", "60", "90", "120",
        "--layout", "european", "tdms", "machine", "--s-mm", "58", "--declared-mm", "52",
        "--seed", "5", "--json"])
    assert result.exit_code == 0, result.output
    printed = json.loads(result.stdout)
    assert [row["file"] for row in printed["rows"]] == [
        "S34x126-1.csv", "S34x126-2.tdms", "S34x126-3.csv"]
    sheet = tomllib.loads((out / "campaign.toml").read_text(encoding="utf-8"))
    assert sheet["drums"]["drum"]["contact_distance_mm"] == 52
    assert sheet["drums"]["drum"]["fitted"] == "s"
    truth = json.loads((out / "truth.json").read_text(encoding="utf-8"))["runs"]
    processed = process_campaign(out, tmp_path / "processed")
    assert not processed.failures
    summary = read_dataset(processed.output / "summary.nc")
    for run in summary["segment_point"].values.astype(str):
        row, true = summary.sel(segment_point=run), truth[run]
        assert float(row["segment_chain_force"]) == pytest.approx(
            true["truth"]["chain_force"][0], rel=0.01)
        assert float(row["segment_contact_ratio"]) == pytest.approx(
            true["contact_force_ratio"], rel=0.01)
        assert float(row["segment_side_ratio"]) == pytest.approx(
            true["side_force_ratio"], rel=0.01)
        assert float(row["segment_fit_s"]) == pytest.approx(58e-3, rel=0.02)
        assert math.isnan(float(row["segment_fit_beta"]))
    # the console's drum table: fitted s with its interval around the truth, the sheet's 52 mm
    out = Console(file=io.StringIO(), width=200, color_system=None)
    _print_result(processed, out=out)
    printed = out.file.getvalue()
    found = re.search(r"│ +drum │ +3 │ +s ([\d.]+) \(([\d.]+)\.\.([\d.]+)\) mm │ +52 mm │ "
                      r"([\d.]+)\.\.([\d.]+) │.*│ +0/3 │", printed)
    assert found, printed
    value, low, high, smallest, largest = map(float, found.groups())
    assert value == pytest.approx(58, rel=0.02) and low <= 58 <= high
    true_ratio = next(iter(truth.values()))["contact_force_ratio"]
    assert smallest == pytest.approx(true_ratio, rel=0.01)
    assert largest == pytest.approx(true_ratio, rel=0.01)


def test_beta_is_fitted_when_asked(tmp_path):
    result = runner.invoke(app, ["simulate", "segment-load", "--out", str(tmp_path),
                                 "--fit", "beta", "--declared-deg", "40", "--levels-kn", "80"])
    assert result.exit_code == 0, result.output
    drum = tomllib.loads((tmp_path / "campaign.toml").read_text(encoding="utf-8"))["drums"]
    # beta is stated at 40 deg (fitted), s at its true 60 mm
    assert drum["drum"] == {"groove_width_mm": 45, "contact_distance_mm": 60,
                            "flank_inclination_deg": 40, "link_inclination_deg": 0,
                            "fitted": "beta"}


@pytest.mark.parametrize("arguments, message", [
    (["--fit", "s", "--declared-deg", "40"], "--declared-deg"),
    (["--chain", "18x64"], "torus radius"),
    (["--chain", "99x999"], "99x999"),
    (["--s-mm", "120"], "below 2 k"),               # s >= 2 k: no contact geometry
    (["--declared-mm", "30"], "run sheet's s"),      # the run sheet's s < c
    (["--levels-kn", "50", "--layout", "plain", "tdms"], "--levels-kn"),
])
def test_bad_options_are_refused_clearly(tmp_path, arguments, message):
    out = tmp_path / "x"
    result = runner.invoke(app, ["simulate", "segment-load", "--out", str(out), *arguments])
    assert result.exit_code != 0
    assert message in result.output
    assert not (out / "campaign.toml").exists()
