"""The demo campaigns of ``raw/``: reproducible to the byte, and they give back their truth."""

from __future__ import annotations

import json
import tomllib
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from pipeline.cli import app
from pipeline.simulate.demo import DEMOS
from pipeline.store.netcdf import read_dataset
from pipeline.theory.link_stiffness import table_1
from pipeline.units import to_si

RAW = Path(__file__).resolve().parents[2] / "raw"

#: Paper 001, Table 1: experimental E0 [kgf] (the published-value file), by the demo's
#: run-sheet chain key.
TABLE_1_E0_EXP_KGF = {f"c{name}": row.E0_exp_kgf for name, row in table_1().items()}


def committed(name: str) -> Path:
    folder = RAW / name
    if not (folder / "campaign.toml").is_file():
        pytest.skip(f"{folder} is absent")
    return folder


@pytest.mark.parametrize("name", list(DEMOS))
def test_regenerates_the_committed_files_byte_for_byte(tmp_path, name):
    folder = committed(name)
    DEMOS[name](tmp_path)
    written = sorted(path.name for path in tmp_path.iterdir())
    assert written == sorted(path.name for path in folder.iterdir())
    for file in written:
        assert (tmp_path / file).read_bytes() == (folder / file).read_bytes(), file


@pytest.mark.parametrize("name", list(DEMOS))
def test_run_sheet_is_marked_synthetic_and_does_not_name_the_truth(name):
    text = (committed(name) / "campaign.toml").read_text(encoding="utf-8")
    campaign = tomllib.loads(text)["campaign"]
    assert campaign["synthetic"] is True
    assert "chainbench simulate demo" in campaign["note"]
    assert "truth.json" not in text


def test_cli_writes_both_demos(tmp_path):
    result = CliRunner().invoke(app, ["simulate", "demo", "--out", str(tmp_path), "--json"])
    assert result.exit_code == 0, result.output
    assert [row["campaign"] for row in json.loads(result.stdout)["rows"]] == list(DEMOS)
    assert all((tmp_path / name / "campaign.toml").is_file() for name in DEMOS)


#: docs/published-values.md, Paper 001: eq. (20) with the printed coefficients [kgf].
EQ_20_KGF = {"c13x50": 1.0553e6, "c14x50": 1.1845e6, "c18x64": 2.0430e6, "c22x86": 3.3705e6}


def test_stiffness_demo_recovers_table_1(processed_demos):
    committed("stiffness-demo")
    summary = read_dataset(processed_demos / "stiffness-demo" / "summary.nc")
    assert sorted(summary["chain"].values) == sorted(TABLE_1_E0_EXP_KGF)
    assert summary.sizes["failed_run"] == 0
    for chain, published in TABLE_1_E0_EXP_KGF.items():
        row = summary.sel(chain=chain)
        assert int(row["n_specimens"]) == 4
        E0_exp = float(row["E0_exp"])
        assert E0_exp == pytest.approx(to_si(published, "kgf"), rel=0.01), chain
        # the band check reports what the data say, row by row, against eq. (20)
        discrepancy = E0_exp / to_si(EQ_20_KGF[chain], "kgf") - 1
        assert float(row["discrepancy"]) == pytest.approx(discrepancy, abs=2e-4), chain
        assert int(row["in_band"]) == int(0.03 <= discrepancy <= 0.06), chain


def test_engagement_demo_recovers_its_truth(processed_demos):
    folder = committed("engagement-demo")
    truth = json.loads((folder / "truth.json").read_text(encoding="utf-8"))["runs"]
    summary = read_dataset(processed_demos / "engagement-demo" / "summary.nc")
    assert summary.sizes["failed_run"] == 0
    assert sorted(summary["operating_point"].values) == sorted(truth)
    for name in ("N_u1", "N_u2"):
        measured = summary[f"{name}_meas"].sel(operating_point=list(truth)).to_numpy()
        expected = np.array([run[name] for run in truth.values()])
        np.testing.assert_allclose(measured, expected, rtol=0.03, err_msg=name)
    assert float(summary["k_fit"]) == pytest.approx(2.0, rel=0.05)
    assert float(summary["k_fit_ci_low"]) <= 2.0 <= float(summary["k_fit_ci_high"])


