"""Roller chains on sprockets (Paper 002) as campaign runs: the demo and the bad inputs.

The fit of xi itself is tested on 20 seeds of the virtual bench in
tests/fit/test_roller_engagement.py; here the campaign must give the same
numbers from the files: run sheet -> engagement pipeline -> sprocket_point table.
"""

from __future__ import annotations

import json
import math
import shutil
from pathlib import Path

import pytest

from pipeline.campaign import process_campaign
from pipeline.runsheet import load_run_sheet

ROOT = Path(__file__).parents[1]
DEMO = ROOT / "raw" / "roller-demo"


@pytest.fixture(scope="module")
def demo(tmp_path_factory):
    output = tmp_path_factory.mktemp("processed") / "roller-demo"
    return process_campaign(DEMO, output)


def test_demo_xi_recovered_and_compared_with_the_involute(demo):
    truth = json.loads((DEMO / "truth.json").read_text())["runs"]
    summary = demo.summary
    assert demo.ok and summary.sizes["sprocket_point"] == 6
    for run in summary["sprocket_point"].values:
        row, xi = summary.sel(sprocket_point=run), truth[str(run)]["xi"]
        assert float(row["xi_fit"]) == pytest.approx(xi, rel=0.03)
        assert float(row["xi_fit_ci_low"]) <= xi <= float(row["xi_fit_ci_high"])
    involute = summary.sel(sprocket_point="R18-100")
    r_b = 8.0 * 18 * math.cos(math.radians(20.0)) / 2  # eq. (4) [mm]
    by_hand = math.sin(math.pi / 18 + math.acos(2 * r_b * math.sin(math.pi / 18) / 25.4))
    assert float(involute["xi_model"]) == pytest.approx(by_hand, rel=1e-9)
    assert int(involute["xi_model_covered"]) == 1
    assert float(involute["xi_min"]) == pytest.approx(math.sin(math.pi / 18))
    assert math.isnan(float(summary.sel(sprocket_point="R12-150")["xi_model"]))


def test_demo_speed_limit_of_eq_8_by_hand(demo):
    summary = demo.summary
    for run in summary["sprocket_point"].values:
        row = summary.sel(sprocket_point=run)
        g_lim = float(row["g_lim"]) * 1e-6  # J/mm^2
        # eq. (8) in the paper's units: 7400 scales with sqrt(G_lim / 3e-4); 16B: t, D, B, q
        n_max = (7400 * math.sqrt(g_lim / 3e-4) / (float(row["xi_fit"]) * 25.4)
                 * math.sqrt(15.88 * 17.02 / (2.70 * 25.4)))
        assert float(row["n_max"]) == pytest.approx(n_max, rel=2e-3)  # 7400 is rounded
        assert int(row["above_n_max"]) == int(float(row["roller_n"]) > n_max)
    assert list(summary["above_n_max"].values) == [0, 0, 0, 0, 0, 1]


def test_demo_outputs_and_report_section(demo):
    assert (demo.output / "roller_summary.csv").is_file()
    page = demo.report.read_text(encoding="utf-8")
    assert 'id="roller"' in page and "measured ξ" in page and "above n_max" in page
    run_page = (demo.output / "report-runs" / "R18-100.html").read_text(encoding="utf-8")
    assert "Ringing of the branch" in run_page


def _campaign(tmp_path: Path, runs: list[str], sprocket: str = "teeth = 18\nmodule_mm = 8\n"
              "profile_angle_deg = 20", chain: str = 'catalog = "16B"') -> Path:
    """A copy of demo logs with a run sheet of `runs` (ids of the demo)."""
    folder = tmp_path / "raw" / "c"
    folder.mkdir(parents=True)
    entries = []
    for run in runs:
        file = next(DEMO.glob(f"{run}.*")).name
        shutil.copy(DEMO / file, folder / file)
        entries.append(f'[[runs]]\nid = "{run}"\nkind = "roller-engagement"\nfile = "{file}"\n'
                       f'chain = "c"\nsprocket = "s"\nbranch_length_m = 1\n'
                       f'rpm = {run.split("-")[1]}\nE0_N = 1e7\n')
    (folder / "campaign.toml").write_text(
        f'[campaign]\nid = "c"\n[chains.c]\n{chain}\n[sprockets.s]\n{sprocket}\n\n'
        + "\n".join(entries), encoding="utf-8")
    return folder


def test_odd_teeth_are_refused_with_a_hint(tmp_path):
    sheet = load_run_sheet(_campaign(tmp_path, ["R18-100"], sprocket="teeth = 17"))
    assert not sheet.runs and "even number of teeth" in sheet.invalid_sprockets["s"].message
    assert "invalid" in sheet.invalid_runs[0].message


def test_chain_without_roller_is_refused(tmp_path):
    sheet = load_run_sheet(_campaign(tmp_path, ["R18-100"], chain='catalog = "18x64"'))
    assert not sheet.runs
    assert "roller_diameter_mm" in sheet.invalid_runs[0].message


def test_involute_that_cannot_hold_the_chain_fails_the_run(tmp_path):
    folder = _campaign(tmp_path, ["R18-100", "R18-200"], sprocket="teeth = 18\n"
                       "base_radius_mm = 80")  # above t / (2 sin(pi/z)) = 73.1 mm: eq. (3)
    result = process_campaign(folder, tmp_path / "out")
    assert len(result.failures) == 2 and "cannot hold" in result.failures[0].message


def test_one_speed_gives_no_xi_and_says_why(tmp_path):
    result = process_campaign(_campaign(tmp_path, ["R18-100"]), tmp_path / "out")
    assert not result.failures
    assert math.isnan(float(result.summary["xi_fit"][0]))
    assert int(result.summary["above_n_max"][0]) == -1
    assert "2 speeds or more" in result.summary.attrs["notes"]


def test_missing_force_channel_and_unit_problem_fail_the_run(tmp_path):
    folder = _campaign(tmp_path, ["R18-100", "R18-200"])
    text = (folder / "R18-100.csv").read_text().splitlines()
    (folder / "R18-100.csv").write_text("\n".join(
        [",".join(line.split(",")[::2]) for line in text]) + "\n")  # time, angle: no force
    (folder / "R18-200.csv").write_text((folder / "R18-200.csv").read_text().replace(
        "force [N]", "force [furlong]", 1))
    result = process_campaign(folder, tmp_path / "out")
    messages = {failure.run_id: failure.message for failure in result.failures}
    assert set(messages) == {"R18-100", "R18-200"}
    assert "force" in messages["R18-100"] and "furlong" in messages["R18-200"]
