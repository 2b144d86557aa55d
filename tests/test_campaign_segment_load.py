"""Segment-load runs as a campaign kind (Paper 003): the demo end to end, and bad inputs.

The fit's recovery over 20 seeds is tested at the fit level (tests/fit/test_segment_load.py);
here the campaign's wiring is checked against the demo's truth: ingest of every layout,
the per-run medians, the drum's fitted s with its interval, the summary table, the report.
"""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from pipeline.campaign import process_campaign
from pipeline.errors import RunSheetError
from pipeline.runsheet import load_run_sheet
from pipeline.store.netcdf import read_dataset

DEMO = Path(__file__).parents[1] / "raw" / "segment-load-demo"


@pytest.fixture(scope="module")
def demo(tmp_path_factory) -> tuple:
    """The demo processed once, with a broken copy of a log added (no segment 2)."""
    folder = tmp_path_factory.mktemp("raw") / "segment-load-demo"
    shutil.copytree(DEMO, folder)
    lines = (folder / "S34-1.csv").read_text(encoding="utf-8").splitlines()
    (folder / "no-segment.csv").write_text(
        "\n".join(",".join(line.split(",")[:3]) for line in lines) + "\n", encoding="utf-8")
    sheet = folder / "campaign.toml"
    sheet.write_text(sheet.read_text(encoding="utf-8") + '\n[[runs]]\nid = "broken"\n'
                     'kind = "segment-load"\nfile = "no-segment.csv"\nchain = "c34x126"\n'
                     'drum = "D34"\n', encoding="utf-8")
    truth = json.loads((folder / "truth.json").read_text(encoding="utf-8"))["runs"]
    return process_campaign(folder, folder.parent / "processed"), truth


def test_medians_and_fitted_s_against_the_truth(demo):
    result, truth = demo
    summary = read_dataset(result.output / "summary.nc")
    for run in summary["segment_point"].values.astype(str):
        row = summary.sel(segment_point=run)
        assert float(row["segment_contact_ratio"]) == pytest.approx(
            truth[run]["contact_force_ratio"], rel=0.01)
        if truth[run]["truth"]["with_side_force"]:
            assert float(row["segment_side_ratio"]) == pytest.approx(
                truth[run]["side_force_ratio"], rel=0.01)
        true_s = truth[run]["s"]
        assert float(row["segment_fit_s"]) == pytest.approx(true_s, rel=0.02)
        assert float(row["segment_fit_s_ci_low"]) <= true_s <= float(row["segment_fit_s_ci_high"])
        # the run sheet declares s = 55 mm: its model is not what was measured
        assert int(row["segment_model_agrees"]) == 0
    assert summary.sizes["segment_point"] == 5  # the broken run is not in it


def test_missing_channel_fails_alone_with_its_reason(demo):
    result, _ = demo
    failures = {failure.run_id: failure.message for failure in result.failures}
    assert set(failures) == {"broken"} and "segment_force_2" in failures["broken"]


def test_summary_table_and_report(demo):
    result, _ = demo
    table = (result.output / "segment_summary.csv").read_text(encoding="utf-8")
    assert table.startswith("segment_point,") and "segment_fit_s [m]" in table
    page = (result.output / "report.html").read_text(encoding="utf-8")
    assert 'id="segment"' in page and "campaign result" in page
    # the measured section stands for Paper 003: no catalogue reference case beside it
    assert "Reference case" not in page and "reference case (catalogue chain 34x126)" in page


def test_run_file_keeps_the_log_around_the_first_seatings(demo):
    result, truth = demo
    run = read_dataset(result.output / "S34-1.nc")
    time = run["trace_time"].values
    # one seating a second: half a period before the first seating (the log starts 0.22 s
    # before it), half a period after the fourth
    assert time[0] == 0.0 and float(run["start"][0]) < 0.5
    assert time[-1] == pytest.approx(float(run["stop"][3]) + 0.5, abs=0.01)
    plateau = (time > float(run["plateau_start"][0])) & (time < float(run["plateau_stop"][0]))
    level = truth["S34-1"]["truth"]["chain_force"][0]
    assert run["trace_F"].values[plateau].mean() == pytest.approx(level, rel=0.01)
    assert {"trace_F_K1", "trace_F_K2", "trace_F_P"} <= set(run.data_vars)


def test_run_page_shows_the_seatings_against_the_model(demo):
    result, truth = demo
    page = (result.output / "report-runs" / "S34-1.html").read_text(encoding="utf-8")
    assert 'id="segment"' in page and "<svg" in page
    assert "Seatings found: 30, of which 30 valid; excluded: none" in page
    run = read_dataset(result.output / "S34-1.nc")
    median = float(run["contact_force_ratio_median"])
    assert median == pytest.approx(truth["S34-1"]["contact_force_ratio"], rel=0.01)
    assert f'<td class="num">{median:.4g}</td>' in page
    assert f'<td class="num">{float(run["model_contact_force_ratio"]):.4g}</td>' in page
    campaign = (result.output / "report.html").read_text(encoding="utf-8")
    assert "chain c34x126, drum D34" in campaign and "F_K/F = " in campaign


@pytest.mark.parametrize("change, column", [
    ("contact_distance_mm = 55", "contact_distance_mm = 110"),  # s >= 2 k = 96.0 mm
    ("contact_distance_mm = 55", "contact_distance_mm = 40"),   # s < c = 45 mm
])
def test_drum_geometry_that_cannot_hold_is_refused(tmp_path, change, column):
    folder = tmp_path / "sheet"
    shutil.copytree(DEMO, folder)
    sheet = folder / "campaign.toml"
    sheet.write_text(sheet.read_text(encoding="utf-8").replace(change, column),
                     encoding="utf-8")
    loaded = load_run_sheet(sheet)
    assert not loaded.runs and len(loaded.invalid_runs) == 5
    assert all(isinstance(error, RunSheetError) and "c <= s < 2 k" in error.message
               and error.column == "drums.D34.contact_distance_mm"
               for error in loaded.invalid_runs)


def test_fitted_parameter_must_be_stated(tmp_path):
    folder = tmp_path / "sheet"
    shutil.copytree(DEMO, folder)
    sheet = folder / "campaign.toml"
    sheet.write_text(sheet.read_text(encoding="utf-8").replace('fitted = "s"\n', ""),
                     encoding="utf-8")
    loaded = load_run_sheet(sheet)
    assert not loaded.runs and "D34" in loaded.invalid_drums