def test_pull_demo_declares_limits_and_one_specimen_fails_one():
    folder = committed("pull-demo")
    sheet = tomllib.loads((folder / "campaign.toml").read_text(encoding="utf-8"))
    limits = sheet["chains"]["c18x64"]
    assert limits["catalog"] == "18x64" and limits["proof_force_kN"] == 320
    runs = {run["id"]: run for run in sheet["runs"]}
    assert all(run["cycles"] == 1 for run in runs.values())
    truth = json.loads((folder / "truth.json").read_text(encoding="utf-8"))["runs"]
    failed = []
    for run_id, run in truth.items():
        # a strain channel needs no gauge length; a proof-load run names its proof force
        assert ("gauge_length_mm" in runs[run_id]) == (not run["truth"]["strain_channel"])
        assert runs[run_id].get("proof_force_kN") == (
            None if run["proof_force_N"] is None else run["proof_force_N"] / 1e3)
        if run["fracture_index"] is not None:
            if run["max_force_N"] < limits["min_breaking_force_kN"] * 1e3:
                failed.append((run_id, "min_breaking_force_kN"))
            if 100 * run["strain_at_fracture"] < limits["min_elongation_at_fracture_pct"]:
                failed.append((run_id, "min_elongation_at_fracture_pct"))
        else:
            strain = run["elongation_at_proof_m"] / run["truth"]["gauge_length"]
            if 100 * strain > limits["max_elongation_at_proof_pct"]:
                failed.append((run_id, "max_elongation_at_proof_pct"))
    assert failed == [("P18-D", "min_breaking_force_kN")]
    assert sum(run["fracture_index"] is not None for run in truth.values()) == 4
    assert all(path.stat().st_size < 300e3 for path in folder.iterdir())


def test_wear_demo_recovers_its_truth_and_the_pin_verdicts(processed_demos):
    folder = committed("wear-demo")
    truth = json.loads((folder / "truth.json").read_text(encoding="utf-8"))["runs"]
    summary = read_dataset(processed_demos / "wear-demo" / "summary.nc")
    assert summary.sizes["failed_run"] == 0
    assert sorted(summary["wear_run"].values) == sorted(truth)
    for run_id, run in truth.items():
        row = summary.sel(wear_run=run_id)
        cycles = run["abscissa"] == "cycles"
        suffix, per = ("_cycles", run["truth"]["cycle_rate"]) if cycles else ("", 1.0)
        assert float(row[f"wear_rate{suffix}"]) == pytest.approx(
            run["truth"]["wear_rate"] / per, rel=0.02), run_id
        assert str(row["wear_model"].values) == ("linear" if run["truth"]["run_in"] == 0
                                                 else "run-in"), run_id
        for limit in ("eq3", "lab"):
            if f"life_{limit}_s" not in run:
                assert np.isnan(float(row["limit_lab"]))
                continue
            true = run[f"life_{limit}_cycles" if cycles else f"life_{limit}_s"]
            assert float(row[f"life_{limit}{suffix}"]) == pytest.approx(true, rel=0.02)
    # the hand-worked load of Paper 004 on chain 16B: a pinned pin fails eq. (1), a clamped
    # one passes (docs/models/paper-004-pin-criterion.md, for z = 40)
    sheet = {run["id"]: run for run in tomllib.loads(
        (folder / "campaign.toml").read_text(encoding="utf-8"))["runs"]}
    for run_id in truth:
        clamped = sheet[run_id].get("pin_support") == "clamped"
        assert int(summary["pin_passes"].sel(wear_run=run_id)) == int(clamped), run_id
    assert all(path.stat().st_size < 20e3 for path in folder.iterdir())
