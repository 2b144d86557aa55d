"""The campaign flow: every run processed, bad runs isolated, raw/ never written."""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from pipeline import run_campaign
from pipeline.campaign import process_campaign
from pipeline.cli import app
from pipeline.store.netcdf import read_dataset

runner = CliRunner()

BROKEN_RUNS = """
[[runs]]
id = "T18-empty"
kind = "tensile"
file = "empty.csv"
chain = "c18x64"
gauge_length_mm = 900

[[runs]]
id = "T18-escape"
kind = "tensile"
file = "../outside.csv"
chain = "c18x64"
gauge_length_mm = 900
"""


def tree_hash(folder: Path) -> str:
    digest = hashlib.sha256()
    for path in sorted(folder.rglob("*")):
        digest.update(str(path.relative_to(folder)).encode())
        if path.is_file():
            digest.update(path.read_bytes())
    return digest.hexdigest()


@pytest.fixture(scope="module")
def campaign(tmp_path_factory) -> Path:
    raw = tmp_path_factory.mktemp("lab") / "raw" / "c18"
    result = runner.invoke(app, ["simulate", "tensile", "--out", str(raw), "--specimens", "3",
                                 "--seed", "7", "--campaign", "c18"])
    assert result.exit_code == 0, result.output
    (raw / "empty.csv").write_text("")
    sheet = raw / "campaign.toml"
    sheet.write_text(sheet.read_text() + BROKEN_RUNS)
    return raw


def test_good_runs_processed_bad_runs_listed(campaign, tmp_path):
    before = tree_hash(campaign)
    result = process_campaign(campaign, tmp_path / "out")
    assert tree_hash(campaign) == before  # raw/ is only read
    assert sorted(result.run_files) == ["T18-1", "T18-2", "T18-3"]
    failed = {failure.run_id: failure.message for failure in result.failures}
    assert set(failed) == {"T18-empty", "runs[4]"}
    assert "empty.csv" in failed["T18-empty"]
    assert "leaves the campaign folder" in failed["runs[4]"]
    assert not result.ok

    truth = json.loads((campaign / "truth.json").read_text())["runs"]
    true_mean = np.mean([run["truth"]["E0"] for run in truth.values()])
    summary = read_dataset(tmp_path / "out" / "summary.nc")
    assert float(summary["E0_exp"].sel(chain="c18x64")) == pytest.approx(true_mean, rel=5e-3)
    assert list(summary["failed_run"].values) == ["runs[4]", "T18-empty"]
    csv = (tmp_path / "out" / "summary.csv").read_text().splitlines()
    assert csv[0].startswith("chain,E0_exp [N],E0_exp_ci_low [N],")
    assert csv[1].startswith("c18x64,")


def test_run_file_carries_provenance(campaign, tmp_path):
    process_campaign(campaign, tmp_path)
    run = read_dataset(tmp_path / "T18-2.nc")
    raw_bytes = (campaign / "T18-2.csv").read_bytes()
    assert run.attrs["raw_sha256"] == hashlib.sha256(raw_bytes).hexdigest()
    sheet_bytes = (campaign / "campaign.toml").read_bytes()
    assert run.attrs["run_sheet_sha256"] == hashlib.sha256(sheet_bytes).hexdigest()
    assert json.loads(run.attrs["run_entry"])["id"] == "T18-2"
    assert run["force"].attrs["units"] == "N"
    assert set(run["fit_E0"].dims) == {"cycle", "branch"}
    assert list(run["gauge"].values) == ["gauge_1", "gauge_2"]  # the bench's two gauges
    mean = run["gauge_elongation"].mean("gauge")
    assert run["elongation"].values == pytest.approx(mean.values)
    assert float(run["specimen_E0_ci_low"]) < float(run["specimen_E0"]) < float(
        run["specimen_E0_ci_high"])


def test_python_api_returns_summary(campaign, tmp_path):
    summary = run_campaign(campaign, tmp_path)
    assert summary["E0_exp"].attrs["units"] == "N"
    assert "c18x64" in summary["chain"].values


def test_cli_exit_code_and_json(campaign, tmp_path):
    result = runner.invoke(app, ["run", str(campaign), "--output", str(tmp_path), "--json"])
    assert result.exit_code == 1  # two runs failed
    document = json.loads(result.stdout)
    (report,) = document
    assert {row["run"] for row in report["failed_runs"]} == {"T18-empty", "runs[4]"}
    assert report["chains"][0]["chain"] == "c18x64"


def test_validate_reports_without_processing(campaign, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    result = runner.invoke(app, ["validate", str(campaign)])
    assert result.exit_code == 1
    assert "empty.csv" in result.output
    assert "leaves the campaign folder" in result.output
    assert not (tmp_path / "processed").exists()
