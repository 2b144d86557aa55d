"""``chainbench run`` and ``validate`` on the single-pull demo: the tables a lab reads."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from typer.testing import CliRunner

from pipeline.cli import app

runner = CliRunner()
DEMO = Path(__file__).parents[2] / "raw" / "pull-demo"


@pytest.fixture
def demo(tmp_path) -> Path:
    if not DEMO.is_dir():
        pytest.skip("raw/pull-demo is absent")
    folder = tmp_path / "raw" / "pull-demo"
    shutil.copytree(DEMO, folder)
    return folder


def test_run_prints_specimens_acceptance_and_channel_warnings(demo, tmp_path):
    result = runner.invoke(app, ["run", str(demo), "--output", str(tmp_path / "out")],
                           env={"COLUMNS": "160"})
    assert result.exit_code == 0, result.output
    lines = result.output.splitlines()
    # specimen D breaks at 404 kN (truth.json), below the declared 410 kN
    row = next(line for line in lines if line.startswith("│ P18-D ") and "FAIL" in line)
    assert row.split("│")[1:-1][1].strip() == "pass"  # carries the proof force
    assert "chain c18x64 acceptance: proof force: pass; breaking force: FAIL" in result.output
    assert "E0 from 'Ekstensometr' (extensometer), 'Trawersa' (crosshead) not used" in (
        result.output.replace("\n", " "))
    assert "F_max [kN]" in result.output and "A at proof [%]" in result.output


def test_validate_says_what_run_would_decide(demo):
    result = runner.invoke(app, ["validate", str(demo)], env={"COLUMNS": "200"})
    assert result.exit_code == 0, result.output
    assert "pull-demo: 5 runs, 0 problems" in result.output
    assert "channel 'Dehnung 1' freezes at" in result.output


def test_validate_refuses_what_run_would_refuse(demo):
    sheet = demo / "campaign.toml"
    sheet.write_text(sheet.read_text(encoding="utf-8").replace(
        'gauge_length_mm = 320\n', '', 1), encoding="utf-8")  # run B reads lengths only
    result = runner.invoke(app, ["validate", str(demo)], env={"COLUMNS": "200"})
    assert result.exit_code == 1
    assert "error P18-B: " in result.output and "gauge_length_mm" in result.output


def test_an_E0_from_the_crosshead_is_marked_in_the_table_and_the_report(tmp_path):
    from pipeline.simulate.pull import PullTruth, simulate_pull

    truth = PullTruth.for_chain("18x64", to_fracture=False, proof_force=300e3)
    log = simulate_pull(truth, seed=3)
    folder = tmp_path / "raw" / "stroke"
    folder.mkdir(parents=True)
    (log[["crosshead", "force"]] * [1e3, 1e-3]).to_csv(
        folder / "p.csv", index=False, header=["Stroke (mm)", "Force (kN)"])
    (folder / "campaign.toml").write_text(
        '[campaign]\nid = "stroke"\n[chains.c]\ncatalog = "18x64"\n'
        '[[runs]]\nid = "S1"\nkind = "tensile"\nfile = "p.csv"\nchain = "c"\ncycles = 1\n'
        'gauge_length_mm = 320\n', encoding="utf-8")
    result = runner.invoke(app, ["run", str(folder), "--output", str(tmp_path / "out")],
                           env={"COLUMNS": "160"})
    assert result.exit_code == 0, result.output
    assert any(line.startswith("│ S1*^ ") for line in result.output.splitlines())
    assert "^ E0 from the crosshead travel, which includes the machine's compliance" in (
        " ".join(result.output.split()))
    report = (tmp_path / "out" / "stroke" / "report.html").read_text(encoding="utf-8")
    assert "(from the crosshead: too low)" in report and "E0 from the crosshead<" in report
