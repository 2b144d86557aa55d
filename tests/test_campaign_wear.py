"""Wear runs through a campaign: the virtual bench's truth comes back, bad logs fail alone.

The campaign is written by ``chainbench simulate wear`` (run-in, then 0.75 um/h per
pitch on a 10-pitch section of chain 16B, read every 5 h for 300 h with 10 um of
noise), in every layout the readers take; ``truth.json`` beside it holds the true
lives (the true curve's crossing of each limit). Broken copies of its logs sit beside
the good ones: each fails with a typed error naming its file, the others are processed.
"""

from __future__ import annotations

import json
import math
import shutil
from pathlib import Path

import pandas as pd
import pytest

from pipeline.campaign import process_campaign
from pipeline.store.netcdf import read_dataset
from pipeline.theory.pin_criterion import check_pin
from pipeline.units import to_si
from pipeline.wear_summary import running_name

HOUR = 3600.0
RATE = 0.75e-6 / HOUR  # the bench's true wear rate per pitch [m/s]
LAYOUTS = ("plain", "european", "machine", "xlsx", "tdms")
#: Paper 004's hand-worked example (docs/models/paper-004-pin-criterion.md), chain 16B.
PIN = ("--f-max-kn", "12", "--sigma-t-mpa", "800", "--wear-coefficient", "1")


def _entry(run_id: str, file: str, **keys) -> str:
    entry = {"id": run_id, "kind": "wear", "file": file, "chain": "c16B",
             "section_pitches": 10, "elongation_reference": "nominal", "sprocket_teeth": 40,
             **keys}
    return "\n[[runs]]\n" + "".join(f"{key} = {json.dumps(value)}\n"
                                    for key, value in entry.items())


@pytest.fixture(scope="module")
def lab(simulated, tmp_path_factory) -> tuple[Path, dict]:
    """The simulated campaign with broken copies of a log, processed once."""
    source = simulated("wear", "--layout", *LAYOUTS, "--limit-pct", "3", *PIN,
                       "--load-kn", "10", "--speed", "1.5", "--campaign", "wear-lab")
    folder = tmp_path_factory.mktemp("raw") / "wear-lab"
    shutil.copytree(source, folder)
    good = (folder / "W16B-plain-1.csv").read_text(encoding="utf-8").splitlines()
    head, rows = good[0], good[1:]
    broken = {
        # no section length: the time, load and speed alone
        "no-length.csv": "\n".join(",".join(line.split(",")[:1] + line.split(",")[2:])
                                   for line in good),
        # the section's length in a column named as a reading: taken for an elongation
        "unnamed.csv": "\n".join([head.replace("section length", "reading"), *rows]),
        # the length written in mm but labelled m: 1000 times too long
        "metres.csv": "\n".join([head.replace("section length [mm]", "section length [m]"),
                                 *rows]),
        # two readings: no wear rate
        "two-readings.csv": "\n".join([head, *rows[:2]]),
    }
    sheet = folder / "campaign.toml"
    text = sheet.read_text(encoding="utf-8")
    for name, content in broken.items():
        (folder / name).write_text(content + "\n", encoding="utf-8")
        text += _entry(name.removesuffix(".csv"), name)
    text += _entry("no-teeth", "W16B-plain-1.csv").replace("sprocket_teeth = 40\n", "")
    sheet.write_text(text, encoding="utf-8")
    truth = json.loads((folder / "truth.json").read_text(encoding="utf-8"))["runs"]
    return process_campaign(folder, folder.parent / "processed"), truth


def test_every_layout_gives_back_the_true_wear_rate_and_lives(lab):
    result, truth = lab
    summary = result.summary
    assert sorted(summary["wear_run"].values) == sorted(truth)
    for run_id, true in truth.items():
        row = summary.sel(wear_run=run_id)
        assert float(row["wear_rate"]) == pytest.approx(RATE, rel=0.02), run_id
        assert str(row["wear_model"].values) == "run-in"
        for limit in ("eq3", "lab"):
            assert float(row[f"limit_{limit}"]) == pytest.approx(true[f"limit_{limit}_m"])
            life = float(row[f"life_{limit}"])
            assert life == pytest.approx(true[f"life_{limit}_s"], rel=0.02), (run_id, limit)
            assert float(row[f"life_{limit}_ci_low"]) < life < float(row[f"life_{limit}_ci_high"])
    # a 95 % interval: the true life inside for most of the five logs
    covered = sum(float(summary.sel(wear_run=run)[f"life_{limit}_ci_low"])
                  <= truth[run][f"life_{limit}_s"]
                  <= float(summary.sel(wear_run=run)[f"life_{limit}_ci_high"])
                  for run in truth for limit in ("eq3", "lab"))
    assert covered >= 8


