"""``chainbench simulate wear``: wear logs in every layout, with their truth beside them."""

from __future__ import annotations

import json
import tomllib

import pytest
from typer.testing import CliRunner

from pipeline.cli import app
from pipeline.ingest import read_table
from pipeline.simulate.wear import WearTruth

runner = CliRunner()
HOUR = 3600.0


def simulate(folder, *arguments: str) -> dict:
    result = runner.invoke(app, ["simulate", "wear", "--out", str(folder), *arguments, "--json"])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def test_writes_a_run_per_layout_with_run_sheet_and_truth(tmp_path):
    printed = simulate(tmp_path, "--layout", "plain", "european", "machine", "xlsx", "tdms",
                       "--teeth", "30", "--limit-pct", "1.5", "--reference", "first",
                       "--abscissa", "both", "--load-kn", "8", "--seed", "3")
    files = [row["file"] for row in printed["rows"]]
    assert files == ["W16B-plain-1.csv", "W16B-european-1.csv", "W16B-machine-1.csv",
                     "W16B-xlsx-1.xlsx", "W16B-tdms-1.tdms"]
    sheet = tomllib.loads((tmp_path / "campaign.toml").read_text(encoding="utf-8"))
    assert sheet["campaign"]["synthetic"] is True
    assert all(run["kind"] == "wear" and run["sprocket_teeth"] == 30
               and run["elongation_reference"] == "first" and run["wear_limit_pct"] == 1.5
               and run["wear_abscissa"] == "time" and "max_link_force_kN" not in run
               for run in sheet["runs"])
    truth = json.loads((tmp_path / "truth.json").read_text(encoding="utf-8"))["runs"]
    for file in files:
        table, _ = read_table(tmp_path / file, kind="wear")
        assert {"time", "cycle_count", "length", "force"} <= set(table.columns), file
        assert table["time"].iloc[-1] == pytest.approx(300 * HOUR)
        assert table["force"].iloc[0] == pytest.approx(8e3)
        run = next(value for value in truth.values() if value["file"] == file)
        # the section's true length at the start: N (t + delta_t0), within the noise
        start = run["truth"]["pitches"] * (run["truth"]["pitch"] + run["truth"]["initial_error"])
        assert table["length"].iloc[0] == pytest.approx(start, abs=5 * run["truth"]["noise"])


def test_truth_lives_solve_the_true_curve(tmp_path):
    simulate(tmp_path, "--teeth", "40", "--limit-pct", "3", "--wear-rate-um-per-h", "1.2")
    run = next(iter(json.loads((tmp_path / "truth.json").read_text())["runs"].values()))
    truth = WearTruth(**run["truth"])
    # Paper 004, eq. (3) against the nominal pitch: 2.5 psi t / z = 2 t / z (psi = 0.8)
    assert run["limit_eq3_m"] == pytest.approx(2 * 0.0254 / 40)
    assert truth.elongation(run["life_eq3_s"]) == pytest.approx(run["limit_eq3_m"])
    assert truth.elongation(run["life_lab_s"]) == pytest.approx(0.03 * 0.0254)
    assert run["life_lab_cycles"] == pytest.approx(0.5 * run["life_lab_s"])


def test_pin_options_are_written_together(tmp_path):
    simulate(tmp_path, "--f-max-kn", "12", "--sigma-t-mpa", "800", "--wear-coefficient", "1")
    run = tomllib.loads((tmp_path / "campaign.toml").read_text())["runs"][0]
    assert (run["max_link_force_kN"], run["pin_allowable_stress_MPa"],
            run["pin_wear_coefficient"]) == (12, 800, 1)
    result = runner.invoke(app, ["simulate", "wear", "--out", str(tmp_path / "x"),
                                 "--f-max-kn", "12"])
    assert result.exit_code != 0 and "--sigma-t-mpa" in result.output


@pytest.mark.parametrize("arguments, words", [
    (("--chain", "99Z"), "unknown chain"),
    (("--time-unit", "fortnight"), "choose one of"),
    (("--interval-h", "500"), "longer than the test"),
])
def test_bad_options_are_refused(tmp_path, arguments, words):
    result = runner.invoke(app, ["simulate", "wear", "--out", str(tmp_path), *arguments])
    assert result.exit_code != 0 and words in result.output