def test_limits_are_eq_3_for_the_sprocket_and_the_labs_percentage(lab):
    result, truth = lab
    row = result.summary.isel(wear_run=0)
    pitch = to_si(25.4, "mm")  # 16B
    # nominal reference: the jump-off pitch error 2.5 psi t / z = 2 t / z with psi = 0.8
    assert float(row["limit_eq3"]) == pytest.approx(2 * pitch / 40)
    assert float(row["limit_lab"]) == pytest.approx(0.03 * pitch)
    assert int(row["lab_limit_within_eq3"]) == 1


def test_pin_criterion_is_the_hand_worked_example_beside_the_measured_wear(lab):
    result, _ = lab
    row = result.summary.isel(wear_run=0)
    # docs/models/paper-004-pin-criterion.md: delta_t1 = 1.168 mm, delta_d = 0.584 mm,
    # K = 1: d_k = 8.67 mm, required 9.25 mm, the 8.28 mm pin fails
    assert float(row["pin_allowed_growth"]) == pytest.approx(1.168e-3, abs=1e-6)
    assert float(row["pin_allowed_wear"]) == pytest.approx(0.584e-3, abs=1e-6)
    assert float(row["pin_critical_diameter"]) == pytest.approx(8.67e-3, abs=0.01e-3)
    assert int(row["pin_passes"]) == 0
    # the pin wear the growth over the log implies, eq. (2): (growth / 2) K_e
    growth = float(row["wear_growth_measured"])
    assert float(row["pin_wear_measured"]) == pytest.approx(growth / 2)
    assert float(row["pin_wear_share"]) == pytest.approx(growth / 1.168e-3, rel=1e-3)
    # the growth over 300 h: the run-in (0.03 mm) and 300 h of wear, per pitch
    assert growth == pytest.approx(0.03e-3 * -math.expm1(-30) + RATE * 300 * HOUR, rel=0.05)


def test_pin_criterion_agrees_with_the_theory_module(lab):
    result, _ = lab
    row = result.summary.isel(wear_run=0)
    check = check_pin(8.28e-3, 25.4e-3, 40, 12e3, 29.78e-3, 25.45e-3, 800e6, 1.0)
    assert float(row["pin_required_diameter"]) == pytest.approx(check.required_diameter)


def test_bad_logs_and_a_bad_run_sheet_entry_fail_alone_with_their_reason(lab):
    result, truth = lab
    failures = {failure.run_id: failure for failure in result.failures}
    assert set(failures) == {"no-length", "unnamed", "metres", "two-readings", "runs[9]"}
    assert "no length or gauge column" in failures["no-length"].message
    assert "columns = {length" in failures["unnamed"].message
    assert "mm given as m" in failures["metres"].message
    assert "2 readings" in failures["two-readings"].message
    assert "a wear run needs sprocket_teeth" in failures["runs[9]"].message
    for run_id in ("no-length", "unnamed", "metres", "two-readings"):
        assert failures[run_id].error.file == f"{run_id}.csv"
    assert result.summary.sizes["wear_run"] == len(truth)
    assert set(result.summary["failed_run"].values) == set(failures)


def test_summary_table_and_run_file(lab):
    result, truth = lab
    table = pd.read_csv(result.output / "wear_summary.csv", index_col=0)
    assert sorted(table.index) == sorted(truth)
    assert "wear_rate [m s-1]" in table.columns and "life_eq3_ci_high [s]" in table.columns
    assert (table["pin_passes"] == 0).all()
    run = read_dataset(result.output / "W16B-plain-1.nc")
    assert run.attrs["kind"] == "wear" and run.attrs["abscissa"] == "time"
    assert run.sizes["reading"] == 61 and list(run["limit"].values) == ["eq3", "lab"]
    assert float(run["load"].mean()) == pytest.approx(10e3)
    assert float(run["speed"].mean()) == pytest.approx(1.5)
    assert run["life"].attrs["units"] == "s"
    assert running_name("life_eq3", "cycles") not in result.summary


def test_a_log_over_cycles_counts_its_life_in_cycles(simulated, tmp_path):
    folder = simulated("wear", "--abscissa", "cycles", "--run-in-um", "0",
                       "--cycle-rate", "2", "--campaign", "wear-cycles")
    result = process_campaign(folder, tmp_path / "processed")
    assert result.ok, [failure.message for failure in result.failures]
    truth = next(iter(json.loads((folder / "truth.json").read_text())["runs"].values()))
    row = result.summary.isel(wear_run=0)
    assert str(row["wear_model"].values) == "linear"
    assert float(row["wear_rate_cycles"]) == pytest.approx(RATE / 2, rel=0.02)
    assert float(row["life_eq3_cycles"]) == pytest.approx(truth["life_eq3_cycles"], rel=0.02)
    assert "wear_rate" not in result.summary
